#!/usr/bin/python3
"""Plot what glossa writes (Debian's /usr/bin/python3 with python3-matplotlib).

  /usr/bin/python3 doc/plot_results.py point POINT.csv doc/figures/muscle_point.png --deck DECK.xml
      a `glossa point` CSV: stress, fibre and contractile stretch, tension and activation
  /usr/bin/python3 doc/plot_results.py run RESULTS_DIR doc/figures/PREFIX
      a run directory: PREFIX_displacement.png (every traced point, ux uy uz over time) and,
      when the run has muscle groups, PREFIX_activation.png (alpha, FFMR and mean fibre stretch
      per group; a passive run, whose groups never activate, gets the fibre stretch alone and
      says so) and, when it was controlled, PREFIX_controls.png (the chosen neural input per
      group, which groups were searched, and the eq. 25 objective over time: a figure like the
      paper's Fig. 6). Titles name the run's deck and the scene it describes (summary.json).
"""
import argparse
import csv
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_style  # noqa: E402
from plot_style import plt  # noqa: E402


def rows_of(path):
    """A run's CSV as dicts keyed by column name without its unit ("ux [m]" -> "ux")."""
    with open(path, newline="") as f:
        return [{k.split(" [")[0]: v for k, v in r.items()} for r in csv.DictReader(f)]


def plot_point(csv_file, png, deck=None):
    rows = rows_of(csv_file)
    t = [float(r["time"]) for r in rows]
    names = list(rows[0].keys())
    has_activation = any(n.startswith("alpha_") for n in names)
    panels = 3 if has_activation else 2
    fig, axes = plt.subplots(panels, 1, figsize=(7.5, 2.7 * panels), sharex=True)
    axes[0].plot(t, [float(r["axial_stress"]) / 1e3 for r in rows], label="axial stress")
    for n in names:
        if n.startswith("T_"):
            axes[0].plot(t, [float(r[n]) / 1e3 for r in rows], label=f"fibre tension {n[2:]}")
    axes[0].set_ylabel("kPa")
    for n in names:
        if n.startswith("lambda_f_") or n.startswith("lambda_c_"):
            axes[1].plot(t, [float(r[n]) for r in rows], label=n)
    axes[1].set_ylabel("stretch")
    if has_activation:
        for n in names:
            if n.startswith("alpha_"):
                axes[2].plot(t, [float(r[n]) for r in rows], label=n)
        axes[2].set_ylabel("activation")
    axes[-1].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        plot_style.legend_right(ax)
    if deck:
        name = os.path.splitext(os.path.basename(deck))[0]
        scene = plot_style.deck_scene(deck)
        title = f"{name}: {scene}" if scene else name
    else:
        title = "glossa point"
    fig.suptitle(title + ("" if has_activation else " (passive: no activation)"), fontsize=10)
    plot_style.save(fig, png)


def traces_of(directory):
    """point -> (t, ux, uy, uz) in mm."""
    traces = defaultdict(lambda: ([], [], [], []))
    for r in rows_of(os.path.join(directory, "traces.csv")):
        series = traces[r["point"]]
        series[0].append(float(r["time"]))
        for i, c in enumerate(("ux", "uy", "uz")):
            series[i + 1].append(float(r[c]) * 1e3)
    return traces


def plot_displacement(directory, title, png):
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), sharex=True)
    for point, (t, *u) in traces_of(directory).items():
        for i in range(3):
            axes[i].plot(t, u[i], label=point)
    for i, c in enumerate("xyz"):
        axes[i].set_title(f"u{c} [mm]")
        axes[i].set_xlabel("time [s]")
        axes[i].grid(True, alpha=0.3)
    plot_style.legend_right(axes[-1], title="traced point")
    fig.suptitle(title, fontsize=10)
    plot_style.save(fig, png)


