#!/usr/bin/env python3
"""Host harnesses for the occam kernels in this directory.

Each configuration names a kernel source (kNN.occ), the oc options it is compiled with, and a
harness: an occam PROC that initialises fixed data, prints "GO", calls the kernel R times in a
`SEQ rr = 0 FOR R` loop, prints "END" and exits. R is a compile-time constant, so the R = 1 and
R = 2 harnesses compile to code of the same size and layout (they differ in an `ldc 1` / `ldc 2`),
and the difference of their two runs is one kernel call plus one iteration of the loop.

  harness.py list               the configuration names, one a line
  harness.py source NAME R      the harness source for NAME calling the kernel R times
  harness.py options NAME       the oc options NAME's kernel is compiled with (may be empty)
  harness.py kernel NAME        the kernel source NAME uses (k01 for k01.occ)
  harness.py label NAME         a short description of NAME's parameters

Python 3 standard library only.
"""
import sys
from collections import namedtuple

Config = namedtuple("Config", "name kernel options label decls init call")

# oc options: range checks on (oc's default, halt mode), off (-k), alias checks off (-a).
RC, NRC, NOALIAS = (), ("-k",), ("-a",)

# --- declarations and initialisation shared by several kernels --------------------------------

X_Y_100 = ["[100]REAL64 x, y :"]
X_Y_100_INIT = [
    "SEQ i = 0 FOR 100",
    "  SEQ",
    "    x[i] := REAL64 ROUND i",
    "    y[i] := 1.0(REAL64)",
]

RE_IM_64 = ["[64]REAL64 re, im :"]
RE_IM_64_INIT = [
    "SEQ i = 0 FOR 64",
    "  SEQ",
    "    re[i] := REAL64 ROUND i",
    "    im[i] := 1.0(REAL64)",
]

INT_X_100 = ["[100]INT x :", "INT s :"]
INT_X_100_INIT = ["SEQ i = 0 FOR 100", "  x[i] := i"]

# k07: rev[i] = i with its 6 bits reversed, a[i] = i.
BITREV_INIT = [
    "SEQ i = 0 FOR 64",
    "  SEQ",
    "    a[i] := i",
    "    INT v :",
    "    SEQ",
    "      v := 0",
    "      SEQ b = 0 FOR 6",
    "        IF",
    "          ((i >> b) /\\ 1) = 1",
    "            v := v \\/ (1 << (5 - b))",
    "          TRUE",
    "            SKIP",
    "      rev[i] := v",
]

PIVOT_ROW = ["[6]REAL64 pivot, row :"]
PIVOT_ROW_INIT = [
    "SEQ i = 0 FOR 6",
    "  SEQ",
    "    pivot[i] := REAL64 ROUND (i + 1)",
    "    row[i] := 10.0(REAL64)",
]

# k12 clamps its argument in place, so each call gets its own copy of the data (xs[rr]): the
# second call then sees the same values as the first.
XS = ["[2][100]REAL64 xs :"]
XS_INIT = ["SEQ j = 0 FOR 2", "  SEQ i = 0 FOR 100", "    xs[j][i] := REAL64 ROUND i"]


def table_1100():
    """k01_codeoff: a 4.4 KB VAL table, 20 values a line. oc puts it in the harness's code,
    which pushes the kernel's code and the harness's vectorspace past the 4 KB of on-chip RAM."""
    lines = []
    for i in range(0, 1100, 20):
        head = "VAL [1100]INT tab IS [" if i == 0 else "  "
        tail = "," if i + 20 < 1100 else "] :"
        lines.append(head + ", ".join(str(j) for j in range(i, min(i + 20, 1100))) + tail)
    return lines


DAXPY = "daxpy100 (2.0(REAL64), x, y)"

