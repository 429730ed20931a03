#!/usr/bin/python3
"""How much a deformable die would change the ironing forces (doc/contact.md, "The ironing problem").

The published die is not rigid: a half-cylindrical shell of outer radius 3 and thickness 0.2,
E = 1000, held at its two straight edges (at the height of its axis) and pressed by them. Glossa's
die is rigid. This estimate treats the shell, per unit of its length, as a thin circular arch
(radius R = 2.9, the mid-surface; bending stiffness EI = E t^3 / 12 per unit length) clamped at both
ends, loaded from below near its crown by the slab, and finds by Castigliano's theorem (bending
energy only, with the crown's moment and horizontal force as the redundants) how far the crown
rises under a unit load:

    delta = c P R^3 / EI,   P the load per unit length (the normal force over the slab's width 4),

for a point load at the crown and for a radial pressure that is elliptical in x over the contact
half-width a the rigid run measures (contact area / (2 x 4)). The die and the slab then act as
springs in series: the die's edges go down 1.4, the crown stays delta behind, and the slab is
pressed d = 1.4 - delta. With the rigid run's press curve N(d) (bench/results/ironing.csv, the
frictionless press, d = 1.4 t), the deformable die's press ends where N(d) = (1.4 - d) 4 EI / (c R^3).

  /usr/bin/python3 bench/ironing_die_flexibility.py [--mesh fine]

Prints c for both load cases (and, as a check, the point load's c from beam elements that also
stretch) and the press depth and normal force the deformable die would reach
against the rigid die's.
"""
import argparse
import csv
import os

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
E_DIE, THICKNESS, R_OUTER, WIDTH, PRESS = 1000.0, 0.2, 3.0, 4.0, 1.4


def crown_deflection(loads, n=4001):
    """c of delta = c P R^3 / EI for R = EI = 1: loads are (psi, fx, fy) on one half of the arch
    (psi the angle from the crown), summing to an upward 1/2; the other half is its mirror image."""
    phi = np.linspace(0.0, np.pi / 2, n)
    x, y = np.sin(phi), -np.cos(phi)
    moment = np.zeros_like(phi)
    for psi, fx, fy in loads:  # moment at the section of the loads between the crown and it
        on = phi >= psi
        moment[on] += fx * (y[on] + np.cos(psi)) - fy * (x[on] - np.sin(psi))
    unit_m0, unit_h = np.ones_like(phi), y + 1.0  # the redundants: the crown's moment and horizontal force
    a = [[np.trapz(u * v, phi) for v in (unit_m0, unit_h)] for u in (unit_m0, unit_h)]
    m0, h = np.linalg.solve(a, [-np.trapz(moment * unit_m0, phi), -np.trapz(moment * unit_h, phi)])
    total = moment + m0 * unit_m0 + h * unit_h
    return np.trapz(total * (-x), phi)  # the virtual unit load at the crown: half on each side


def frame_crown_deflection(radius, ei, ea, n=400):
    """The same arch's c for a point load at the crown from straight Euler-Bernoulli beam elements
    that also stretch (EA): a check of the bending-only value that owes nothing to Castigliano."""
    phi = np.linspace(-np.pi / 2, np.pi / 2, n + 1)
    x, y = radius * np.sin(phi), -radius * np.cos(phi)
    k = np.zeros((3 * (n + 1), 3 * (n + 1)))
    for e in range(n):
        dx, dy = x[e + 1] - x[e], y[e + 1] - y[e]
        length = np.hypot(dx, dy)
        c, s = dx / length, dy / length
        local = np.zeros((6, 6))
        local[np.ix_([0, 3], [0, 3])] = ea / length * np.array([[1, -1], [-1, 1]])
        bend = [[12, 6 * length, -12, 6 * length], [6 * length, 4 * length ** 2, -6 * length, 2 * length ** 2],
                [-12, -6 * length, 12, -6 * length], [6 * length, 2 * length ** 2, -6 * length, 4 * length ** 2]]
        local[np.ix_([1, 2, 4, 5], [1, 2, 4, 5])] = ei / length ** 3 * np.array(bend)
        rotation = np.kron(np.eye(2), np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]]))
        dofs = list(range(3 * e, 3 * e + 6))
        k[np.ix_(dofs, dofs)] += rotation.T @ local @ rotation
    free = np.arange(3, 3 * n)  # both ends clamped
    load = np.zeros(3 * (n + 1))
    load[3 * (n // 2) + 1] = 1.0
    u = np.linalg.solve(k[np.ix_(free, free)], load[free])
    return u[3 * (n // 2) + 1 - 3] * ei / radius ** 3


def elliptical(half_width, n=400):
    """A radial pressure elliptical in x over |x| < half_width (in units of R), total upward 1."""
    psi = np.linspace(0.0, np.arcsin(min(half_width, 1.0)), n)[1:]
    radial = np.sqrt(np.maximum(0.0, 1.0 - (np.sin(psi) / half_width) ** 2)) * (psi[1] - psi[0])
    fx, fy = -radial * np.sin(psi), radial * np.cos(psi)
    scale = 2.0 * fy.sum()
    return list(zip(psi, fx / scale, fy / scale))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--mesh", default="fine")
    a = p.parse_args()
    with open(os.path.join(ROOT, "bench", "results", "ironing.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["mesh"] == a.mesh and float(r["mu"]) == 0.0]
    press = [(PRESS * float(r["time"]), float(r["N"]), float(r["area"])) for r in rows if float(r["time"]) <= 1.0 + 1e-9]
    radius = R_OUTER - THICKNESS / 2
    ei = E_DIE * THICKNESS ** 3 / 12.0
    n_rigid, area = press[-1][1], press[-1][2]
    cases = {"point load at the crown": crown_deflection([(0.0, 0.0, 0.5)]),
             f"elliptical over a = {area / (2 * WIDTH):.2f}": crown_deflection(elliptical(area / (2 * WIDTH) / radius))}
    print(f"check: point load from beam elements with axial strain, c = "
          f"{frame_crown_deflection(radius, ei, E_DIE * THICKNESS):.5f}")
    print(f"rigid die, {a.mesh} mesh: pressed {PRESS}, N = {n_rigid:.3f}, contact half-width {area / (2 * WIDTH):.2f}")
    for name, c in cases.items():
        stiffness = WIDTH * ei / (c * radius ** 3)  # die force per unit crown deflection
        depth, force = PRESS, n_rigid
        for (d0, n0, _), (d1, n1, _) in zip(press, press[1:]):
            # N(d) rises, the die's force (1.4 - d) k falls: they cross once
            g0, g1 = n0 - stiffness * (PRESS - d0), n1 - stiffness * (PRESS - d1)
            if g0 <= 0.0 <= g1:
                depth = d0 + (d1 - d0) * (-g0) / (g1 - g0)
                force = n0 + (n1 - n0) * (depth - d0) / (d1 - d0)
        print(f"{name}: c = {c:.5f}, die stiffness {stiffness:.1f}; under the rigid die's N the crown would rise "
              f"{n_rigid / stiffness:.2f}; in series: pressed {depth:.2f}, N = {force:.2f} "
              f"({100 * (force / n_rigid - 1):+.0f} %)")


if __name__ == "__main__":
    main()
