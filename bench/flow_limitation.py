#!/usr/bin/env python3
"""Flow limitation and the closing pressure from the flow (doc/airflow.md, "Pcrit from the flow").

A Starling resistor carries at most V-max = (P_nasal - Pcrit) / R_upstream, whatever the
downstream pressure: so at each of several nasal pressures the tracheal pressure is lowered until
the flow stops rising (or the airway closes, or the solve stops), the largest flow rate is that
nasal pressure's V-max, and the zero of the least-squares line through (P_nasal, V-max) is Pcrit
from the flow, as a sleep laboratory measures it. It is set beside the static Pcrit, the uniform
suction at which a section closes with no flow (the closing-pressure search of doc/airway.md):
- the collapsible channel (inputs/verification/airflow_collapsible_channel.xml; static:
  airflow_collapsible_channel_static.xml), nasal pressures 0 to -250 Pa, each swept 300 Pa down;
- the passive coarse tongue, supine and upright (inputs/paper/tongue_flow_*.xml; static:
  tongue_pcrit_*.xml), nasal pressures 0 to -1500 Pa, each swept 3000 Pa down over [1, 2] s.

Writes bench/results/flow_limitation.csv, a row per scene, posture and tone (passive here), with
pcrit_static_cmH2O and pcrit_flow_cmH2O. Needs build/glossa; about 15 minutes on 1 core.
"""
import argparse
import csv
import json
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLOSSA = os.path.join(ROOT, "build", "glossa")
CMH2O = 98.0665  # Pa
SCENES = [
    # scene, posture, flow deck, static deck, nasal pressures [Pa], sweep [Pa], sweep times, step [s]
    ("collapsible channel", "-", "inputs/verification/airflow_collapsible_channel.xml",
     "inputs/verification/airflow_collapsible_channel_static.xml", (0, -50, -100, -150, -200, -250), 300,
     "{0, 1}", 0.05),
    ("tongue", "supine", "inputs/paper/tongue_flow_supine.xml", "inputs/paper/tongue_pcrit_supine.xml",
     (0, -500, -1000, -1500), 3000, "{0, 1, 2}", 0.0625),
    ("tongue", "upright", "inputs/paper/tongue_flow_upright.xml", "inputs/paper/tongue_pcrit_upright.xml",
     (0, -500, -1000, -1500), 3000, "{0, 1, 2}", 0.0625),
]


def glossa(deck, out, sets):
    cmd = [GLOSSA, "run", os.path.join(ROOT, deck), "--output", out, "--quiet", "--set", "Output/fields=false"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=False)  # a sweep may end where the airway closes or the solve stops
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def vmax(deck, out, nasal, sweep, times, step):
    # Both end pressures reach the nasal pressure when the sweep starts (on the tongue, after the
    # gravity ramp: the two-point table has no such wait); the tracheal one then falls by `sweep`.
    two = times.count(",") == 1
    tracheal = f"{{{nasal}, {nasal - sweep}}}" if two else f"{{0, {nasal}, {nasal - sweep}}}"
    nasal_shape = "{1, 1}" if two else "{0, 1, 1}"
    summary = glossa(deck, out, ["Airflow/nasal pressure=" + str(nasal),
                                 "Airflow/nasal pressure time function/type=table",
                                 f"Airflow/nasal pressure time function/times={times}",
                                 f"Airflow/nasal pressure time function/values={nasal_shape}",
                                 "Airflow/tracheal pressure=1",
                                 "Airflow/tracheal pressure time function/type=table",
                                 f"Airflow/tracheal pressure time function/times={times}",
                                 f"Airflow/tracheal pressure time function/values={tracheal}",
                                 f"Time/step size={step}"])
    with open(os.path.join(out, "airflow.csv")) as f:
        rows = list(csv.DictReader(f))
    best = max(rows, key=lambda r: float(r["flow_rate [m^3/s]"]))
    return {"vmax": float(best["flow_rate [m^3/s]"]), "at": float(best["tracheal_pressure [Pa]"]),
            "reached": float(rows[-1]["tracheal_pressure [Pa]"]), "converged": summary["converged"],
            "why": summary.get("failure", "")}


def line_zero(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    slope = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
    return mx - my / slope, slope


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scratch", default="/tmp/glossa_flow_limitation", help="where the runs write")
    parser.add_argument("--table", default=os.path.join(ROOT, "bench", "results", "flow_limitation.csv"))
    parser.add_argument("--only", help="run only the scenes whose name or posture contains this")
    args = parser.parse_args()
    rows = []
    for scene, posture, flow_deck, static_deck, nasals, sweep, times, step in SCENES:
        if args.only and args.only not in scene and args.only not in posture:
            continue
        tag = f"{scene}_{posture}".replace(" ", "_").replace("-", "")
        peaks = [vmax(flow_deck, os.path.join(args.scratch, f"{tag}_{-n}"), n, sweep, times, step) for n in nasals]
        for n, p in zip(nasals, peaks):
            print(f"{scene} {posture}: nasal {n} Pa: V-max {1e3 * p['vmax']:.5f} L/s at {p['at']:.1f} Pa "
                  f"(swept to {p['reached']:.1f} Pa{'' if p['converged'] else ': ' + p['why'][:90]})", flush=True)
        zero, slope = line_zero(list(nasals), [p["vmax"] for p in peaks])
        static = glossa(static_deck, os.path.join(args.scratch, f"{tag}_static"), [])
        pcrit = static.get("pcrit", {})
        closed = bool(pcrit.get("closed"))
        static_pa = pcrit["Pa"] if closed else float("nan")
        note = "" if closed else ("no static closure: " + (static.get("failure") or "never closed")[:160])
        print(f"{scene} {posture}: Pcrit from the flow {zero:.1f} Pa ({zero / CMH2O:.2f} cmH2O), "
              f"static {static_pa:.1f} Pa ({static_pa / CMH2O:.2f} cmH2O) {note}", flush=True)
        rows.append({"scene": scene, "posture": posture, "tone": "passive",
                     "nasal_pressures_Pa": " ".join(str(n) for n in nasals),
                     "vmax_L_s": " ".join(f"{1e3 * p['vmax']:.6g}" for p in peaks),
                     "upstream_resistance_Pa_s_per_L": 1.0 / (1e3 * slope),
                     "pcrit_flow_Pa": zero, "pcrit_flow_cmH2O": zero / CMH2O,
                     "pcrit_static_Pa": static_pa, "pcrit_static_cmH2O": static_pa / CMH2O,
                     "difference_cmH2O": (zero - static_pa) / CMH2O, "note": note})
    os.makedirs(os.path.dirname(args.table), exist_ok=True)
    with open(args.table, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {args.table}")


if __name__ == "__main__":
    main()
