#!/usr/bin/python3
"""Glossa benchmarks, run on demand (never in CI): each writes a CSV to bench/results/.

  /usr/bin/python3 bench/run_bench.py scaling   # step-44 block, 4-32 per side, 1-2 ranks
  /usr/bin/python3 bench/run_bench.py kappa     # kappa/mu from 10 to 1e7, with and without Uzawa
  /usr/bin/python3 bench/run_bench.py all

Options: --glossa PATH (default build/glossa), --sizes 4,8,16,32, --repeats N (wall times are
medians over N runs; iteration counts do not vary). Standard library only.
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "inputs", "verification", "step44_block.xml")
RESULTS = os.path.join(ROOT, "bench", "results")


def run(glossa, ranks, overrides, deck=DECK):
    out = tempfile.mkdtemp(prefix="glossa-bench-")
    cmd = glossa_run_command(glossa, deck, out, overrides, ranks)
    subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def totals(s):
    steps = s["steps"]
    return {
        "converged": s["converged"],
        "dofs": s["dofs"],
        "newton": sum(x["newton_iterations"] for x in steps),
        "krylov": sum(x["linear_iterations"] for x in steps),
        "uzawa": sum(x["uzawa_iterations"] for x in steps),
        "max_dilatation_error": max(x["max_dilatation_error"] for x in steps) if steps else float("nan"),
        "uy_top_centre_mm": s["final_displacement"].get("top_centre", [0, float("nan"), 0])[1] * 1e3,
    }


def timed(glossa, ranks, overrides, repeats):
    runs = [run(glossa, ranks, overrides) for _ in range(repeats)]
    row = totals(runs[0])
    for key, name in [("wall_seconds", "wall_s"), ("assembly_seconds", "assembly_s"),
                      ("preconditioner_setup_seconds", "prec_setup_s"), ("linear_solve_seconds", "krylov_s")]:
        row[name] = round(statistics.median(r.get(key, float("nan")) for r in runs), 3)
    row["peak_mb_per_rank"] = round(max(r["peak_memory_mb_per_rank"] for r in runs), 1)
    return row


def write(name, rows):
    os.makedirs(RESULTS, exist_ok=True)
    path = os.path.join(RESULTS, name)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote", path)


def dealii_times():
    path = os.path.join(RESULTS, "step44_dealii_timing.csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return {int(r["elements_per_side"]): r for r in csv.DictReader(f)}


def scaling(args):
    rows = []
    ref = dealii_times()
    for n in args.sizes:
        for ranks in (1, 2):
            for method in args.methods:
                o = [f"Mesh/Box/cells={n},{n},{n}", f"Incompressibility/method={method}"]
                row = {"elements_per_side": n, "ranks": ranks, "method": method}
                row.update(timed(args.glossa, ranks, o, args.repeats))
                d = ref.get(n)
                row["dealii_wall_s"] = d["wall_seconds"] if d else ""
                row["dealii_cg_iterations"] = d["cg_iterations_total"] if d else ""
                row["speedup_vs_dealii"] = round(float(d["wall_seconds"]) / row["wall_s"], 2) if d else ""
                print(row, flush=True)
                rows.append(row)
                write(args.output_name, rows)


def kappa(args):
    rows = []
    n = args.kappa_size
    for ratio in (10, 100, 1e3, 1e4, 1e5, 1e6, 1e7):
        for method in ("augmented Lagrangian", "penalty"):
            o = [f"Mesh/Box/cells={n},{n},{n}", f"Incompressibility/method={method}",
                 f"Incompressibility/penalty ratio={ratio:g}", f"Material/bulk modulus={ratio * 80.194e6:g}"]
            row = {"kappa_over_mu": ratio, "method": method, "elements_per_side": n}
            row.update(timed(args.glossa, 1, o, args.repeats))
            print(row, flush=True)
            rows.append(row)
            write("kappa_uzawa_trade.csv", rows)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("what", choices=["scaling", "kappa", "all"])
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--sizes", default="4,8,16,32", type=lambda s: [int(x) for x in s.split(",")])
    p.add_argument("--kappa-size", default=8, type=int)
    p.add_argument("--methods", default="penalty,augmented Lagrangian", type=lambda s: s.split(","))
    p.add_argument("--output-name", default="step44_scaling.csv")
    p.add_argument("--repeats", default=1, type=int)
    args = p.parse_args()
    if args.what in ("scaling", "all"):
        scaling(args)
    if args.what in ("kappa", "all"):
        kappa(args)


if __name__ == "__main__":
    sys.exit(main())
