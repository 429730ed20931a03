#!/usr/bin/env python3
"""The airflow's coupling to the solid, measured (doc/airflow.md, "Coupling").

For the collapsible channel (inputs/verification/airflow_collapsible_channel.xml) and the tongue's
flow decks (inputs/paper/tongue_flow_supine.xml and _upright.xml, coarse tongue, passive):
- each coupling loop (inside the Uzawa loop, or around whole step solves) with each coupling
  method (constant relaxation, Aitken, quasi-Newton IQN-ILS): the coupling iterations per step,
  the Newton iterations and the wall seconds of the coupled steps, the last flow rate;
- the explicit (staggered) step, the flow's pressure taken once from the step's starting lumen
  and not iterated (coupling tolerance 1e9): the uncoupled cost, and how far its flow is off;
- the ratio of each coupled run's step seconds to the explicit run's, median over --repeats runs.
Only the steps with a flow count (on the tongue, t > 1 s, after gravity).

Writes bench/results/airflow_coupling.csv. Needs build/glossa.
"""
import argparse
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
METHODS = ("constant relaxation", "Aitken", "quasi-Newton")


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


def measured(deck, out, sets, flow_from, repeats):
    runs = [run(deck, out, sets, flow_from) for _ in range(repeats)]
    row = dict(runs[0])
    row["seconds"] = statistics.median(r["seconds"] for r in runs)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scratch", default="/tmp/glossa_airflow_coupling", help="where the runs write")
    parser.add_argument("--repeats", type=int, default=3, help="runs of each case; the median seconds are kept")
    parser.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "airflow_coupling.csv"))
    args = parser.parse_args()
    rows = []
    for scene, (deck, flow_from) in SCENES.items():
        out = os.path.join(args.scratch, scene.replace(" ", "_"))
        explicit = measured(deck, out, ["Airflow/coupling tolerance=1e9"], flow_from, args.repeats)
        rows.append({"scene": scene, "loop": "explicit (not iterated)", "method": "-", **explicit,
                     "seconds_over_explicit": 1.0})
        for loop in LOOPS:
            for method in METHODS:
                r = measured(deck, out, [f"Airflow/coupling loop={loop}", f"Airflow/coupling method={method}",
                                         "Airflow/maximum coupling iterations=100"], flow_from, args.repeats)
                rows.append({"scene": scene, "loop": loop, "method": method, **r,
                             "seconds_over_explicit": r["seconds"] / explicit["seconds"]})
                print(f"{scene:20s} {loop:11s} {method:20s} iterations {r['coupling_iterations']:4d} "
                      f"newton {r['newton_iterations']:4d} {r['seconds']:.2f} s "
                      f"({r['seconds'] / explicit['seconds']:.2f} x explicit) Q {1e3 * r['flow_rate_m3_s']:.5f} L/s",
                      flush=True)
    write_rows(args.table, rows)


if __name__ == "__main__":
    main()
