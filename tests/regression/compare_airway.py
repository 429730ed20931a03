#!/usr/bin/env python3
"""A run's airway.csv against a stored reference (doc/airway.md).

    compare_airway.py REFERENCE.csv RUN_DIR [--tolerance T]

Every row of the reference (one a recorded step) must be in RUN_DIR/airway.csv at the same time
(within T x the last time), with the same sections: each area, the smallest area and the contact
area within T x (the reference's largest area), the same smallest section, the same closed flag
and count ('nan' where the reference has 'nan'); no row may be missing or extra. Exit status 0
when it matches, 1 when not, 2 for unreadable input."""
import math
import sys

from reference_csv import arguments, load


def main(argv):
    given = arguments(argv, __doc__)
    if given is None:
        return 2
    reference, run_dir, tolerance = given
    tables = load(reference, run_dir, "airway.csv", "compare_airway")
    if tables is None:
        return 2
    ref_header, ref, run_header, run = tables
    if ref_header != run_header:
        print(f"compare_airway: columns differ: {ref_header} against {run_header}")
        return 1
    if len(ref) != len(run):
        print(f"compare_airway: {len(run)} rows, the reference has {len(ref)}")
        return 1
    areas = [c for c in ref_header if c.startswith("area_")] + ["smallest_area", "contact_area"]
    scale = max(abs(float(r[c])) for r in ref for c in areas if not math.isnan(float(r[c])))
    last = float(ref[-1]["time"])
    worst, where = 0.0, ""
    for a, b in zip(ref, run):
        t = a["time"]
        if abs(float(a["time"]) - float(b["time"])) > tolerance * last:
            print(f"compare_airway: time {b['time']} where the reference has {t}")
            return 1
        for c in ("smallest_section", "closed", "closed_sections"):
            if a[c] != b[c]:
                print(f"compare_airway: t = {t}: {c} {b[c]}, the reference's {a[c]}")
                return 1
        for c in areas:
            x, y = float(a[c]), float(b[c])
            if math.isnan(x) != math.isnan(y):
                print(f"compare_airway: t = {t}: {c} {b[c]}, the reference's {a[c]}")
                return 1
            if not math.isnan(x) and abs(x - y) > worst:
                worst, where = abs(x - y), f"t = {t}, {c}"
    print(f"compare_airway: largest area difference {worst:.3e} m^2 ({worst / scale:.2e} of the largest area, "
          f"{where or 'none'}) over {len(ref)} rows")
    return 0 if worst <= tolerance * scale else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
