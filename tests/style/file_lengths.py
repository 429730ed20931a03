#!/usr/bin/env python3
"""Lists the C++ files longer than a limit in the given folders and fails if there is one.

    file_lengths.py LIMIT DIR...

A file that has outgrown the limit holds more than one concept: split it (doc/architecture.md).
"""
import os
import sys


def main():
    limit, folders = int(sys.argv[1]), sys.argv[2:]
    found = []
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp")):
                    path = os.path.join(root, name)
                    with open(path, encoding="utf-8") as f:
                        lines = sum(1 for _ in f)
                    if lines > limit:
                        found.append(f"{path}: {lines} lines (limit {limit})")
    for line in found:
        print(line)
    print(f"{len(found)} file(s) over {limit} lines in {' '.join(folders)}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
