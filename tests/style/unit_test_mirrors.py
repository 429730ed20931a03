#!/usr/bin/env python3
"""Lists the source folders without unit tests of their own and fails if there is one.

    unit_test_mirrors.py DIR...        (run from the source root)

tests/unit mirrors the source folders: src/X goes to tests/unit/X (src/io/deck to
tests/unit/io/deck), any other folder T/Y to tests/unit/T/Y (materials to tests/unit/materials,
solvers/linear to tests/unit/solvers/linear). Every folder under DIR that holds a .cpp file needs
its mirror, holding at least one test_*.cpp, and every test_*.cpp there must be named by a
CMakeLists.txt under tests/: a test file that is never built tests nothing.
"""
import os
import re
import sys


def mirror_of(folder):
    parts = os.path.normpath(folder).split(os.sep)
    return os.path.join("tests", "unit", *(parts[1:] if parts[0] == "src" else parts))


def built_test_names():
    text = ""
    for root, _, names in os.walk("tests"):
        if "CMakeLists.txt" in names:
            with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as f:
                text += re.sub(r"#.*", "", f.read()) + "\n"
    return set(re.findall(r"(test_\w+\.cpp)", text))


def main():
    built = built_test_names()
    failures = 0
    for top in sys.argv[1:]:
        for folder, _, names in sorted(os.walk(top)):
            if not any(name.endswith(".cpp") for name in names):
                continue
            mirror = mirror_of(folder)
            tests = sorted(n for n in (os.listdir(mirror) if os.path.isdir(mirror) else [])
                           if n.startswith("test_") and n.endswith(".cpp"))
            if not tests:
                print(f"{folder}: no unit test (a test_*.cpp in {mirror})")
                failures += 1
            for test in tests:
                if test not in built:
                    print(f"{folder}: {os.path.join(mirror, test)} is built by no CMakeLists.txt in tests/")
                    failures += 1
    print(f"{failures} problem(s): source folders of {', '.join(sys.argv[1:])} without built unit tests in tests/unit")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
