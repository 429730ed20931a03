#!/usr/bin/env python3
"""A run's closing pressure (summary.json's pcrit, doc/airway.md) against a stored one.

    compare_pcrit.py REFERENCE.json RUN_DIR [--tolerance T]

The run must have closed and bracketed its closing pressure as the reference did, at the same
section, and its Pcrit must lie within T x the reference's bracket tolerance (tolerance_Pa, the
deck's 'closing pressure tolerance') of the reference's: with T = 1, the two bisections agree to
their own resolution. Exit status 0 when it matches, 1 when not, 2 for unreadable input."""
import json
import sys

from reference_csv import arguments


def main(argv):
    given = arguments(argv, __doc__)
    if given is None:
        return 2
    reference, run_dir, tolerance = given
    try:
        with open(reference) as f:
            ref = json.load(f)
        with open(run_dir + "/summary.json") as f:
            run = json.load(f).get("pcrit")
    except (OSError, ValueError) as e:
        print(f"compare_pcrit: {e}", file=sys.stderr)
        return 2
    if run is None:
        print("compare_pcrit: the run's summary.json has no pcrit (no closing pressure search)")
        return 1
    for key in ("closed", "bracketed", "section", "load"):
        if run.get(key) != ref.get(key):
            print(f"compare_pcrit: {key} {run.get(key)!r}, the reference's {ref.get(key)!r}")
            return 1
    if not ref.get("bracketed"):
        print("compare_pcrit: neither closed: nothing more to compare")
        return 0
    difference = abs(run["Pa"] - ref["Pa"])
    bound = tolerance * ref["tolerance_Pa"]
    print(f"compare_pcrit: Pcrit {run['Pa']:.3f} Pa against the reference's {ref['Pa']:.3f} Pa "
          f"(difference {difference:.3g} Pa, allowed {bound:.3g} Pa), section {run['section']}, "
          f"{run['bisection_solves']} bisection solves against {ref['bisection_solves']}")
    return 0 if difference <= bound else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
