#!/usr/bin/python3
"""Fuzzing Glossa's inputs: mutated decks and mesh files, each either accepted with
exactly the value it holds or refused with a message; never a signal, a hang, a value silently
changed, a Trilinos source path as the message, or a NaN in the output.

  /usr/bin/python3 tests/fuzz/fuzz_inputs.py GLOSSA WORKDIR [--decks N] [--meshes N] [--runs N] [--seed S]

Decks: inputs/verification/uniaxial_tension.xml with one mutation each (a value replaced by text a
strtod-style reader would misread or by a plausible number, an element or line duplicated or
dropped, the file cut short, tags broken, a deep nest), checked with `glossa validate --print`; when
accepted, the mutated parameter must read back as exactly its text. The first --runs accepted
decks are also run (to t = 0.2) and their traces checked for NaN. Meshes: a two-cube Abaqus file
with one mutation each, checked with `glossa mesh`. Prints the counts (ran, refused, crashed,
hung, wrong) and exits 1 if any is wrong, crashed or hung. The ctest `fuzz.Inputs` runs a few
hundred in CI; `--decks 3000 --meshes 1000` is the longer run on demand.
"""
import argparse
import concurrent.futures
import os
import random
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECIMAL = re.compile(r"^\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$")
INTEGER = re.compile(r"^\s*[+-]?\d+\s*$")
JUNK = ["0,4999", "3.5abc", "2 3", "0x10", "", "eighty", "{}", "1e999", "-1e999", "inf", "-inf", "nan", "1e", ".",
        "1..2", "1_000", "+-1", "0.3 Pa", " ", "１", "1e-400", "4.5", "-0", "1e308", "2147483648", "007"]
PLAUSIBLE = ["0", "1", "-1", "0.5", "0.4999", "1e-3", "2", "100", "1e5", "-0.25", "3"]

CUBES = """*Node
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 0, 0, 2
10, 1, 0, 2
11, 1, 1, 2
12, 0, 1, 2
*Element, type=C3D8, elset=lower
1, 1, 2, 3, 4, 5, 6, 7, 8
*Element, type=C3D8, elset=upper
2, 5, 6, 7, 8, 9, 10, 11, 12
*NSET, NSET=bottom, GENERATE
1, 4
*SURFACE, NAME=top
2, S2
"""


def strict_number(text, kind):
    if kind == "int":
        return bool(INTEGER.match(text)) and -2**31 <= int(text) < 2**31
    if not DECIMAL.match(text):
        return False
    try:
        return abs(float(text)) != float("inf")
    except ValueError:
        return False


def strict_array(text, kind):
    t = text.strip()
    if not (t.startswith("{") and t.endswith("}")):
        return False
    inner = t[1:-1].strip()
    return inner == "" or all(e.strip() and strict_number(e, kind) for e in inner.split(","))


def values_equal(printed, text, kind):
    """Whether the deck Glossa printed holds exactly the number `text` means."""
    if kind in ("double", "int"):
        return float(printed) == float(text)
    if kind.startswith("Array"):
        a = [p for p in printed.strip().strip("{}").split(",") if p.strip()]
        b = [p for p in text.strip().strip("{}").split(",") if p.strip()]
        return len(a) == len(b) and all(float(x) == float(y) for x, y in zip(a, b))
    return printed == text


def parameters(root, path=()):
    for child in root:
        name = child.get("name")
        if child.tag == "ParameterList":
            yield from parameters(child, path + (name,))
        elif child.tag == "Parameter":
            yield path + (name,), child


def find(root, path):
    node = root
    for name in path[:-1]:
        node = next((c for c in node if c.tag == "ParameterList" and c.get("name") == name), None)
        if node is None:
            return None
    return next((c for c in node if c.tag == "Parameter" and c.get("name") == path[-1]), None)


def mutate_deck(text, rng):
    """(mutated text, (path, new value text, type) or None)."""
    kind = rng.random()
    if kind < 0.6:  # a value
        root = ET.fromstring(text)
        numeric = [(p, e) for p, e in parameters(root) if e.get("type") in ("double", "int", "Array(double)", "Array(int)")]
        path, element = rng.choice(numeric)
        t = element.get("type")
        if t.startswith("Array"):
            entries = element.get("value").strip("{}").split(",")
            i = rng.randrange(len(entries))
            entries[i] = rng.choice(JUNK + PLAUSIBLE)
            value = "{" + ",".join(entries) + "}" if rng.random() < 0.9 else ",".join(entries)
        else:
            value = rng.choice(JUNK + PLAUSIBLE)
        element.set("value", value)
        return ET.tostring(root, encoding="unicode"), (path, value, t)
    lines = text.split("\n")
    if kind < 0.7:  # a line duplicated
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind < 0.8:  # a line dropped
        del lines[rng.randrange(len(lines))]
    elif kind < 0.9:  # the file cut short
        return text[: rng.randrange(len(text))], None
    elif kind < 0.95:  # a character replaced
        i = rng.randrange(len(text))
        return text[:i] + rng.choice("<>\"'&/= \n{}x") + text[i + 1:], None
    else:  # a deep nest
        depth = rng.choice([10, 70, 3000])
        return "<ParameterList name=\"a\">" * depth + "</ParameterList>" * depth, None
    return "\n".join(lines), None


