#!/usr/bin/python3
"""Contact with near-incompressibility (doc/contact.md, "A nearly incompressible block on a sphere"):
inputs/verification/indentation_nearly_incompressible.xml run under several incompressibility
methods, contact enforcements, contact point rules, penalties, Poisson's ratios and block sizes.

  /usr/bin/python3 bench/contact_near_incompressible.py methods|rules|hertz [--glossa PATH] [--only TEXT]

methods: augmented Lagrangian contact + augmented Lagrangian volume, penalty contact + augmented
Lagrangian volume, the penalty volume method and the mixed method, on the deck as it is.
rules: Uzawa and Newton counts of the Gauss and nodal contact points against the penalty and nu.
hertz: the block (quarter s x s x s, R = 1 mm) scaled by s = 1 to 4 mm at the same cell size,
against Hertz's F = 4/3 E* sqrt(R) d^(3/2) with E* = 2 mu / (1 - nu) and d the far face's travel.

Per run: steps (and cut-backs), Uzawa solves, Newton iterations, contact updates, the largest
dilatation error and gap error of the last step, the gap tolerance, and the full block's force
(4 x the far face's reaction). Appends to bench/results/contact_near_incompressible.csv as it goes.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "inputs", "verification", "indentation_nearly_incompressible.xml")
RESULTS = os.path.join(ROOT, "bench", "results", "contact_near_incompressible.csv")
MU, R, TRAVEL = 1e4, 1e-3, 1e-4  # the deck's shear modulus, sphere radius and far-face travel

AL = "augmented Lagrangian"


def case(label, method=AL, enforcement=AL, rule="gauss", eps=1e10, nu=0.49999, size=1e-3, cells=8):
    return dict(label=label, method=method, enforcement=enforcement, rule=rule, eps=eps, nu=nu, size=size,
                cells=cells)


def overrides(c):
    s = c["size"]
    return [f"Incompressibility/method={c['method']}", f"Contact/sphere/enforcement={c['enforcement']}",
            f"Contact/sphere/contact points={c['rule']}", f"Contact/sphere/penalty={c['eps']:g}",
            f"Material/Poisson's ratio={c['nu']}", f"Mesh/Box/lengths={s:g},{s:g},{s:g}",
            f"Mesh/Box/cells={c['cells']},{c['cells']},{c['cells']}", "Output/fields=false"]


def run(glossa, c, timeout):
    with tempfile.TemporaryDirectory() as out:
        args = [glossa, "run", DECK, "--output", out, "--quiet"]
        for o in overrides(c):
            args += ["--set", o]
        start = time.time()
        proc = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
        wall = time.time() - start
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
    steps = s["steps"]
    last = steps[-1] if steps else {}
    contact = last.get("contacts", {}).get("sphere", {})
    force = -4.0 * last["reactions"]["press"][2] if steps else float("nan")
    nu = c["nu"]
    hertz = 4.0 / 3.0 * (2.0 * MU / (1.0 - nu)) * math.sqrt(R) * TRAVEL ** 1.5
    return dict(c, status=proc.returncode, steps=len(steps),
                uzawa=sum(t["uzawa_iterations"] for t in steps),
                newton=sum(t["newton_iterations"] for t in steps),
                contact_updates=sum(t["contact_updates"] for t in steps),
                max_uzawa_per_step=max((t["uzawa_iterations"] for t in steps), default=0),
                dilatation_error=last.get("max_dilatation_error", float("nan")),
                volume_change=last.get("max_volume_change", float("nan")),
                gap_error=contact.get("largest_gap_error", float("nan")),
                penetration=contact.get("largest_penetration", float("nan")),
                gap_met=s.get("contact", {}).get("gap_tolerance_met"),
                force=force, hertz=hertz, force_over_hertz=force / hertz, wall=round(wall, 2))


SWEEPS = {
    "methods": lambda: [case("AL contact + AL volume"),
                        case("penalty contact + AL volume", enforcement="penalty"),
                        case("penalty contact + penalty volume", method="penalty", enforcement="penalty"),
                        case("AL contact + penalty volume", method="penalty"),
                        case("AL contact + mixed", method="mixed")],
    "rules": lambda: [case(f"{rule} eps={eps:g} nu={nu}", rule=rule, eps=eps, nu=nu)
                      for nu in (0.3, 0.45, 0.49999) for rule in ("gauss", "nodal") for eps in (1e8, 1e9, 1e10, 1e11)],
    "hertz": lambda: [case(f"s={s * 1e3:g} mm {rule}", size=s, cells=round(8 * s / 1e-3), rule=rule)
                      for rule, sizes in (("gauss", (1e-3, 2e-3, 3e-3, 4e-3)), ("nodal", (1e-3, 2e-3))) for s in sizes],
}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("sweep", choices=sorted(SWEEPS))
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--timeout", type=float, default=3600)
    p.add_argument("--only", default="", help="run only the cases whose label contains this text")
    a = p.parse_args()
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    new = not os.path.exists(RESULTS)
    with open(RESULTS, "a", newline="") as f:
        w = None
        for c in (c for c in SWEEPS[a.sweep]() if a.only in c["label"]):
            r = dict(sweep=a.sweep, **run(a.glossa, c, a.timeout))
            if w is None:
                w = csv.DictWriter(f, fieldnames=list(r))
                if new:
                    w.writeheader()
            w.writerow(r)
            f.flush()
            print(", ".join(f"{k}={v}" for k, v in r.items()), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
