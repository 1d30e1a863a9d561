#!/usr/bin/env python3
"""Writes the seed corpora of the instruction-set simulator's fuzz targets (fuzz/iss_harness.hpp):
fuzz/corpus/decoder (a configuration byte, then machine code), fuzz/corpus/sp (framed SP request
bodies) and fuzz/corpus/asm (assembler source). Each seed is a small program or session that means
something; libFuzzer mutates from there. Operation codes are read from t800/isa/opcode.cpp, the
encodings are the compiler writer's guide's (pfix/nfix chains, opr, `ldc code; fpentry`).

    python3 fuzz/make_iss_seeds.py      # from anywhere; rewrites the three directories' seeds
"""
import re
import struct
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "fuzz" / "corpus"

table = {}
for name, kind, code in re.findall(r'\{Op::\w+, "(\w+)", ([DOF]), (0x[0-9A-Fa-f]+)\}',
                                   (ROOT / "t800/isa/opcode.cpp").read_text()):
    table[name] = (kind, int(code, 16))


def prefixed(function, operand):
    """A direct function with its pfix/nfix chain (CWG, "prefixing")."""
    if 0 <= operand < 16:
        return bytes([function << 4 | operand])
    if operand >= 16:
        return prefixed(0x2, operand >> 4) + bytes([function << 4 | (operand & 15)])
    return prefixed(0x6, (~operand) >> 4) + bytes([function << 4 | (operand & 15)])


def ins(name, operand=0):
    kind, code = table[name]
    if kind == "D":
        operand = operand - (1 << 32) if operand >= 1 << 31 else operand
        return prefixed(code, operand)
    if kind == "O":
        return prefixed(0xF, code)
    return prefixed(0x4, code) + prefixed(0xF, table["fpentry"][1])  # ldc code; fpentry


def program(*parts):
    out = b""
    for p in parts:
        out += ins(*p) if isinstance(p, tuple) else ins(p)
    return out


# Configuration byte (iss_harness.cpp run_once): bits 0-1 processor (T800-20, T805-20, T414-20,
# T805-30), bits 2-4 installed memory (4 K, 6 K, 8 K, 12 K, 64 K, 100000, 256 K, 1 M), bit 5 links
# connected, bits 6-7 boot link.
T800, T805, T414 = 0, 1, 2
def config(processor, memory=4, links=False, boot_link=0):
    return bytes([processor | memory << 2 | (0x20 if links else 0) | boot_link << 6])


decoder = {
    "arithmetic": config(T800) + program(("ajw", 16), ("ldc", 7), ("ldc", 5), "add", ("ldc", -3),
                                         "mul", ("stl", 1), ("ldl", 1), ("adc", 1000), "stopp"),
    "overflow_error": config(T805) + program("sethalterr", "mint", ("ldc", -1), "div", "stopp"),
    # A counted loop: lend back to `top` until the count runs out (offsets worked out by hand: the
    # loop body is ldlp 2; ldc 4; lend = 4 bytes from top to after lend).
    "loop": config(T800) + program(("ajw", 16), ("ldc", 0), ("stl", 2), ("ldc", 5), ("stl", 3),
                                   ("ldlp", 2), ("ldc", 4), "lend", "stopp"),
    "link_output": config(T800, links=True) + program(("ajw", 16), ("ldc", 0x41), ("stl", 0),
                                                      ("ldlp", 0), ("ldc", 0x80000000), ("ldc", 4),
                                                      "out", ("ldc", 0x80000000), ("ldc", 7),
                                                      "outbyte", "stopp"),
    "link_input": config(T805, links=True, boot_link=1) + program(
        ("ajw", 16), ("ldlp", 1), ("ldc", 0x80000014), ("ldc", 8), "in", ("ldl", 1), "stopp"),
    "t414_float": config(T414, memory=1) + program(
        ("ajw", 16), ("ldc", 0x3F800000), "unpacksn", ("stl", 1), ("stl", 2), ("ldc", 254),
        ("stl", 0), ("ldc", 0), ("ldl", 1), ("ldl", 1), "lmul", "norm", "postnormsn", "roundsn",
        "cflerr", "ldinf", "cflerr", "stopp"),
    "fpu": config(T800, memory=3) + program(("ajw", 16), "fpldzerosn", "fpldzerosn", "fpadd",
                                            "fpuabs", ("ldlp", 1), "fpstnlsn", "fpurz",
                                            "fpldzerodb", "fpdup", "fpdiv", "fpchkerror", "stopp"),
    "wild_access": config(T805, memory=5) + program(("ldc", 0x7FFFFFF0), ("ldnl", 0),
                                                    ("ldc", 0x12345678), "sb", "stopp"),
    "timer": config(T805, memory=4) + program(("ajw", 16), ("ldc", 0), "sttimer", "ldtimer",
                                              ("adc", 50), "tin", "ldtimer", "stopp"),
    "undefined_operation": config(T800) + program(("ajw", 16), ("ldc", 1)) + prefixed(0xF, 0x1FE),
    "processes": config(T800, memory=6) + program(
        ("ajw", 32), "mint", "sthf", "mint", "stlf", ("ldc", 3), ("ldlp", -8), "startp",
        "testerr", "clrhalterr", "testhalterr", "ldpri", "stopp", "stopp"),
    "runaway": config(T414, memory=7) + bytes([0xF0]) * 3 + prefixed(0x0, -2),  # rev x 3, then a j to itself
    "move2d": config(T800) + program(("ajw", 16), ("ldc", 4), ("ldc", 8), ("ldc", 2),
                                     "move2dinit", ("ldc", 0x80000070), ("ldc", 0x80000200),
                                     ("ldc", 4), "move2dall", ("ldc", 7), "bitcnt", "stopp"),
}


