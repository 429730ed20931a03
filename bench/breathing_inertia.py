#!/usr/bin/python3
"""s8_5's passive breathing with inertia against without: the quasi-static assumption's error at P_A
and P_P (doc/dynamics.md, "Breathing with inertia"). Runs inputs/paper/s8_5_passive_supine_dynamic.xml
(three 350 Pa breaths, supine, generalized-alpha) and the quasi-static s8_5_passive_supine.xml at the
same dilatation tolerance, and compares the two points' displacements at the quasi-static run's
steps once the breathing has begun (t >= 1.25 s; before it the decks bring gravity on differently).

    /usr/bin/python3 bench/breathing_inertia.py [--glossa build/glossa] [--runs DIR]
        [--table bench/results/breathing_inertia.csv] [--set path=value ...] (dynamic run only,
        e.g. "Time/step size=0.009765625" for half as many steps, "Time/end time=3.75" for the
        first breath alone: the passive response repeats breath after breath)

Prints, per point, the largest |u_dynamic - u_static| over the breaths, the largest breathing
displacement |u_static(t) - u_static(1.25 s)| it compares with, their ratio (the quasi-static
assumption's error), the dynamic run's largest kinetic energy, the steps, Newton iterations and
run times.

    /usr/bin/python3 bench/breathing_inertia.py --estimate [TRACES.csv] [--period 0.16]

runs nothing: the single-mode estimate of the same error from a quasi-static trace (default
tests/regression/s8_5_passive_supine.csv): one undamped mode of the given period driven through
the breaths' quasi-static history, u_d'' = -w^2 (u_d - u_s), u_s proportional to eq. 27.
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
DECKS = {"dynamic": os.path.join(ROOT, "inputs", "paper", "s8_5_passive_supine_dynamic.xml"),
         "static": os.path.join(ROOT, "inputs", "paper", "s8_5_passive_supine.xml")}
POINTS = ("P_A", "P_P")
BREATHS_START = 1.25  # [s]
TOLERANCE = "Incompressibility/dilatation tolerance=1e-6"


def traces(out):
    """{(point, time): (ux, uy, uz)} with times rounded to the microsecond (both runs' steps are
    binary fractions of 0.3125 s, so equal times print alike)."""
    with open(os.path.join(out, "traces.csv")) as f:
        return {(r["point"], round(float(r["time [s]"]), 6)): tuple(float(r[k]) for k in ("ux [m]", "uy [m]", "uz [m]"))
                for r in csv.DictReader(f) if r["point"] in POINTS}


def distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def breath(t):
    """Eq. 27's profile, max(sin(2 pi (t - t0)/T), 0)^1.75, T = 2.5 s, t0 = 1.25 s."""
    return max(math.sin(2 * math.pi * (t - BREATHS_START) / 2.5), 0.0) ** 1.75 if t >= BREATHS_START else 0.0


def single_mode_lag(period, breaths=3, dt=1e-4):
    """The largest |u_d - u_s| / swing of one undamped mode driven through u_s = breath(t) from rest
    (velocity Verlet at a step of period/1600: exact to far below the figures printed)."""
    w2 = (2 * math.pi / period) ** 2
    t, u, v, worst = BREATHS_START, 0.0, 0.0, 0.0
    while t < BREATHS_START + 2.5 * breaths:
        a = -w2 * (u - breath(t))
        u += v * dt + 0.5 * a * dt * dt
        t += dt
        v += 0.5 * (a - w2 * (u - breath(t))) * dt
        worst = max(worst, abs(u - breath(t)))
    return worst


