#!/usr/bin/env python3
"""Free vibration by generalized-alpha over the long runs CI leaves out (doc/dynamics.md).

- the large-amplitude cantilever (inputs/verification/nonlinear_vibration.xml), 10 periods, at
  rho_inf = 1 and 0.5 and at 60, 120 and 240 steps a period: the largest relative change of the
  total energy (energy.csv) and its value at the end;
- the axial bar (inputs/verification/axial_vibration.xml) at 10 to 160 steps a period: the period
  against the continuum's 4 L / c and the trapezoidal rule's prediction, and the log-log slope;
- the same cantilever nearly incompressible
  (inputs/verification/nonlinear_vibration_nearly_incompressible.xml, nu = 0.49999, augmented
  Lagrangian), 10 periods: the energy-conserving step at 120 and 240 steps a period, and
  generalized-alpha at rho_inf = 1 (which gains energy and stops) and 0.5, with the time reached,
  the Newton iterations and the largest dilatation error.

Writes bench/results/free_vibration.csv. Needs build/glossa.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLOSSA = os.path.join(ROOT, "build", "glossa")


def run(deck, out, sets, check=True):
    cmd = [GLOSSA, "run", os.path.join(ROOT, "inputs", "verification", deck), "--output", out, "--quiet"]
    for s in sets + ["Output/fields=false"]:
        cmd += ["--set", s]
    subprocess.run(cmd, check=check)


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
    for integrator, rho, steps in (("energy conserving", "", 120), ("energy conserving", "", 240),
                                   ("generalized-alpha", 1.0, 120), ("generalized-alpha", 0.5, 240)):
        out = os.path.join(args.scratch, f"incompressible_{integrator.replace(' ', '_')}_{rho}_{steps}")
        sets = [f"Time/integrator={integrator}", f"Time/step size={0.6 / steps}"]
        if rho != "":
            sets.append(f"Time/spectral radius={rho}")
        # rho_inf = 1 stops when the Uzawa loop can no longer hold the dilatation: its rows say when.
        run("nonlinear_vibration_nearly_incompressible.xml", out, sets, check=False)
        energy = column(os.path.join(out, "energy.csv"), "all", 4)
        E = [e for _, e in energy]
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        rows.append({"case": "nearly incompressible cantilever 10 periods", "integrator": integrator, "rho_inf": rho,
                     "steps_per_period": steps, "largest_energy_change": max(abs(e / E[0] - 1.0) for e in E),
                     "final_energy_ratio": E[-1] / E[0], "end_time": energy[-1][0],
                     "newton_iterations": sum(s.get("newton_iterations", 0) for s in summary["steps"]),
                     "max_dilatation_error": max(s.get("max_dilatation_error", 0.0) for s in summary["steps"])})
        print(rows[-1], flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(ROOT, "bench", "results", "free_vibration.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
