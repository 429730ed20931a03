#!/usr/bin/python3
"""GA against gradient controller on the §7.2 block (doc/control.md), run on demand:

  /usr/bin/python3 bench/control.py [--end-time 1.25] [--ranks 1,2] [--glossa build/glossa]

Runs inputs/paper/s7_2_passive.xml once, then s7_2_ga.xml and s7_2_gradient.xml on each rank
count (the GA on N ranks with --control-groups N, one rank per group; the gradient controller's
solves are sequential, so on N ranks every solve is distributed) and writes
bench/results/control.csv: control steps, displacement solves (candidates) in all and per step,
sensitivity evaluations, wall time per control step (median over steps and mean), the eq. 25
objective (mean and largest over steps), and P's largest displacement as a fraction of the
passive run's peak over the same time. With --plot, bench/results/control_inputs.png: the inputs
each controller chose per group against time, over the load (a figure like the paper's Fig. 6).
"""
import argparse
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(glossa, deck, ranks, end_time, extra=()):
    out = tempfile.mkdtemp(prefix="glossa-control-")
    cmd = [glossa, "run", os.path.join(ROOT, "inputs", "paper", deck), "--output", out, "--quiet",
           "--set", "Time/end time=%g" % end_time, "--set", "Output/fields=false"] + list(extra)
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), out


def peak_of_p(out):
    peak = 0.0
    with open(os.path.join(out, "traces.csv")) as f:
        for row in csv.DictReader(f):
            row = {k.split(" [")[0]: v for k, v in row.items()}  # "ux [m]" -> "ux"
            if row["point"] == "P":
                peak = max(peak, math.sqrt(sum(float(row[c]) ** 2 for c in ("ux", "uy", "uz"))))
    return peak


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"), help="the solver (default: build/glossa)")
    p.add_argument("--end-time", default=1.25, type=float, help="seconds of the scene (one breath: 1.25)")
    p.add_argument("--ranks", default="1,2", type=lambda s: [int(x) for x in s.split(",")],
                   help="comma-separated rank counts to run each controller on (default: 1,2)")
    p.add_argument("--csv", default=os.path.join(ROOT, "bench", "results", "control.csv"),
                   help="where the table goes (default: bench/results/control.csv)")
    p.add_argument("--plot", action="store_true",
                   help="also draw bench/results/control_inputs.png from the first rank count's runs")
    args = p.parse_args()
    passive, passive_out = run(args.glossa, "s7_2_passive.xml", 1, args.end_time)
    passive_peak = peak_of_p(passive_out)
    rows, chosen = [], {}
    for controller, deck in (("genetic algorithm", "s7_2_ga.xml"), ("gradient", "s7_2_gradient.xml")):
        for ranks in args.ranks:
            extra = ["--control-groups", str(ranks)] if controller == "genetic algorithm" and ranks > 1 else []
            s, out = run(args.glossa, deck, ranks, args.end_time, extra)
            steps = s["steps"]
            control = [x["control"] for x in steps]
            seconds = [x["seconds"] for x in steps]
            row = {
                "controller": controller, "ranks": ranks, "control_groups": s.get("control_groups", 1),
                "end_time": args.end_time, "steps": len(steps),
                "solves": sum(c["candidates"] for c in control),
                "solves_per_step": round(statistics.mean(c["candidates"] for c in control), 2),
                "max_solves_per_step": max(c["candidates"] for c in control),
                "sensitivity_evaluations": sum(c.get("sensitivity_evaluations", 0) for c in control),
                "sensitivity_krylov": sum(c.get("sensitivity_krylov", 0) for c in control),
                "median_s_per_step": round(statistics.median(seconds), 3),
                "mean_s_per_step": round(statistics.mean(seconds), 3), "wall_s": round(s["wall_seconds"], 1),
                "mean_objective_um": round(1e6 * statistics.mean(c["objective"] for c in control), 3),
                "max_objective_um": round(1e6 * max(c["objective"] for c in control), 3),
                "p_peak_um": round(1e6 * peak_of_p(out), 3), "passive_p_peak_um": round(1e6 * passive_peak, 3),
                "p_peak_fraction_of_passive": round(peak_of_p(out) / passive_peak, 4),
            }
            print(row, flush=True)
            rows.append(row)
            if ranks == args.ranks[0]:
                chosen[controller] = steps
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    path = args.csv
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote", path)
    if args.plot:
        plot(chosen, os.path.join(ROOT, "bench", "results", "control_inputs.png"))


def plot(chosen, path):
    sys.path.insert(0, os.path.join(ROOT, "doc"))
    import plot_style
    plt = plot_style.plt
    fig, axes = plt.subplots(len(chosen) + 1, 1, figsize=(8, 2.2 * (len(chosen) + 1)), sharex=True)
    for ax, (controller, steps) in zip(axes, chosen.items()):
        t = [x["time"] for x in steps]
        for g in steps[0]["control"]["inputs"]:
            ax.step(t, [x["control"]["inputs"][g] for x in steps], where="post", label=g)
        ax.set_ylabel("neural input u")
        ax.set_ylim(-0.05, 1.05)
        ax.set_title(controller)
        plot_style.legend_right(ax, title="muscle group")
    ax = axes[-1]
    for controller, steps in chosen.items():
        ax.plot([x["time"] for x in steps], [1e6 * x["control"]["objective"] for x in steps], label=controller)
    ax.set_yscale("log")
    ax.set_ylabel("objective eq. 25 [um]")
    ax.set_xlabel("time [s]")
    plot_style.legend_right(ax, title="controller")
    fig.suptitle(f"Paper §7.2 block: the inputs each controller chose (end time {chosen_end(chosen):g} s)", fontsize=10)
    plot_style.save(fig, path)


def chosen_end(chosen):
    return max(x["time"] for steps in chosen.values() for x in steps)


if __name__ == "__main__":
    main()
