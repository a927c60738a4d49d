#!/usr/bin/env python3
"""Writes a simplified Pelton bucket as a binary STL: two cups side by side that meet at a knife-edge
splitter, an open surface of zero thickness (for [[wall]] shape = "mesh", side = "back", thin = true).

Geometry (metres). The splitter ridge runs along x at y = 0, z = 0; the cups lie at y < 0 and y > 0 and
open upwards (+z); the jet comes down along -z onto the ridge. Each cup is the surface
    x = -a cos(psi),  y = +-c (1 - cos(theta)),  z = -D sin(theta) sin(psi),   theta, psi in [0, pi],
so its rim is the rectangle |x| <= a, 0 <= |y| <= 2c at z = 0, its deepest point is D below the ridge at
|y| = c, and the surface leaves the ridge and the outer rim vertically: the splitter is a cusp of zero
thickness (thinner than any smoothing length), and water turned by a cup leaves its outer rim upwards,
as in a Pelton runner (a turn of nearly 180 degrees). The facet normals point into the cups (the wet
side). The cosine spacing in theta and psi puts small facets where the surface is steep.

Usage: python3 scripts/pelton_bucket_stl.py OUT.stl [--a 0.028] [--c 0.016] [--depth 0.018]
                                                   [--n-theta 24] [--n-psi 24]
Defaults: 56 mm long (2a), 64 mm wide (4c), 18 mm deep: a bucket for a jet of about 20 mm
(width about 3.2 jet diameters, length 2.8, depth 0.9: the usual proportions of Pelton buckets).
"""
import argparse
import math
import struct


def cup_points(a, c, depth, side, n_theta, n_psi):
    """Grid of points of one cup (side = +1 for y > 0, -1 for y < 0), rows in theta, columns in psi."""
    rows = []
    for i in range(n_theta + 1):
        theta = math.pi * i / n_theta
        row = []
        for j in range(n_psi + 1):
            psi = math.pi * j / n_psi
            # Exact zeros on the ridge and the rim (+ 0.0 turns -0.0 into 0.0), so the two cups share
            # the ridge's corners bit for bit and grit welds them into one edge.
            s_theta = 0.0 if i in (0, n_theta) else math.sin(theta)
            s_psi = 0.0 if j in (0, n_psi) else math.sin(psi)
            x = -a * math.cos(psi) + 0.0
            y = side * c * (1.0 - math.cos(theta)) + 0.0
            z = -depth * s_theta * s_psi + 0.0
            row.append((x, y, z))
        rows.append(row)
    return rows


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def bucket_facets(a, c, depth, n_theta, n_psi):
    facets = []
    for side in (-1.0, 1.0):
        centre = (0.0, side * c, 0.0)  # the cup's centre on the rim plane: the normals face it
        g = cup_points(a, c, depth, side, n_theta, n_psi)
        for i in range(n_theta):
            for j in range(n_psi):
                p00, p01, p10, p11 = g[i][j], g[i][j + 1], g[i + 1][j], g[i + 1][j + 1]
                for tri in ((p00, p10, p11), (p00, p11, p01)):
                    n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]))
                    mid = tuple(sum(p[k] for p in tri) / 3.0 for k in range(3))
                    if dot(n, sub(centre, mid)) < 0.0:
                        tri = (tri[0], tri[2], tri[1])
                    facets.append(tri)
    return facets


def write_binary_stl(path, facets):
    with open(path, "wb") as out:
        out.write(b"grit Pelton bucket (scripts/pelton_bucket_stl.py)".ljust(80, b" "))
        out.write(struct.pack("<I", len(facets)))
        for tri in facets:
            n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]))
            length = math.sqrt(dot(n, n))
            out.write(struct.pack("<3f", *(x / length for x in n)))
            for p in tri:
                out.write(struct.pack("<3f", *p))
            out.write(struct.pack("<H", 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--a", type=float, default=0.028, help="half length along x [m]")
    parser.add_argument("--c", type=float, default=0.016, help="half width of one cup along y [m]")
    parser.add_argument("--depth", type=float, default=0.018, help="depth below the ridge [m]")
    parser.add_argument("--n-theta", type=int, default=24)
    parser.add_argument("--n-psi", type=int, default=24)
    args = parser.parse_args()
    facets = bucket_facets(args.a, args.c, args.depth, args.n_theta, args.n_psi)
    write_binary_stl(args.out, facets)
    print(f"{args.out}: {len(facets)} facets")


if __name__ == "__main__":
    main()