def le16(v):
    return struct.pack("<H", v & 0xFFFF)


def le32(v):
    return struct.pack("<I", v & 0xFFFFFFFF)


def slice_(s):
    s = s.encode() if isinstance(s, str) else s
    return le16(len(s)) + s


def body(*fields):
    b = b"".join(fields)
    return b + (b"\0" if len(b) % 2 else b"")  # the hostio library pads to an even length


def framed(*bodies):
    """First byte even: a sequence of framed packets (iss_harness.cpp serve_sp_requests)."""
    return b"\0" + b"".join(le16(len(b)) + b for b in bodies)


OPEN, CLOSE, READ, WRITE, GETS, PUTS, FLUSH, SEEK, TELL, EOF, FERROR, REMOVE, RENAME = range(10, 23)
GETKEY, POLLKEY, GETENV, TIME, SYSTEM, EXIT = range(30, 36)
COMMANDLINE, CORE, VERSION = 40, 41, 42
TEXT, BINARY = b"\2", b"\1"
R, W, A, RPLUS, WPLUS = b"\1", b"\2", b"\3", b"\4", b"\5"

sp = {
    "read_file": framed(body(bytes([OPEN]), slice_("a.txt"), TEXT, R),
                        body(bytes([READ]), le32(3), le16(100)),
                        body(bytes([EOF]), le32(3)), body(bytes([CLOSE]), le32(3))),
    "write_seek_tell": framed(body(bytes([OPEN]), slice_("new.bin"), BINARY, WPLUS),
                              body(bytes([WRITE]), le32(3), slice_("hello, world")),
                              body(bytes([FLUSH]), le32(3)),
                              body(bytes([SEEK]), le32(3), le32(2), le32(1)),
                              body(bytes([TELL]), le32(3)),
                              body(bytes([GETS]), le32(3), le16(20)),
                              body(bytes([FERROR]), le32(3)), body(bytes([CLOSE]), le32(3)),
                              body(bytes([RENAME]), slice_("new.bin"), slice_("sub/renamed")),
                              body(bytes([REMOVE]), slice_("sub/renamed"))),
    "host_requests": framed(body(bytes([GETENV]), slice_("ISEARCH")), body(bytes([TIME])),
                            body(bytes([VERSION])), body(bytes([COMMANDLINE, 1])),
                            body(bytes([CORE]), le32(8), le16(16)), body(bytes([POLLKEY])),
                            body(bytes([GETKEY])),
                            body(bytes([PUTS]), le32(1), slice_("to stdout")),
                            body(bytes([EXIT]), le32(999999999)),
                            body(bytes([PUTS]), le32(1), slice_("after exit"))),
    "escapes": framed(body(bytes([OPEN]), slice_("../outside/secret"), BINARY, W),
                      body(bytes([OPEN]), slice_("/etc/passwd"), TEXT, R),
                      body(bytes([OPEN]), slice_("out"), BINARY, A),
                      body(bytes([OPEN]), slice_("sub/../../outside/new"), TEXT, W),
                      body(bytes([RENAME]), slice_("a.txt"), slice_("../stolen")),
                      body(bytes([REMOVE]), slice_("out")),
                      body(bytes([REMOVE]), slice_("../outside/secret"))),
    "system_refused": framed(body(bytes([SYSTEM]), slice_("touch ../outside/pwned"))),
    "one_body_gets": b"\1" + body(bytes([GETS]), le32(0), le16(10)),
    "short_and_unknown": framed(b"", bytes([OPEN]), bytes([READ, 3]), bytes([53, 0, 0, 0, 0, 0]),
                                bytes([200]) * 8, body(bytes([CLOSE]), le32(0x7FFFFFFF))),
}

asm = {
    "hello.s": """-- output "hi" on link 0, then stop
        ajw 16
        ldc msg - here
        ldpi
here:   ldc #80000000
        ldc 2
        out
        stopp
msg:    .ascii "hi"
""",
    "loop.s": """count = 5
start:  ajw 16
        ldc 0
        stl 2
        ldc count
        stl 3
top:    ldlp 2
        ldc after - top
        lend
after:  j start + 0
        .align 4
        .word #12345678, -1, 'A'
        .byte 1, 2, 3
        .space 3, #FF
""",
    "t414_float.s": """; REAL32 1.0 * 1.0 the T414 way
        ajw 16
        ldc #3F800000
        unpacksn
        stl 1
        stl 2
        ldc 254
        stl 0
        ldc 0
        ldl 1
        ldl 1
        lmul
        norm
        postnormsn
        roundsn
        cflerr
        stopp
""",
    "errors.s": """        ldc undefined.name
        j 1 +
bad:    .align 3
        ldc (1 + 2 * 3
        opr #17C
bad:
""",
    "fpu.s": """        fpldzerosn
        fpuabs
        fpusqrtfirst
        fpentry
        ldc 'a' + '\\n'
        nfix 1
        ldc 5 - -3
        call 0
        cj done
done:   .equ twelve, 12
        ldc twelve * . - done
""",
}


def write(directory, name, data):
    directory.mkdir(parents=True, exist_ok=True)
    (directory / name).write_bytes(data.encode() if isinstance(data, str) else data)


for name, data in decoder.items():
    write(CORPUS / "decoder", name, data)
for name, data in sp.items():
    write(CORPUS / "sp", name, data)
for name, data in asm.items():
    write(CORPUS / "asm", name, data)
