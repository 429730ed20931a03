#!/usr/bin/python3
"""What a controller's candidate solve costs on the tongue, one change at a time (doc/tongue.md,
s8_5), run on demand:

  /usr/bin/python3 bench/tongue_candidate_solves.py [--glossa build/glossa] [--repeats 3]
                                                    [--end-time 0.9375] [--medium]

Every configuration runs the first control steps of inputs/paper/s8_5_ga_upright.xml (the GA:
every candidate is a full step solve from the committed state, no sensitivity solves) and
reads from summary.json the displacement solves (candidates), the wall time and its split into
assembly, preconditioner set-up and Krylov iterations; per candidate solve they are divided by
the number of candidates. The configurations: MueLu (reuse RP within a Newton solve), MueLu's
hierarchy kept for the whole run (reuse scope run, so one preconditioner set-up serves many
candidates), a sparse direct solve with Amesos2 KLU2 and with MUMPS (the default, Linear
solver/type = auto, on one rank below 'direct up to' unknowns), every candidate started from the
linear extrapolation of the last two committed states (Time/predictor), and the candidates
shared out over 2 control groups on 2 ranks (there the time per solve is the throughput, the split
that of one group's solves). --medium adds
the medium tongue (refined once, 20,097 dofs, on the imaged geometry since the zero-strain
coordinates are the coarse mesh's) for MueLu and the direct solves, as step solves of the passive supine deck
(its first step; the coarse tongue the same way, for the ratio). Medians over
--repeats runs; writes bench/results/tongue_candidate_solves.csv.
"""
import argparse
import csv
import json
import math
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "inputs", "paper", "s8_5_ga_upright.xml")
MEDIUM = ["Mesh/File/refine=1", "Mesh/reference coordinates file="]
CONFIGURATIONS = [
    ("coarse", "MueLu", ["Linear solver/type=iterative"], 1),
    ("coarse", "MueLu, reuse scope run", ["Linear solver/type=iterative", "Linear solver/MueLu reuse scope=run"], 1),
    ("coarse", "direct (KLU2)", ["Linear solver/type=direct", "Linear solver/direct solver=KLU2"], 1),
    ("coarse", "direct (MUMPS, the default auto)", [], 1),
    ("coarse", "MueLu, predictor linear extrapolation", ["Linear solver/type=iterative", "Time/predictor=linear extrapolation"], 1),
    ("coarse", "MueLu, 2 control groups on 2 ranks", [], 2),
]
PASSIVE = os.path.join(ROOT, "inputs", "paper", "s8_5_passive_supine.xml")
# (mesh, configuration, --set options, ranks, deck): a step solve of the passive deck is what one
# candidate costs (the same solve without the controller), cheap enough on the medium mesh.
MEDIUM_CONFIGURATIONS = [
    ("coarse, passive step", "MueLu", ["Linear solver/type=iterative"], 1, PASSIVE),
    ("coarse, passive step", "direct (KLU2)", ["Linear solver/type=direct", "Linear solver/direct solver=KLU2"], 1, PASSIVE),
    ("coarse, passive step", "direct (MUMPS, the default auto)", [], 1, PASSIVE),
    ("medium, passive step", "MueLu", MEDIUM + ["Linear solver/type=iterative"], 1, PASSIVE),
    ("medium, passive step", "direct (KLU2)", MEDIUM + ["Linear solver/type=direct", "Linear solver/direct solver=KLU2"], 1, PASSIVE),
    ("medium, passive step", "direct (MUMPS, the default auto)", MEDIUM, 1, PASSIVE),
]


def run(glossa, sets, ranks, end_time, deck=DECK):
    out = tempfile.mkdtemp(prefix="glossa-candidates-")
    cmd = [glossa, "run", deck, "--output", out, "--quiet", "--set", "Output/fields=false",
           "--set", f"Time/end time={end_time}"]
    for s in sets:
        cmd += ["--set", s]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd + \
              ["--control-groups", str(ranks)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    # A controlled step's candidates, or one solve per step without a controller.
    solves = sum(step["control"]["candidates"] if "control" in step else 1 for step in s["steps"])
    return {"solves": solves, "wall": s["wall_seconds"], "assembly": s["assembly_seconds"],
            "setup": s["preconditioner_setup_seconds"], "krylov": s["linear_solve_seconds"],
            "objective": [step["control"]["objective"] if "control" in step else math.nan for step in s["steps"]]}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--repeats", default=3, type=int)
    p.add_argument("--end-time", default=0.9375, type=float, help="three control steps of 0.3125 s")
    p.add_argument("--medium", action="store_true")
    p.add_argument("--output", default=os.path.join(ROOT, "bench", "results", "tongue_candidate_solves.csv"))
    args = p.parse_args()
    rows = []
    configurations = [c + (DECK,) for c in CONFIGURATIONS] + (MEDIUM_CONFIGURATIONS if args.medium else [])
    for mesh, name, sets, ranks, deck in configurations:
        end_time = args.end_time if deck == DECK else 0.3125  # one passive step
        runs = [run(args.glossa, sets, ranks, end_time, deck) for _ in range(args.repeats)]
        # Wall time per solve is the throughput; the split is rank 0's own, over the solves its
        # control group made (about solves / ranks).
        per = lambda key: statistics.median(r[key] / r["solves"] for r in runs) * (1 if key == "wall" else ranks)
        row = {"mesh": mesh, "configuration": name, "ranks": ranks, "repeats": args.repeats,
               "solves": runs[0]["solves"], "wall_s_median": round(statistics.median(r["wall"] for r in runs), 2),
               "ms_per_solve": round(1e3 * per("wall"), 1), "assembly_ms_per_solve": round(1e3 * per("assembly"), 1),
               "setup_ms_per_solve": round(1e3 * per("setup"), 1), "krylov_ms_per_solve": round(1e3 * per("krylov"), 1),
               "last_objective_mm": round(1e3 * runs[0]["objective"][-1], 4)}
        print(row, flush=True)
        rows.append(row)
    base = {r["mesh"]: r["ms_per_solve"] for r in rows if r["configuration"] == "MueLu"}
    for r in rows:
        r["speed_up_vs_default"] = round(base[r["mesh"]] / r["ms_per_solve"], 2)
    with open(args.output, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
