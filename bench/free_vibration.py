#!/usr/bin/env python3
"""Free vibration by generalized-alpha over the long runs CI leaves out (doc/dynamics.md).

- the large-amplitude cantilever (inputs/verification/nonlinear_vibration.xml), 10 periods, at
  rho_inf = 1 and 0.5 and at 60, 120 and 240 steps a period: the largest relative change of the
  total energy (energy.csv) and its value at the end;
- the axial bar (inputs/verification/axial_vibration.xml) at 10 to 160 steps a period: the period
  against the continuum's 4 L / c and the trapezoidal rule's prediction, and the log-log slope.

Writes bench/results/free_vibration.csv. Needs build/glossa.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLOSSA = os.path.join(ROOT, "build", "glossa")


def run(deck, out, sets):
    cmd = [GLOSSA, "run", os.path.join(ROOT, "inputs", "verification", deck), "--output", out, "--quiet"]
    for s in sets + ["Output/fields=false"]:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)


def column(path, key, index):
    with open(path) as f:
        rows = [r for r in csv.reader(f)][1:]
    return [(float(r[0]), float(r[index])) for r in rows if r[1] == key]


def bar_period(out):
    u = column(os.path.join(out, "traces.csv"), "tip", 2)
    up = [t0 + (t1 - t0) * (-u0) / (u1 - u0) for (t0, u0), (t1, u1) in zip(u, u[1:]) if u0 < 0.0 <= u1]
    return up[-1] / len(up)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scratch", default="/tmp/glossa_free_vibration", help="where the runs write")
    args = parser.parse_args()
    rows = []
    for rho in (1.0, 0.5):
        for steps in (60, 120, 240):
            out = os.path.join(args.scratch, f"cantilever_rho{rho}_{steps}")
            run("nonlinear_vibration.xml", out, [f"Time/spectral radius={rho}", f"Time/step size={0.6 / steps}"])
            E = [e for _, e in column(os.path.join(out, "energy.csv"), "all", 4)]
            worst = max(abs(e / E[0] - 1.0) for e in E)
            rows.append({"case": "cantilever 10 periods", "rho_inf": rho, "steps_per_period": steps,
                         "largest_energy_change": worst, "final_energy_ratio": E[-1] / E[0]})
            print(rows[-1], flush=True)
    mu, nu, rho, L = 1000.0, 0.3, 1000.0, 0.1
    c = math.sqrt((2 * mu * (1 + nu) / (3 * (1 - 2 * nu)) + 4 * mu / 3) / rho)
    T = 4 * L / c
    h, k = L / 20, math.pi / (2 * L)
    Th = 2 * math.pi / math.sqrt(6 * c * c / h / h * (1 - math.cos(k * h)) / (2 + math.cos(k * h)))
    previous = None
    for steps in (10, 20, 40, 80, 160):
        out = os.path.join(args.scratch, f"bar_{steps}")
        dt = T / steps
        run("axial_vibration.xml", out, [f"Time/step size={dt!r}", f"Time/end time={1.1 * T!r}"])
        measured = bar_period(out)
        omega = 2 * math.pi / Th * dt
        error = measured / Th - 1.0
        rows.append({"case": "axial bar", "rho_inf": 1.0, "steps_per_period": steps, "period": measured,
                     "period_vs_continuum": measured / T - 1.0, "period_error": error,
                     "vs_trapezoidal_prediction": measured / (Th * omega / (2 * math.atan(omega / 2))) - 1.0,
                     "slope": math.log(previous / error) / math.log(2.0) if previous else ""})
        previous = error
        print(rows[-1], flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    keys = sorted({k for r in rows for k in r}, key=lambda k: list(rows[-1]).index(k) if k in rows[-1] else 99)
    with open(os.path.join(ROOT, "bench", "results", "free_vibration.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
