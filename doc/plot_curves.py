#!/usr/bin/python3
"""Plot the muscle curves tabulated by `glossa curves` (doc/materials.md, "Plots of the curves").

    build/glossa curves --output /tmp/curves && /usr/bin/python3 doc/plot_curves.py /tmp/curves

Reads force_length.csv, force_velocity.csv and passive_series.csv from the directory given and
writes doc/figures/{force_length,force_velocity,passive_series}.png (Debian's python3-matplotlib).
"""
import os
import sys

os.environ.setdefault("MPLBACKEND", "Agg")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FIGURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "figures")


def read(directory, name):
    return np.genfromtxt(os.path.join(directory, name), delimiter=",", names=True)


def save(fig, ax, name, title):
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(FIGURES, name)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print("wrote", path)


def main(directory):
    os.makedirs(FIGURES, exist_ok=True)

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
    if len(sys.argv) != 2:
        sys.exit("usage: plot_curves.py DIR  (DIR: the output of `glossa curves --output DIR`)")
    main(sys.argv[1])
