#!/usr/bin/python3
"""MUMPS's fill-reducing orderings side by side on the scenes solved directly:

  /usr/bin/python3 bench/direct_ordering.py [--scenes cook,s7_1_a,...] [--orderings PORD,auto,AMD,AMF,QAMD]
      [--repeats 3] [--glossa build/glossa] [--append]

For every scene the orderings (`Linear solver/direct ordering`) run in turn within each repeat, one
rank, the direct solve forced (`Linear solver/type = direct`). Each row of
bench/results/direct_ordering.csv gives what MUMPS reported of the last factorisation
(`summary.json` `direct_factors`: the ordering it used, the factors' entries and the flops of one
elimination; these do not depend on the machine), the factorisations and substitutions with their
mean cost (medians over the repeats), the CPU time of the whole process (median) and its ratio
to the ordering `auto` (MUMPS's own choice, the default before 2026-12-07), Newton iterations and
the largest difference of the traces from the first ordering's. Standard library only. The
choice: doc/performance.md, "The direct solver's ordering".
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import tempfile

from glossa_command import cpu_seconds_of, glossa_run_command
from result_table import write_rows

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results", "direct_ordering.csv")
V = os.path.join(ROOT, "inputs", "verification")
P = os.path.join(ROOT, "inputs", "paper")

# name: (deck, --set overrides). Short versions of the scenes, a few seconds each.
SCENES = {
    "cook": (os.path.join(V, "cook_membrane.xml"), []),
    "step44_8": (os.path.join(V, "step44_block.xml"), []),
    "step44_16": (os.path.join(V, "step44_block.xml"), ["Mesh/Box/cells=16,16,16"]),
    "s7_1_a": (os.path.join(P, "s7_1_a_internal.xml"), ["Time/end time=0.1"]),
    "tongue_passive": (os.path.join(P, "s8_5_passive_supine.xml"), ["Time/end time=2.5"]),
    "tongue_ga": (os.path.join(P, "s8_5_ga_supine.xml"), ["Time/end time=0.3125", "Control/generations=3"]),
}
ORDERINGS = ["auto", "PORD", "AMD", "AMF", "QAMD"]


def run(glossa, deck, sets):
    """One run on one rank: (CPU seconds of the process, summary.json, {(t, point): (ux, uy, uz)})."""
    out = tempfile.mkdtemp(prefix="glossa-ordering-")
    cmd = glossa_run_command(glossa, deck, out, sets + ["Output/fields=false"])
    try:
        cpu = cpu_seconds_of(cmd, ROOT, "direct_ordering")
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        traces = {}
        with open(os.path.join(out, "traces.csv")) as f:
            for r in csv.DictReader(f):
                r = {k.split(" [")[0]: v for k, v in r.items()}
                traces[(r["time"], r["point"])] = tuple(float(r[c]) for c in ("ux", "uy", "uz"))
        return cpu, summary, traces
    finally:
        shutil.rmtree(out, ignore_errors=True)


def largest_difference(a, b):
    keys = set(a) & set(b)
    if not keys or len(keys) != len(a):
        return float("inf")
    return max(max(abs(x - y) for x, y in zip(a[k], b[k])) for k in keys)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default=",".join(SCENES))
    p.add_argument("--orderings", default=",".join(ORDERINGS))
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--append", action="store_true", help="keep the table's other rows")
    args = p.parse_args()
    orderings = args.orderings.split(",")
    rows = []
    for scene in args.scenes.split(","):
        deck, sets = SCENES[scene]
        runs = {o: [] for o in orderings}
        for _ in range(args.repeats):
            for o in orderings:
                runs[o].append(run(args.glossa, deck, sets + ["Linear solver/type=direct",
                                                              f"Linear solver/direct ordering={o}"]))
        reference = runs[orderings[0]][0][2]
        cpu = {o: statistics.median(r[0] for r in runs[o]) for o in orderings}
        for o in orderings:
            s = runs[o][0][1]
            split = s["time_split"]
            factorisations = split["direct_factorisation"]["calls"]
            solves = split["direct_solve"]["calls"]
            factor_ms = statistics.median(r[1]["time_split"]["direct_factorisation"]["seconds"] for r in runs[o])
            solve_ms = statistics.median(r[1]["time_split"]["direct_solve"]["seconds"] for r in runs[o])
            direct = s.get("direct_factors", {})
            rows.append({
                "scene": scene, "ordering": o, "ordering_used": direct.get("ordering", ""),
                "dofs": s["dofs"],
                "factor_entries": int(direct.get("entries", 0)), "flops": f"{direct.get('flops', 0.0):.4g}",
                "factorisations": factorisations,
                "ms_per_factorisation": round(1e3 * factor_ms / max(factorisations, 1), 2),
                "substitutions": solves, "ms_per_substitution": round(1e3 * solve_ms / max(solves, 1), 3),
                "newton_iterations": sum(step["newton_iterations"] for step in s["steps"]),
                "cpu_s_median": round(cpu[o], 3),
                "cpu_vs_auto": round(cpu[o] / cpu["auto"], 3) if "auto" in cpu else "",
                "traces_max_diff_m": f"{largest_difference(runs[o][0][2], reference):.1e}",
                "repeats": args.repeats,
            })
            print(rows[-1], flush=True)
    if args.append and os.path.exists(RESULTS):
        with open(RESULTS) as f:
            done = {(r["scene"], r["ordering"]) for r in rows}
            rows = [r for r in csv.DictReader(f) if (r["scene"], r["ordering"]) not in done] + rows
    write_rows(RESULTS, rows)


if __name__ == "__main__":
    main()
