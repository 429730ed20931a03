#!/usr/bin/env python3
"""Counts the public member functions (constructors and overloads included) of a class in a
header and fails if there are more than a limit.

    public_methods.py HEADER CLASS LIMIT

The Assembler builds residual and tangent and nothing else; what is computed from a state belongs
to the ResultEvaluator (doc/architecture.md). A declaration counts when it stands directly in the
class body, in a public section, and has a parameter list; nested types, data members, using and
friend declarations do not.
"""
import re
import sys


def strip(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r'"(\\.|[^"\\])*"', '""', text)


def public_functions(text, name):
    match = re.search(r"\b(class|struct)\s+" + re.escape(name) + r"\b[^;{]*\{", text)
    if not match:
        raise SystemExit(f"no class {name}")
    access = "private" if match.group(1) == "class" else "public"
    depth, statement, found = 1, "", []
    i = match.end()
    while i < len(text) and depth > 0:
        ch = text[i]
        if depth == 1 and ch in ";{}":
            words = statement.strip()
            label = re.match(r"(public|private|protected)\s*:(?!:)\s*(.*)", words, flags=re.S)
            while label:
                access, words = label.group(1), label.group(2).strip()
                label = re.match(r"(public|private|protected)\s*:(?!:)\s*(.*)", words, flags=re.S)
            is_function = "(" in words and not re.match(r"(using|friend|typedef|struct|class|enum)\b", words)
            if ch != "}" and access == "public" and is_function:
                found.append(" ".join(words.split()))
            statement = ""
            if ch == "{":
                depth += 1
                inner = 1
                i += 1
                while i < len(text) and inner > 0:  # skip a body or a nested type
                    inner += {"{": 1, "}": -1}.get(text[i], 0)
                    i += 1
                depth -= 1
                continue
            if ch == "}":
                depth -= 1
        else:
            statement += ch
        i += 1
    return found


def main():
    header, name, limit = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with open(header, encoding="utf-8") as f:
        found = public_functions(strip(f.read()), name)
    for declaration in found:
        print(declaration[:120])
    print(f"{name}: {len(found)} public member function(s) (limit {limit})")
    return 1 if len(found) > limit else 0


if __name__ == "__main__":
    sys.exit(main())