def estimate(traces_path, periods):
    with open(traces_path) as f:
        rows = [r for r in csv.DictReader(f) if r["point"] in POINTS]
    for point in POINTS:
        u = {round(float(r["time [s]"]), 6): tuple(float(r[k]) for k in ("ux [m]", "uy [m]", "uz [m]"))
             for r in rows if r["point"] == point}
        swing = max(distance(u[t], u[BREATHS_START]) for t in u if t >= BREATHS_START)
        print(f"{point}: quasi-static breathing displacement up to {1e3 * swing:.4g} mm")
        for period in periods:
            lag = single_mode_lag(period)
            print(f"  single mode of period {1e3 * period:g} ms: lags by up to {100 * lag:.3g} % of it, "
                  f"{1e6 * lag * swing:.3g} um")
    return 0


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--runs", default=os.path.join(ROOT, "build", "bench", "breathing_inertia"))
    p.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "breathing_inertia.csv"))
    p.add_argument("--set", action="append", default=[], help="path=value, for the dynamic run")
    p.add_argument("--estimate", nargs="?", const=os.path.join(ROOT, "tests", "regression", "s8_5_passive_supine.csv"),
                   help="run nothing: the single-mode estimate from this quasi-static trace")
    p.add_argument("--period", type=float, action="append", help="the mode's period [s] for --estimate (0.16)")
    args = p.parse_args(argv)
    if args.estimate:
        return estimate(args.estimate, args.period or [0.16])
    outs, walls, summaries = {}, {}, {}
    for analysis, deck in DECKS.items():
        outs[analysis] = os.path.join(args.runs, analysis)
        sets = [TOLERANCE, "Output/fields=false"] if analysis == "static" else args.set
        command = [args.glossa, "run", deck, "--output", outs[analysis], "--quiet"]
        for s in sets:
            command += ["--set", s]
        start = time.time()
        subprocess.run(command, check=True)
        walls[analysis] = time.time() - start
        summaries[analysis] = json.load(open(os.path.join(outs[analysis], "summary.json")))
    dynamic, static = traces(outs["dynamic"]), traces(outs["static"])
    # (a shortened dynamic run, --set "Time/end time=3.75": its first breath only)
    times = sorted({t for (_, t) in static if t >= BREATHS_START and ("P_A", t) in dynamic})
    os.makedirs(os.path.dirname(args.table), exist_ok=True)
    with open(args.table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time [s]", "point"] + [f"{a}_{c} [mm]" for a in ("dynamic", "static") for c in ("ux", "uy", "uz")] +
                   ["difference [um]"])
        for t in times:
            for point in POINTS:
                d, s = dynamic[(point, t)], static[(point, t)]
                w.writerow([f"{t:.6g}", point] + [f"{1e3 * x:.6g}" for x in d + s] + [f"{1e6 * distance(d, s):.4g}"])
    for point in POINTS:
        base = static[(point, BREATHS_START)]
        error = max(distance(dynamic[(point, t)], static[(point, t)]) for t in times)
        at = max(times, key=lambda t: distance(dynamic[(point, t)], static[(point, t)]))
        swing = max(distance(static[(point, t)], base) for t in times)
        print(f"{point}: largest |u_dynamic - u_static| {1e6 * error:.4g} um (t = {at:g} s), breathing "
              f"displacement up to {1e6 * swing:.4g} um: quasi-static error {100 * error / swing:.3g} %")
    with open(os.path.join(outs["dynamic"], "energy.csv")) as f:
        kinetic = [(float(r["time [s]"]), float(r["kinetic_energy [J]"])) for r in csv.DictReader(f)]
    late = max((k for t, k in kinetic if t >= BREATHS_START), default=0.0)
    print(f"largest kinetic energy {max(k for _, k in kinetic):.3g} J (during the breaths {late:.3g} J)")
    for analysis, s in summaries.items():
        steps = s["steps"]
        print(f"{analysis}: {len(steps)} steps, Newton {sum(x['newton_iterations'] for x in steps)}, largest "
              f"dilatation error {max(x['max_dilatation_error'] for x in steps):.2g}, {walls[analysis]:.0f} s, "
              f"converged {s['converged']}")
    return 0 if all(s["converged"] for s in summaries.values()) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
