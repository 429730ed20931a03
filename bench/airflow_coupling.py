#!/usr/bin/env python3
"""The airflow's coupling to the solid, measured (doc/airflow.md, "Coupling").

For the collapsible channel (inputs/verification/airflow_collapsible_channel.xml) and the tongue's
flow decks (inputs/paper/tongue_flow_supine.xml and _upright.xml, coarse tongue, passive):
- each coupling loop (inside the Uzawa loop, or around whole step solves) with each coupling
  method (constant relaxation, Aitken, quasi-Newton IQN-ILS, Newton with the solid's Jacobian): the coupling iterations per step,
  the Newton iterations and the wall seconds of the coupled steps, the last flow rate;
- the explicit (staggered) step, the flow's pressure taken once from the step's starting lumen
  and not iterated (coupling tolerance 1e9): the uncoupled cost, and how far its flow is off;
- the ratio of each coupled run's step seconds to the explicit run's: the explicit run and the
  coupled one run in turn, --repeats pairs, and the median of the pairs' ratios is kept (so that
  the ratio holds while a shared machine's speed drifts), beside the median seconds.
Only the steps with a flow count (on the tongue, t > 1 s, after gravity).

Writes bench/results/airflow_coupling.csv. Needs build/glossa.
"""
import argparse
import csv
import json
import os
import statistics
import subprocess

from result_table import write_rows

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLOSSA = os.path.join(ROOT, "build", "glossa")
SCENES = {"collapsible channel": ("inputs/verification/airflow_collapsible_channel.xml", 0.0),
          "tongue supine": ("inputs/paper/tongue_flow_supine.xml", 1.0),
          "tongue upright": ("inputs/paper/tongue_flow_upright.xml", 1.0)}
LOOPS = ("Uzawa loop", "step solve")
METHODS = ("constant relaxation", "Aitken", "quasi-Newton", "Newton")


def total(v):
    return sum(v) if isinstance(v, list) else v


def run(deck, out, sets, flow_from):
    cmd = [GLOSSA, "run", os.path.join(ROOT, deck), "--output", out, "--quiet", "--set", "Output/fields=false"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    steps = [s for s in summary["steps"] if s["time"] > flow_from + 1e-9]
    return {"converged": summary["converged"], "steps": len(steps),
            "coupling_iterations": sum(s["airflow"]["coupling_iterations"] for s in steps),
            "largest_coupling_iterations": max(s["airflow"]["coupling_iterations"] for s in steps),
            "newton_iterations": sum(total(s["newton_iterations"]) for s in steps),
            "seconds": sum(s["seconds"] for s in steps),
            "flow_rate_m3_s": steps[-1]["airflow"]["flow_rate"],
            "smallest_area_m2": steps[-1]["airflow"]["smallest_area"]}


EXPLICIT = ["Airflow/coupling tolerance=1e9"]


def measured(deck, out, sets, flow_from, repeats):
    """The run with `sets` and the explicit one in turn, `repeats` pairs: the coupled run's figures,
    its median seconds and the median of its seconds over the explicit run's, pair by pair."""
    runs, ratios = [], []
    for _ in range(repeats):
        explicit = run(deck, out, EXPLICIT, flow_from)
        runs.append(run(deck, out, sets, flow_from))
        ratios.append(runs[-1]["seconds"] / explicit["seconds"])
    row = dict(runs[0])
    row["seconds"] = statistics.median(r["seconds"] for r in runs)
    row["seconds_over_explicit"] = statistics.median(ratios)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scratch", default="/tmp/glossa_airflow_coupling", help="where the runs write")
    parser.add_argument("--repeats", type=int, default=3,
                        help="runs of each case, each after an explicit run; the medians are kept")
    parser.add_argument("--only", nargs="*", default=None, help="only these scenes (e.g. 'tongue supine')")
    parser.add_argument("--loops", nargs="*", default=list(LOOPS), help="only these coupling loops")
    parser.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "airflow_coupling.csv"))
    args = parser.parse_args()
    rows = []
    for scene, (deck, flow_from) in SCENES.items():
        if args.only is not None and scene not in args.only:
            continue
        out = os.path.join(args.scratch, scene.replace(" ", "_"))
        explicit = measured(deck, out, EXPLICIT, flow_from, args.repeats)
        rows.append({"scene": scene, "loop": "explicit (not iterated)", "method": "-", **explicit})
        for loop in args.loops:
            for method in METHODS:
                r = measured(deck, out, [f"Airflow/coupling loop={loop}", f"Airflow/coupling method={method}",
                                         "Airflow/maximum coupling iterations=100"], flow_from, args.repeats)
                rows.append({"scene": scene, "loop": loop, "method": method, **r})
                print(f"{scene:20s} {loop:11s} {method:20s} iterations {r['coupling_iterations']:4d} "
                      f"newton {r['newton_iterations']:4d} {r['seconds']:.2f} s "
                      f"({r['seconds_over_explicit']:.2f} x explicit) Q {1e3 * r['flow_rate_m3_s']:.5f} L/s",
                      flush=True)
    if args.only is not None or set(args.loops) != set(LOOPS):
        # A part of the study: its rows replace theirs in the table, the others stay.
        key = lambda r: (r["scene"], r["loop"], r["method"])
        measured_now = {key(r): r for r in rows}
        if os.path.exists(args.table):
            with open(args.table, newline="") as f:
                kept = [measured_now.pop(key(r), r) for r in csv.DictReader(f)]
            rows = kept + list(measured_now.values())
    scenes, loops = list(SCENES), ["explicit (not iterated)", *LOOPS]
    methods = ["-", *METHODS]
    rows.sort(key=lambda r: (scenes.index(r["scene"]), loops.index(r["loop"]), methods.index(r["method"])))
    write_rows(args.table, rows)


if __name__ == "__main__":
    main()
