#!/usr/bin/env python3
"""Writes a closed box as an ASCII STL (normals outwards), for mesh walls in cases.

Usage: python3 scripts/box_stl.py XMIN YMIN ZMIN XMAX YMAX ZMAX OUT.stl [CELL]

Without CELL each face is two triangles (12 facets). With CELL [m] each face is split into a grid of
rectangles about CELL across, two triangles each: a wear map (wear per triangle) then shows where on a
face the grains hit (the sloshing tank's right wall).
"""
import math
import sys


def box_facets(lo, hi, cell=None):
    def p(i, j, k):
        return (hi[0] if i else lo[0], hi[1] if j else lo[1], hi[2] if k else lo[2])

    quads = [  # counter-clockwise seen from outside
        (p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)),  # bottom
        (p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)),  # top
        (p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)),  # front (y = min)
        (p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)),  # back
        (p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)),  # left (x = min)
        (p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)),  # right
    ]
    for a, b, c, d in quads:
        # Corner (s, t) of the face: a + s (b - a) + t (d - a), s and t in [0, 1]; the split keeps the order.
        def at(s, t):
            return tuple(a[k] + s * (b[k] - a[k]) + t * (d[k] - a[k]) for k in range(3))

        ns = nt = 1
        if cell:
            ns = max(1, round(math.dist(a, b) / cell))
            nt = max(1, round(math.dist(a, d) / cell))
        for i in range(ns):
            for j in range(nt):
                q0, q1 = at(i / ns, j / nt), at((i + 1) / ns, j / nt)
                q2, q3 = at((i + 1) / ns, (j + 1) / nt), at(i / ns, (j + 1) / nt)
                yield q0, q1, q2
                yield q0, q2, q3


def main():
    if len(sys.argv) not in (8, 9):
        sys.exit(__doc__)
    v = [float(x) for x in sys.argv[1:7]]
    lo, hi = v[:3], v[3:]
    cell = float(sys.argv[8]) if len(sys.argv) == 9 else None
    with open(sys.argv[7], "w") as out:
        out.write("solid box\n")
        for f in box_facets(lo, hi, cell):
            out.write("  facet normal 0 0 0\n    outer loop\n")
            for x in f:
                out.write(f"      vertex {x[0]:.9g} {x[1]:.9g} {x[2]:.9g}\n")
            out.write("    endloop\n  endfacet\n")
        out.write("endsolid box\n")


if __name__ == "__main__":
    main()
