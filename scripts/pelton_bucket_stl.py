#!/usr/bin/env python3
"""Writes a simplified Pelton bucket as a binary STL: two cups side by side that meet at a splitter
edge, an open surface of zero thickness (for [[wall]] shape = "mesh", side = "back", thin = true).

Geometry (metres). The splitter ridge runs along x at y = 0, z = 0; the cups lie at y < 0 and y > 0 and
open upwards (+z); the jet comes down along -z onto the ridge. Each cup is the surface
    x = -a cos(psi),  y = +-[c (1 - cos(theta)) + k sin(theta) (1 + cos(theta)) / 2],
    z = -D sin(theta) sin(psi),   theta, psi in [0, pi],
so its rim is the rectangle |x| <= a, 0 <= |y| <= 2c at z = 0, its deepest point is D below the ridge,
and the surface leaves the outer rim vertically: water turned by a cup leaves upwards, as in a Pelton
runner (a turn of nearly 180 degrees). k = D tan(beta / 2) for the splitter's included angle beta
(--splitter-angle): at mid-length the two flanks leave the edge at beta / 2 from the splitter's plane,
a wedge, as a real splitter is. With beta = 0 (k = 0) they leave it vertically and the splitter is a
cusp of zero thickness, narrower than the kernel's support (5 mm at dx = 2 mm) for nearly 10 mm below
the edge and than a spacing for 6 mm: the lattice lays wall particles in it only that deep, and the
water pressed onto the flanks near the edge got behind them (docs/validation.md). The facet normals point
into the cups (the wet side). The cosine spacing in theta and psi puts small facets where the surface
is steep.

Usage: python3 scripts/pelton_bucket_stl.py OUT.stl [--a 0.028] [--c 0.016] [--depth 0.018]
                                                   [--splitter-angle 40] [--n-theta 24] [--n-psi 24]
Defaults: 56 mm long (2a), 64 mm wide (4c), 18 mm deep: a bucket for a jet of about 20 mm
(width about 3.2 jet diameters, length 2.8, depth 0.9: the usual proportions of Pelton buckets), and a
splitter of 40 degrees, the least of 10, 20, 30 and 40 that kept all water in front of the sheet in
cases/pelton_jet_3d at dx = 2 mm (docs/validation.md).
"""
import argparse
import math
import struct


def cup_points(a, c, depth, side, n_theta, n_psi, splitter_angle=0.0):
    """Grid of points of one cup (side = +1 for y > 0, -1 for y < 0), rows in theta, columns in psi."""
    k = wedge_term(depth, splitter_angle)
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
            y = side * cup_y(c, k, theta) + 0.0
            z = -depth * s_theta * s_psi + 0.0
            row.append((x, y, z))
        rows.append(row)
    return rows


def wedge_term(depth, splitter_angle):
    """k of cup_y for the splitter's included angle [deg]: the flanks leave the edge at half of it from the
    splitter's plane at mid-length (psi = pi/2), where dz/dtheta = -depth at the edge."""
    return depth * math.tan(math.radians(0.5 * splitter_angle))


def cup_y(c, k, theta):
    """|y| of a cup at theta: c (1 - cos theta), plus the wedge term k sin(theta) (1 + cos theta) / 2, whose
    slope is k at the edge (theta = 0) and 0 at the outer rim (theta = pi), so the rim stays vertical."""
    if k == 0.0:
        return c * (1.0 - math.cos(theta))  # the cusp, bit for bit as before the wedge term
    return c * (1.0 - math.cos(theta)) + 0.5 * k * math.sin(theta) * (1.0 + math.cos(theta))


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def bucket_facets(a, c, depth, n_theta, n_psi, splitter_angle=0.0):
    k = wedge_term(depth, splitter_angle)
    # |y| must grow from the edge to the outer rim, or a cup folds over itself.
    ys = [cup_y(c, k, math.pi * i / 1000) for i in range(1001)]
    if any(y1 <= y0 for y0, y1 in zip(ys, ys[1:])):
        raise SystemExit(f"--splitter-angle {splitter_angle}: too wide for --c {c} and --depth {depth} "
                         "(the cup's width would not grow monotonically to its outer rim)")
    facets = []
    for side in (-1.0, 1.0):
        centre = (0.0, side * c, 0.0)  # the cup's centre on the rim plane: the normals face it
        g = cup_points(a, c, depth, side, n_theta, n_psi, splitter_angle)
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
    parser.add_argument("--splitter-angle", type=float, default=40.0,
                        help="the splitter's included angle at the edge [deg]; 0: a cusp")
    parser.add_argument("--n-theta", type=int, default=24)
    parser.add_argument("--n-psi", type=int, default=24)
    args = parser.parse_args()
    if not 0.0 <= args.splitter_angle < 180.0:
        raise SystemExit(f"--splitter-angle {args.splitter_angle}: must be in [0, 180) degrees")
    facets = bucket_facets(args.a, args.c, args.depth, args.n_theta, args.n_psi, args.splitter_angle)
    write_binary_stl(args.out, facets)
    print(f"{args.out}: {len(facets)} facets")


if __name__ == "__main__":
    main()
