#!/usr/bin/python3
"""Where a Newton iteration goes, beside each part's physical floor:

  /usr/bin/python3 bench/newton_profile.py [--scene s7_1_a] [--repeats 3] [--label NAME] [--set path=value]
                                           [--no-perf] [--glossa build/glossa] [--append]

Runs a scene `--repeats` times on one rank (CPU time from the child's rusage: user + system) and
once more under `perf record` (when perf is installed), and writes bench/results/newton_profile.csv,
one row per part of the median run:

- from the run's own timers (summary.json, wall time): the assembly (point laws, element kernels, loads and
  the scatter into the matrix), the direct solver's analysis, numeric factorisations and solves,
  the rest of the Krylov solves, the three-field bases, the Uzawa updates, the muscle history and
  the step output; what is left of the process (start-up, mesh, NOX) is `other`;
- from perf's samples (self time by symbol, as shares of the CPU time): the assembly split into point laws (materials::,
  libm), element kernels (fem::, Eigen) and the rest of glossa's assembly (scatter, loads,
  Tpetra), and the factorisation's dense kernels (MUMPS, BLAS).

Each part is given in ms per Newton iteration (with a controller: per candidate solve, as the
summary counts the Newton iterations of the winning candidates only), with its calls, and its
floor: the
assembly's a single pass per Newton iteration at the element work `bench_assembly_cost` measures
on the scene's mesh (or its stored row), the point laws' every point once at `bench_material_cost`'s
active muscle (the §7.1 blocks), the factorisation's a
single numeric factorisation per Newton iteration at the run's mean cost, the solve's a
single forward and backward substitution. Scenes: s7_1_a (the §7.1 (a) block), tongue_passive
(the coarse tongue, s8_5 passive supine, its first 8 steps), tongue_ga (its GA deck, the first
control step).
Standard library only (perf is optional).
"""
import argparse
import csv
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

from glossa_command import cpu_seconds_of, glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results", "newton_profile.csv")

SCENES = {
    "s7_1_a": ("inputs/paper/s7_1_a_internal.xml", []),
    "tongue_passive": ("inputs/paper/s8_5_passive_supine.xml", ["Time/end time=2.5"]),
    "tongue_ga": ("inputs/paper/s8_5_ga_supine.xml", ["Time/end time=0.3125"]),
}

# perf's self-time samples by shared object and symbol, into the parts of the assembly and the
# factorisation (the first pattern that matches wins).
PERF_CLASSES = [
    ("point_laws", r"^glossa .*glossa::(materials|model::TissuePointLaw)|^libm[.-]"),
    ("element_kernels", r"^glossa .*(glossa::fem::|Eigen::)"),
    ("assembly_other", r"^glossa .*glossa::(assembly|loads|contact)::|^libtrilinos_(tpetra|kokkos)"),
    ("factorisation_kernels", r"^lib(dmumps|mumps_common|openblas|blas|lapack|gfortran|scotch|metis|esmumps)"),
    ("mpi", r"^lib(mpi|open-pal|open-rte|pmix|ucx|uc[pts])"),
    ("allocation_and_copies", r"^libc[.-]"),
    ("kernel", r"^\[kernel"),
]


def run_once(glossa, deck, overrides, perf_data=None):
    out = tempfile.mkdtemp(prefix="glossa-profile-")
    cmd = glossa_run_command(glossa, deck, out, overrides)
    if perf_data:
        cmd = ["perf", "record", "-q", "-F", "999", "-o", perf_data, "--"] + cmd
    cpu = cpu_seconds_of(cmd, ROOT, "newton_profile")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    shutil.rmtree(out, ignore_errors=True)
    summary["cpu_seconds"] = cpu
    return summary


