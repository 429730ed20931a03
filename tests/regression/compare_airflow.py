#!/usr/bin/env python3
"""A run's airflow.csv against a stored reference (doc/airflow.md).

    compare_airflow.py REFERENCE.csv RUN_DIR [--tolerance T]

The run must have the reference's columns and rows (one a recorded step, at the same times to
T x the last time). The flow rate must agree within T x the reference's largest flow rate, the
smallest area within T x its largest smallest area, the end and section pressures within
T x its largest pressure magnitude; the closed and choked flags and the smallest section exactly.
The coupling's iteration count and last change are not compared: they follow the solver's
round-off near the coupling tolerance. Exit status 0 when it matches, 1 when not, 2 for
unreadable input."""
import sys

from reference_csv import arguments, load

EXACT = ("closed", "choked", "smallest_section")
SKIPPED = ("coupling_iterations", "coupling_change", "airway")


def largest(table, columns):
    return max((abs(float(r[c])) for r in table for c in columns), default=0.0) or 1.0


def main(argv):
    given = arguments(argv, __doc__)
    if given is None:
        return 2
    reference, run_dir, tolerance = given
    tables = load(reference, run_dir, "airflow.csv", "compare_airflow")
    if tables is None:
        return 2
    names, ref, run_names, run = tables
    if names != run_names or len(ref) != len(run):
        print(f"compare_airflow: {len(run)} rows of {run_names}; the reference has {len(ref)} of {names}")
        return 1
    pressures = [c for c in names if c.endswith("pressure") or c.startswith("pressure_")]
    scales = {"flow_rate": largest(ref, ["flow_rate"]), "smallest_area": largest(ref, ["smallest_area"])}
    scales.update({c: largest(ref, pressures) for c in pressures})
    last = abs(float(ref[-1]["time"])) or 1.0
    worst, where = 0.0, "none"
    for a, b in zip(ref, run):
        t = a["time"]
        if abs(float(a["time"]) - float(b["time"])) > tolerance * last:
            print(f"compare_airflow: a row at t = {b['time']} where the reference's is at {t}")
            return 1
        for c in names:
            if c == "time" or c in SKIPPED:
                continue
            if c in EXACT:
                if float(a[c]) != float(b[c]):
                    print(f"compare_airflow: t = {t}: {c} {b[c]}, the reference's {a[c]}")
                    return 1
                continue
            error = abs(float(a[c]) - float(b[c])) / scales[c]
            if error > worst:
                worst, where = error, f"t = {t}, {c}"
    print(f"compare_airflow: largest relative difference {worst:.2e} ({where}) over {len(ref)} rows")
    return 0 if worst <= tolerance else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
