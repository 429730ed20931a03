#!/usr/bin/env python3
"""Flow limitation and the closing pressure from the flow (doc/airflow.md, "Pcrit from the flow").

A Starling resistor carries at most V-max = (P_nasal - Pcrit) / R_upstream, whatever the
downstream pressure: so at each of several nasal pressures the tracheal pressure is lowered until
the flow stops rising (or the airway closes, or the solve stops), the largest flow rate is that
nasal pressure's V-max, and the zero of the least-squares line through (P_nasal, V-max) is Pcrit
from the flow, as a sleep laboratory measures it. A sweep whose solve stops before the flow
starts (a nasal suction the tongue's solve cannot carry) has no V-max and is left out of the fit;
one that stops before the flow plateaus gives the largest flow it reached (its last slope against
the tracheal pressure, over its first, says how flat the flow had become). It is set beside the static Pcrit, the uniform
suction at which a section closes with no flow (the closing-pressure search of doc/airway.md):
- the collapsible channel (inputs/verification/airflow_collapsible_channel.xml; static:
  airflow_collapsible_channel_static.xml), nasal pressures 0 to -250 Pa, each swept 300 Pa down;
- the coarse tongue, supine and upright (inputs/paper/tongue_flow_*.xml; static:
  tongue_pcrit_*.xml), passive and with a genioglossus tone (GGa, GGm and GGp fully driven at
  T0s = FFMR, 2 % by default: --tones), nasal pressures 0 to -1500 Pa, each swept 3000 Pa down
  over [1, 2] s.

Writes bench/results/flow_limitation.csv, a row per scene, posture and tone, with
pcrit_static_cmH2O and pcrit_flow_cmH2O. Needs build/glossa; about 25 minutes on 1 core.
"""
import argparse
import csv
import json
import os
import subprocess

from result_table import write_rows

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


def tone_sets(ffmr):
    """The genioglossus parts driven at full neural input with T0s = FFMR (passive: none)."""
    if ffmr == 0.0:
        return []
    return [f"Material/Muscle groups/{g}/{key}" for g in ("GGa", "GGm", "GGp")
            for key in ("neural input scale=1", f"T0s={ffmr}")]


def vmax(deck, out, nasal, sweep, times, step, tone):
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
                                 f"Time/step size={step}"] + tone)
    with open(os.path.join(out, "airflow.csv")) as f:
        rows = list(csv.DictReader(f))
    flowing = [r for r in rows if float(r["flow_rate [m^3/s]"]) > 0.0]
    out = {"reached": float(rows[-1]["tracheal_pressure [Pa]"]), "converged": summary["converged"],
           "why": summary.get("failure", ""), "swept": len(flowing) >= 3}
    if not out["swept"]:  # the solve stopped before the sweep: no V-max at this nasal pressure
        return {**out, "vmax": float("nan"), "at": float("nan"), "end_slope_ratio": float("nan")}
    best = max(flowing, key=lambda r: float(r["flow_rate [m^3/s]"]))

    def slope(a, b):
        return (float(b["flow_rate [m^3/s]"]) - float(a["flow_rate [m^3/s]"])) / \
               (float(a["tracheal_pressure [Pa]"]) - float(b["tracheal_pressure [Pa]"]))
    # How flat the flow has become: its last slope against the tracheal pressure, over its first.
    first = slope(rows[rows.index(flowing[0]) - 1], flowing[0])
    return {**out, "vmax": float(best["flow_rate [m^3/s]"]), "at": float(best["tracheal_pressure [Pa]"]),
            "end_slope_ratio": slope(flowing[-2], flowing[-1]) / first}


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
    parser.add_argument("--tones", type=float, nargs="*", default=[0.02],
                        help="the genioglossus tones (FFMR, e.g. 0.02) run beside the passive tongue")
    args = parser.parse_args()
    rows = []
    for scene, posture, flow_deck, static_deck, nasals, sweep, times, step in SCENES:
        if args.only and args.only not in scene and args.only not in posture:
            continue
        for ffmr in [0.0] + (args.tones if scene == "tongue" else []):
            tone = "passive" if ffmr == 0.0 else f"GGa, GGm, GGp at FFMR {100 * ffmr:g} %"
            tag = f"{scene}_{posture}_{ffmr:g}".replace(" ", "_").replace("-", "")
            peaks = [vmax(flow_deck, os.path.join(args.scratch, f"{tag}_{-n}"), n, sweep, times, step,
                          tone_sets(ffmr)) for n in nasals]
            for n, p in zip(nasals, peaks):
                print(f"{scene} {posture} {tone}: nasal {n} Pa: V-max {1e3 * p['vmax']:.5f} L/s at {p['at']:.1f} Pa, "
                      f"last slope {p['end_slope_ratio']:.3f} of the first (swept to {p['reached']:.1f} Pa"
                      f"{'' if p['converged'] else ': ' + p['why'][:90]})", flush=True)
            fitted = [(n, p["vmax"]) for n, p in zip(nasals, peaks) if p["swept"]]
            zero, slope = line_zero([n for n, _ in fitted], [v for _, v in fitted])
            static = glossa(static_deck, os.path.join(args.scratch, f"{tag}_static"), tone_sets(ffmr))
            pcrit = static.get("pcrit", {})
            closed = bool(pcrit.get("closed"))
            static_pa = pcrit["Pa"] if closed else float("nan")
            note = "" if closed else ("no static closure: " + (static.get("failure") or "never closed")[:160])
            print(f"{scene} {posture} {tone}: Pcrit from the flow {zero:.1f} Pa ({zero / CMH2O:.2f} cmH2O), "
                  f"static {static_pa:.1f} Pa ({static_pa / CMH2O:.2f} cmH2O) {note}", flush=True)
            rows.append({"scene": scene, "posture": posture, "tone": tone,
                         "nasal_pressures_Pa": " ".join(str(n) for n in nasals),
                         "vmax_L_s": " ".join(f"{1e3 * p['vmax']:.6g}" for p in peaks),
                         "vmax_at_tracheal_Pa": " ".join(f"{p['at']:.6g}" for p in peaks),
                         "end_slope_over_first": " ".join(f"{p['end_slope_ratio']:.3g}" for p in peaks),
                         "sweeps_fitted": len(fitted),
                         "upstream_resistance_Pa_s_per_L": 1.0 / (1e3 * slope),
                         "pcrit_flow_Pa": zero, "pcrit_flow_cmH2O": zero / CMH2O,
                         "pcrit_static_Pa": static_pa, "pcrit_static_cmH2O": static_pa / CMH2O,
                         "difference_cmH2O": (zero - static_pa) / CMH2O, "note": note})
    write_rows(args.table, rows)


if __name__ == "__main__":
    main()
