#!/usr/bin/env python3
"""The airway past its closing suction, passive against controlled (doc/airway.md, "Control past
the closing suction"): the first breath's peak of airway_control_{passive,gradient}_supine.xml.

    check_airway_held_open.py PASSIVE_RUN_DIR CONTROLLED_RUN_DIR CLOSING_AREA_MM2

Asserts, on the two runs' airway.csv, what the scene is for: the passive airway closes (a step
with a closed section, its smallest area below the closing area), and the controlled one never
does (every step open, its smallest area above the closing area), at the same suction on the same
tongue and wall. Exit status 0 when both hold, 1 when not, 2 for unreadable input."""
import csv
import os
import sys


def rows(run_dir):
    with open(os.path.join(run_dir, "airway.csv")) as f:
        return [(float(r["time [s]"]), 1e6 * float(r["smallest_area [m^2]"]), int(r["closed [-]"]))
                for r in csv.DictReader(f)]


def main(argv):
    if len(argv) != 4:
        print(__doc__)
        return 2
    try:
        passive, controlled, closing = rows(argv[1]), rows(argv[2]), float(argv[3])
    except (OSError, KeyError, ValueError) as e:
        print("check_airway_held_open:", e)
        return 2
    ok = True
    closed = [(t, a) for t, a, c in passive if c]
    if not closed or min(a for _, a in closed) >= closing:
        print(f"the passive airway does not close: smallest {min(a for _, a, _ in passive):.3f} mm^2")
        ok = False
    else:
        print(f"passive: closed from t = {closed[0][0]:.4f} s, smallest {min(a for _, a in closed):.3f} mm^2")
    t, a, _ = min(controlled, key=lambda r: r[1])
    if any(c for _, _, c in controlled) or a <= closing:
        print(f"the controlled airway closes: smallest {a:.3f} mm^2 at t = {t:.4f} s")
        ok = False
    else:
        print(f"controlled: open at every step, smallest {a:.3f} mm^2 at t = {t:.4f} s")
    if passive[-1][0] != controlled[-1][0]:
        print(f"the runs end at different times: {passive[-1][0]} and {controlled[-1][0]} s")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
