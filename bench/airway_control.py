#!/usr/bin/python3
"""The airway held open by neural control past its closing suction (doc/airway.md, "Control past
the closing suction").

    /usr/bin/python3 bench/airway_control.py [--glossa build/glossa] [--ga-ranks 2]
        [--gradient-ranks 1] [--force] [--check] [--plot]

Runs inputs/paper/airway_control_{passive,gradient,ga}_supine.xml (s8_5's supine breaths with the
palate and pharyngeal wall, p_max = -3000 Pa, the mended tongue) into
bench/results/airway_control/ (without their lumen outlines and checkpoints), reusing finished
runs unless --force. The GA runs on --ga-ranks
ranks, one control group each; the others on --gradient-ranks.

Writes bench/results/airway_control.csv: per run its wall time, ranks, candidate solves, the
smallest lumen area over the run and when, the first closed step, the number of closed steps, the
eq. 25 objective over the breaths (mean, largest) and the mean genioglossus input. --plot draws
doc/figures/airway_control_area.png (the smallest area over time, passive against controlled).
--check asserts what doc/airway.md states and exits 1 if one fails: the passive airway closes; the
controlled ones never close over the three breaths; the gradient controller needs at least 5x fewer
candidate solves than the GA.
"""
import argparse
import csv
import json
import os
import shutil
import sys

import tongue_control as tc

ROOT = tc.ROOT
RUNS = (("passive", "airway_control_passive_supine.xml", "passive"),
        ("gradient", "airway_control_gradient_supine.xml", "gradient"),
        ("ga", "airway_control_ga_supine.xml", "GA"))
CLOSING_AREA_MM2 = 5.0  # the decks' Airway/closing area


def lumen(directory):
    """[(t, smallest area mm^2, closed)] of the committed steps."""
    return [(float(r["time"]), 1e6 * float(r["smallest_area"]), int(r["closed"]) != 0)
            for r in tc.read_csv(os.path.join(directory, "airway.csv"))]


def summarise(name, controller, directory):
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    steps = s["steps"]
    areas = lumen(directory)
    t_min, a_min, _ = min(areas, key=lambda r: r[1])
    closed = [t for t, _, c in areas if c]
    row = {"run": name, "controller": controller, "ranks": s["ranks"], "control_groups": s.get("control_groups", 1),
           "end_time_s": s["final_time"], "steps": len(steps), "wall_s": round(s["wall_seconds"], 1),
           "solves": sum(st.get("control", {}).get("candidates", 0) for st in steps) if controller != "passive" else "",
           "smallest_area_mm2": round(a_min, 2), "at_s": round(t_min, 4),
           "first_closed_s": round(closed[0], 4) if closed else "", "closed_steps": len(closed)}
    objectives = [st["control"]["objective"] for st in steps
                  if "control" in st and st["time"] >= tc.CYCLES_START - 1e-9]
    row["objective_mean_mm"] = round(1e3 * sum(objectives) / len(objectives), 3) if objectives else ""
    row["objective_max_mm"] = round(1e3 * max(objectives), 3) if objectives else ""
    gg = [v for g in ("GGa", "GGm", "GGp") for t, v in tc.group_history(directory, g, "u") if t >= tc.CYCLES_START]
    row["GG_input_mean"] = round(sum(gg) / len(gg), 3) if gg and controller != "passive" else ""
    return row


def check(rows):
    by = {r["run"]: r for r in rows}
    failures = []
    if "passive" in by and not by["passive"]["closed_steps"]:
        failures.append(f"the passive airway does not close (smallest {by['passive']['smallest_area_mm2']} mm^2)")
    for name in ("gradient", "ga"):
        r = by.get(name)
        if r is None:
            continue
        if r["end_time_s"] < tc.END - 1e-9:
            failures.append(f"{name} stopped at t = {r['end_time_s']} s")
        if r["closed_steps"] or r["smallest_area_mm2"] < CLOSING_AREA_MM2:
            failures.append(f"{name}: the airway closed (smallest {r['smallest_area_mm2']} mm^2 at {r['at_s']} s)")
    if "gradient" in by and "ga" in by and not 5 * by["gradient"]["solves"] <= by["ga"]["solves"]:
        failures.append(f"gradient {by['gradient']['solves']} solves against the GA's {by['ga']['solves']}: not 5x fewer")
    for f in failures:
        print("CHECK FAILED:", f)
    return not failures


def plot(rows, runs_dir):
    sys.path.insert(0, os.path.join(ROOT, "doc"))
    import plot_style
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 5.2), sharex=True, height_ratios=(1, 3))
    t = [i * 0.01 for i in range(int(tc.END / 0.01) + 1)]
    top.plot(t, [-tc.pressure(x, 3000.0) for x in t], color="0.3")
    top.set_ylabel("p at P_P [Pa]")
    for r in rows:
        series = lumen(os.path.join(runs_dir, r["run"]))
        bottom.plot([s[0] for s in series], [s[1] for s in series], label=r["run"], marker=".", markersize=3)
    bottom.axhline(CLOSING_AREA_MM2, color="k", linestyle=":", label=f"closed below {CLOSING_AREA_MM2:g} mm$^2$")
    bottom.set_yscale("log")
    bottom.set_xlabel("time [s]")
    bottom.set_ylabel("smallest lumen area [mm$^2$]")
    plot_style.legend_right(bottom, title="run")
    top.set_title("The supine airway at p_max = -3000 Pa: passive against controlled")
    plot_style.save(fig, os.path.join(plot_style.FIGURES, "airway_control_area.png"))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--runs", default=os.path.join(ROOT, "bench", "results", "airway_control"))
    p.add_argument("--csv", default=os.path.join(ROOT, "bench", "results", "airway_control.csv"))
    p.add_argument("--ga-ranks", type=int, default=2)
    p.add_argument("--gradient-ranks", type=int, default=1)
    p.add_argument("--force", action="store_true")
    p.add_argument("--check", action="store_true")
    p.add_argument("--plot", action="store_true")
    args = p.parse_args()
    rows = []
    for name, deck, controller in RUNS:
        directory = os.path.join(args.runs, name)
        if args.force or not tc.finished(directory):
            tc.execute(args.glossa, name, deck, [], controller, directory, args.ga_ranks, args.gradient_ranks)
            # What the table and the figure do not read, and would make the results 30x larger.
            for bulky in ("airway_sections", "checkpoint"):
                shutil.rmtree(os.path.join(directory, bulky), ignore_errors=True)
            if os.path.exists(os.path.join(directory, "airway_sections.vtk.series")):
                os.remove(os.path.join(directory, "airway_sections.vtk.series"))
        rows.append(summarise(name, controller, directory))
    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    for r in rows:
        print(r)
    print("wrote", args.csv)
    if args.plot:
        plot(rows, args.runs)
    if args.check and not check(rows):
        sys.exit(1)


if __name__ == "__main__":
    main()
