#!/usr/bin/python3
"""Mends the tongue mesh's most distorted elements by moving interior nodes only.

Writes tongue_mended_nodes.txt beside this script: 'id x y z' [m] for every node it moved, read by
a deck's Mesh/File/moved nodes (doc/meshes.md, "Moved nodes"). The surface, the sets and the
element connectivity stay as published (tongue.node, tongue.elem); only interior nodes move.

An element's quality is its smallest scaled corner Jacobian, the triple product of the three edges
at a corner over their lengths (1 for a cube, 0 for a corner collapsed flat). Each sweep takes
every interior node of an element below --threshold and moves it by compass search (steps of
0.2 mm halved down to 1 um along the axes) to raise the worst quality among its elements, until a
sweep moves no node. Deterministic: the same files give the same moves.

    /usr/bin/python3 inputs/tongue/mend_tongue.py [--threshold 0.1]
"""
import argparse
import collections
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
# Each corner and its three neighbours along the hexahedron's edges, right-handed.
CORNERS = {0: (1, 3, 4), 1: (2, 0, 5), 2: (3, 1, 6), 3: (0, 2, 7),
           4: (7, 5, 0), 5: (4, 6, 1), 6: (5, 7, 2), 7: (6, 4, 3)}


def read_mesh():
    nodes, order = {}, []
    with open(os.path.join(HERE, "tongue.node")) as f:
        for line in f:
            fields = line.split()
            nodes[int(fields[0])] = np.array([float(v) for v in fields[1:4]])
            order.append(int(fields[0]))
    elements = {}
    with open(os.path.join(HERE, "tongue.elem")) as f:
        for line in f:
            fields = [int(v) for v in line.split()]
            elements[fields[13]] = fields[:8]
    return nodes, order, elements


def boundary_nodes(elements):
    count = collections.Counter(tuple(sorted(e[i] for i in face)) for e in elements.values() for face in FACES)
    return {n for face, k in count.items() if k == 1 for n in face}


def quality(nodes, element):
    p = [nodes[i] for i in element]
    worst = np.inf
    for c, (a, b, d) in CORNERS.items():
        e1, e2, e3 = p[a] - p[c], p[b] - p[c], p[d] - p[c]
        worst = min(worst, np.dot(np.cross(e1, e2), e3) / (np.linalg.norm(e1) * np.linalg.norm(e2) * np.linalg.norm(e3)))
    return worst


def mend(nodes, elements, threshold):
    fixed = boundary_nodes(elements)
    around = collections.defaultdict(list)
    for e, element in elements.items():
        for i in element:
            around[i].append(e)
    moved = set()
    for sweep in range(30):
        bad = [e for e in sorted(elements) if quality(nodes, elements[e]) < threshold]
        candidates = sorted({i for e in bad for i in elements[e] if i not in fixed})
        changed = 0
        for i in candidates:
            local = lambda: min(quality(nodes, elements[e]) for e in around[i])
            start = best = local()
            x, h = nodes[i].copy(), 2e-4
            while h >= 1e-6:
                step = None
                for d in np.vstack([np.eye(3), -np.eye(3)]):
                    nodes[i] = x + h * d
                    q = local()
                    if q > best + 1e-9:
                        best, step = q, nodes[i].copy()
                nodes[i] = x
                if step is None:
                    h *= 0.5
                else:
                    x = step
                    nodes[i] = x
            if best > start + 1e-9:
                changed += 1
                moved.add(i)
        worst = min(quality(nodes, element) for element in elements.values())
        below = sum(1 for element in elements.values() if quality(nodes, element) < threshold)
        print(f"sweep {sweep}: {changed} nodes moved, worst element {worst:.4f}, {below} below {threshold}")
        if changed == 0:
            break
    return moved


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threshold", type=float, default=0.1, help="the smallest scaled corner Jacobian sought")
    parser.add_argument("--output", default=os.path.join(HERE, "tongue_mended_nodes.txt"))
    args = parser.parse_args()
    nodes, order, elements = read_mesh()
    original = {i: x.copy() for i, x in nodes.items()}
    before = min(quality(nodes, element) for element in elements.values())
    moved = mend(nodes, elements, args.threshold)
    largest = max(np.linalg.norm(nodes[i] - original[i]) for i in moved)
    with open(args.output, "w") as f:
        f.write(f"# tongue.node's interior nodes moved by mend_tongue.py --threshold {args.threshold:g}: "
                f"{len(moved)} nodes, by up to {1e3 * largest:.2f} mm; 'id x y z' [m]\n")
        for i in order:
            if i in moved:
                f.write("%d %.9g %.9g %.9g\n" % (i, *nodes[i]))
    print(f"{len(moved)} nodes moved (largest move {1e3 * largest:.2f} mm); worst element {before:.4f} -> "
          f"{min(quality(nodes, element) for element in elements.values()):.4f}; wrote {args.output}")


if __name__ == "__main__":
    main()
