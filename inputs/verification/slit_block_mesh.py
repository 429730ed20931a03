#!/usr/bin/env python3
"""Writes slit_block.inp (Abaqus), the self-contact test's mesh (doc/contact.md).

A block 4 mm long (x), 1 mm wide (y, one element) and 2.25 mm high (z) with a slit 0.25 mm high
cut from its end x = 4 mm back to x = 1 mm between z = 1 and 1.25 mm: a lumen between a lower
arm and an upper arm joined at x < 1 mm. Pressed on its top, the upper arm bends down and closes
the slit from its mouth.

Face sets: zmin (the bottom), ymin and ymax (the sides), press (the upper arm's top over the
slit), lumen (the slit's walls: the lower arm's top, the upper arm's bottom and the slit's end).
"""
import sys

MM = 1e-3
XS = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
YS = [0.0, 1.0]
ZS = [0.0, 0.5, 1.0, 1.25, 1.75, 2.25]
SLIT_X, SLIT_Z = 1.0, (1.0, 1.25)


def main(path):
    nx, ny = len(XS), len(YS)

    def node(i, j, k):
        return 1 + i + nx * (j + ny * k)

    nodes = [(x * MM, y * MM, z * MM) for z in ZS for y in YS for x in XS]
    elements, faces = [], {}
    for k in range(len(ZS) - 1):
        for i in range(nx - 1):
            in_slit = XS[i] >= SLIT_X and ZS[k] == SLIT_Z[0]
            if in_slit:
                continue
            j = 0
            e = len(elements) + 1
            elements.append((node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                             node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                             node(i, j + 1, k + 1)))
            # Abaqus C3D8 faces: S1 bottom (z-), S2 top (z+), S3 y-, S4 x+, S5 y+.
            faces.setdefault("ymin", []).append((e, "S3"))
            faces.setdefault("ymax", []).append((e, "S5"))
            if k == 0:
                faces.setdefault("zmin", []).append((e, "S1"))
            if k == len(ZS) - 2 and XS[i] >= SLIT_X:
                faces.setdefault("press", []).append((e, "S2"))
            if XS[i] >= SLIT_X and ZS[k + 1] == SLIT_Z[0]:
                faces.setdefault("lumen", []).append((e, "S2"))
            if XS[i] >= SLIT_X and ZS[k] == SLIT_Z[1]:
                faces.setdefault("lumen", []).append((e, "S1"))
            if XS[i + 1] == SLIT_X and ZS[k] == SLIT_Z[0]:
                faces.setdefault("lumen", []).append((e, "S4"))
    with open(path, "w") as f:
        f.write("** The self-contact test's slit block (slit_block_mesh.py writes it; doc/contact.md)\n")
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


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "slit_block.inp")
