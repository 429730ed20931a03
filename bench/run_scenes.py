#!/usr/bin/python3
"""Time per step and per Newton iteration of every scene deck, run on demand:

  /usr/bin/python3 bench/run_scenes.py [--repeats 3] [--ranks 1,2] [--glossa build/glossa] [--only 's7_1_*']

Runs inputs/paper/*.xml (those matching --only, a glob on the file name; and any deck given with
--deck) and writes bench/results/scenes.csv:
steps, Newton, Krylov and Uzawa iterations, wall time (median over repeats), seconds per step and
per Newton iteration, the assembly share, and the largest dilatation error. Standard library only.
"""
import argparse
import csv
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(glossa, deck, ranks):
    out = tempfile.mkdtemp(prefix="glossa-scene-")
    cmd = glossa_run_command(glossa, deck, out, ranks=ranks)
    subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--repeats", default=3, type=int)
    p.add_argument("--ranks", default="1", type=lambda s: [int(x) for x in s.split(",")])
    p.add_argument("--deck", action="append", default=[])
    p.add_argument("--only", default="*", help="glob on the file names of inputs/paper (default: every deck)")
    args = p.parse_args()
    decks = sorted(glob.glob(os.path.join(ROOT, "inputs", "paper", args.only + ("" if args.only.endswith(".xml") else ".xml"))))
    decks += args.deck
    rows = []
    for deck in decks:
        for ranks in args.ranks:
            runs = [run(args.glossa, deck, ranks) for _ in range(args.repeats)]
            s = runs[0]
            steps = s["steps"]
            newton = sum(x["newton_iterations"] for x in steps)
            wall = statistics.median(r["wall_seconds"] for r in runs)
            assembly = statistics.median(r["assembly_seconds"] for r in runs)
            row = {
                "deck": os.path.relpath(deck, ROOT), "ranks": ranks, "converged": s["converged"],
                "elements": s["elements"], "dofs": s["dofs"], "steps": len(steps), "newton": newton,
                "krylov": sum(x["linear_iterations"] for x in steps),
                "uzawa": sum(x["uzawa_iterations"] for x in steps),
                "wall_s": round(wall, 3), "s_per_step": round(wall / max(len(steps), 1), 4),
                "s_per_newton": round(wall / max(newton, 1), 4), "assembly_share": round(assembly / wall, 3),
                "max_dilatation_error": max(x["max_dilatation_error"] for x in steps),
                "repeats": args.repeats,
            }
            print(row, flush=True)
            rows.append(row)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    path = os.path.join(ROOT, "bench", "results", "scenes.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote", path)


if __name__ == "__main__":
    sys.exit(main())
