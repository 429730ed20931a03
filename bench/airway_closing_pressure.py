#!/usr/bin/python3
"""The tongue's airway closing pressure against genioglossus tone (doc/airway.md, "Closing
pressure at a set area"): inputs/paper/tongue_pcrit_{supine,upright}.xml with GGa, GGm and GGp
held at a constant FFMR (T0s with full activation from t = 0), the suction ramped to --suction at
P_P, and a section counted closed below --area. The coarse tongue cannot press its last 3-4 mm^2
shut (doc/airway.md), so the default area, 5 mm^2, sits above that floor: what is measured is the
pressure at which the narrowest section narrows to it, bracketed to 0.1 cmH2O by the run's own
search (summary.json: pcrit). A run that stops first (an element folds) or never narrows that far
says so, with the largest suction it reached.

    /usr/bin/python3 bench/airway_closing_pressure.py [--glossa build/glossa] [--area 5e-6]
        [--suction 4500] [--tones 0,0.01,0.02,0.05,0.1] [--postures supine,upright] [--jobs 2]
        [--runs DIR] [--table bench/results/airway_closing_pressure.csv] [--figure FILE.png]

Writes the table (posture, tone, outcome, closing pressure and bracket in cmH2O and Pa, section,
largest suction reached, smallest area there, wall time) and a figure of closing pressure against
tone, and prints both.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import subprocess
import sys
import time

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PA_PER_CMH2O = 98.0665
GENIOGLOSSUS = ("GGa", "GGm", "GGp")


def overrides(area, suction, tone):
    o = [f"Airway/closing area={area}", f"Loads/airway pressure/pressure={-suction}"]
    if tone > 0:
        for g in GENIOGLOSSUS:
            o += [f"Material/Muscle groups/{g}/T0s={tone}", f"Material/Muscle groups/{g}/initial activation=1",
                  f"Material/Muscle groups/{g}/neural input scale=1"]
    return o


def smallest_area_at_end(out):
    with open(os.path.join(out, "airway.csv")) as f:
        rows = list(csv.DictReader(f))
    return 1e6 * float(rows[-1]["smallest_area [m^2]"]) if rows else float("nan")


def one(args, posture, tone):
    out = os.path.join(args.runs, f"{posture}_ffmr_{tone:g}")
    deck = os.path.join(ROOT, "inputs", "paper", f"tongue_pcrit_{posture}.xml")
    start = time.time()
    run = subprocess.run(glossa_run_command(args.glossa, deck, out, overrides(args.area, args.suction, tone)),
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.time() - start
    with open(os.path.join(out, "summary.json")) as f:
        pcrit = json.load(f).get("pcrit", {})
    row = {"posture": posture, "GG FFMR [-]": tone, "exit status": run.returncode, "wall [s]": round(seconds, 1),
           "smallest area at the end [mm^2]": round(smallest_area_at_end(out), 3)}
    if pcrit.get("bracketed"):
        row.update({"outcome": "closed", "closing pressure [cmH2O]": round(pcrit["cmH2O"], 3),
                    "low [cmH2O]": round(pcrit["low_cmH2O"], 3), "high [cmH2O]": round(pcrit["high_cmH2O"], 3),
                    "closing pressure [Pa]": round(pcrit["Pa"], 2), "section": pcrit["section"],
                    "largest suction [Pa]": round(pcrit["low_Pa"], 2)})
    else:
        reached = pcrit.get("largest_suction_Pa", float("nan"))
        stopped = reached != pcrit.get("deck_largest_suction_Pa")
        row.update({"outcome": "solve stopped, open" if stopped else "open to the largest suction",
                    "largest suction [Pa]": round(reached, 2)})
    return row


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--area", type=float, default=5e-6, help="closing area [m^2]")
    p.add_argument("--suction", type=float, default=4500.0, help="largest suction at P_P [Pa], > 0")
    p.add_argument("--tones", default="0,0.01,0.02,0.05,0.1", help="GG FFMR values, comma-separated")
    p.add_argument("--postures", default="supine,upright")
    p.add_argument("--jobs", type=int, default=2, help="runs at once (one rank each)")
    p.add_argument("--runs", default=os.path.join(ROOT, "build", "bench", "airway_closing_pressure"))
    p.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "airway_closing_pressure.csv"))
    p.add_argument("--figure", default=os.path.join(ROOT, "doc", "figures", "airway_closing_pressure.png"))
    args = p.parse_args(argv)
    cases = [(posture, float(t)) for posture in args.postures.split(",") for t in args.tones.split(",")]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(lambda c: one(args, *c), cases))
    header = ["posture", "GG FFMR [-]", "outcome", "closing pressure [cmH2O]", "low [cmH2O]", "high [cmH2O]",
              "closing pressure [Pa]", "section", "largest suction [Pa]", "smallest area at the end [mm^2]",
              "exit status", "wall [s]"]
    os.makedirs(os.path.dirname(args.table), exist_ok=True)
    with open(args.table, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=header)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in header})
    for r in rows:
        print(", ".join(f"{k} {r[k]}" for k in header if k in r))
    print(f"table {os.path.relpath(args.table, ROOT)}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no figure")
        return 0
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for posture, colour in (("supine", "tab:blue"), ("upright", "tab:green")):
        mine = [r for r in rows if r["posture"] == posture]
        closed = [r for r in mine if r["outcome"] == "closed"]
        ax.plot([100 * r["GG FFMR [-]"] for r in closed], [r["closing pressure [cmH2O]"] for r in closed], "o-",
                color=colour, label=f"{posture}: closed to {args.area * 1e6:g} mm²")
        for outcome, marker, text in (("open to the largest suction", "^", "open at the largest suction"),
                                      ("solve stopped, open", "x", "solve stopped, open")):
            these = [r for r in mine if r["outcome"] == outcome]
            if not these:
                continue
            ax.plot([100 * r["GG FFMR [-]"] for r in these], [r["largest suction [Pa]"] / PA_PER_CMH2O for r in these],
                    marker, color=colour, mfc="none", label=f"{posture}: {text}")
            for r in these:
                ax.annotate(f"{r['smallest area at the end [mm^2]']:.0f} mm²",
                            (100 * r["GG FFMR [-]"], r["largest suction [Pa]"] / PA_PER_CMH2O), fontsize=6,
                            xytext=(4, 2), textcoords="offset points", color=colour)
    ax.set_xlabel("genioglossus tone, FFMR [%]")
    ax.set_ylabel("airway pressure at P_P [cmH2O]")
    ax.set_title("Closing pressure against tone (coarse tongue)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.figure), exist_ok=True)
    fig.savefig(args.figure, dpi=120)
    print(f"figure {os.path.relpath(args.figure, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
