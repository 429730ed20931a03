#!/usr/bin/python3
"""The styloglossus twitch, dynamic against quasi-static (inputs/paper/tongue_twitch_dynamic.xml and
tongue_twitch_static.xml, 0.6 s; the first 40 ms of the dynamic one are the CI regression test
regression.tongue_twitch_onset): runs the quasi-static deck, the dynamic one (Rayleigh mass damping
15 /s) and the dynamic one undamped, and compares the tip's trajectories (doc/dynamics.md, "The
tongue twitch").

    /usr/bin/python3 bench/tongue_twitch.py [--glossa build/glossa] [--runs DIR]
        [--table bench/results/tongue_twitch.csv] [--figure doc/figures/tongue_twitch.png]
        [--set path=value ...]   (applied to every run, e.g. Time/step size=0.001)

Definitions (u_d, u_s the tip P_A's displacement from the dynamic and the quasi-static run,
u_f = u_s at the end time, the quasi-static final displacement):
  overshoot        max_t (u_d . e - |u_f|) / |u_f|, e = u_f / |u_f|: how far past the final
                   position the tip goes along the direction of its motion;
  settling time    the first time after which |u_d(t) - u_f| <= 2 % |u_f| for good;
  period           twice the mean time between the sign changes of (u_d - u_s) . e once the
                   activation has risen (t > 40 ms): the tongue's oscillation about its moving
                   equilibrium (of the undamped run).
Writes a table per time (the runs' tip displacements, the damped run's difference from the
quasi-static one, its kinetic and strain energy) and prints the figures of both dynamic runs, the
Newton counts, the largest dilatation error of any step and the run times.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECKS = {a: os.path.join(ROOT, "inputs", "paper", f"tongue_twitch_{a}.xml") for a in ("dynamic", "static")}
# run name: (deck, its own settings)
RUNS = {"static": ("static", []), "dynamic": ("dynamic", []),
        "undamped": ("dynamic", ["Time/Rayleigh mass coefficient=0"])}
POINT = "P_A"
SETTLING_BAND = 0.02
RISEN = 0.04  # [s]: 6 rise times; the activation is within 0.3 % of full beyond it


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def tip(out):
    """{time: (ux, uy, uz)} of the tip."""
    return {float(r["time [s]"]): tuple(float(r[k]) for k in ("ux [m]", "uy [m]", "uz [m]"))
            for r in rows(os.path.join(out, "traces.csv")) if r["point"] == POINT}


def norm(v):
    return math.sqrt(sum(x * x for x in v))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def measures(dynamic, static):
    """Overshoot, settling time, period and the largest |u_d - u_s| (see the module's text)."""
    times = sorted(dynamic)
    final = static[max(static)]
    e = tuple(x / norm(final) for x in final)
    overshoot = max((dot(dynamic[t], e) - norm(final)) / norm(final) for t in times)
    settling = 0.0
    for t in times:
        if norm(sub(dynamic[t], final)) > SETTLING_BAND * norm(final):
            settling = None
        elif settling is None:
            settling = t
    crossings = []
    for t0, t1 in zip(times, times[1:]):
        if t0 < RISEN:
            continue
        d0, d1 = dot(sub(dynamic[t0], static[t0]), e), dot(sub(dynamic[t1], static[t1]), e)
        if d0 * d1 < 0:
            crossings.append(t0 + (t1 - t0) * d0 / (d0 - d1))
    period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1) if len(crossings) > 1 else None
    difference = max(norm(sub(dynamic[t], static[t])) for t in times)
    return overshoot, settling, period, difference


