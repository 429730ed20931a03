#!/usr/bin/python3
"""The tongue pressed on the palate, the whole run (inputs/paper/tongue_palate.xml, 2 s; its first
1.4 s are the CI regression test regression.tongue_palate_onset): runs it and tabulates, per step,
the contact with the palate beside the measured tongue-palate pressures (doc/tongue.md).

    /usr/bin/python3 bench/tongue_palate.py [--glossa build/glossa] [--runs DIR] [--ranks N]
                                            [--table bench/results/tongue_palate.csv]

Writes the table (time, contact area, normal force, mean pressure = force / area, active
points, largest penetration and gap error, the palate zone's resultant) and prints the last
step, the balance of the palate zone's resultant against the contact's normal force, and the
largest penetration against the gap tolerance; then the steps and Newton iterations, each
contact at the last step, the palate's largest multipliers (the peak contact pressure, from the
last checkpoint) and the zones' resultants and the reactions there. The peak of the nodal
contact pressure comes from the fields (doc/render_tongue.py draws them).
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
sys.path.insert(0, os.path.join(ROOT, "tests", "fuzz"))
import checkpoint_part  # noqa: E402 (the checkpoint fuzz's reader of a checkpoint part)
DECK = os.path.join(ROOT, "inputs", "paper", "tongue_palate.xml")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def latest_checkpoint_part(checkpoint, rank):
    """The state one rank wrote in the run's latest checkpoint (doc/output.md)."""
    with open(os.path.join(checkpoint, "latest")) as f:
        step = f.read().strip()
    with open(os.path.join(checkpoint, step, f"rank_{rank:04d}.cbor"), "rb") as f:
        return checkpoint_part.decode(checkpoint_part.unframe(f.read())[2])


def report_contacts(out, summary, ranks):
    """The run's steps and Newton iterations, and at its last step each contact's force, points and
    penetration and the palate's largest multipliers (the contact pressures of its points, from the
    last checkpoint: the peak pressure) with the resultants of the zones."""
    steps = summary["steps"]
    print(f"{len(steps)} steps (smallest {min(x['dt'] for x in steps):g} s), Newton "
          f"{sum(x['newton_iterations'] for x in steps)}, Uzawa {sum(x['uzawa_iterations'] for x in steps)}")
    for name, c in steps[-1]["contacts"].items():
        print(f"  {name}: {c['normal_force']:.4g} N on {c['active_points']} points, area {1e4 * c['area']:.3g} cm^2, "
              f"largest penetration {1e6 * c['largest_penetration']:.3g} um")
    parts = [latest_checkpoint_part(os.path.join(out, "checkpoint"), rank) for rank in range(ranks)]
    palate = sorted((m for part in parts for m in part["contact"][0]["multipliers"] if m > 0), reverse=True)
    print(f"  palate multipliers > 0 ({len(palate)}), largest first [kPa]: "
          + ", ".join(f"{1e-3 * m:.2g}" for m in palate))
    last = max(float(r["time [s]"]) for r in rows(os.path.join(out, "resultants.csv")))
    for r in rows(os.path.join(out, "resultants.csv")):
        if float(r["time [s]"]) == last:
            print(f"  resultant of {r['face_set']}: ({float(r['fx [N]']):.3f}, {float(r['fy [N]']):.3f}, "
                  f"{float(r['fz [N]']):.3f}) N")
    for r in rows(os.path.join(out, "reactions.csv")):
        if float(r["time [s]"]) == last:
            print(f"  reaction of {r['condition']}: ({float(r['fx [N]']):.3f}, {float(r['fy [N]']):.3f}, "
                  f"{float(r['fz [N]']):.3f}) N")


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--runs", default=os.path.join(ROOT, "build", "bench", "tongue_palate"))
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "tongue_palate.csv"))
    args = p.parse_args(argv)
    out = os.path.join(args.runs, f"{args.ranks}_ranks")
    command = [args.glossa, "run", DECK, "--output", out, "--quiet"]
    if args.ranks > 1:
        command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(args.ranks)] + command
    start = time.time()
    subprocess.run(command, check=True)
    wall = time.time() - start
    summary = json.load(open(os.path.join(out, "summary.json")))
    contact = [r for r in rows(os.path.join(out, "contact.csv")) if r["contact"] == "palate"]
    zone = {r["time [s]"]: r for r in rows(os.path.join(out, "resultants.csv")) if r["face_set"] == "palate zone"}
    os.makedirs(os.path.dirname(args.table), exist_ok=True)
    with open(args.table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time [s]", "area [cm^2]", "normal_force [N]", "mean_pressure [kPa]", "active_points [-]",
                    "largest_penetration [um]", "largest_gap_error [um]", "zone_resultant [N]"])
        for r in contact:
            area, force = float(r["area [m^2]"]), float(r["normal_force [N]"])
            z = zone[r["time [s]"]]
            resultant = math.sqrt(sum(float(z[k]) ** 2 for k in ("fx [N]", "fy [N]", "fz [N]")))
            w.writerow([f"{float(r['time [s]']):.6g}", f"{1e4 * area:.4g}", f"{force:.4g}",
                        f"{1e-3 * force / area if area > 0 else 0:.4g}", r["active_points [-]"],
                        f"{1e6 * float(r['largest_penetration [m]']):.4g}",
                        f"{1e6 * float(r['largest_gap_error [m]']):.4g}", f"{resultant:.4g}"])
    last = contact[-1]
    area, force = float(last["area [m^2]"]), float(last["normal_force [N]"])
    onset = next((r["time [s]"] for r in contact if int(float(r["active_points [-]"])) > 0 and float(r["time [s]"]) > 0), None)
    print(f"{args.ranks} rank(s), {wall:.0f} s, converged {summary['converged']}, gap tolerance met "
          f"{summary['contact']['gap_tolerance_met']} (largest gap error {1e6 * summary['contact']['largest_gap_error']:.2f} um)")
    print(f"contact from t = {float(onset):.4g} s; at t = {float(last['time [s]']):g} s: area {1e4 * area:.3g} cm^2, "
          f"force {force:.3g} N, mean pressure {1e-3 * force / area:.3g} kPa, "
          f"{last['active_points [-]']} active points; table in {args.table}")
    report_contacts(out, summary, args.ranks)
    return 0 if summary["converged"] else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