def mutate_mesh(text, rng):
    lines = text.split("\n")
    kind = rng.random()
    if kind < 0.5:  # a number replaced
        i = rng.randrange(len(lines))
        fields = lines[i].split(",")
        j = rng.randrange(len(fields))
        fields[j] = " " + rng.choice(JUNK + PLAUSIBLE + ["13", "99", "1", "0.5"])
        lines[i] = ",".join(fields)
    elif kind < 0.65:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind < 0.8:
        del lines[rng.randrange(len(lines))]
    elif kind < 0.9:
        return text[: rng.randrange(len(text))]
    else:  # an extra node or element
        lines.insert(13, f"{rng.choice([12, 13, 50])}, {rng.choice(['0.5', '1', '1e-12', '3'])}, 0, 0")
    return "\n".join(lines)


class Tally:
    def __init__(self):
        self.counts = {"ran": 0, "refused": 0, "crashed": 0, "hung": 0, "wrong": 0}
        self.problems = []

    def bad(self, kind, what, file):
        self.counts[kind] += 1
        self.problems.append(f"{kind}: {what} ({file})")


def invoke(cmd, tally, file, timeout=30):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        tally.bad("hung", " ".join(cmd), file)
        return None
    if p.returncode < 0 or p.returncode > 5:
        tally.bad("crashed", f"exit status {p.returncode}: {p.stderr[-300:]}", file)
        return None
    if p.returncode != 0:
        if "glossa: error:" not in p.stderr and "glossa: stopped:" not in p.stderr:
            tally.bad("wrong", f"exit status {p.returncode} without a message: {p.stderr[-300:]}", file)
            return None
        if re.search(r"\.(hpp|cpp|h):\d+", p.stderr) or "Throw number" in p.stderr:
            tally.bad("wrong", f"a source path in the message: {p.stderr[-300:]}", file)
            return None
    return p


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("glossa")
    ap.add_argument("workdir")
    ap.add_argument("--decks", type=int, default=200)
    ap.add_argument("--meshes", type=int, default=100)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    os.makedirs(a.workdir, exist_ok=True)
    base = open(os.path.join(ROOT, "inputs", "verification", "uniaxial_tension.xml")).read()
    tally = Tally()
    decks = []
    for k in range(a.decks):  # every mutation first, from the one seeded stream
        text, change = mutate_deck(base, rng)
        deck = os.path.join(a.workdir, f"deck_{k:05d}.xml")
        with open(deck, "w") as f:
            f.write(text)
        decks.append((deck, change))
    meshes = []
    for k in range(a.meshes):
        mesh = os.path.join(a.workdir, f"mesh_{k:05d}.inp")
        with open(mesh, "w") as f:
            f.write(mutate_mesh(CUBES, rng))
        meshes.append(mesh)
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        validated = list(pool.map(lambda d: invoke([a.glossa, "validate", d[0], "--print"], tally, d[0]), decks))
        described = list(pool.map(lambda m: invoke([a.glossa, "mesh", m], tally, m), meshes))
    accepted = []
    for (deck, change), p in zip(decks, validated):
        if p is None:
            continue
        if p.returncode == 2:
            tally.counts["refused"] += 1
            continue
        if p.returncode != 0:
            tally.bad("wrong", f"validate exit status {p.returncode}", deck)
            continue
        if change:
            path, value, t = change
            ok_text = strict_array(value, "int" if t == "Array(int)" else "double") if t.startswith("Array") \
                else strict_number(value, t)
            printed = find(ET.fromstring(p.stdout), path)
            if not ok_text:
                tally.bad("wrong", f"'{'/'.join(path)}' = '{value}' was accepted", deck)
                continue
            if printed is None or not values_equal(printed.get("value"), value, t):
                tally.bad("wrong", f"'{'/'.join(path)}' = '{value}' reads back as "
                                   f"{None if printed is None else printed.get('value')}", deck)
                continue
        tally.counts["ran"] += 1
        accepted.append(deck)
    for deck in accepted[: a.runs]:
        out = deck[:-4] + "_run"
        p = invoke([a.glossa, "run", deck, "--quiet", "--output", out, "--set", "Time/end time=0.2"], tally, deck, 120)
        traces = os.path.join(out, "traces.csv")
        if p is not None and p.returncode == 0 and os.path.exists(traces) and \
                re.search(r"\bnan\b|\binf\b", open(traces).read(), re.I):
            tally.bad("wrong", "a NaN or inf in traces.csv", deck)
    for mesh, p in zip(meshes, described):
        if p is None:
            continue
        if p.returncode == 0:
            tally.counts["ran"] += 1
        elif p.returncode == 2:
            tally.counts["refused"] += 1
        else:
            tally.bad("wrong", f"mesh exit status {p.returncode}: {p.stderr[-200:]}", mesh)
    c = tally.counts
    for line in tally.problems[:30]:
        print(line)
    print(f"fuzz: {a.decks} decks, {a.meshes} meshes (seed {a.seed}): ran {c['ran']}, refused {c['refused']}, "
          f"crashed {c['crashed']}, hung {c['hung']}, wrong {c['wrong']}")
    sys.exit(1 if c["crashed"] or c["hung"] or c["wrong"] else 0)


if __name__ == "__main__":
    main()