def perf_shares(perf_data):
    """Share of the samples of each PERF_CLASSES part (and 'rest')."""
    text = subprocess.run(["perf", "report", "-i", perf_data, "--no-children", "--sort", "dso,sym", "-g", "none",
                           "--stdio"], capture_output=True, text=True).stdout
    shares = {name: 0.0 for name, _ in PERF_CLASSES}
    shares["rest"] = 0.0
    for line in text.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+(\S+)\s+\[[.k]\]\s+(.*)", line)
        if not m:
            continue
        key = f"{m.group(2)} {m.group(3)}"
        for name, pattern in PERF_CLASSES:
            if re.search(pattern, key):
                shares[name] += float(m.group(1)) / 100
                break
        else:
            shares["rest"] += float(m.group(1)) / 100
    return shares


def assembly_floor_ms(deck):
    """The element work of one assembly of the deck's mesh: bench_assembly_cost when it is built,
    else its latest stored row in bench/results/assembly_cost.csv; None without either."""
    exe = os.path.join(ROOT, "build", "bench_assembly_cost")
    out = tempfile.mkdtemp(prefix="glossa-assembly-")
    csv_path = os.path.join(out, "assembly.csv")
    if os.path.exists(exe):
        subprocess.run([exe, "--repeats", "5", "--out", csv_path, os.path.join(ROOT, deck)], capture_output=True,
                       cwd=ROOT)
    if not os.path.exists(csv_path):
        csv_path = os.path.join(ROOT, "bench", "results", "assembly_cost.csv")
    floor = None
    if os.path.exists(csv_path):
        with open(csv_path) as f:
            rows = [r for r in csv.DictReader(f) if r["deck"] == deck and not r["contacts"]]
        if rows:
            floor = float(rows[-1]["element_work_ms"])
    shutil.rmtree(out, ignore_errors=True)
    return floor


def point_law_floor_ms(summary, deck):
    """One pass of every Gauss point at bench_material_cost's median cost of the active three-family
    muscle (bench/results/material_cost.json), for the muscle decks; None otherwise."""
    path = os.path.join(ROOT, "bench", "results", "material_cost.json")
    if "s7_1" not in deck or not os.path.exists(path):
        return None
    with open(path) as f:
        marks = {b["name"]: b for b in json.load(f)["benchmarks"]}
    mark = marks.get("ActiveMuscleThreeFamilies_median")
    return None if mark is None else 8 * summary["elements"] * mark["real_time"] * 1e-6


def newton_iterations(summary):
    return sum(s["newton_iterations"] for s in summary["steps"])


def units(summary):
    """What the figures are per: a Newton iteration, or with a controller a candidate solve (the
    summary counts the Newton iterations of the winners only)."""
    candidates = sum(s["control"]["candidates"] for s in summary["steps"] if "control" in s)
    return (candidates, "candidate solve") if candidates else (newton_iterations(summary), "Newton iteration")


