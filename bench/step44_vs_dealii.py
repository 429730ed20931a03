#!/usr/bin/python3
"""The step-44 block at n elements per side, Glossa against deal.II step-44.

Glossa: the block of inputs/verification/step44_block.xml with the augmented Lagrangian, run `--repeats`
times per configuration on one rank (or `--ranks`), CPU time (user + system, from the child's rusage)
and wall time, with the median of each, Newton/Krylov/Uzawa iterations, time split and u_y at the top
centre.

deal.II step-44 (Q1-DGPM0-DGPM0, CG + SSOR, one thread), one of:
  --dealii run     run it here, in this invocation, at the same n (n = 2^level), `--dealii-repeats`
                   times, before Glossa.  bench/step44_dealii/run_step44.sh builds the patched
                   tutorial once into `--dealii-scratch` (PREPARE_ONLY=1; 2-3 min the first time,
                   nothing to rebuild later) and writes the run's parameter file; the build is not
                   timed.  This script then runs the executable itself with DEAL_II_NUM_THREADS=1 and
                   takes its CPU (user + system) from the child's rusage, as for Glossa.  Its Newton
                   and CG iterations (the convergence table) and u_y at the top centre at t = 1
                   (the STEP44_TRACE line) are read from its log.  deal.II still writes its VTU files
                   (as shipped, part of its time; deleted after each run).  About 1.4 s at n = 4,
                   3 min at n = 16, 1.5 h at n = 32.
  (default)        the stored reference: deal.II's row for n in bench/results/step44_32_vs_dealii.csv
                   (CPU, includes the 2-3 min of building step-44), else its wall time in
                   step44_dealii_timing.csv; its u_y from step44_dealii.csv.  `--dealii-cpu S` gives
                   the CPU seconds by hand instead.

  nice -n 10 /usr/bin/python3 bench/step44_vs_dealii.py [--n 32] [--repeats 3] [--configs default,power-newton-scope]
        [--glossa build/glossa] [--ranks 1] [--dealii run [--dealii-repeats 1] [--dealii-scratch DIR]
        | --dealii-cpu 4900]

Appends to bench/results/step44_vs_dealii_runs.csv one row per run and one `median` row per
configuration; with `--dealii run` also deal.II's own rows (config `deal.II`: its runs and their
median; krylov = its CG iterations).  Every Glossa row carries deal.II's CPU and wall, where they come
from (dealii_source: run, stored or given), deal.II's u_y and Glossa's u_y relative difference from it
(the target: within 0.5 %), and the CPU speed-up.  A file with the older, shorter header is rewritten with
the new columns (empty, dealii_source = stored where a reference was used) before appending.  Prints a
summary table at the end.  Run it on an otherwise quiet machine: CPU time is the fair measure, but
cache contention with another job still inflates it.
"""
import argparse
import csv
import glob
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
DEALII_SUMMARY = os.path.join(ROOT, "bench", "step44_dealii", "summarise_log.awk")
DEALII_SCRIPT = os.path.join(ROOT, "bench", "step44_dealii", "run_step44.sh")
ANSWER_TOLERANCE = 0.005  # the same answer within 0.5 %
CONFIGS = {
    "default": [],
    "iterative": ["Linear solver/type=iterative"],
    # The defaults before 2026-12-03: the power-method eigenvalue estimate (50 iterations) and the
    # hierarchy rebuilt at every Newton solve (bench/LOG.md).
    "power-newton-scope": ["Linear solver/Chebyshev eigenvalue method=power",
                           "Linear solver/MueLu reuse scope=Newton solve"],
}
FIELDS = ["n", "ranks", "config", "run", "newton", "krylov", "uzawa", "uy_top_centre_mm", "cpu_s", "wall_s",
          "assembly_s", "prec_setup_s", "krylov_s", "peak_mb", "dealii_cpu_s", "speedup_cpu",
          # added later (older rows leave them empty)
          "dealii_source", "dealii_wall_s", "dealii_uy_top_centre_mm", "uy_rel_diff"]


