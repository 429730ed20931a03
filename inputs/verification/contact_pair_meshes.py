#!/usr/bin/env python3
"""Writes the meshes of the deformable-contact tests (doc/contact.md), Abaqus files beside it.

two_blocks.inp, the two-block contact patch test: two 1 x 1 x 0.75 mm blocks, one on the other,
not joined: the lower one (the master) on a uniform 4 x 4 grid, the upper one (the slave) on a
graded 4 x 4 grid whose lines fall between the lower one's (0.18, 0.43, 0.71 mm against 0.25,
0.5, 0.75 mm), so that no interior node of the interface meets another: a non-matching
interface. Each block has two layers of elements, 32 elements each, so that the coordinate
bisection of 2 ranks puts one block on each rank. Face sets: zmin (the lower block's bottom),
zmax (the upper one's top), xmin and ymin (both blocks' symmetry faces), master (the lower
block's top), slave (the upper block's bottom).

slit_block.inp, the self-contact test: a block 4 mm long (x), 1 mm wide (y, one element) and
2.25 mm high (z) with a slit 0.25 mm high cut from its end x = 4 mm back to x = 1 mm between
z = 1 and 1.25 mm: a lumen between a lower arm and an upper arm joined at x < 1 mm. Pressed on
its top, the upper arm bends down and closes the slit from its mouth. Face sets: zmin (the
bottom), ymin and ymax (the sides), press (the upper arm's top over the slit), lumen (the slit's
walls: the lower arm's top, the upper arm's bottom and the slit's end).

Abaqus C3D8 faces: S1 bottom (z-), S2 top (z+), S3 y-, S4 x+, S5 y+, S6 x-.
"""
import os

MM = 1e-3


def hexahedron(node, i, j, k):
    """The eight nodes of grid cell (i, j, k), Abaqus order (bottom counterclockwise, then top)."""
    return (node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
            node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1))


def write_abaqus(path, title, nodes, elements, faces):
    with open(path, "w") as f:
        f.write("** %s (contact_pair_meshes.py writes it; doc/contact.md)\n" % title)
        f.write("*NODE\n")
        for i, (x, y, z) in enumerate(nodes, 1):
            f.write("%d, %.17g, %.17g, %.17g\n" % (i, x, y, z))
        f.write("*ELEMENT, TYPE=C3D8, ELSET=body\n")
        for i, e in enumerate(elements, 1):
            f.write("%d, %s\n" % (i, ", ".join(str(n) for n in e)))
        for name, entries in faces.items():
            f.write("*SURFACE, TYPE=ELEMENT, NAME=%s\n" % name)
            for e, s in entries:
                f.write("%d, %s\n" % (e, s))


MASTER = [0.0, 0.25, 0.5, 0.75, 1.0]
SLAVE = [0.0, 0.18, 0.43, 0.71, 1.0]
HEIGHT = 0.75
LAYERS = 2


def block(grid, z0, bottom, top, nodes, elements, faces):
    """Adds a block on `grid` (both in-plane directions) from z0 up HEIGHT, its bottom and top
    faces in the face sets named `bottom` and `top`."""
    first = len(nodes) + 1
    n = len(grid)
    for k in range(LAYERS + 1):
        for y in grid:
            for x in grid:
                nodes.append((x * MM, y * MM, (z0 + HEIGHT * k / LAYERS) * MM))

    def node(i, j, k):
        return first + i + n * (j + n * k)

    for k in range(LAYERS):
        for j in range(n - 1):
            for i in range(n - 1):
                elements.append(hexahedron(node, i, j, k))
                e = len(elements)
                for name, s, on in ((bottom, "S1", k == 0), (top, "S2", k == LAYERS - 1),
                                    ("ymin", "S3", j == 0), ("xmin", "S6", i == 0)):
                    if on:
                        faces.setdefault(name, []).append((e, s))


def two_blocks(path):
    nodes, elements, faces = [], [], {}
    block(MASTER, 0.0, "zmin", "master", nodes, elements, faces)
    block(SLAVE, HEIGHT, "slave", "zmax", nodes, elements, faces)
    write_abaqus(path, "The two-block contact patch test", nodes, elements, faces)


XS = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
YS = [0.0, 1.0]
ZS = [0.0, 0.5, 1.0, 1.25, 1.75, 2.25]
SLIT_X, SLIT_Z = 1.0, (1.0, 1.25)


def slit_block(path):
    nx, ny = len(XS), len(YS)

    def node(i, j, k):
        return 1 + i + nx * (j + ny * k)

    nodes = [(x * MM, y * MM, z * MM) for z in ZS for y in YS for x in XS]
    elements, faces = [], {}
    for k in range(len(ZS) - 1):
        for i in range(nx - 1):
            beyond = XS[i] >= SLIT_X
            if beyond and ZS[k] == SLIT_Z[0]:
                continue  # the slit
            elements.append(hexahedron(node, i, 0, k))
            e = len(elements)
            for name, s, on in (("ymin", "S3", True), ("ymax", "S5", True), ("zmin", "S1", k == 0),
                                ("press", "S2", k == len(ZS) - 2 and beyond),
                                ("lumen", "S2", beyond and ZS[k + 1] == SLIT_Z[0]),
                                ("lumen", "S1", beyond and ZS[k] == SLIT_Z[1]),
                                ("lumen", "S4", XS[i + 1] == SLIT_X and ZS[k] == SLIT_Z[0])):
                if on:
                    faces.setdefault(name, []).append((e, s))
    write_abaqus(path, "The self-contact test's slit block", nodes, elements, faces)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    two_blocks(os.path.join(here, "two_blocks.inp"))
    slit_block(os.path.join(here, "slit_block.inp"))
