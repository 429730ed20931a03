#!/usr/bin/python3
"""The breath driven by the airflow (doc/airflow.md, "A breath driven by the flow"), run on demand:

  /usr/bin/python3 bench/flow_breath.py [--glossa build/glossa] [--runs DIR] [--only NAME,...]
                                        [--ga-ranks 2] [--force]

Runs inputs/paper/s8_5_flow_{passive,gradient,ga}_{supine,upright}.xml (the coarse tongue, three
breaths, the flow coupled to the tongue at every step and in every controller candidate) into
RUNS/<name>/ (default bench/results/flow_breath/; no fields). A run whose summary says it finished
is reused unless --force. The GA runs on --ga-ranks ranks with one control group per rank.

Writes bench/results/flow_breath.csv, per run: the steps, the wall time, the candidate solves,
the coupling iterations (passive runs: in all and the largest in a step), eq. 25's
objective over the breaths (largest), P_A's and P_P's distance from the imaged position over the
breaths (largest), the smallest area of the lumen over the breaths (the least and the largest
of each step's smallest), whether a section closed, and the peak flow rate.
"""
import argparse
import json
import os
import sys

from result_table import write_rows
from tongue_control import CYCLES_START, distances, execute, finished, over_cycles, read_csv

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONTROLLERS = {"passive": "passive", "gradient": "gradient", "ga": "GA"}


def runs():
    """(name, deck, controller, posture) of every run."""
    return [(f"{kind}_{posture}", f"s8_5_flow_{kind}_{posture}.xml", controller, posture)
            for posture in ("supine", "upright") for kind, controller in CONTROLLERS.items()]


def summarise(name, controller, posture, directory):
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    steps = s["steps"]
    flow = [r for r in read_csv(os.path.join(directory, "airflow.csv")) if float(r["time"]) >= CYCLES_START - 1e-9]
    coupling = [st["airflow"]["coupling_iterations"] for st in steps if "airflow" in st]
    smallest = [1e6 * float(r["smallest_area"]) for r in flow]
    row = {"run": name, "controller": controller, "posture": posture, "ranks": s["ranks"],
           "control_groups": s.get("control_groups", 1), "steps": len(steps), "wall_s": round(s["wall_seconds"], 1),
           "coupling_iterations": sum(coupling), "coupling_iterations_max": max(coupling),
           "smallest_area_min_mm2": round(min(smallest), 1), "smallest_area_max_mm2": round(max(smallest), 1),
           "closed": any(r["closed"] not in ("0", "false", "False") for r in flow),
           "peak_flow_L_s": round(1e3 * max(abs(float(r["flow_rate"])) for r in flow), 2)}
    row["solves"], row["eq25_max_mm"] = "", ""  # a passive run has neither
    if controller != "passive":
        # A controlled step records its winner's coupling, not its candidates': not a step's cost.
        row["coupling_iterations"], row["coupling_iterations_max"] = "", ""
        row["solves"] = sum(st["control"]["candidates"] for st in steps)
        objective = [st["control"]["objective"] for st in steps if st["time"] >= CYCLES_START - 1e-9]
        row["eq25_max_mm"] = round(1e3 * max(objective), 2)
    for point in ("P_A", "P_P"):
        row[f"{point}_max_mm"] = round(max(v for _, v in over_cycles(distances(directory, point))), 2)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    ap.add_argument("--runs", default=os.path.join(ROOT, "bench", "results", "flow_breath"))
    ap.add_argument("--only", default="", help="comma-separated run names, e.g. ga_supine")
    ap.add_argument("--ga-ranks", type=int, default=2)
    ap.add_argument("--force", action="store_true")
    a = ap.parse_args()
    only = set(filter(None, a.only.split(",")))
    rows = []
    for name, deck, controller, posture in runs():
        directory = os.path.join(a.runs, name)
        wanted = not only or name in only
        if wanted and (a.force or not finished(directory)):
            execute(a.glossa, name, deck, [], controller, directory, a.ga_ranks)
        if finished(directory):
            rows.append(summarise(name, controller, posture, directory))
    if not rows:
        sys.exit("no finished run to tabulate")
    write_rows(os.path.join(ROOT, "bench", "results", "flow_breath.csv"), rows)


if __name__ == "__main__":
    main()
