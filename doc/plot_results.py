#!/usr/bin/python3
"""Plot what glossa writes (Debian's python3-matplotlib):

    /usr/bin/python3 doc/plot_results.py point point.csv doc/figures/muscle_point.png
        a `glossa point` CSV: stress, fibre and contractile stretch, tension and activation
    /usr/bin/python3 doc/plot_results.py run RESULTS_DIR doc/figures/PREFIX
        a run directory: PREFIX_displacement.png (every traced point, ux uy uz over time) and,
        when the run has muscle groups, PREFIX_activation.png (alpha and FFMR per group) and,
        when it was controlled, PREFIX_controls.png (the chosen neural input per group, which
        groups were searched, and the eq. 25 objective over time: a figure like the paper's Fig. 6)
"""
import csv
import os
import sys
from collections import defaultdict

os.environ.setdefault("MPLBACKEND", "Agg")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def columns(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def plot_point(csv_file, png):
    rows = columns(csv_file)
    t = [float(r["time"]) for r in rows]
    names = rows[0].keys()
    fig, axes = plt.subplots(3, 1, figsize=(6.5, 8), sharex=True)
    axes[0].plot(t, [float(r["axial_stress"]) / 1e3 for r in rows], label="axial stress")
    for n in names:
        if n.startswith("T_"):
            axes[0].plot(t, [float(r[n]) / 1e3 for r in rows], "--", label=f"fibre tension {n[2:]}")
    axes[0].set_ylabel("kPa")
    for n in names:
        if n.startswith("lambda_f_") or n.startswith("lambda_c_"):
            axes[1].plot(t, [float(r[n]) for r in rows], label=n)
    axes[1].set_ylabel("stretch")
    for n in names:
        if n.startswith("alpha_"):
            axes[2].plot(t, [float(r[n]) for r in rows], label=n)
    axes[2].set_ylabel("activation")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    fig.suptitle(os.path.basename(csv_file))
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("wrote", png)


def plot_run(directory, prefix):
    traces = defaultdict(lambda: ([], [], [], []))
    for r in columns(os.path.join(directory, "traces.csv")):
        series = traces[r["point"]]
        series[0].append(float(r["time"]))
        for i, c in enumerate(("ux", "uy", "uz")):
            series[i + 1].append(float(r[c]) * 1e3)
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6), sharex=True)
    for point, (t, *u) in traces.items():
        for i in range(3):
            axes[i].plot(t, u[i], label=point)
    for i, c in enumerate("xyz"):
        axes[i].set_title(f"u{c} [mm]")
        axes[i].set_xlabel("time [s]")
        axes[i].grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_displacement.png", dpi=120)
    print("wrote", prefix + "_displacement.png")
    activation = os.path.join(directory, "activation.csv")
    if not os.path.exists(activation):
        return
    groups = defaultdict(lambda: ([], [], [], []))
    for r in columns(activation):
        g = groups[r["group"]]
        g[0].append(float(r["time"]))
        g[1].append(float(r["alpha"]))
        g[2].append(float(r["ffmr"]))
        g[3].append(float(r["mean_fibre_stretch"]))
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6), sharex=True)
    for name, (t, alpha, ffmr, stretch) in groups.items():
        axes[0].plot(t, alpha, label=name)
        axes[1].plot(t, ffmr, label=name)
        axes[2].plot(t, stretch, label=name)
    for ax, title in zip(axes, ("activation alpha", "FFMR = T0s alpha", "mean fibre stretch")):
        ax.set_title(title)
        ax.set_xlabel("time [s]")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_activation.png", dpi=120)
    print("wrote", prefix + "_activation.png")
    controls = os.path.join(directory, "controls.csv")
    if os.path.exists(controls):
        plot_controls(columns(controls), prefix + "_controls.png")


def plot_controls(rows, png):
    groups = defaultdict(lambda: ([], [], []))
    objective = {}
    for r in rows:
        g = groups[r["group"]]
        g[0].append(float(r["time"]))
        g[1].append(float(r["u"]))
        g[2].append(float(r["evaluated"]))
        objective[float(r["time"])] = float(r["objective"])
    fig, axes = plt.subplots(len(groups) + 1, 1, figsize=(7, 1.5 * (len(groups) + 1)), sharex=True)
    for ax, (name, (t, u, searched)) in zip(axes, groups.items()):
        ax.step(t, u, where="post", color="C0", label="input u")
        ax.fill_between(t, 0, searched, step="post", color="C1", alpha=0.15, label="searched")
        ax.set_ylim(-0.05, 1.05)
        ax.set_ylabel(name)
    axes[0].legend(fontsize=7, loc="upper right")
    t = sorted(objective)
    axes[-1].semilogy(t, [max(objective[x], 1e-12) * 1e6 for x in t], color="C2")
    axes[-1].set_ylabel("eq. 25 [um]")
    axes[-1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] not in ("point", "run"):
        sys.exit(__doc__)
    (plot_point if sys.argv[1] == "point" else plot_run)(sys.argv[2], sys.argv[3])
