"""Shared look of Glossa's plots (doc/plot_results.py, doc/plot_curves.py, bench/*.py).

Imported, not run. It gives every script the same answers to the issues readers met:
  - lines stay distinguishable past ten: colour x line style (10 tab10 colours, then the same
    colours dashed, dotted, dash-dotted: 40 distinct lines) instead of matplotlib's 10 colours;
  - legends sit outside the data (right of the axes, or below them in columns);
  - titles name the run (its deck and the scene the deck describes), never a file name.
"""
import json
import os
import re

# Agg before pyplot: the scripts run headless (ctest, ssh) and must never look for a display.
os.environ.setdefault("MPLBACKEND", "Agg")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from cycler import cycler  # noqa: E402
from matplotlib.legend import Legend  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = os.path.join(ROOT, "doc", "figures")
COLOURS = list(plt.get_cmap("tab10").colors)
LINE_STYLES = ["-", "--", ":", "-."]


def line_style(i):
    """Colour and line style of the i-th line: the colour varies fastest, so the first ten lines
    are solid and the eleventh is the first colour dashed (SL and GGa no longer look alike)."""
    return {"color": COLOURS[i % len(COLOURS)], "linestyle": LINE_STYLES[(i // len(COLOURS)) % len(LINE_STYLES)]}


MARKERS = ["o", "s", "^", "D", "v"]


def marker_style(i):
    """Colour and marker of the i-th series, for plots whose line style already means something
    else (e.g. the mesh size): the colour varies fastest, the marker changes every ten."""
    return {"color": COLOURS[i % len(COLOURS)], "marker": MARKERS[(i // len(COLOURS)) % len(MARKERS)]}


# Every axis any script creates cycles through line_style(0), line_style(1), ...
plt.rcParams["axes.prop_cycle"] = cycler(linestyle=LINE_STYLES) * cycler(color=COLOURS)
plt.rcParams["legend.fontsize"] = 8


def legend_right(ax, title=None, **kwargs):
    """The legend of ax to the right of it, outside the data; save() keeps it in the picture."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                  title=title, **kwargs)


def legend_keys(ax, entries, title, anchor_y=1.0):
    """A legend to the right of ax of proxy lines, entries = [(label, style dict)]: one key per
    series property (e.g. strategy by colour, mesh size by line style) instead of one per line.
    Returns it so that a second one can be stacked under it (anchor_y)."""
    handles = [Line2D([], [], **style) for _, style in entries]
    legend = ax.legend(handles, [label for label, _ in entries], title=title, loc="upper left",
                       bbox_to_anchor=(1.02, anchor_y), borderaxespad=0.0)
    ax.add_artist(legend)  # kept when ax.legend() is called again for the next key
    legend.set_clip_on(False)  # add_artist clips to the axes, and the key is outside them
    return legend


def legend_below(fig, ax, ncol=None, **kwargs):
    """One legend for the figure, from ax's lines, in columns under every axis (for many entries
    or wide figures, where a legend to the right would squeeze the plots)."""
    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return
    ncol = ncol or min(len(handles), 6)
    fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=ncol, **kwargs)


def save(fig, path, dpi=120):
    """Write and close the figure. tight_layout makes room for the suptitle (3.6 counts it) and
    keeps the axes from overlapping; bbox 'tight' widens the canvas to hold legends placed outside
    the axes, which tight_layout leaves out of its sums."""
    legends = [a for ax in fig.axes for a in ax.get_children() if isinstance(a, Legend)]
    for legend in legends:
        legend.set_in_layout(False)
    fig.tight_layout()
    for legend in legends:
        legend.set_in_layout(True)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    print("wrote", path)


def deck_path(deck):
    """The deck a summary.json names, or the same file in this checkout (results are copied between
    checkouts; the path written is the one of the run's machine)."""
    if deck and os.path.exists(deck):
        return deck
    if deck and "inputs" + os.sep in deck:
        local = os.path.join(ROOT, "inputs", deck.split("inputs" + os.sep, 1)[1])
        if os.path.exists(local):
            return local
    return None


def deck_scene(deck, longest=130):
    """The scene a deck describes: the first sentence of its opening XML comment (decks open with
    one), shortened at a word to fit a title line; '' if the deck has none or is not at hand."""
    path = deck_path(deck)
    if not path:
        return ""
    with open(path) as f:
        text = f.read(4000).lstrip()
    if not text.startswith("<!--"):
        return ""
    words = " ".join(text[4:].split("-->", 1)[0].split())
    # A sentence ends at a full stop before a capital: "Figs. 8" and "0.5" do not end one.
    sentence = re.split(r"\.\s+(?=[A-Z])", words, maxsplit=1)[0].rstrip(".")
    if len(sentence) > longest:
        sentence = sentence[:longest].rsplit(" ", 1)[0].rstrip(",;:") + " ..."
    return sentence


def run_title(directory):
    """'deck name: scene' of a run directory, from its summary.json; the directory's name if the
    run wrote none."""
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            deck = json.load(f).get("deck", "")
    except (OSError, ValueError):
        deck = ""
    if not deck:
        return os.path.basename(os.path.normpath(directory))
    name = os.path.splitext(os.path.basename(deck))[0]
    scene = deck_scene(deck)
    return f"{name}: {scene}" if scene else name


if __name__ == "__main__":
    import argparse

    # Not a script: --help says what the module is for (tests/integration/doc_scripts_help.py
    # runs every doc/*.py with --help).
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
