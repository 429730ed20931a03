#!/usr/bin/python3
"""The airway's tube law, passive (a start): the smallest lumen area against the
suction on the tongue's airway surface, from inputs/paper/airway_supine.xml (or _upright): after
the gravity ramp over [0, 1] s the suction, linear from 0 at P_A to p_max at P_P, ramps over
[1, 2] s, so each step's time t gives the suction at P_P, p = p_max (t - 1). One run per posture
with a deeper suction than the paper's and finer steps; a run that stops (no convergence, the
tongue folded) is tabulated up to its last converged step, and says so.

    /usr/bin/python3 bench/airway_tube_law.py [--glossa build/glossa] [--posture supine]
        [--deck airway|tongue_pcrit] [--suction 2000] [--step 0.05] [--runs DIR]
        [--table bench/results/airway_tube_law_supine.csv]

--deck tongue_pcrit runs inputs/paper/tongue_pcrit_{posture}.xml instead: the same ramp, with the
lateral walls and the implicit palate surface of the Pcrit decks (doc/airway.md), their closing
pressure search switched off (Airway/closing pressure load empty), so that the ramp goes on past
their 5 mm^2 closure.

Writes the table: time [s], suction at P_P [Pa and cmH2O], smallest area [mm^2], its section and
arc length [mm], contact area [mm^2], closed; and prints it.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PA_PER_CMH2O = 98.0665


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--posture", default="supine", choices=["supine", "upright"])
    p.add_argument("--deck", default="airway", choices=["airway", "tongue_pcrit"])
    p.add_argument("--suction", type=float, default=2000.0, help="p_max at P_P [Pa], > 0 for suction")
    p.add_argument("--step", type=float, default=0.05, help="step size [s]")
    p.add_argument("--runs", default=os.path.join(ROOT, "build", "bench", "airway_tube_law"))
    p.add_argument("--table", default=None)
    args = p.parse_args(argv)
    deck = os.path.join(ROOT, "inputs", "paper", f"{args.deck}_{args.posture}.xml")
    out = os.path.join(args.runs, f"{args.deck}_{args.posture}")
    table = args.table or os.path.join(ROOT, "bench", "results", f"{args.deck}_tube_law_{args.posture}.csv")
    start = time.time()
    run = subprocess.run([args.glossa, "run", deck, "--quiet", "--output", out,
                          "--set", f"Loads/airway pressure/pressure={-args.suction}",
                          "--set", f"Time/step size={args.step}"]
                         + (["--set", "Airway/closing pressure load="] if args.deck == "tongue_pcrit" else []))
    seconds = time.time() - start
    with open(os.path.join(out, "airway.csv")) as f:
        rows = list(csv.DictReader(f))
    header = ["time [s]", "suction_P_P [Pa]", "suction_P_P [cmH2O]", "smallest_area [mm^2]", "smallest_section [-]",
              "smallest_arc_length [mm]", "contact_area [mm^2]", "closed [-]"]
    lines = []
    for r in rows:
        t = float(r["time [s]"])
        suction = args.suction * min(max(t - 1.0, 0.0), 1.0)
        lines.append([t, suction, suction / PA_PER_CMH2O, 1e6 * float(r["smallest_area [m^2]"]),
                      int(float(r["smallest_section [-]"])), 1e3 * float(r["smallest_arc_length [m]"]),
                      1e6 * float(r["contact_area [m^2]"]), int(float(r["closed [-]"]))])
    os.makedirs(os.path.dirname(table), exist_ok=True)
    with open(table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(lines)
    for line in lines:
        print("t %.3f s  suction %7.1f Pa (%5.2f cmH2O)  smallest %8.2f mm^2 at section %2d (s = %5.1f mm)  "
              "contact %7.2f mm^2  closed %d" % tuple(line))
    print(f"{args.posture}: exit status {run.returncode}, {len(lines)} steps recorded, {seconds:.0f} s; "
          f"table {os.path.relpath(table, ROOT)}")
    if run.returncode != 0:
        print("the run stopped before the end of the ramp: the table ends at its last converged step")
    return 0 if not math.isnan(lines[-1][3]) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
