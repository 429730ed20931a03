#!/usr/bin/python3
"""Fuzzing Glossa's checkpoints: every damaged or edited checkpoint is either refused with exit
status 2 and a message naming the file, or restarts and ends byte for byte as the uninterrupted
run; none crashes, hangs, exits 5 or claims convergence early.

  /usr/bin/python3 tests/fuzz/fuzz_checkpoints.py GLOSSA WORKDIR [--mutants N] [--forged N] [--seed S]

The run: the step-44 block (inputs/verification/step44_block.xml) at 4^3 cells, ten steps, a
checkpoint every four, so its directory keeps the checkpoint after step 8. Each mutant is a copy
of that directory with one change to its checkpoint, restarted with --restart:
- a bit flipped at a random offset of the part (rank_0000.cbor) or of `latest`;
- the part or `latest` cut short at a random length;
- a value edited and the part's CRC made good again (time NaN, 1e300 or negative, a negative,
  zero or NaN step size, a negative step number or count of successes, a NaN or infinite
  displacement, a displacement dropped, a key removed, a number made text): the sanity checks
  must refuse these, since the CRC cannot.
The --forged mutants flip a random bit of the state and make the CRC good again, as only a
deliberate forgery could: these may restart with other results, so they are held only to no
crash, no hang, no exit 5, no message without the file and no convergence claimed early.
A restart of an unchanged copy, and of one re-encoded by checkpoint_part.py, must end as the
uninterrupted run (the harness's own check). Prints the counts and exits 1 on any failure. The
ctest `fuzz.Checkpoints` runs the default counts in CI.
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys

import checkpoint_part

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "step44_block.xml")
SETS = ["Mesh/Box/cells=4,4,4", "Output/checkpoint every=4"]
CSV = ["traces.csv", "reactions.csv", "activation.csv", "resultants.csv", "volumes.csv"]


def edit(path, value):
    """An edit of the decoded part: sets the value at `path` (keys and indices), or removes the
    key when `value` is REMOVE."""
    def apply(state):
        node = state
        for key in path[:-1]:
            node = node[key]
        if value is REMOVE:
            del node[path[-1]]
        else:
            node[path[-1]] = value(node[path[-1]]) if callable(value) else value
    return apply


REMOVE = object()
EDITS = {
    "time NaN": edit(["run", "time"], math.nan),
    "time 1e300": edit(["run", "time"], 1e300),
    "time negative": edit(["run", "time"], -0.1),
    "time past the end": edit(["run", "time"], 1.5),
    "step size negative": edit(["run", "step_size", 0], lambda dt: -dt),
    "step size zero": edit(["run", "step_size", 0], 0.0),
    "step size NaN": edit(["run", "step_size", 0], math.nan),
    "step size 1e300": edit(["run", "step_size", 0], 1e300),
    "step number negative": edit(["run", "step"], -8),
    "successes negative": edit(["run", "step_size", 1], -1),
    "displacement NaN": edit(["u", 7], math.nan),
    "displacement inf": edit(["u", 7], math.inf),
    "displacement dropped": edit(["u"], lambda u: u[:-1]),
    "multipliers dropped": edit(["lambda"], lambda v: v[:-1]),
    "time removed": edit(["run", "time"], REMOVE),
    "time as text": edit(["run", "time"], "0.8"),
    "ranks as text": edit(["run", "ranks"], "1"),
    "summary an array": edit(["run", "summary"], []),
    "traces longer than the file": edit(["run", "outputs", "csv_bytes", "traces.csv"], lambda n: n + 10**6),
    "muscle time changed": edit(["muscle", "time"], 0.5),
}


def run_glossa(glossa, args, timeout=120):
    try:
        return subprocess.run([glossa, "run", DECK, *sum((["--set", s] for s in SETS), []), "--quiet", *args],
                              capture_output=True, text=True, timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        return None


def same_as(whole, out):
    """'' if the run in `out` ended as the uninterrupted one in `whole`, else what differs."""
    for f in CSV:
        a, b = os.path.join(whole, f), os.path.join(out, f)
        if os.path.exists(a) and (not os.path.exists(b) or open(a, "rb").read() != open(b, "rb").read()):
            return f"{f} differs"
    x, y = (json.load(open(os.path.join(d, "summary.json"))) for d in (whole, out))
    if y.get("converged") is not True or y.get("running") is not False:
        return f"summary: converged {y.get('converged')}, running {y.get('running')}"
    if len(x["steps"]) != len(y["steps"]):
        return f"summary: {len(y['steps'])} steps, the uninterrupted run made {len(x['steps'])}"
    keys = ["time", "dt", "newton_iterations", "linear_iterations", "uzawa_iterations", "max_dilatation_error"]
    for k, (s, t) in enumerate(zip(x["steps"], y["steps"])):
        for key in keys:
            if s.get(key) != t.get(key):
                return f"summary step {k + 1}: {key} {t.get(key)}, the uninterrupted run's {s.get(key)}"
    if x["final_displacement"] != y["final_displacement"]:
        return "final_displacement differs"
    grids = [len(re.findall(r"<Grid Name=\"step", open(os.path.join(d, "results.xdmf")).read())) for d in (whole, out)]
    return "" if grids[0] == grids[1] else f"results.xdmf: {grids[1]} field steps, not {grids[0]}"


def claims_early_convergence(whole, out):
    try:
        x, y = (json.load(open(os.path.join(d, "summary.json"))) for d in (whole, out))
    except (OSError, ValueError):
        return False
    return y.get("converged") is True and len(y.get("steps", [])) < len(x["steps"])


class Mutant:
    def __init__(self, name, kind, target, change):
        self.name, self.kind, self.target, self.change = name, kind, target, change  # change(bytes) -> bytes


def make_mutants(rng, part_bytes, latest_bytes, count, forged):
    mutants = []
    names = list(EDITS)
    for k in range(count):
        if k < len(names):  # every edit once, then the random ones
            name = names[k]
            mutants.append(Mutant(f"edit: {name}", "refuse", "part", reedit(EDITS[name])))
            continue
        target = "latest" if rng.random() < 0.15 else "part"
        size = len(latest_bytes if target == "latest" else part_bytes)
        if rng.random() < 0.6:
            at, bit = rng.randrange(size), rng.randrange(8)
            mutants.append(Mutant(f"flip: {target} byte {at} bit {bit}", "refuse", target, flip(at, bit)))
        else:
            length = rng.randrange(size)
            mutants.append(Mutant(f"cut: {target} at {length} of {size} bytes", "refuse", target, lambda b, n=length: b[:n]))
    for _ in range(forged):
        rank, step, cbor = checkpoint_part.unframe(part_bytes)
        at, bit = rng.randrange(len(cbor)), rng.randrange(8)
        mutants.append(Mutant(f"forged: state byte {at} bit {bit}", "forged", "part",
                              lambda b, a=at, i=bit: forge(b, a, i)))
    return mutants


def flip(at, bit):
    return lambda b: b[:at] + bytes([b[at] ^ (1 << bit)]) + b[at + 1:]


def reedit(apply):
    def change(b):
        rank, step, cbor = checkpoint_part.unframe(b)
        state = checkpoint_part.decode(cbor)
        apply(state)
        return checkpoint_part.frame(rank, step, checkpoint_part.encode(state))
    return change


def forge(b, at, bit):
    rank, step, cbor = checkpoint_part.unframe(b)
    return checkpoint_part.frame(rank, step, cbor[:at] + bytes([cbor[at] ^ (1 << bit)]) + cbor[at + 1:])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("glossa")
    ap.add_argument("workdir")
    ap.add_argument("--mutants", type=int, default=60)
    ap.add_argument("--forged", type=int, default=10)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir)
    whole = os.path.join(a.workdir, "whole")
    p = run_glossa(a.glossa, ["--output", whole])
    if p is None or p.returncode != 0:
        sys.exit(f"the uninterrupted run failed: {p and p.stderr[-500:]}")
    latest_file = os.path.join(whole, "checkpoint", "latest")
    latest_bytes = open(latest_file, "rb").read()
    step_dir = latest_bytes.decode().strip()
    part_file = os.path.join(whole, "checkpoint", step_dir, "rank_0000.cbor")
    part_bytes = open(part_file, "rb").read()
    rng = random.Random(a.seed)
    controls = [Mutant("control: unchanged", "identical", "part", lambda b: b),
                Mutant("control: re-encoded", "identical", "part", reedit(lambda state: None))]
    mutants = controls + make_mutants(rng, part_bytes, latest_bytes, a.mutants, a.forged)

    def attempt(k_mutant):
        k, m = k_mutant
        out = os.path.join(a.workdir, f"mutant_{k:04d}")
        shutil.copytree(whole, out)
        target = os.path.join(out, "checkpoint", "latest" if m.target == "latest" else os.path.join(step_dir, "rank_0000.cbor"))
        original = open(target, "rb").read()
        with open(target, "wb") as f:
            f.write(m.change(original))
        p = run_glossa(a.glossa, ["--restart", out], timeout=60)
        verdict = judge(m, p, whole, out)
        if not verdict.startswith("wrong") and not verdict.startswith("hung") and not verdict.startswith("crashed"):
            shutil.rmtree(out, ignore_errors=True)
        return m, verdict

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(attempt, enumerate(mutants)))
    counts = {"refused": 0, "identical": 0, "forged ran": 0, "crashed": 0, "hung": 0, "wrong": 0}
    problems = []
    for m, verdict in results:
        kind = verdict.split(":")[0]
        counts[kind] += 1
        if kind in ("crashed", "hung", "wrong"):
            problems.append(f"{m.name}: {verdict}")
    for line in problems[:30]:
        print(line)
    print(f"checkpoint fuzz: {len(mutants)} mutants ({a.mutants} flips, cuts and edits, {a.forged} forged, "
          f"{len(controls)} controls; seed {a.seed}): " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    sys.exit(1 if counts["crashed"] or counts["hung"] or counts["wrong"] else 0)


def judge(m, p, whole, out):
    if p is None:
        return "hung: no end within 60 s"
    if p.returncode < 0 or p.returncode > 4:
        return f"crashed: exit status {p.returncode}: {p.stderr[-300:]}"
    if m.kind == "identical":
        if p.returncode != 0:
            return f"wrong: the control's restart exit status {p.returncode}: {p.stderr[-300:]}"
        why = same_as(whole, out)
        return "identical" if not why else f"wrong: the control's restart ended otherwise: {why}"
    if p.returncode == 2:
        named = os.path.join(out, "checkpoint") + "/"
        if named not in p.stderr or "glossa: error:" not in p.stderr:
            return f"wrong: refused without naming the checkpoint's file: {p.stderr[-300:]}"
        return "refused"
    if claims_early_convergence(whole, out):
        return f"wrong: exit status {p.returncode} and convergence claimed early"
    if m.kind == "forged":
        return "forged ran"
    if p.returncode == 0 and not same_as(whole, out):
        return "identical"
    return f"wrong: exit status {p.returncode}, neither refused nor the uninterrupted run's: " \
           f"{same_as(whole, out) if p.returncode == 0 else p.stderr[-300:]}"


if __name__ == "__main__":
    main()
