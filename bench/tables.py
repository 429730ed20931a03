#!/usr/bin/python3
"""Prints the bench CSVs (bench/results/) as the markdown tables of doc/incompressibility.md."""
import csv
import os
import sys

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")


def kappa():
    rows = list(csv.DictReader(open(os.path.join(RESULTS, "kappa_uzawa_trade.csv"))))
    out = ["| kappa/mu | method | Newton solves | Newton its | Krylov its | max dilatation error | uy top centre [mm] | wall [s] |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        note = "" if r["converged"] == "True" else " (did not finish)"
        out.append(f"| {float(r['kappa_over_mu']):g} | {r['method']} | {r['uzawa']} | {r['newton']} | {r['krylov']} | "
                   f"{float(r['max_dilatation_error']):.1e} | {float(r['uy_top_centre_mm']):.5f} | {r['wall_s']}{note} |")
    return "\n".join(out)


def scaling(name):
    rows = list(csv.DictReader(open(os.path.join(RESULTS, name))))
    out = ["| n | ranks | method | dofs | Newton | Krylov | Uzawa | max dil. err. | wall [s] | assembly [s] | prec. set-up [s] "
           "| Krylov [s] | peak MB/rank | deal.II [s] | speed-up |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['elements_per_side']} | {r['ranks']} | {r['method']} | {r['dofs']} | {r['newton']} | {r['krylov']} | "
                   f"{r['uzawa']} | {float(r['max_dilatation_error']):.1e} | {r['wall_s']} | {r['assembly_s']} | "
                   f"{r['prec_setup_s']} | {r['krylov_s']} | {r['peak_mb_per_rank']} | {r['dealii_wall_s']} | "
                   f"{r['speedup_vs_dealii']} |")
    return "\n".join(out)


if __name__ == "__main__":
    what = sys.argv[1] if len(sys.argv) > 1 else "kappa"
    print(kappa() if what == "kappa" else scaling(what))
