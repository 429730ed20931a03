#!/usr/bin/env python3
"""Writes two_blocks.inp (Abaqus), the two-block contact patch test's mesh (doc/contact.md).

Two 1 x 1 x 0.75 mm blocks, one on the other, not joined: the lower one (the master) on a
uniform 4 x 4 grid, the upper one (the slave) on a graded 4 x 4 grid whose lines fall between
the lower one's (0.18, 0.43, 0.71 mm against 0.25, 0.5, 0.75 mm), so that no interior node of the
interface meets another: a non-matching interface. Each block has two layers of elements, 32
elements each, so that the coordinate bisection of 2 ranks puts one block on each rank.

Face sets: zmin (the lower block's bottom), zmax (the upper one's top), xmin and ymin (both
blocks' symmetry faces), master (the lower block's top), slave (the upper block's bottom).
"""
import sys

MM = 1e-3
MASTER = [0.0, 0.25, 0.5, 0.75, 1.0]
SLAVE = [0.0, 0.18, 0.43, 0.71, 1.0]
HEIGHT = 0.75
LAYERS = 2


def block(grid, z0, nodes, elements, faces):
    """Adds a block on `grid` (both in-plane directions) from z0 up HEIGHT; returns its element ids."""
    first = len(nodes) + 1
    n = len(grid)
    zs = [z0 + HEIGHT * k / LAYERS for k in range(LAYERS + 1)]
    for z in zs:
        for y in grid:
            for x in grid:
                nodes.append((x * MM, y * MM, z * MM))

    def node(i, j, k):
        return first + i + n * (j + n * k)

    ids = []
    for k in range(LAYERS):
        for j in range(n - 1):
            for i in range(n - 1):
                e = len(elements) + 1
                elements.append((node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                                 node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                                 node(i, j + 1, k + 1)))
                ids.append(e)
                # Abaqus C3D8 faces: S1 bottom, S2 top, S3 y-, S6 x-.
                if k == 0:
                    faces.setdefault("bottom%d" % first, []).append((e, "S1"))
                if k == LAYERS - 1:
                    faces.setdefault("top%d" % first, []).append((e, "S2"))
                if j == 0:
                    faces.setdefault("ymin", []).append((e, "S3"))
                if i == 0:
                    faces.setdefault("xmin", []).append((e, "S6"))
    return first


def main(path):
    nodes, elements, faces = [], [], {}
    lower = block(MASTER, 0.0, nodes, elements, faces)
    upper = block(SLAVE, HEIGHT, nodes, elements, faces)
    named = {"zmin": faces["bottom%d" % lower], "master": faces["top%d" % lower],
             "slave": faces["bottom%d" % upper], "zmax": faces["top%d" % upper],
             "xmin": faces["xmin"], "ymin": faces["ymin"]}
    with open(path, "w") as f:
        f.write("** The two-block contact patch test (two_blocks_mesh.py writes it; doc/contact.md)\n")
        f.write("*NODE\n")
        for i, (x, y, z) in enumerate(nodes, 1):
            f.write("%d, %.17g, %.17g, %.17g\n" % (i, x, y, z))
        f.write("*ELEMENT, TYPE=C3D8, ELSET=body\n")
        for i, e in enumerate(elements, 1):
            f.write("%d, %s\n" % (i, ", ".join(str(n) for n in e)))
        for name, entries in named.items():
            f.write("*SURFACE, TYPE=ELEMENT, NAME=%s\n" % name)
            for e, s in entries:
                f.write("%d, %s\n" % (e, s))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "two_blocks.inp")