CONFIGS = [
    Config("k01", "k01", RC, "n=100 (fixed)", X_Y_100, X_Y_100_INIT, DAXPY),
    Config("k02_rc", "k02", RC, "n=100", X_Y_100, X_Y_100_INIT,
           "daxpyn (100, 2.0(REAL64), x, y)"),
    Config("k02_nrc", "k02", NRC, "n=100, -k", X_Y_100, X_Y_100_INIT,
           "daxpyn (100, 2.0(REAL64), x, y)"),
    Config("k13c_rc", "k13c", RC, "n=100", X_Y_100, X_Y_100_INIT,
           "daxpynab (100, 2.0(REAL64), x, y)"),
    Config("k13c_nrc", "k13c", NRC, "n=100, -k", X_Y_100, X_Y_100_INIT,
           "daxpynab (100, 2.0(REAL64), x, y)"),
    Config("k03", "k03", RC, "n=100", ["[100]REAL32 x, y :"],
           ["SEQ i = 0 FOR 100", "  SEQ", "    x[i] := REAL32 ROUND i", "    y[i] := 1.0(REAL32)"],
           "saxpy100 (2.0(REAL32), x, y)"),
    Config("k04", "k04", RC, "n=100", X_Y_100 + ["REAL64 s :"], X_Y_100_INIT, "dot100 (x, y, s)"),
    Config("k05", "k05", RC, "6x6", ["[6][6]REAL64 m :", "[6]REAL64 v, r :"],
           ["SEQ i = 0 FOR 6", "  SEQ", "    v[i] := REAL64 ROUND i", "    r[i] := 0.0(REAL64)",
            "    SEQ j = 0 FOR 6", "      m[i][j] := REAL64 ROUND (i + j)"],
           "matvec6 (m, v, r)"),
    Config("k06_rc_h16", "k06", RC, "h=16, nb=2", RE_IM_64, RE_IM_64_INIT,
           "butterfly (16, 2, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k06_rc_h1", "k06", RC, "h=1, nb=32", RE_IM_64, RE_IM_64_INIT,
           "butterfly (1, 32, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k06_nrc_h16", "k06", NRC, "h=16, nb=2, -k", RE_IM_64, RE_IM_64_INIT,
           "butterfly (16, 2, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k06_nrc_h1", "k06", NRC, "h=1, nb=32, -k", RE_IM_64, RE_IM_64_INIT,
           "butterfly (1, 32, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k13d_rc_h16", "k13d", RC, "h=16, nb=2", RE_IM_64, RE_IM_64_INIT,
           "butterflyab (16, 2, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k13d_a_h16", "k13d", NOALIAS, "h=16, nb=2, -a", RE_IM_64, RE_IM_64_INIT,
           "butterflyab (16, 2, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k13d_nrc_h16", "k13d", NRC, "h=16, nb=2, -k", RE_IM_64, RE_IM_64_INIT,
           "butterflyab (16, 2, 0.5(REAL64), 0.25(REAL64), re, im)"),
    Config("k07_rc", "k07", RC, "6-bit reversal (28 swaps)", ["[64]INT rev, a :"], BITREV_INIT,
           "bitrev64 (rev, a)"),
    Config("k07_nrc", "k07", NRC, "6-bit reversal, -k", ["[64]INT rev, a :"], BITREV_INIT,
           "bitrev64 (rev, a)"),
    Config("k08", "k08", RC, "7 iterations, x=2", ["[8]INT c :", "INT p :"],
           ["SEQ i = 0 FOR 8", "  c[i] := i + 1"], "horner8 (c, 2, p)"),
    Config("k09", "k09", RC, "n=100", INT_X_100, INT_X_100_INIT, "isum100 (x, s)"),
    Config("k13b", "k13b", RC, "n=100", INT_X_100, INT_X_100_INIT, "isum100ab (x, s)"),
    Config("k10", "k10", RC, "a..h = 1..8", ["REAL64 r, r2 :"], ["SKIP"],
           "deepexpr (1.0(REAL64), 2.0(REAL64), 3.0(REAL64), 4.0(REAL64), 5.0(REAL64), "
           "6.0(REAL64), 7.0(REAL64), 8.0(REAL64), r, r2)"),
    Config("k11_k0", "k11", RC, "k=0 (6 iter)", PIVOT_ROW, PIVOT_ROW_INIT,
           "elimrow (0, 0.5(REAL64), pivot, row)"),
    Config("k11_k3", "k11", RC, "k=3 (3 iter)", PIVOT_ROW, PIVOT_ROW_INIT,
           "elimrow (3, 0.5(REAL64), pivot, row)"),
    Config("k12_in", "k12", RC, "all in range", XS, XS_INIT,
           "clamp100 (-1.0(REAL64), 1000.0(REAL64), xs[rr])"),
    Config("k12_lo", "k12", RC, "all below lo", XS, XS_INIT,
           "clamp100 (1000.0(REAL64), 2000.0(REAL64), xs[rr])"),
    Config("k13a", "k13a", RC, "n=100", X_Y_100, X_Y_100_INIT, "daxpy100ab (2.0(REAL64), x, y)"),
    # Placement variants of k01: external memory costs 3 cycles a word where on-chip RAM
    # (#80000000..#80000FFF) costs 1. x and y PLACEd at words #4000 / #4100 = #80010000 / #80010400.
    Config("k01_off", "k01", RC, "n=100, x,y PLACEd off chip",
           ["[100]REAL64 x :", "PLACE x AT #4000 :", "[100]REAL64 y :", "PLACE y AT #4100 :"],
           X_Y_100_INIT, DAXPY),
    Config("k01_codeoff", "k01", RC, "n=100, 4.4 KB table in harness code",
           table_1100() + X_Y_100,
           ["SEQ i = 0 FOR 100", "  SEQ", "    x[i] := REAL64 ROUND tab[i*11]",
            "    y[i] := 1.0(REAL64)"],
           DAXPY),
]
BY_NAME = {c.name: c for c in CONFIGS}


