#!/usr/bin/python3
"""Plot the muscle curves tabulated by `glossa curves` (doc/materials.md, "Plots of the curves").

    build/glossa curves --output CURVES_DIR && /usr/bin/python3 doc/plot_curves.py CURVES_DIR

Reads force_length.csv, force_velocity.csv and passive_series.csv from CURVES_DIR and writes
force_length.png, force_velocity.png and passive_series.png to --figures (default doc/figures/;
Debian's python3-matplotlib).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402

import plot_style  # noqa: E402
from plot_style import plt  # noqa: E402


def read(directory, name):
    """A table of `glossa curves` as columns keyed by name without the unit ("lambda_c [-]")."""
    path = os.path.join(directory, name)
    with open(path) as f:
        names = [c.split(" [")[0] for c in f.readline().strip().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def main(directory, figures):
    os.makedirs(figures, exist_ok=True)

    def save(fig, ax, name, title):
        ax.set_title(title)
        ax.grid(True, alpha=0.3)
        plot_style.legend_below(fig, ax, ncol=2)
        plot_style.save(fig, os.path.join(figures, name), dpi=100)

    d = read(directory, "force_length.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(d["lambda_c"], d["f_cL_physiological"], label="physiological (default)")
    ax.plot(d["lambda_c"], d["f_cL_paper_table_II"], "--", label="paper Table II")
    ax.set_xlabel(r"contractile stretch $\lambda_c$ [-]")
    ax.set_ylabel(r"force-length factor $f_{cL}$ [-]")
    save(fig, ax, "force_length.png", "Force-length curve (eq. 19; cf. the paper's Fig. 4)")

    d = read(directory, "force_velocity.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(d["lambda_c_rate"], d["f_cV_physiological"], label="physiological (default)")
    ax.plot(d["lambda_c_rate"], d["f_cV_paper_table_II"], "--", label="paper Table II")
    ax.set_xlabel(r"contractile stretch rate $\dot\lambda_c$ [1/s] (< 0: shortening)")
    ax.set_ylabel(r"force-velocity factor $f_{cV}$ [-]")
    save(fig, ax, "force_velocity.png", "Force-velocity curve (eq. 20; cf. the paper's Fig. 4)")

    d = read(directory, "passive_series.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(d["lambda"], d["f_p"], label=r"parallel $f_p = T_p/T_0^{max}$ (eq. 17)")
    ax.plot(d["lambda"], d["f_s"], "--", label=r"series $f_s = T_s/T_0^{max}$ at $\lambda_c = 1$ (eq. 18)")
    ax.set_ylim(-0.05, 1.5)  # f_s grows like exp(100 (lambda - 1)): clipped
    ax.set_xlabel(r"stretch $\lambda$ (series: $\lambda_s = \lambda$) [-]")
    ax.set_ylabel(r"tension / $T_0^{max}$ [-]  ($T_0^{max}$ = 668.8 kPa)")
    save(fig, ax, "passive_series.png", "Parallel and series elements, Table I (cf. the paper's Fig. 4)")


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("curves", help="the directory `glossa curves --output CURVES_DIR` wrote")
    p.add_argument("--figures", default=plot_style.FIGURES, help="where the pictures go (default: doc/figures/)")
    a = p.parse_args()
    main(a.curves, a.figures)