def plot_activation(directory, title, png):
    groups = defaultdict(lambda: ([], [], [], []))
    for r in rows_of(os.path.join(directory, "activation.csv")):
        g = groups[r["group"]]
        g[0].append(float(r["time"]))
        g[1].append(float(r["alpha"]))
        g[2].append(float(r["ffmr"]))
        g[3].append(float(r["mean_fibre_stretch"]))
    active = any(a != 0.0 for _, alpha, _, _ in groups.values() for a in alpha)
    # A passive run's alpha and FFMR are zero throughout: panels of flat lines at 0 say nothing,
    # so only the fibre stretch (which gravity and pressure still change) is drawn.
    panels = [(1, "activation alpha"), (2, "FFMR = T0s alpha"), (3, "mean fibre stretch")] if active \
        else [(3, "mean fibre stretch")]
    fig, axes = plt.subplots(1, len(panels), figsize=(4.3 * len(panels) + 1, 3.8), sharex=True, squeeze=False)
    axes = axes[0]
    for name, series in groups.items():
        for ax, (column, _) in zip(axes, panels):
            ax.plot(series[0], series[column], label=name)
    for ax, (column, heading) in zip(axes, panels):
        if column == 3:
            # An isometric run holds the stretch at 1 to 1e-7: without a floor on the span the
            # axis would magnify round-off into a saw-tooth under an unreadable offset label.
            low, high = ax.get_ylim()
            if high - low < 2e-3:
                middle = 0.5 * (low + high)
                ax.set_ylim(middle - 1e-3, middle + 1e-3)
            ax.ticklabel_format(axis="y", useOffset=False)
        ax.set_title(heading)
        ax.set_xlabel("time [s]")
        ax.grid(True, alpha=0.3)
    plot_style.legend_right(axes[-1], title="muscle group")
    fig.suptitle(title if active else f"{title}\npassive: no activation (alpha = FFMR = 0 in every group)",
                 fontsize=10)
    plot_style.save(fig, png)


def plot_controls(directory, title, png):
    groups = defaultdict(lambda: ([], [], []))
    objective = {}
    for r in rows_of(os.path.join(directory, "controls.csv")):
        g = groups[r["group"]]
        g[0].append(float(r["time"]))
        g[1].append(float(r["u"]))
        g[2].append(float(r["evaluated"]))
        objective[float(r["time"])] = float(r["objective"])
    fig, axes = plt.subplots(len(groups) + 1, 1, figsize=(8, 1.3 * (len(groups) + 1) + 0.6), sharex=True)
    input_style, searched_style, objective_style = (plot_style.line_style(i)["color"] for i in range(3))
    for ax, (name, (t, u, searched)) in zip(axes, groups.items()):
        ax.step(t, u, where="post", color=input_style, label="input u")
        ax.fill_between(t, 0, searched, step="post", color=searched_style, alpha=0.15, label="searched")
        ax.set_ylim(-0.05, 1.05)
        ax.set_ylabel(name, rotation=0, ha="right", va="center")
    plot_style.legend_right(axes[0])
    t = sorted(objective)
    axes[-1].semilogy(t, [max(objective[x], 1e-12) * 1e6 for x in t], color=objective_style)
    axes[-1].set_ylabel("eq. 25 [um]")
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(title, fontsize=10)
    plot_style.save(fig, png)


def plot_run(directory, prefix):
    title = plot_style.run_title(directory)
    plot_displacement(directory, title, prefix + "_displacement.png")
    if os.path.exists(os.path.join(directory, "activation.csv")):
        plot_activation(directory, title, prefix + "_activation.png")
    if os.path.exists(os.path.join(directory, "controls.csv")):
        plot_controls(directory, title, prefix + "_controls.png")


def missing_input(a):
    """What the command line names that is not there, said as a user would fix it; None if all is."""
    if a.what == "point":
        if not os.path.isfile(a.csv):
            return f"no file {a.csv} (write it with `glossa point DECK --output {a.csv}`)"
        if a.deck and not os.path.isfile(a.deck):
            return f"--deck {a.deck}: no such file"
        return None
    if not os.path.isdir(a.directory):
        return f"no output directory {a.directory} (a run writes it: `glossa run DECK --output {a.directory}`)"
    if not os.path.isfile(os.path.join(a.directory, "traces.csv")):
        return f"{a.directory} has no traces.csv: not the output directory of a glossa run"
    return None


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="what", required=True, metavar="{point,run}")
    point = sub.add_parser("point", help="plot a `glossa point` CSV")
    point.add_argument("csv", help="the CSV `glossa point DECK --output CSV` wrote")
    point.add_argument("png", help="the picture to write")
    point.add_argument("--deck", help="the deck the CSV came from: its name and scene make the title")
    run = sub.add_parser("run", help="plot a run directory (traces.csv, activation.csv, controls.csv)")
    run.add_argument("directory", help="the run's output directory (`glossa run DECK --output DIR`)")
    run.add_argument("prefix", help="path prefix of the pictures: PREFIX_displacement.png, ...")
    a = p.parse_args(argv)
    missing = missing_input(a)
    if missing:
        # A clear line and argparse's status for a bad command line, not a traceback.
        print(f"plot_results.py: error: {missing}", file=sys.stderr)
        return 2
    if a.what == "point":
        plot_point(a.csv, a.png, a.deck)
    else:
        plot_run(a.directory, a.prefix)
    return 0


if __name__ == "__main__":
    sys.exit(main())
