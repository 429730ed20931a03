#!/usr/bin/python3
"""The incompressibility matrix (doc/incompressibility.md): nu x n x strategy on the step-44 block
and on Cook's membrane, augmented Lagrangian with the material's physical kappa (nu = 0.5: exact).

  /usr/bin/python3 bench/incompressibility.py [--sizes 8,16] [--nus 0.3,...,0.5]
        [--strategies cheb3,sgs2,...] [--scenes block,cook] [--timeout 900] [--glossa PATH]

Per run: Newton, Krylov (total and max per linear solve) and Uzawa iterations, preconditioner
set-up and Krylov time, wall time, peak memory, dilatation error (distance from the physical law)
and max |theta - 1|, and the answer (top-centre uy of the block, tip uy of Cook's membrane) with
its relative difference from the first strategy's answer for the same scene, nu and n (and, for
the block at nu = 0.4999, from deal.II step-44). Writes bench/results/incompressibility_<scene>.csv
and .png (Krylov iterations per solve against nu, one line per strategy and n). Appends as it
goes, so an interrupted run keeps what it measured. Iteration counts are the primary figures;
times on the shared 2-core machines are noisy.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

from glossa_command import glossa_run_command

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results")
SCENES = {
    "block": (os.path.join(ROOT, "inputs", "verification", "step44_block.xml"), "top_centre",
              lambda n: [f"Mesh/Box/cells={n},{n},{n}", "Linear solver/type=iterative"]),
    "cook": (os.path.join(ROOT, "inputs", "verification", "cook_membrane.xml"), "tip",
             # 1 cell through the thickness leaves fewer rows than MueLu's default coarse size:
             # a coarse size of 100 makes the smoother matter.
             # type = iterative: the matrix compares iterative strategies (auto would solve small
             # meshes directly).
             lambda n: [f"Mesh/Cook membrane/cells per side={n}", "Linear solver/type=iterative",
                        "Linear solver/coarse size=100"]),
}
# Chebyshev degree 6 with eigenvalue ratio 100 (the default smoother), and with the inexact first
# Uzawa solve (the default loop): the strategies below vary one setting from these.
CHEB6R100 = ["Linear solver/MueLu smoother=Chebyshev", "Linear solver/smoother degree=6",
             "Linear solver/Chebyshev eigenvalue ratio=100"]
CHEB6R100_INEXACT = CHEB6R100 + ["Incompressibility/Uzawa acceleration=inexact"]
STRATEGIES = {
    "cheb3": ["Linear solver/MueLu smoother=Chebyshev", "Linear solver/smoother degree=3"],
    "cheb6r100": CHEB6R100,
    "sgs2": ["Linear solver/MueLu smoother=symmetric Gauss-Seidel", "Linear solver/smoother degree=2"],
    "nbgs2": ["Linear solver/MueLu smoother=node-block Gauss-Seidel", "Linear solver/smoother degree=2"],
    "patch": ["Linear solver/MueLu smoother=vertex-patch"],
    "patch-inexact": ["Linear solver/MueLu smoother=vertex-patch", "Incompressibility/Uzawa acceleration=inexact"],
    "frosch": ["Linear solver/preconditioner=FROSch", "Incompressibility/Uzawa acceleration=inexact"],
    "cheb3-run": ["Linear solver/MueLu smoother=Chebyshev", "Linear solver/MueLu reuse scope=run"],
    # The plain nested Uzawa loop against the inexact first solve (the default).
    "cheb3-plain": ["Linear solver/MueLu smoother=Chebyshev", "Incompressibility/Uzawa acceleration=none"],
    "cheb3-inexact": ["Linear solver/MueLu smoother=Chebyshev", "Incompressibility/Uzawa acceleration=inexact"],
    "cheb6r100-inexact": CHEB6R100_INEXACT,
    # The default with kappa_AL = 30 mu instead of 100 mu (the whole run's Krylov total within 3x of
    # nu = 0.3's), and smaller ones for counts independent of nu and n: smaller kappa_AL bound the
    # tangent's volumetric modulus, kappa_t <= kappa_AL, so the linear solves stay alike from
    # nu = 0.3 up; the Uzawa loop does the rest.
    **{f"cheb6r100-inexact-kal{r}": CHEB6R100_INEXACT + [f"Incompressibility/penalty ratio={r}"]
       for r in (30, 10, 3)},
    # The same with every Krylov solve to the Linear solver tolerance (no Eisenstat-Walker forcing):
    # the largest count per solve then measures the preconditioner alone, not how little the
    # forcing asks of the easiest solves.
    **{f"cheb6r100-inexact-kal{r}-constant": CHEB6R100_INEXACT + [f"Incompressibility/penalty ratio={r}",
                                                                  "Nonlinear solver/forcing term=constant"]
       for r in (30, 3)},
    # Incompressibility/method = mixed: element pressures as unknowns, GMRES on the block system with
    # Teko's block upper-triangular preconditioner (the default MueLu on K, C + M_p/mu on the Schur
    # complement); no Uzawa loop at any nu, nu = 0.5 exactly.
    "mixed": ["Incompressibility/method=mixed"],
    "sgs2-inexact": ["Linear solver/MueLu smoother=symmetric Gauss-Seidel", "Linear solver/smoother degree=2",
                     "Incompressibility/Uzawa acceleration=inexact"],
}


def dealii_reference():
    """deal.II step-44 (nu = 0.4999), uy of the top centre at t = 1 [m] by elements per side."""
    ref = {}
    with open(os.path.join(ROOT, "tests", "regression", "step44_dealii_reference.csv")) as f:
        for r in csv.DictReader(f):
            if abs(float(r["time"]) - 1.0) < 1e-12:
                ref[int(r["elements_per_side"])] = float(r["uy_top_centre_m"])
    return ref


DEALII = dealii_reference()
FIELDS = ["scene", "n", "nu", "strategy", "ranks", "converged", "dofs", "newton", "krylov", "krylov_max_per_solve",
          "uzawa", "max_dilatation_error", "max_volume_change", "answer_mm", "rel_diff_first_strategy",
          "rel_diff_dealii", "prec_setup_s", "krylov_s", "wall_s", "peak_mb", "note"]


def run(glossa, deck, overrides, timeout, ranks):
    out = tempfile.mkdtemp(prefix="glossa-incomp-")
    cmd = glossa_run_command(glossa, deck, out, overrides, ranks)
    t0 = time.time()
    note = ""
    try:
        subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout)
    except subprocess.TimeoutExpired:
        note = f"timeout {timeout} s"
    try:
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
    except (OSError, ValueError):
        s = {"converged": False, "steps": []}
    return s, note or s.get("failure", ""), time.time() - t0


def row_of(scene, n, nu, strategy, ranks, s, note, wall, point):
    steps = s.get("steps", [])
    krylov_max = 0
    for st in steps:
        for solve in st.get("newton_solves", []):
            krylov_max = max([krylov_max] + solve.get("krylov", []))
    disp = s.get("final_displacement", {}).get(point)
    return {
        "scene": scene, "n": n, "nu": nu, "strategy": strategy, "ranks": ranks,
        "converged": s.get("converged", False), "dofs": s.get("dofs", ""),
        "newton": sum(x["newton_iterations"] for x in steps),
        "krylov": sum(x["linear_iterations"] for x in steps),
        "krylov_max_per_solve": krylov_max,
        "uzawa": sum(x["uzawa_iterations"] for x in steps),
        "max_dilatation_error": max((x["max_dilatation_error"] for x in steps), default=float("nan")),
        "max_volume_change": max((x.get("max_volume_change", float("nan")) for x in steps), default=float("nan")),
        "answer_mm": disp[1] * 1e3 if disp and s.get("converged") else float("nan"),
        "rel_diff_first_strategy": "", "rel_diff_dealii": "",
        "prec_setup_s": round(s.get("preconditioner_setup_seconds", float("nan")), 3),
        "krylov_s": round(s.get("linear_solve_seconds", float("nan")), 3),
        "wall_s": round(s.get("wall_seconds", wall), 3),
        "peak_mb": round(s.get("peak_memory_mb_per_rank", float("nan")), 1),
        "note": note.replace(",", ";")[:120],
    }


def plot(scene, rows):
    try:
        sys.path.insert(0, os.path.join(ROOT, "doc"))
        import plot_style
    except ImportError:
        print("matplotlib missing (use /usr/bin/python3): no plot")
        return
    plt = plot_style.plt
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    keys = sorted({(r["strategy"], r["n"], str(r.get("ranks") or "1")) for r in rows},
                  key=lambda k: (list(STRATEGIES).index(k[0]), k[1], k[2]))
    series = sorted({(k[0], k[2]) for k in keys}, key=lambda k: (list(STRATEGIES).index(k[0]), k[1]))
    sizes = sorted({k[1] for k in keys})
    # Strategy (and rank count): colour and marker; n: line style. Two keys of 15 + 3 entries
    # beside the axes, where one entry per line (28) covered the data.
    strategy_style = {k: plot_style.marker_style(i) for i, k in enumerate(series)}
    size_style = {n: plot_style.LINE_STYLES[i % len(plot_style.LINE_STYLES)] for i, n in enumerate(sizes)}
    drawn_series, drawn_sizes = [], []
    for strategy, n, ranks in keys:
        pts = [(float(r["nu"]), r["krylov_max_per_solve"]) for r in rows
               if r["strategy"] == strategy and r["n"] == n and str(r.get("ranks") or "1") == ranks and r["converged"]]
        if not pts:
            continue
        pts.sort()
        # x: -log10(0.5 - nu), nu = 0.5 drawn one decade past 0.49999.
        xs = [6.0 if nu >= 0.5 else -math.log10(0.5 - nu) for nu, _ in pts]
        ax.plot(xs, [k for _, k in pts], linestyle=size_style[n], markersize=4, **strategy_style[(strategy, ranks)])
        drawn_series += [(strategy, ranks)] if (strategy, ranks) not in drawn_series else []
        drawn_sizes += [n] if n not in drawn_sizes else []
    ax.set_xticks([-math.log10(0.2), 2, 3, 4, 5, 6])
    ax.set_xticklabels(["0.3", "0.49", "0.499", "0.4999", "0.49999", "0.5"])
    ax.set_xlabel("Poisson's ratio")
    ax.set_ylabel("max Krylov iterations per linear solve")
    ax.set_yscale("log")
    ax.set_title(f"{scene}: augmented Lagrangian (kappa_AL = 100 mu; -kal30: 30 mu) and mixed", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    strategies = plot_style.legend_keys(
        ax, [(s + (f", {r} ranks" if r != "1" else ""), dict(strategy_style[(s, r)], linestyle="-"))
             for s, r in series if (s, r) in drawn_series], "strategy")
    fig.canvas.draw()  # the strategies' key must have its size before the next is put under it
    box = strategies.get_window_extent().transformed(ax.transAxes.inverted())
    plot_style.legend_keys(ax, [(f"n = {n}", {"color": "0.3", "linestyle": size_style[n]})
                                for n in sizes if n in drawn_sizes], "cells per side", box.y0 - 0.03)
    plot_style.save(fig, os.path.join(RESULTS, f"incompressibility_{scene}.png"))


def tables(scene):
    """Markdown tables of the scene's CSV: one per figure, strategies x nu, cells 'n=8 / n=16 ...'."""
    path = os.path.join(RESULTS, f"incompressibility_{scene}.csv")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    nus = sorted({r["nu"] for r in rows}, key=float)
    sizes = sorted({int(r["n"]) for r in rows})
    keys = []
    for r in rows:
        k = (r["strategy"], r.get("ranks") or "1")
        if k not in keys:
            keys.append(k)
    out = []
    for field, title in [("krylov_max_per_solve", "max Krylov iterations per linear solve"),
                         ("krylov", "total Krylov iterations"), ("newton", "total Newton iterations"),
                         ("uzawa", "Uzawa solves"), ("wall_s", "wall time [s]")]:
        out.append(f"\n{scene}: {title} (n = {' / '.join(map(str, sizes))}; '-' not run, 'x' failed)\n")
        out.append("| strategy | ranks | " + " | ".join(nus) + " |")
        out.append("|---|---|" + "---|" * len(nus))
        for strategy, ranks in keys:
            cells = []
            for nu in nus:
                vals = []
                for n in sizes:
                    m = [r for r in rows if r["strategy"] == strategy and (r.get("ranks") or "1") == ranks
                         and r["nu"] == nu and int(r["n"]) == n]
                    if not m:
                        vals.append("-")
                    elif m[-1]["converged"] != "True":
                        vals.append("x")
                    else:
                        v = m[-1][field]
                        vals.append(f"{float(v):.3g}" if field == "wall_s" else v)
                cells.append(" / ".join(vals))
            out.append(f"| {strategy} | {ranks} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--glossa", default=os.path.join(ROOT, "build", "glossa"), help="the solver (default: build/glossa)")
    ap.add_argument("--sizes", default="8,16", help="cells per side, comma-separated (default: 8,16)")
    ap.add_argument("--nus", default="0.3,0.49,0.499,0.4999,0.49999,0.5", help="Poisson's ratios, comma-separated")
    ap.add_argument("--strategies", default=",".join(STRATEGIES),
                    help="comma-separated, of: " + ", ".join(STRATEGIES) + " (default: all)")
    ap.add_argument("--scenes", default="block,cook", help="block (step-44) and/or cook (default: both)")
    ap.add_argument("--timeout", type=float, default=900.0, help="seconds per run before it is stopped (default: 900)")
    ap.add_argument("--ranks", type=int, default=1, help="MPI ranks per run (default: 1)")
    ap.add_argument("--append", action="store_true", help="add to the existing CSVs")
    ap.add_argument("--plot-only", action="store_true",
                    help="run nothing: redraw incompressibility_<scene>.png from the existing CSV")
    ap.add_argument("--tables", action="store_true", help="print markdown tables of the CSVs and stop")
    a = ap.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    if a.tables:
        for scene in a.scenes.split(","):
            print(tables(scene))
        return
    for scene in a.scenes.split(","):
        deck, point, mesh = SCENES[scene]
        path = os.path.join(RESULTS, f"incompressibility_{scene}.csv")
        rows = []
        if (a.append or a.plot_only) and os.path.exists(path):
            with open(path) as f:
                for r in csv.DictReader(f):
                    r["n"] = int(r["n"])
                    r["krylov_max_per_solve"] = int(r["krylov_max_per_solve"])
                    r["converged"] = r["converged"] == "True"
                    r.setdefault("ranks", "1")
                    rows.append(r)
        if not a.plot_only:
            if not a.append:
                with open(path, "w", newline="") as f:
                    csv.DictWriter(f, FIELDS).writeheader()
            for n in [int(x) for x in a.sizes.split(",")]:
                for nu in a.nus.split(","):
                    first = None
                    for strategy in a.strategies.split(","):
                        o = mesh(n) + [f"Material/Poisson's ratio={nu}", "Incompressibility/method=augmented Lagrangian",
                                       "Output/fields=false"] + STRATEGIES[strategy]
                        s, note, wall = run(a.glossa, deck, o, a.timeout, a.ranks)
                        r = row_of(scene, n, nu, strategy, a.ranks, s, note, wall, point)
                        ans = r["answer_mm"]
                        if first is None and not math.isnan(ans):
                            first = ans
                        if first is not None and not math.isnan(ans):
                            r["rel_diff_first_strategy"] = f"{abs(ans - first) / abs(first):.1e}"
                        if scene == "block" and nu == "0.4999" and n in DEALII and not math.isnan(ans):
                            r["rel_diff_dealii"] = f"{abs(ans * 1e-3 - DEALII[n]) / abs(DEALII[n]):.1e}"
                        rows.append(r)
                        with open(path, "a", newline="") as f:
                            csv.DictWriter(f, FIELDS).writerow(r)
                        print(f"{scene} n={n} nu={nu} {strategy}: conv={r['converged']} newton={r['newton']} "
                              f"krylov={r['krylov']} max/solve={r['krylov_max_per_solve']} uzawa={r['uzawa']} "
                              f"dil={r['max_dilatation_error']:.1e} ans={ans:.6f} wall={r['wall_s']} {r['note']}",
                              flush=True)
        plot(scene, rows)


if __name__ == "__main__":
    main()