def child_times(cmd, **kw):
    """Runs cmd; returns (CPU seconds = user + system of the child from rusage, wall seconds)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run(cmd, check=True, **kw)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall


def run_once(glossa, n, ranks, overrides):
    out = tempfile.mkdtemp(prefix="glossa_s44_")
    cmd = [glossa, "run", DECK, "--output", out, "--quiet", "--set", f"Mesh/Box/cells={n},{n},{n}",
           "--set", "Incompressibility/method=augmented Lagrangian", "--set", "Output/fields=false"]
    for o in overrides:
        cmd += ["--set", o]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    cpu, wall = child_times(cmd)
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


def dealii_level(n):
    level = n.bit_length() - 1
    if n < 2 or 1 << level != n:
        raise SystemExit(f"--dealii run needs n = 2^level >= 2 (step-44 refines its unit cube globally), not {n}")
    return level


def dealii_prepare(n, scratch):
    """Builds the patched step-44 into scratch (untimed; no rebuild when up to date) and writes the
    parameter file for n via run_step44.sh PREPARE_ONLY=1; returns (executable, run directory)."""
    level = dealii_level(n)
    env = dict(os.environ, PREPARE_ONLY="1", LEVELS=str(level), SC_COMPARE="")
    print(f"deal.II: building step-44 in {scratch} (untimed) ...", flush=True)
    p = subprocess.run(["bash", DEALII_SCRIPT, scratch], env=env, check=True, stdout=subprocess.PIPE, text=True)
    exe = run_dir = None
    for line in p.stdout.splitlines():
        f = line.split(maxsplit=2)
        if f and f[0] == "STEP44_EXE":
            exe = line.split(maxsplit=1)[1]
        elif f and f[0] == "STEP44_RUN_DIR" and int(f[1]) == level:
            run_dir = f[2]
    if not exe or not run_dir:
        raise SystemExit(f"run_step44.sh did not report its executable and run directory:\n{p.stdout}")
    return exe, run_dir


def dealii_parse_log(path, n):
    """u_y at the top centre at t = 1 (last STEP44_TRACE line, in mm); dofs, Newton and CG
    iterations as step44_dealii/summarise_log.awk counts them (shared with run_step44.sh)."""
    trace = None
    with open(path) as f:
        for line in f:
            if line.startswith("STEP44_TRACE"):
                _, eps, t, uy = line.split()
                trace = (int(eps), float(t), float(uy))
    if trace is None or trace[0] != n or abs(trace[1] - 1.0) > 1e-9:
        raise SystemExit(f"{path}: no STEP44_TRACE line for n = {n} at t = 1 (last: {trace})")
    counts = subprocess.run(["awk", "-f", DEALII_SUMMARY, path], check=True, stdout=subprocess.PIPE, text=True)
    dofs, newton, cg = counts.stdout.strip().split(",")
    return {"uy_top_centre_mm": trace[2] * 1e3, "newton": int(newton or 0), "krylov": int(cg or 0),
            "dofs": int(dofs) if dofs else None}


def dealii_run(n, repeats, scratch):
    """Runs deal.II step-44 at n `repeats` times; returns the list of per-run dicts."""
    exe, run_dir = dealii_prepare(n, scratch)
    env = dict(os.environ, DEAL_II_NUM_THREADS="1", OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    runs = []
    for k in range(1, repeats + 1):
        log = os.path.join(run_dir, f"step44_run{k}.log")
        with open(log, "w") as out:
            cpu, wall = child_times([exe], cwd=run_dir, env=env, stdout=out, stderr=subprocess.STDOUT)
        for vtu in glob.glob(os.path.join(run_dir, "solution-*.vtu")):
            os.remove(vtu)
        r = dict(dealii_parse_log(log, n), cpu_s=round(cpu, 2), wall_s=round(wall, 2))
        print("deal.II", k, r, f"(log {log})", flush=True)
        runs.append(r)
    return runs


def stored_dealii(n):
    """deal.II's stored CPU seconds at n: its row in step44_32_vs_dealii.csv (which includes the 2-3 min
    of building step-44), else its wall time in step44_dealii_timing.csv (quiet-machine runs); that
    wall time; and its u_y at t = 1 from step44_dealii.csv (mm).  None where not stored."""
    cpu = wall = uy = None
    with open(os.path.join(RESULTS, "step44_32_vs_dealii.csv")) as f:
        for r in csv.DictReader(f):
            if r["code"].startswith("deal.II") and int(r["elements_per_side"]) == n and r["cpu_s"]:
                cpu, wall = float(r["cpu_s"]), float(r["wall_s"])
                if r.get("uy_top_centre_mm"):
                    uy = float(r["uy_top_centre_mm"])
                break
    with open(os.path.join(RESULTS, "step44_dealii_timing.csv")) as f:
        for r in csv.DictReader(f):
            if int(r["elements_per_side"]) == n:
                wall = wall if wall is not None else float(r["wall_seconds"])
                cpu = cpu if cpu is not None else float(r["wall_seconds"])
    with open(os.path.join(RESULTS, "step44_dealii.csv")) as f:
        for r in csv.DictReader(f):
            if int(r["elements_per_side"]) == n and abs(float(r["time"]) - 1.0) < 1e-9:
                uy = float(r["uy_top_centre_m"]) * 1e3
    return cpu, wall, uy


def open_results(path):
    """Opens the runs CSV for appending; a file written with an older header is first rewritten with
    FIELDS (new columns empty; dealii_source = stored where the row used a reference)."""
    if os.path.exists(path):
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            header, rows = reader.fieldnames, list(reader)
        if header != FIELDS:
            unknown = set(header) - set(FIELDS)
            if unknown:
                raise SystemExit(f"{path}: unknown columns {sorted(unknown)}")
            for r in rows:
                if r.get("dealii_cpu_s") and not r.get("dealii_source"):
                    r["dealii_source"] = "stored"
            with open(path, "w", newline="") as f:
                w = csv.DictWriter(f, FIELDS)
                w.writeheader()
                w.writerows(rows)
    else:
        with open(path, "w", newline="") as f:
            csv.DictWriter(f, FIELDS).writeheader()
    return open(path, "a", newline="")


def rel_diff(uy, reference):
    return (uy - reference) / abs(reference) if uy is not None and reference else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"), help="the glossa binary")
    ap.add_argument("--n", type=int, default=32, help="elements per side")
    ap.add_argument("--ranks", type=int, default=1, help="Glossa's ranks (deal.II always runs on one)")
    ap.add_argument("--repeats", type=int, default=3, help="Glossa runs per configuration")
    ap.add_argument("--configs", default=",".join(CONFIGS), help=f"of {','.join(CONFIGS)}")
    ap.add_argument("--dealii", choices=["stored", "run"], default="stored",
                    help="run: run deal.II step-44 here at the same n; stored (default): its stored row")
    ap.add_argument("--dealii-repeats", type=int, default=1, help="deal.II runs with --dealii run (median taken)")
    ap.add_argument("--dealii-scratch", default=os.path.join(tempfile.gettempdir(), "glossa_step44_dealii"),
                    help="where run_step44.sh builds step-44 and its run directories live (kept between calls)")
    ap.add_argument("--dealii-cpu", type=float, default=None,
                    help="deal.II's CPU seconds for the same n, by hand (instead of the stored row)")
    a = ap.parse_args()
    configs = a.configs.split(",")
    for c in configs:
        if c not in CONFIGS:
            ap.error(f"unknown config {c!r}")
    if a.dealii == "run" and a.dealii_cpu is not None:
        ap.error("--dealii-cpu and --dealii run exclude each other")
    if a.dealii == "run":
        dealii_level(a.n)
    if not os.access(a.glossa, os.X_OK):
        ap.error(f"no glossa binary at {a.glossa} (build it, or give --glossa PATH)")

    path = os.path.join(RESULTS, "step44_vs_dealii_runs.csv")
    with open_results(path) as f:
        w = csv.DictWriter(f, FIELDS)
        if a.dealii == "run":
            runs = dealii_run(a.n, a.dealii_repeats, os.path.abspath(a.dealii_scratch))
            ref_cpu = round(statistics.median(r["cpu_s"] for r in runs), 2)
            ref_wall = round(statistics.median(r["wall_s"] for r in runs), 2)
            ref_uy = runs[-1]["uy_top_centre_mm"]
            source = "run"
            for k, r in enumerate(runs, 1):
                w.writerow({"n": a.n, "ranks": 1, "config": "deal.II", "run": k, "newton": r["newton"],
                            "krylov": r["krylov"], "uy_top_centre_mm": r["uy_top_centre_mm"], "cpu_s": r["cpu_s"],
                            "wall_s": r["wall_s"], "dealii_source": source})
            w.writerow({"n": a.n, "ranks": 1, "config": "deal.II", "run": "median", "cpu_s": ref_cpu,
                        "wall_s": ref_wall, "dealii_source": source})
            f.flush()
            dealii_iters = f"{runs[-1]['newton']} Newton, {runs[-1]['krylov']} CG, {runs[-1]['dofs']} dofs"
        else:
            ref_cpu, ref_wall, ref_uy = stored_dealii(a.n)
            source = "stored" if ref_cpu is not None else ""
            if a.dealii_cpu is not None:
                ref_cpu, ref_wall, source = a.dealii_cpu, None, "given"
            dealii_iters = ""
        reference = {"dealii_cpu_s": ref_cpu if ref_cpu is not None else "",
                     "dealii_wall_s": ref_wall if ref_wall is not None else "",
                     "dealii_source": source, "dealii_uy_top_centre_mm": ref_uy if ref_uy is not None else ""}

        summary = []
        for config in configs:
            cpus, walls, uys = [], [], []
            for k in range(1, a.repeats + 1):
                r = run_once(a.glossa, a.n, a.ranks, CONFIGS[config])
                cpus.append(r["cpu_s"])
                walls.append(r["wall_s"])
                uys.append(r["uy_top_centre_mm"])
                d = rel_diff(r["uy_top_centre_mm"], ref_uy)
                row = dict(r, **reference, n=a.n, ranks=a.ranks, config=config, run=k,
                           speedup_cpu=round(ref_cpu / r["cpu_s"], 1) if ref_cpu else "",
                           uy_rel_diff=f"{d:.3e}" if d is not None else "")
                w.writerow(row)
                f.flush()
                print(config, k, r, flush=True)
            med = statistics.median(cpus)
            d = rel_diff(statistics.median(uys), ref_uy)
            w.writerow(dict(reference, n=a.n, ranks=a.ranks, config=config, run="median", cpu_s=med,
                            wall_s=statistics.median(walls),
                            speedup_cpu=round(ref_cpu / med, 1) if ref_cpu else "",
                            uy_rel_diff=f"{d:.3e}" if d is not None else ""))
            f.flush()
            summary.append((config, med, statistics.median(walls), statistics.median(uys), d))

    print(f"\nstep-44 block, n = {a.n} per side, Glossa on {a.ranks} rank(s), median of {a.repeats}; deal.II "
          + (f"run here (median of {a.dealii_repeats}, {dealii_iters})" if source == "run" else f"{source or 'no'} reference"))
    fmt = "{:<10} {:>12} {:>12} {:>13} {:>9} {:>15} {:>15} {:>11}"
    print(fmt.format("config", "Glossa CPU s", "deal.II CPU s", "deal.II wall s", "speed-up",
                     "Glossa u_y mm", "deal.II u_y mm", "u_y diff"))
    for config, med, _, uy, d in summary:
        print(fmt.format(config, f"{med:.1f}", f"{ref_cpu:.2f}" if ref_cpu else "-",
                         f"{ref_wall:.2f}" if ref_wall else "-", f"{ref_cpu / med:.1f}x" if ref_cpu else "-",
                         f"{uy:.6f}", f"{ref_uy:.6f}" if ref_uy is not None else "-",
                         (f"{100 * d:+.4f} %" + ("" if abs(d) <= ANSWER_TOLERANCE else " (!)")) if d is not None else "-"))
    if any(d is not None and abs(d) > ANSWER_TOLERANCE for *_, d in summary):
        print(f"(!) u_y differs from deal.II's by more than {100 * ANSWER_TOLERANCE:g} %")
    print(f"rows appended to {path}")


if __name__ == "__main__":
    main()