def profile_rows(summary, shares, label, scene, deck):
    """The run's own timers are wall time (ms per Newton iteration); perf's shares are of the CPU
    time. On a quiet machine the two agree; on a shared one the wall time is the larger."""
    n, unit = units(summary)
    n = max(n, 1)
    split = summary.get("time_split", {})

    def part(key):
        p = split.get(key, {"seconds": 0.0, "calls": 0})
        return p["seconds"], p["calls"]

    cpu, wall = summary["cpu_seconds"], summary["wall_seconds"]
    assembly = summary["assembly_seconds"]
    analysis, analyses = part("direct_analysis")
    factor, factorisations = part("direct_factorisation")
    solve, solves = part("direct_solve")
    rows = []

    def row(name, clock, seconds, calls, floor, note=""):
        rows.append({"label": label, "scene": scene, "dofs": summary["dofs"], "unit": unit, "units": n,
                     "newton": newton_iterations(summary), "cpu_s": round(cpu, 3), "wall_s": round(wall, 3),
                     "cpu_ms_per_unit": round(1e3 * cpu / n, 2), "part": name, "clock": clock,
                     "ms_per_unit": round(1e3 * seconds / n, 3),
                     "calls_per_unit": "" if calls is None else round(calls / n, 3),
                     "floor_ms_per_unit": "" if floor is None else round(floor, 3), "note": note})

    row("assembly", "wall", assembly, summary["residual_evaluations"], assembly_floor_ms(deck),
        "floor: one pass per Newton iteration at the element work of bench_assembly_cost")
    if shares:
        row("  point laws", "cpu", shares["point_laws"] * cpu, None, point_law_floor_ms(summary, deck),
            "perf: materials:: and libm; floor: every point once per Newton iteration at bench_material_cost")
        row("  element kernels", "cpu", shares["element_kernels"] * cpu, None, None, "perf: fem:: and Eigen")
        row("  scatter, loads, Tpetra", "cpu", shares["assembly_other"] * cpu, None, None, "perf")
    row("direct analysis", "wall", analysis, analyses, 0.0, "once per sparsity pattern")
    row("direct factorisation", "wall", factor, factorisations,
        None if not factorisations else 1e3 * factor / factorisations,
        "floor: one numeric factorisation per Newton iteration at this run's mean")
    if shares:
        row("  dense kernels", "cpu", shares["factorisation_kernels"] * cpu, None, None, "perf: MUMPS and BLAS")
    row("direct solve", "wall", solve, solves, None if not solves else 1e3 * solve / solves,
        "floor: one forward and backward substitution per Newton iteration")
    row("preconditioner set-up, other", "wall", summary["preconditioner_setup_seconds"] - factor - analysis, None,
        0.0, "Stratimikos and Thyra around the factorisation")
    row("Krylov, other", "wall", summary["linear_solve_seconds"] - solve, None, 0.0,
        "Belos around the direct solve (matrix products, vectors)")
    timed = assembly + summary["preconditioner_setup_seconds"] + summary["linear_solve_seconds"]
    for key in ("three_field_bases", "uzawa_update", "muscle_history", "step_output"):
        seconds, calls = part(key)
        timed += seconds
        row(key.replace("_", " "), "wall", seconds, calls, None)
    row("other (start-up, mesh, NOX)", "wall", wall - timed, None, None, "wall time outside the timers")
    if shares:
        for key in ("mpi", "allocation_and_copies", "kernel", "rest"):
            row(f"  {key.replace('_', ' ')}", "cpu", shares[key] * cpu, None, None, "perf")
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--scene", default="s7_1_a", choices=sorted(SCENES))
    p.add_argument("--repeats", default=3, type=int)
    p.add_argument("--label", default="main", help="names the build or change in the CSV")
    p.add_argument("--set", action="append", default=[], help="a deck override, as glossa's --set")
    p.add_argument("--no-perf", action="store_true", help="skip the perf run (no split of the assembly)")
    p.add_argument("--append", action="store_true", help="add rows to the CSV instead of replacing it")
    args = p.parse_args()
    deck, overrides = SCENES[args.scene]
    overrides = overrides + args.set
    runs = [run_once(args.glossa, deck, overrides) for _ in range(args.repeats)]
    runs.sort(key=lambda s: s["cpu_seconds"])
    median = runs[len(runs) // 2]
    shares = None
    if not args.no_perf and shutil.which("perf"):
        data = tempfile.mktemp(prefix="glossa-perf-")
        run_once(args.glossa, deck, overrides, perf_data=data)
        shares = perf_shares(data)
        os.remove(data)
    rows = profile_rows(median, shares, args.label, args.scene, deck)
    cpus = [r["cpu_seconds"] for r in runs]
    n, unit = units(median)
    print(f"{args.scene} [{args.label}]: {n} {unit}s, {newton_iterations(median)} Newton iterations committed, "
          f"CPU {statistics.median(cpus):.2f} s (min {min(cpus):.2f}, max {max(cpus):.2f}), "
          f"{1e3 * statistics.median(cpus) / max(n, 1):.1f} ms per {unit}")
    for r in rows:
        print(f"  {r['part']:30s} {r['clock']:4s} {r['ms_per_unit']:9.3f} ms  calls per {unit} "
              f"{r['calls_per_unit']!s:7s} floor {r['floor_ms_per_unit']!s}")
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    exists = os.path.exists(RESULTS)
    with open(RESULTS, "a" if args.append and exists else "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        if not (args.append and exists):
            w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