def figure(path, dynamic, static, undamped, energy):
    sys.path.insert(0, os.path.join(ROOT, "doc"))
    import plot_style
    plt = plot_style.plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    times = sorted(dynamic)
    for c, name in ((0, "ux (posterior)"), (2, "uz (superior)")):
        ax.plot(times, [1e3 * dynamic[t][c] for t in times], label=f"{name}, dynamic (damped)", **plot_style.line_style(c))
        ax.plot(times, [1e3 * undamped[t][c] for t in times], label=f"{name}, dynamic undamped",
                color=plot_style.COLOURS[c], linestyle=":", linewidth=0.8)
        ax.plot(times, [1e3 * static[t][c] for t in times], label=f"{name}, quasi-static",
                color=plot_style.COLOURS[c], linestyle="--")
    ax.set_ylabel(f"tip {POINT} displacement [mm]")
    plot_style.legend_right(ax)
    bx.plot(times, [1e6 * energy[t][0] for t in times], label="kinetic")
    bx.plot(times, [1e6 * energy[t][1] for t in times], label="strain (passive)")
    bx.set_xlabel("time [s]")
    bx.set_ylabel("damped run's energy [µJ]")
    plot_style.legend_right(bx)
    fig.suptitle("Styloglossus twitch (FFMR 25 %, activation 95 % in 20 ms): dynamic against quasi-static")
    plot_style.save(fig, path)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--runs", default=os.path.join(ROOT, "build", "bench", "tongue_twitch"))
    p.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "tongue_twitch.csv"))
    p.add_argument("--figure", default=os.path.join(ROOT, "doc", "figures", "tongue_twitch.png"))
    p.add_argument("--set", action="append", default=[], help="path=value, applied to both runs")
    args = p.parse_args(argv)
    summaries, walls, outs = {}, {}, {}
    for run, (analysis, sets) in RUNS.items():
        outs[run] = os.path.join(args.runs, run)
        command = [args.glossa, "run", DECKS[analysis], "--output", outs[run], "--quiet"]
        for s in sets + args.set:
            command += ["--set", s]
        start = time.time()
        subprocess.run(command, check=True)
        walls[run] = time.time() - start
        summaries[run] = json.load(open(os.path.join(outs[run], "summary.json")))
    dynamic, static, undamped = tip(outs["dynamic"]), tip(outs["static"]), tip(outs["undamped"])
    energy = {float(r["time [s]"]): (float(r["kinetic_energy [J]"]), float(r["strain_energy [J]"]))
              for r in rows(os.path.join(outs["dynamic"], "energy.csv"))}
    os.makedirs(os.path.dirname(args.table), exist_ok=True)
    with open(args.table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time [s]"] + [f"{a}_{c} [mm]" for a in ("dynamic", "undamped", "static") for c in ("ux", "uy", "uz")] +
                   ["difference [mm]", "kinetic_energy [uJ]", "strain_energy [uJ]"])
        for t in sorted(dynamic):
            w.writerow([f"{t:.6g}"] + [f"{1e3 * x:.6g}" for x in dynamic[t] + undamped[t] + static[t]] +
                       [f"{1e3 * norm(sub(dynamic[t], static[t])):.6g}", f"{1e6 * energy[t][0]:.6g}",
                        f"{1e6 * energy[t][1]:.6g}"])
    final = static[max(static)]
    print(f"tip {POINT}: quasi-static final displacement {1e3 * norm(final):.4g} mm "
          f"({', '.join(f'{1e3 * x:.4g}' for x in final)} mm)")
    for run, trajectory in (("damped", dynamic), ("undamped", undamped)):
        overshoot, settling, period, difference = measures(trajectory, static)
        print(f"{run}: overshoot {100 * overshoot:.3g} %, settling time (2 %) "
              f"{'not settled' if settling is None else f'{1e3 * settling:.4g} ms'}, "
              f"period {'-' if period is None else f'{1e3 * period:.4g} ms'}, "
              f"largest |u_dynamic - u_static| {1e3 * difference:.4g} mm, final "
              f"{1e3 * norm(trajectory[max(trajectory)]):.4g} mm")
    print(f"damped: largest kinetic energy {1e6 * max(k for k, _ in energy.values()):.4g} uJ, final strain energy "
          f"{1e6 * energy[max(energy)][1]:.4g} uJ, final kinetic {1e6 * energy[max(energy)][0]:.3g} uJ")
    for run, s in summaries.items():
        steps = s["steps"]
        print(f"{run}: {len(steps)} steps, Newton {sum(x['newton_iterations'] for x in steps)} "
              f"(largest {max(x['newton_iterations'] for x in steps)} a step), Uzawa "
              f"{sum(x['uzawa_iterations'] for x in steps)}, largest dilatation error "
              f"{max(x['max_dilatation_error'] for x in steps):.2g}, {walls[run]:.0f} s, "
              f"converged {s['converged']}")
    if args.figure:
        figure(args.figure, dynamic, static, undamped, energy)
    return 0 if all(s["converged"] for s in summaries.values()) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
