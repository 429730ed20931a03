#!/usr/bin/python3
"""The 3D ironing problem of Puso and Laursen with a rigid die (inputs/verification/ironing_rigid_die.xml;
doc/contact.md, "The ironing problem"): the die pressed 1.4 into the slab and slid 4, without
friction and with mu = 0.3, on the CI mesh (h = 0.5, 30 steps of 0.1) and a finer one (h = 0.25,
60 steps of 0.05).

  /usr/bin/python3 bench/ironing.py [--meshes coarse,fine] [--glossa build/glossa] [--plot-only]

Per run and step: time, step size, the contact area, the contact's normal force N and friction force T
(contact.csv) and T/N, the force the die exerts on the top (the zmax resultant: Fx along the
sliding, Fz against the press), Newton and Uzawa iterations, seconds. Writes
bench/results/ironing.csv and doc/figures/ironing_forces.png (N, T and the die's Fx, Fz against
time for every run), and prints per run the steps, Newton and Uzawa counts, the smallest step, the
wall time, T/N from t = 2 on (min and max), the largest step-to-step change of N while the die
slides (t > 1) and, without friction, the largest mirror difference |N(t) - N(4 - t)| / N(t):
the die's start and end (x = 2.5 and 6.5) are mirror images about the slab's middle.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "doc"))
import plot_style  # noqa: E402

ROOT = plot_style.ROOT
DECK = os.path.join(ROOT, "inputs", "verification", "ironing_rigid_die.xml")
RESULTS = os.path.join(ROOT, "bench", "results")
MESHES = {"coarse": [], "fine": ["Mesh/Box/cells=36,8,12", "Time/step size=0.05"]}
COLUMNS = ["mesh", "mu", "time", "dt", "area", "N", "T", "T_over_N", "Fx", "Fz", "newton", "uzawa", "seconds"]


def keyed(path, key):
    with open(path) as f:
        return [[float(v) for v in row[:1] + row[2:]] for row in csv.reader(f) if row and row[1] == key]


def run(glossa, mesh, mu, scratch):
    out = os.path.join(scratch, f"{mesh}_mu{mu}")
    cmd = [glossa, "run", DECK, "--quiet", "--output", out, "--set", f"Contact/die/friction coefficient={mu}"]
    for s in MESHES[mesh]:
        cmd += ["--set", s]
    start = time.time()
    subprocess.run(cmd, check=True)
    wall = time.time() - start
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    contact = keyed(os.path.join(out, "contact.csv"), "die")
    top = keyed(os.path.join(out, "resultants.csv"), "zmax")
    rows = []
    for k, step in enumerate(summary["steps"]):
        c, r = contact[k + 1], top[k + 1]
        N, T = c[2], c[6]
        rows.append({"mesh": mesh, "mu": mu, "time": step["time"], "dt": step["dt"], "area": c[1], "N": N, "T": T,
                     "T_over_N": T / N if N > 0 else 0.0, "Fx": r[1], "Fz": r[3],
                     "newton": step["newton_iterations"], "uzawa": step["uzawa_iterations"],
                     "seconds": step["seconds"]})
    sliding = [r["T_over_N"] for r in rows if r["time"] >= 2.0 - 1e-9]
    print(f"{mesh} mu={mu}: {len(rows)} steps, Newton {sum(r['newton'] for r in rows)}, "
          f"Uzawa {sum(r['uzawa'] for r in rows)}, smallest step {min(r['dt'] for r in rows):.3g}, "
          f"wall {wall:.1f} s, T/N from t = 2 {min(sliding):.4f}..{max(sliding):.4f}, "
          f"largest step change of N while sliding {largest_step_change(rows):.4f}, "
          f"mirror difference of N {mirror_difference(rows):.2e}")
    return rows


def largest_step_change(rows):
    """The largest |N(k) - N(k-1)| / N(k-1) over the steps that end while the die slides."""
    return max(abs(b["N"] - a["N"]) / a["N"] for a, b in zip(rows, rows[1:]) if b["time"] > 1.0 + 1e-9)


def mirror_difference(rows):
    """The largest |N(t) - N(4 - t)| / N(t) over the sliding steps whose mirror time is a step too."""
    by_time = {round(r["time"], 9): r["N"] for r in rows}
    pairs = [(n, by_time[round(4.0 - t, 9)]) for t, n in by_time.items() if t >= 1.0 and round(4.0 - t, 9) in by_time]
    return max(abs(a - b) / a for a, b in pairs)


def plot(rows):
    fig, axes = plot_style.plt.subplots(1, 2, figsize=(11, 4))
    runs = sorted({(r["mesh"], r["mu"]) for r in rows})
    for i, (mesh, mu) in enumerate(runs):
        sel = [r for r in rows if r["mesh"] == mesh and float(r["mu"]) == float(mu)]
        t = [r["time"] for r in sel]
        style = plot_style.line_style(i)
        axes[0].plot(t, [r["N"] for r in sel], label=f"{mesh}, mu = {mu}: N", **style)
        if float(mu) > 0:
            axes[0].plot(t, [r["T"] for r in sel], label=f"{mesh}, mu = {mu}: T", marker=".", **style)
        axes[1].plot(t, [-r["Fz"] for r in sel], label=f"{mesh}, mu = {mu}: -Fz", **style)
        axes[1].plot(t, [r["Fx"] for r in sel], label=f"{mesh}, mu = {mu}: Fx", marker=".", **style)
    axes[0].set_title("contact.csv: normal N and friction T")
    axes[1].set_title("the die's force on the slab (zmax resultant)")
    for ax in axes:
        ax.set_xlabel("time (press 0-1, slide 1-3)")
        ax.set_ylabel("force [N, E = 1]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=2, fontsize=7)
    fig.suptitle("3D ironing (Puso and Laursen): rigid die R = 3 pressed 1.4 and slid 4 on a 9 x 4 x 3 neo-Hookean slab")
    plot_style.save(fig, os.path.join(plot_style.FIGURES, "ironing_forces.png"))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--meshes", default="coarse,fine")
    p.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"))
    p.add_argument("--plot-only", action="store_true")
    a = p.parse_args()
    path = os.path.join(RESULTS, "ironing.csv")
    if a.plot_only:
        with open(path) as f:
            rows = [{k: (v if k == "mesh" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
    else:
        rows = []
        # The runs' own files (fields, checkpoints) are not kept: the CSV holds what is measured.
        with tempfile.TemporaryDirectory(prefix="glossa_ironing_") as scratch:
            for mesh in a.meshes.split(","):
                for mu in (0.0, 0.3):
                    rows += run(a.glossa, mesh, mu, scratch)
        with open(path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=COLUMNS)
            w.writeheader()
            w.writerows(rows)
    plot(rows)


if __name__ == "__main__":
    main()
