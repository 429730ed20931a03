#!/usr/bin/python3
"""Glossa's side of the step-44 comparison at n elements per side (issue 8): the block of
inputs/verification/step44_block.xml with the augmented Lagrangian, run `--repeats` times per
configuration on one rank, CPU time (user + system, from the child's rusage) and wall time, with
the median of each, against deal.II step-44's row for the same n in bench/results/step44_dealii_timing.csv
(see dealii_cpu) or a `--dealii-cpu` given by hand (deal.II at 32 per side runs for 1.5 h: bench/step44_dealii/run_step44.sh).

  /usr/bin/python3 bench/step44_vs_dealii.py [--n 32] [--repeats 3] [--configs default,rap-eig20]
        [--dealii-cpu 4900] [--ranks 1]

Appends one row per run and one `median` row per configuration to bench/results/step44_vs_dealii_runs.csv.
Run it on an otherwise quiet machine: CPU time is the fair measure, but cache contention with
another job still inflates it.
"""
import argparse
import csv
import json
import os
import resource
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results")
DECK = os.path.join(ROOT, "inputs", "verification", "step44_block.xml")
CONFIGS = {
    "default": [],
    "iterative": ["Linear solver/type=iterative"],
    # What this scene needs of the smoother: MueLu keeps its coarse levels between Newton iterations
    # (only the finest smoother is rebuilt) and the Chebyshev eigenvalue estimate takes 20 power
    # iterations (the default 50 guards the active-muscle scenes, doc/incompressibility.md).
    "rap-eig20": ["Linear solver/MueLu reuse=RAP", "Linear solver/Chebyshev eigenvalue iterations=20"],
}
FIELDS = ["n", "ranks", "config", "run", "newton", "krylov", "uzawa", "uy_top_centre_mm", "cpu_s", "wall_s",
          "assembly_s", "prec_setup_s", "krylov_s", "peak_mb", "dealii_cpu_s", "speedup_cpu"]


def run_once(glossa, n, ranks, overrides):
    out = tempfile.mkdtemp(prefix="glossa_s44_")
    cmd = [glossa, "run", DECK, "--output", out, "--quiet", "--set", f"Mesh/Box/cells={n},{n},{n}",
           "--set", "Incompressibility/method=augmented Lagrangian", "--set", "Output/fields=false"]
    for o in overrides:
        cmd += ["--set", o]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run(cmd, check=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    steps = s["steps"]
    return {
        "newton": sum(x["newton_iterations"] for x in steps),
        "krylov": sum(x["linear_iterations"] for x in steps),
        "uzawa": sum(x["uzawa_iterations"] for x in steps),
        "uy_top_centre_mm": s["final_displacement"]["top_centre"][1] * 1e3,
        "cpu_s": round(cpu, 1), "wall_s": round(wall, 1),
        "assembly_s": round(s["assembly_seconds"], 1), "prec_setup_s": round(s["preconditioner_setup_seconds"], 1),
        "krylov_s": round(s["linear_solve_seconds"], 1), "peak_mb": round(s["peak_memory_mb_per_rank"]),
    }


def dealii_cpu(n):
    """deal.II's CPU seconds at n: its row in step44_32_vs_dealii.csv (which includes the 2-3 min
    of building step-44), else its wall time in step44_dealii_timing.csv (quiet-machine runs)."""
    with open(os.path.join(RESULTS, "step44_32_vs_dealii.csv")) as f:
        for r in csv.DictReader(f):
            if r["code"].startswith("deal.II") and int(r["elements_per_side"]) == n and r["cpu_s"]:
                return float(r["cpu_s"])
    with open(os.path.join(RESULTS, "step44_dealii_timing.csv")) as f:
        for r in csv.DictReader(f):
            if int(r["elements_per_side"]) == n:
                return float(r["wall_seconds"])
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    ap.add_argument("--n", type=int, default=32)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--configs", default=",".join(CONFIGS))
    ap.add_argument("--dealii-cpu", type=float, default=None,
                    help="deal.II's CPU seconds for the same n (default: dealii_cpu)")
    a = ap.parse_args()
    reference = a.dealii_cpu if a.dealii_cpu is not None else dealii_cpu(a.n)
    path = os.path.join(RESULTS, "step44_vs_dealii_runs.csv")
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        if new:
            w.writeheader()
        for config in a.configs.split(","):
            cpus, walls = [], []
            for k in range(1, a.repeats + 1):
                r = run_once(a.glossa, a.n, a.ranks, CONFIGS[config])
                cpus.append(r["cpu_s"])
                walls.append(r["wall_s"])
                row = dict(r, n=a.n, ranks=a.ranks, config=config, run=k, dealii_cpu_s=reference,
                           speedup_cpu=round(reference / r["cpu_s"], 1) if reference else "")
                w.writerow(row)
                f.flush()
                print(config, k, r, flush=True)
            med = statistics.median(cpus)
            w.writerow({"n": a.n, "ranks": a.ranks, "config": config, "run": "median", "cpu_s": med,
                        "wall_s": statistics.median(walls), "dealii_cpu_s": reference,
                        "speedup_cpu": round(reference / med, 1) if reference else ""})
            f.flush()
            print(f"{config}: median CPU {med:.1f} s, speed-up {reference / med if reference else float('nan'):.1f}x",
                  flush=True)


if __name__ == "__main__":
    main()
