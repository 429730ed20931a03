#!/usr/bin/python3
"""Each `Linear solver` choice side by side, on 1 and 2 ranks, for the rule `type = auto` follows:

  /usr/bin/python3 bench/linear_solver_choice.py [--scenes cook,step44_8,...] [--ranks 1,2]
      [--repeats 3] [--glossa build/glossa] [--append]

For every scene and rank count the choices run in turn within each repeat (auto, direct
gathered on rank 0, direct distributed over the ranks, iterative), so that a drift of the shared
machine's speed touches them alike; the wall time of the whole process (mpiexec included) is
measured here, and its median, minimum and maximum over the repeats go to
bench/results/linear_solver_choice.csv with what auto chose, the unknowns, Newton and Krylov
iterations and the answer's largest difference from the first choice's traces. On one rank the
gathered and distributed direct solves are the same solve: only one runs. Standard library only.
The rule and its crossovers: doc/incompressibility.md, "Choosing direct or iterative".
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
V = os.path.join(ROOT, "inputs", "verification")
P = os.path.join(ROOT, "inputs", "paper")

# name: (deck, --set overrides). The §7.1 scenes run their first 0.1 s (20 of 100 steps) and the
# tongue's gravity + pressure deck its whole 2 s; the medium tongue only under gravity (1 s).
SCENES = {
    "cook": (os.path.join(V, "cook_membrane.xml"), []),
    "step44_8": (os.path.join(V, "step44_block.xml"), []),
    "step44_12": (os.path.join(V, "step44_block.xml"), ["Mesh/Box/cells=12,12,12"]),
    "step44_16": (os.path.join(V, "step44_block.xml"), ["Mesh/Box/cells=16,16,16"]),
    "s7_1_a": (os.path.join(P, "s7_1_a_internal.xml"), ["Time/end time=0.1"]),
    "s7_1_b": (os.path.join(P, "s7_1_b_external_cs1.xml"), ["Time/end time=0.1"]),
    "s7_1_c": (os.path.join(P, "s7_1_c_external_cs2.xml"), ["Time/end time=0.1"]),
    "tongue_coarse": (os.path.join(P, "s8_2_gravity_pressure.xml"), ["Mesh/File/refine=0"]),
    "tongue_medium": (os.path.join(P, "s8_2_gravity.xml"), ["Mesh/File/refine=1"]),
}
CHOICES = {
    "auto": [],
    "direct_gathered": ["Linear solver/type=direct", "Linear solver/direct distribution=gathered"],
    "direct_distributed": ["Linear solver/type=direct", "Linear solver/direct distribution=distributed"],
    "iterative": ["Linear solver/type=iterative"],
}


def run(glossa, deck, sets, ranks):
    """One run: (wall seconds of the whole process, summary.json, traces rows)."""
    out = tempfile.mkdtemp(prefix="glossa-linear-choice-")
    cmd = glossa_run_command(glossa, deck, out, sets, ranks)
    start = time.perf_counter()
    try:
        subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL, timeout=900)
    except subprocess.TimeoutExpired:
        pass
    wall = time.perf_counter() - start
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        with open(os.path.join(out, "traces.csv")) as f:
            traces = list(csv.DictReader(f))
    except (OSError, ValueError):
        summary, traces = {"converged": False, "steps": []}, []
    shutil.rmtree(out, ignore_errors=True)
    return wall, summary, traces


def largest_difference(a, b):
    """The largest |difference| of the displacement columns of two trace tables over their largest |value|."""
    cols = [c for c in ("ux", "uy", "uz") if a and c in a[0]]
    if not a or len(a) != len(b):
        return float("nan")
    scale = max((abs(float(r[c])) for r in a for c in cols), default=0.0) or 1.0
    return max((abs(float(x[c]) - float(y[c])) for x, y in zip(a, b) for c in cols), default=0.0) / scale


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--scenes", default=",".join(SCENES), type=lambda s: s.split(","))
    p.add_argument("--ranks", default="1,2", type=lambda s: [int(x) for x in s.split(",")])
    p.add_argument("--choices", default=",".join(CHOICES), type=lambda s: s.split(","))
    p.add_argument("--repeats", default=3, type=int)
    p.add_argument("--once", default="step44_16,tongue_medium", type=lambda s: s.split(","),
                   help="scenes run once whatever --repeats says (the large ones)")
    p.add_argument("--append", action="store_true", help="add rows to the CSV instead of rewriting it")
    args = p.parse_args()
    rows = []
    for name in args.scenes:
        deck, sets = SCENES[name]
        for ranks in args.ranks:
            choices = [c for c in args.choices if not (ranks == 1 and c == "direct_distributed")]
            walls = {c: [] for c in choices}
            first = {}
            repeats = 1 if name in args.once else args.repeats
            for _ in range(repeats):
                for c in choices:
                    wall, summary, traces = run(args.glossa, deck, sets + CHOICES[c], ranks)
                    walls[c].append(wall)
                    first.setdefault(c, (summary, traces))
            reference = first[choices[0]][1]
            for c in choices:
                s, traces = first[c]
                steps = s.get("steps", [])
                row = {
                    "scene": name, "ranks": ranks, "choice": c, "linear_solver": s.get("linear_solver", ""),
                    "dofs": s.get("dofs", ""), "converged": s.get("converged", False),
                    "newton": sum(x.get("newton_iterations", 0) for x in steps),
                    "krylov": sum(x.get("linear_iterations", 0) for x in steps),
                    "wall_median_s": round(statistics.median(walls[c]), 3),
                    "wall_min_s": round(min(walls[c]), 3), "wall_max_s": round(max(walls[c]), 3),
                    "repeats": repeats,
                    "max_rel_difference": "%.1e" % largest_difference(reference, traces),
                    "date": time.strftime("%Y-%m-%d"),
                }
                print(row, flush=True)
                rows.append(row)
    path = os.path.join(ROOT, "bench", "results", "linear_solver_choice.csv")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    append = args.append and os.path.exists(path)
    with open(path, "a" if append else "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        if not append:
            w.writeheader()
        w.writerows(rows)
    print("wrote", path)


if __name__ == "__main__":
    sys.exit(main())