def source(c, repeats):
    """The harness for configuration c, calling its kernel `repeats` times."""
    lines = [
        '#INCLUDE "hostio.inc"',
        "PROC harness (CHAN OF SP fs, ts, []INT memory)",
        '  #USE "hostio.lib"',
        '  #USE "%s.t8c"' % c.kernel,  # the kernel, compiled by oc to kNN.t8c
        "  VAL INT R IS %d :" % repeats,
    ]
    lines += ["  " + d for d in c.decls]
    lines += ["  SEQ"] + ["    " + i for i in c.init]
    lines += [
        '    so.write.string.nl (fs, ts, "GO")',
        "    SEQ rr = 0 FOR R",
        "      " + c.call,
        '    so.write.string.nl (fs, ts, "END")',
        "    so.exit (fs, ts, sps.success)",
        ":",
    ]
    return "\n".join(lines) + "\n"


def usage():
    sys.stderr.write(__doc__.split("\n\n")[2] + "\n")
    sys.exit(2)


def config(name):
    if name not in BY_NAME:
        sys.stderr.write("harness.py: no configuration %r (harness.py list names them)\n" % name)
        sys.exit(2)
    return BY_NAME[name]


def main(argv):
    if argv == ["list"]:
        print("\n".join(c.name for c in CONFIGS))
    elif len(argv) == 3 and argv[0] == "source" and argv[2].isdigit() and int(argv[2]) > 0:
        sys.stdout.write(source(config(argv[1]), int(argv[2])))
    elif len(argv) == 2 and argv[0] == "options":
        print(" ".join(config(argv[1]).options))
    elif len(argv) == 2 and argv[0] == "kernel":
        print(config(argv[1]).kernel)
    elif len(argv) == 2 and argv[0] == "label":
        print(config(argv[1]).label)
    else:
        usage()


if __name__ == "__main__":
    main(sys.argv[1:])
