#!/usr/bin/python3
"""How a controller's sensitivities are solved, side by side on the medium tongue:

  /usr/bin/python3 bench/sensitivity_solve.py [--choices auto,as-newton,direct-newton] [--ranks 2]
      [--end 2.5] [--repeats 1] [--glossa build/glossa] [--append]

Runs the supine gradient deck (inputs/paper/s8_5_gradient_supine.xml) on the tongue refined once
(20,097 unknowns, its own zero-strain configuration) to `--end` seconds (8 control steps at 2.5),
once per choice within each repeat, in turn, so that a drift of the shared machine's speed
touches them alike:
- auto: the defaults (MueLu for Newton; the sensitivities factored by MUMPS, which makes the
  sensitivity tangent `auto` the converged Uzawa loop's);
- as-newton: `Linear solver/sensitivity solve = as Newton` (MueLu for them too, with the inner
  tangent: the behaviour before 2026-12-07);
- direct-newton: `Linear solver/type = direct` with `direct reuse scope = step` (MUMPS for
  everything).
Writes bench/results/sensitivity_solve.csv: per run the wall time of the whole process, the
summary's time split (assembly, MueLu set-up and Krylov, factorisations, the sensitivities'
tangents and solves, df/dalpha), the candidates, Newton iterations and the controller's summed
objective (eq. 25 in m, summed over the control steps). doc/performance.md has the figures.
Standard library only.
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import tempfile
import time

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results", "sensitivity_solve.csv")
DECK = os.path.join(ROOT, "inputs", "paper", "s8_5_gradient_supine.xml")
MEDIUM = ["Mesh/File/refine=1", "Mesh/reference coordinates file=s8_1/reference_inverse_refine1.txt"]
CHOICES = {
    "auto": [],
    "as-newton": ["Linear solver/sensitivity solve=as Newton"],
    "direct-newton": ["Linear solver/type=direct", "Linear solver/direct reuse scope=step"],
}
SPLIT = ["direct_factorisation", "direct_solve", "input_derivatives", "tangent_setup", "tangent_solve"]
FIELDS = (["choice", "repeat", "ranks", "end_time", "converged", "wall_s", "assembly_s", "preconditioner_setup_s",
           "linear_solve_s"] + [f"{k}_s" for k in SPLIT] + ["factorisations", "candidates", "newton_iterations",
                                                          "objective_sum_m", "sensitivity_solve", "sensitivity_tangent",
                                                          "date"])


def run(glossa, sets, ranks):
    out = tempfile.mkdtemp(prefix="glossa-sensitivity-solve-")
    start = time.perf_counter()
    subprocess.run(glossa_run_command(glossa, DECK, out, sets, ranks), check=False, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        summary = {"converged": False, "steps": []}
    shutil.rmtree(out, ignore_errors=True)
    return wall, summary


def row(choice, repeat, ranks, end, wall, s):
    split = s.get("time_split", {})
    controls = [step.get("control", {}) for step in s.get("steps", [])]
    r = {"choice": choice, "repeat": repeat, "ranks": ranks, "end_time": end, "converged": s.get("converged", False),
         "wall_s": round(wall, 1), "assembly_s": round(s.get("assembly_seconds", 0.0), 1),
         "preconditioner_setup_s": round(s.get("preconditioner_setup_seconds", 0.0), 1),
         "linear_solve_s": round(s.get("linear_solve_seconds", 0.0), 1),
         "factorisations": split.get("direct_factorisation", {}).get("calls", 0),
         "candidates": sum(c.get("candidates", 0) for c in controls),
         "newton_iterations": sum(step.get("newton_iterations", 0) for step in s.get("steps", [])),
         "objective_sum_m": round(sum(c.get("objective", 0.0) for c in controls), 7),
         "sensitivity_solve": s.get("sensitivity_solve", ""),
         "sensitivity_tangent": controls[-1].get("sensitivity_tangent", "") if controls else "",
         "date": time.strftime("%Y-%m-%d")}
    for k in SPLIT:
        r[f"{k}_s"] = round(split.get(k, {}).get("seconds", 0.0), 1)
    return r


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--choices", default=",".join(CHOICES), type=lambda s: s.split(","))
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--end", default="2.5")
    p.add_argument("--repeats", type=int, default=1)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--append", action="store_true", help="add to the CSV instead of replacing it")
    args = p.parse_args()
    rows = []
    for repeat in range(1, args.repeats + 1):
        for choice in args.choices:
            wall, summary = run(args.glossa, MEDIUM + [f"Time/end time={args.end}"] + CHOICES[choice], args.ranks)
            rows.append(row(choice, repeat, args.ranks, args.end, wall, summary))
            r = rows[-1]
            print(f"{choice:14s} repeat {repeat}: {r['wall_s']:7.1f} s, {r['candidates']} candidates, "
                  f"{r['newton_iterations']} Newton iterations, objectives {r['objective_sum_m']:.6f} m", flush=True)
    exists = args.append and os.path.exists(RESULTS)
    with open(RESULTS, "a" if exists else "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        if not exists:
            w.writeheader()
        w.writerows(rows)
    print(f"wrote {RESULTS}")


if __name__ == "__main__":
    main()
