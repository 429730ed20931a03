#!/usr/bin/env python3
"""Lists the reads of the deck outside the parsing layer and fails if there is one.

    deck_reads.py DIR...        (run from the source root)

The parsing layer (src/io/deck, src/input, solvers/parameters) parses each deck section once into
its typed struct; everything else reads the structs, so that a parameter's name is spelt in one
place and a section is not parsed twice. A deck reaches code as an io::Deck, and its parameters
only through three of its methods: root() (the Teuchos list), given() and where() (whether, and
where, a parameter was given). So a deck read is
  - root(), given( or where( called on a Deck: on a name declared as one in the folders given
    (`const io::Deck &deck`, a member `io::Deck deck_;`, `auto deck = Deck::fromFile(...)` or
    `= f(...)` with f declared to return a Deck), on what such an f returns, or, for given({ and
    where({ with a braced path (Deck's signature), on anything;
  - any keyed read (get<T>(...), get(...), sublist(...), isParameter(...), isSublist(...),
    isType<T>(...), getEntry(...), getEntryPtr(...), getPtr<T>(...)) on a name bound to what a
    deck read gives (`const auto &D = deck.root();`, `p = deck.root().sublist("Point")`), or bound
    to such a name, in the same file: the reads the first rule's root() leads to.
Parameter lists a file builds itself for NOX, LOCA, Belos, MueLu, Ifpack2 or Stratimikos come from
no Deck and are not flagged, nor is nlohmann::json (`.at("x")`, `.get<T>()`, a summary's root()):
its objects are not Decks. Comments and the text of string literals are blanked first, so that a
comment about deck.root() does not count.
"""
import os
import re
import sys

PARSING_LAYER = ("src/io/deck", "src/input", "solvers/parameters")
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".cc")

LIST_READS = r"(?:sublist|get|isParameter|isSublist|isType|getEntry|getEntryPtr|getPtr)"
TEMPLATE_ARGUMENTS = r"(?:<[^;(){}]*?>)?"


def blank_comments_and_strings(text):
    """The text with comments and the insides of string and character literals replaced by
    blanks; newlines (hence line numbers) are kept."""
    out, i, n = [], 0, len(text)
    blank = lambda s: re.sub(r"[^\n]", " ", s)
    while i < n:
        raw = re.match(r'R"([^()\\\s]{0,16})\(', text[i:i + 20]) if not re.match(r"\w", text[i - 1:i]) else None
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append(blank(text[i:end]))
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(blank(text[i:end]))
        elif raw:
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.append('R"' + blank(text[i + 2:end - 1]) + '"')
        elif text[i] == '"' or (text[i] == "'" and not re.match(r"\w", text[i - 1:i])):  # not 1'000
            quote, end = text[i], i + 1
            while end < n and text[end] not in (quote, "\n"):
                end += 2 if text[end] == "\\" else 1
            end = min(end + 1, n) if end < n and text[end] == quote else end
            out.append(quote + blank(text[i + 1:end - 1]) + text[end - 1])
        else:
            end = i + 1
            out.append(text[i])
        i = end
    return "".join(out)


def deck_declarations(files):
    """Names declared as a Deck in `files`, and functions declared to return one."""
    names, functions = set(), set()
    for code in files.values():
        for m in re.finditer(r"\bDeck\b\s*(?:const\s*)?[&*]*\s*(\w+)\s*([,;)={(])", code):
            (functions if m.group(2) == "(" else names).add(m.group(1))
    for code in files.values():
        for m in re.finditer(r"\bauto\s*[&*]*\s*(\w+)\s*=\s*[\w:]*?\b(\w+)\s*\(", code):
            if m.group(2) in functions:
                names.add(m.group(1))
    return names, functions


def either(words):
    return "|".join(map(re.escape, sorted(words)))


def deck_objects(names, functions):
    """Patterns of an expression that is a Deck: a Deck's name, or a call of a function that
    returns one."""
    objects = [r"\b(?:%s)" % either(names)] if names else []
    if functions:
        objects.append(r"\b(?:%s)\s*\([^;(){}]*\)" % either(functions))
    return objects


def deck_calls(code, names, functions):
    """(offset of the method's name, text) of each root(), given( or where( called on a Deck."""
    patterns = [obj + r"\s*(?:\.|->)\s*(?P<method>root|given|where)\s*\(" for obj in deck_objects(names, functions)]
    patterns.append(r"(?:\.|->)\s*(?P<method>given|where)\s*\(\s*\{")  # Deck's braced path, on anything
    calls = {}
    for pattern in patterns:
        for m in re.finditer(pattern, code):
            calls.setdefault(m.start("method"), m.group(0))
    return sorted(calls.items())


def bound_to_deck(code, names, functions):
    """Names bound (by `=`) to the deck's list or one of its sublists: to root() of a Deck, or to
    such a name, followed by nothing but sublist(...) calls."""
    roots = [obj + r"\s*(?:\.|->)\s*root\s*\(\s*\)" for obj in deck_objects(names, functions)]
    assignments = [(m.group(1), m.group(2)) for m in re.finditer(r"\b(\w+)\s*=(?!=)\s*([^;]*)", code)]
    bound = set()
    while True:
        starts = roots + ([r"\b(?:%s)\b" % either(bound)] if bound else [])
        if not starts:
            return bound
        whole = re.compile(r"\s*[&*]?\s*(?:%s)\s*(?:(?:\.|->)\s*sublist\s*\([^;]*?\)\s*)*" % "|".join(starts))
        grown = {name for name, expression in assignments if name not in bound and whole.fullmatch(expression)}
        if not grown:
            return bound
        bound |= grown


def call_text(matched):
    """`deck . where ( {` as `deck.where(...)`."""
    return re.sub(r"\s+", "", matched).rstrip("({") + "(...)"


def deck_reads(code, names, functions):
    """(line, what) of each deck read in a blanked file."""
    found = {}
    line_of = lambda offset: code.count("\n", 0, offset) + 1
    for offset, text in deck_calls(code, names, functions):
        found.setdefault(line_of(offset), call_text(text))
    bound = bound_to_deck(code, names, functions)
    if bound:
        pattern = r"\b(?:%s)\s*(?:\.|->)\s*(?P<method>%s)\s*%s\s*\((?=\s*[^\s)])" % (
            either(bound), LIST_READS, TEMPLATE_ARGUMENTS)
        for m in re.finditer(pattern, code):
            found.setdefault(line_of(m.start("method")), call_text(m.group(0)))
    return sorted(found.items())


def in_parsing_layer(path):
    path = path.replace(os.sep, "/")
    return any(path == layer or path.startswith(layer + "/") for layer in PARSING_LAYER)


def main():
    folders = sys.argv[1:]
    files = {}
    for folder in folders:
        for root, _, entries in os.walk(folder):
            for name in sorted(entries):
                if name.endswith(SOURCE_SUFFIXES):
                    path = os.path.normpath(os.path.join(root, name))
                    with open(path, encoding="utf-8") as f:
                        files[path] = blank_comments_and_strings(f.read())
    names, functions = deck_declarations(files)
    failures = 0
    for path in sorted(files):
        if in_parsing_layer(path):
            continue
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        for line, what in deck_reads(files[path], names, functions):
            print(f"{path}:{line}: reads the deck: {what}: {lines[line - 1].strip()}")
            failures += 1
    print(f"{failures} deck read(s) outside the parsing layer ({', '.join(PARSING_LAYER)}) in {', '.join(folders)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
