#!/usr/bin/env python3
"""File-local names that would meet in a unity build.

The sanitizer build (scripts/sanitize.sh) compiles each target in batches of sources pasted into
one translation unit, so two files' anonymous namespaces become one: the same name defined in both
is a compile error there (or, for an overload, a silent change of which function is called) while
./build, one object a source, compiles. This check finds such names without building: it lists
the names each .cpp file defines at the top level of an anonymous namespace and reports every name
defined by two files of one batch, as CMake made the batches in a build directory configured
with -DCMAKE_UNITY_BUILD=ON (scripts/unity_names.sh configures one).

Usage: scripts/unity_names.py BUILD_DIR   (exit 1 and a list of clashes when there are any)
"""
import pathlib
import re
import sys

TYPE = re.compile(r"\b(?:struct|class|union|enum(?:\s+class)?)\s+(\w+)\s*(?:final\s*)?[:{]")
ALIAS = re.compile(r"\busing\s+(\w+)\s*=\s*([^;]*)")
VARIABLE = re.compile(r"\b(?:constexpr|const|static|inline)\b[^;={}()]*?\b(\w+)\s*(?:\[[^\]]*\]\s*)*(?:=|\{)")
FUNCTION = re.compile(r"(?<!::)\b(\w+)\s*\([^;{}]*\)\s*(?:const\s*)?(?:noexcept\s*)?(?:->[^{;]*)?\{")
NOT_NAMES = {"if", "for", "while", "switch", "return", "catch", "sizeof", "decltype", "operator"}


def strip(text):
    """The source without comments, string and character literals or preprocessor lines."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r'R"(\w*)\(.*?\)\1"', '""', text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)
    text = re.sub(r"'(?:\\.|[^'\\\n])*'", "''", text)
    return re.sub(r"^\s*#[^\n]*(?:\\\n[^\n]*)*", " ", text, flags=re.M)


def top_level_statements(body):
    """The statements of a namespace body at its own depth (nested braces collapsed to {})."""
    out, depth, current = [], 0, []
    for ch in body:
        if ch == "{":
            if depth == 0:
                current.append("{")
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                out.append("".join(current) + "}")
                current = []
        elif depth == 0:
            current.append(ch)
            if ch == ";":
                out.append("".join(current))
                current = []
    return out


def anonymous_bodies(text):
    for m in re.finditer(r"\bnamespace\s*\{", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        yield text[m.end():i - 1]


def local_names(path):
    names = set()
    for body in anonymous_bodies(strip(path.read_text(errors="replace"))):
        for statement in top_level_statements(body):
            head = statement.split("{", 1)[0] + ("{" if "{" in statement else "")
            names.update(TYPE.findall(head))
            # The same alias twice is legal C++; the name then stands for its type.
            names.update(f"{n} = {' '.join(t.split())}" for n, t in ALIAS.findall(statement))
            if TYPE.search(head) or ALIAS.search(head):
                continue
            f = FUNCTION.search(head)
            if f and f.group(1) not in NOT_NAMES:
                names.add(f.group(1))
                continue
            v = VARIABLE.search(head)
            if v:
                names.add(v.group(1))
    return names


MACRO = re.compile(r"^[A-Z][A-Z0-9_]*$")  # TEST, TEST_P, ...: GoogleTest's macros, not names
OVERLOADED = {"PrintTo", "operator"}  # meant to be overloaded, one per type


def batches(build):
    """Each unity batch CMake generated in BUILD: the sources it pastes together."""
    for unity in sorted(build.rglob("Unity/unity_*.cxx")):
        sources = re.findall(r'#include\s+"([^"]+\.cpp)"', unity.read_text())
        if len(sources) > 1:
            yield unity, [pathlib.Path(s) for s in sources]


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    build = pathlib.Path(sys.argv[1])
    found = list(batches(build))
    if not found:
        print(f"{build}: no unity batches (configure it with -DCMAKE_UNITY_BUILD=ON)", file=sys.stderr)
        return 2
    clashes = 0
    for unity, sources in found:
        defined = {}
        for source in sources:
            for entry in local_names(source):
                name = entry.split(" = ")[0]
                if not MACRO.match(name) and name not in OVERLOADED:
                    defined.setdefault(name, {}).setdefault(entry, []).append(source.name)
        for name, meanings in sorted(defined.items()):
            files = [f for users in meanings.values() for f in users]
            if len(files) > 1 and not (len(meanings) == 1 and " = " in next(iter(meanings))):
                clashes += 1
                print(f"{', '.join(files)}: each defines '{name}' in an anonymous namespace, and the "
                      f"unity build ({unity.relative_to(build)}) compiles them as one file: rename "
                      "one, or share it in a header")
    return 1 if clashes else 0


if __name__ == "__main__":
    sys.exit(main())
