#!/usr/bin/env python3
"""compare_pcrit.py on made-up runs: the reference itself matches; a Pcrit moved by just under its
bracket tolerance matches, by just over it does not; another section, an open run or a summary
without pcrit do not; a missing run directory is unreadable (2)."""
import json
import os
import sys
import tempfile

import compare_pcrit

REFERENCE = {"Pa": -2781.74, "bisection_solves": 5, "bracketed": True, "closed": True, "cmH2O": -28.366,
             "load": "airway pressure", "section": 9, "tolerance_Pa": 9.80665}


def verdict(root, name, pcrit):
    run = os.path.join(root, name)
    os.makedirs(run)
    with open(os.path.join(run, "summary.json"), "w") as f:
        json.dump({} if pcrit is None else {"pcrit": pcrit}, f)
    return compare_pcrit.main(["compare_pcrit.py", os.path.join(root, "reference.json"), run, "--tolerance", "1"])


def main():
    with tempfile.TemporaryDirectory() as root:
        with open(os.path.join(root, "reference.json"), "w") as f:
            json.dump(REFERENCE, f)
        cases = [("same", REFERENCE, 0),
                 ("just_inside", {**REFERENCE, "Pa": REFERENCE["Pa"] + 0.99 * REFERENCE["tolerance_Pa"]}, 0),
                 ("just_outside", {**REFERENCE, "Pa": REFERENCE["Pa"] - 1.01 * REFERENCE["tolerance_Pa"]}, 1),
                 ("other_section", {**REFERENCE, "section": 4}, 1),
                 ("open", {**REFERENCE, "closed": False, "bracketed": False}, 1),
                 ("no_pcrit", None, 1)]
        failed = [name for name, pcrit, expected in cases if verdict(root, name, pcrit) != expected]
        missing = compare_pcrit.main(["compare_pcrit.py", os.path.join(root, "reference.json"),
                                      os.path.join(root, "nowhere")])
        if missing != 2:
            failed.append("nowhere")
    print("compare_pcrit_selftest: " + ("every case as expected" if not failed else "wrong verdict: " + ", ".join(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
