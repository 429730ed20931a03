#!/usr/bin/env python3
"""Lists the C++ functions longer than a limit in the given folders and fails if there is one.

    function_lengths.py LIMIT DIR...

A function is a brace block opened after a parameter list ')' (with const, override, noexcept,
a trailing return type or a constructor's initialiser list between) that is not inside another
function; its length counts its lines from the signature's last line to the closing brace.
Comments, strings and character literals are blanked first so that braces in them do not count.
"""
import os
import re
import sys

SIGNATURE_END = re.compile(r"\)\s*(const)?\s*(override)?\s*(noexcept)?\s*(->\s*[\w:<>]+)?\s*(:.*)?$")
SCOPE = re.compile(r"\bnamespace\b[^;]*$|\b(class|struct|union|enum)\b[^;()]*$")


def blank(line):
    line = re.sub(r"//.*", "", line)
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    return re.sub(r"'(\\.|[^'\\])'", "''", line)


def long_functions(path, limit):
    found, stack, previous = [], [], ""
    in_comment = False
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for number, raw in enumerate(lines, start=1):
        code = raw
        if in_comment:
            if "*/" not in code:
                continue
            code, in_comment = code.split("*/", 1)[1], False
        code = re.sub(r"/\*.*?\*/", "", code)
        if "/*" in code:
            code, in_comment = code.split("/*", 1)[0], True
        code = blank(code)
        for i, ch in enumerate(code):
            if ch == "{":
                context = (previous + " " + code[:i]).strip()
                in_function = any(kind == "function" for kind, _ in stack)
                if SCOPE.search(context):
                    kind = "scope"
                elif SIGNATURE_END.search(context) and not in_function:
                    kind = "function"
                else:
                    kind = "block"
                stack.append((kind, number))
            elif ch == "}" and stack:
                kind, start = stack.pop()
                if kind == "function" and number - start + 1 > limit:
                    found.append((number - start + 1, start, lines[start - 1].strip()))
        if code.strip():
            previous = code
    return found


def main():
    limit, folders = int(sys.argv[1]), sys.argv[2:]
    failures = 0
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp")):
                    path = os.path.join(root, name)
                    for length, start, text in long_functions(path, limit):
                        print(f"{path}:{start}: {length} lines (limit {limit}): {text}")
                        failures += 1
    print(f"{failures} function(s) over {limit} lines in {', '.join(folders)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
