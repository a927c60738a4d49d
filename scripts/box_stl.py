#!/usr/bin/env python3
"""Writes a closed box as an ASCII STL (12 facets, normals outwards), for mesh walls in cases.

Usage: python3 scripts/box_stl.py XMIN YMIN ZMIN XMAX YMAX ZMAX OUT.stl
"""
import sys


def box_facets(lo, hi):
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
        yield a, b, c
        yield a, c, d


def main():
    if len(sys.argv) != 8:
        sys.exit(__doc__)
    v = [float(x) for x in sys.argv[1:7]]
    lo, hi = v[:3], v[3:]
    with open(sys.argv[7], "w") as out:
        out.write("solid box\n")
        for f in box_facets(lo, hi):
            out.write("  facet normal 0 0 0\n    outer loop\n")
            for x in f:
                out.write(f"      vertex {x[0]:.9g} {x[1]:.9g} {x[2]:.9g}\n")
            out.write("    endloop\n  endfacet\n")
        out.write("endsolid box\n")


if __name__ == "__main__":
    main()
