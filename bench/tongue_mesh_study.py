#!/usr/bin/python3
"""s8_2 mesh dependence of the tongue (paper Tables III-IV analogue) and the fine-tongue bench
(doc/tongue.md, s8_2), run on demand:

  /usr/bin/python3 bench/tongue_mesh_study.py [--glossa build/glossa] [--refines 0,1,2]
      [--fine-ranks 2] [--fine-decks D1,D2] [--timeout 720] [--workdir DIR] [--reuse] [--wait-for PATTERN]

Runs inputs/paper/s8_2_gravity.xml (upright gravity) and s8_2_gravity_pressure.xml (gravity, then
the 500 Pa airway pressure) with Mesh/File/refine = 0, 1, 2 (740, 5920, 47360 hexahedra) on one
rank, and the finest also on --fine-ranks ranks, and writes bench/results/tongue_mesh_study.csv:
elements, dofs, ranks, |u| at P_A and P_P at the end time, the relative error of those |u|
against the finest one-rank mesh that finished, the wall time and its ratio to refine 0 (same
deck, one rank), Newton / Krylov / Uzawa iterations, the time split (assembly, preconditioner
set-up, Krylov), peak memory per rank and the largest dilatation error of any step.

A run that exceeds --timeout seconds is stopped and recorded with status "timeout"; the finest
mesh that finished on one rank is then the reference (the CSV's column `reference_refine` says
which). --reuse takes a run's summary.json from --workdir when it is there (to resume a study).
--wait-for PATTERN waits, before each run, until `pgrep -f PATTERN` finds nothing (a shared
machine). Standard library only.
"""
import argparse
import csv
import json
import math
import os
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECKS = ["s8_2_gravity", "s8_2_gravity_pressure"]


def wait_for_quiet(pattern):
    def others():  # pgrep -f also matches this script, whose command line holds the pattern
        out = subprocess.run(["pgrep", "-f", pattern], stdout=subprocess.PIPE, text=True).stdout.split()
        return [pid for pid in out if int(pid) != os.getpid()]
    while pattern and others():
        print(f"waiting for '{pattern}' to finish", flush=True)
        time.sleep(30)


def run(args, deck, refine, ranks):
    out = os.path.join(args.workdir, f"{deck}_r{refine}_np{ranks}")
    summary = os.path.join(out, "summary.json")
    wait_for_quiet(args.wait_for)
    if args.reuse and os.path.exists(summary):
        with open(summary) as f:
            s = json.load(f)
        if not s.get("running"):  # a finished run (a stopped one still says running)
            return ("ok" if s.get("converged") else "not converged"), s
    os.makedirs(out, exist_ok=True)
    cmd = [args.glossa, "run", os.path.join(ROOT, "inputs", "paper", deck + ".xml"),
           "--set", f"Mesh/File/refine={refine}", "--output", out, "--quiet"]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    print("running", " ".join(cmd), flush=True)
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, start_new_session=True)
    try:
        proc.wait(timeout=args.timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGTERM)  # the run's own process group only
        proc.wait()
        return "timeout", None
    if not os.path.exists(summary):
        return f"failed ({proc.returncode})", None
    with open(summary) as f:
        s = json.load(f)
    return ("ok" if s.get("converged") else "not converged"), s


def norm(v):
    return math.sqrt(sum(x * x for x in v))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--refines", default="0,1,2", type=lambda s: [int(x) for x in s.split(",")])
    p.add_argument("--fine-ranks", default=2, type=int, help="also run the finest mesh on this many ranks (0: no)")
    p.add_argument("--fine-decks", default=",".join(DECKS), type=lambda s: s.split(","),
                   help="the decks run on --fine-ranks ranks")
    p.add_argument("--timeout", default=720, type=float, help="seconds per run before it is stopped")
    p.add_argument("--workdir", default="/tmp/glossa-tongue-mesh-study")
    p.add_argument("--reuse", action="store_true")
    p.add_argument("--wait-for", default="")
    args = p.parse_args()
    finest = max(args.refines)
    cases = [(d, r, 1) for r in sorted(args.refines) for d in DECKS]
    if args.fine_ranks > 1:
        # gravity + pressure first: it is the fine-tongue bench
        cases += [(d, finest, args.fine_ranks) for d in reversed(DECKS) if d in args.fine_decks]
    results = {}
    for deck, refine, ranks in cases:
        if ranks > 1 and results.get((deck, refine, 1), ("",))[0] == "timeout":
            results[(deck, refine, ranks)] = ("skipped (1 rank timed out)", None)
            continue
        results[(deck, refine, ranks)] = run(args, deck, refine, ranks)
        status, s = results[(deck, refine, ranks)]
        print(deck, refine, ranks, status, s and round(s["wall_seconds"], 1), flush=True)

    rows = []
    for deck in DECKS:
        done = [r for r in sorted(args.refines) if results[(deck, r, 1)][0] == "ok"]
        ref = results[(deck, done[-1], 1)][1] if done else None
        base = results.get((deck, min(args.refines), 1), (None, None))[1]
        for (d, refine, ranks), (status, s) in results.items():
            if d != deck:
                continue
            row = {"deck": deck, "refine": refine, "ranks": ranks, "status": status,
                   "reference_refine": done[-1] if done else ""}
            if s is not None:
                steps = s["steps"]
                ua, up = norm(s["final_displacement"]["P_A"]), norm(s["final_displacement"]["P_P"])
                ra = norm(ref["final_displacement"]["P_A"]) if ref else float("nan")
                rp = norm(ref["final_displacement"]["P_P"]) if ref else float("nan")
                mem = s["peak_memory_mb_per_rank"]
                row.update({
                    "elements": s["elements"], "dofs": s["dofs"],
                    "u_PA_mm": round(1e3 * ua, 5), "u_PP_mm": round(1e3 * up, 5),
                    "rel_err_PA": f"{abs(ua - ra) / ra:.3e}", "rel_err_PP": f"{abs(up - rp) / rp:.3e}",
                    "wall_s": round(s["wall_seconds"], 2),
                    "wall_ratio": round(s["wall_seconds"] / base["wall_seconds"], 2) if base else "",
                    "steps": len(steps),
                    "newton": sum(x["newton_iterations"] for x in steps),
                    "krylov": sum(x["linear_iterations"] for x in steps),
                    "uzawa": sum(x["uzawa_iterations"] for x in steps),
                    "assembly_s": round(s["assembly_seconds"], 2),
                    "prec_setup_s": round(s["preconditioner_setup_seconds"], 2),
                    "krylov_s": round(s["linear_solve_seconds"], 2),
                    "peak_mem_mb_per_rank": round(max(mem) if isinstance(mem, list) else mem, 1),
                    "max_dilatation_error": f"{max(x['max_dilatation_error'] for x in steps):.2e}",
                })
            rows.append(row)
    fields = ["deck", "refine", "elements", "dofs", "ranks", "status", "u_PA_mm", "u_PP_mm",
              "reference_refine", "rel_err_PA", "rel_err_PP", "wall_s", "wall_ratio", "steps", "newton",
              "krylov", "uzawa", "assembly_s", "prec_setup_s", "krylov_s", "peak_mem_mb_per_rank",
              "max_dilatation_error"]
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    path = os.path.join(ROOT, "bench", "results", "tongue_mesh_study.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    print("wrote", path)


if __name__ == "__main__":
    sys.exit(main())
