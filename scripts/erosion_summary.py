#!/usr/bin/env python3
"""How a specimen lost its mass, from a run's eroded.csv (one row per removed solid particle): the
removals by cause and by time window, and the state the particles failed in (median and range of the
plastic strain, triaxiality -p/sigma_vm, relative density rho/rho0 - 1 and depth below the surface, and
how many were on the solid's surface),
and how much the removals cluster: how many follow an earlier removal within --radius and --window,
against how many would if the same removals, at the same times, lay at random places (a chain of
failures, each starting the next, would show many more, and within a microsecond).

  python3 scripts/erosion_summary.py output/awj_copper_2d [--bins 4] [--surface 0.0] [--radius 2e-4] [--window 2e-5]

--surface: the specimen's initial top (y in 2D, z in 3D) for the depth column; 0 by default, as in the
AWJ cases. Uses the standard library, and numpy (Debian's python3-numpy) for the clustering.
"""
import argparse
import csv
import math
import pathlib
import statistics
import sys

from debian_python import require_numpy_and_matplotlib


def quantiles(values):
    """(min, median, max) of the finite values, or None."""
    finite = sorted(v for v in values if math.isfinite(v))
    if not finite:
        return None
    return finite[0], statistics.median(finite), finite[-1]


def describe(rows):
    lines = []
    columns = [("plastic strain", lambda r: float(r["plastic_strain"]), "{:.3g}"),
               ("triaxiality -p/s_vm", lambda r: float(r["triaxiality"]), "{:.3g}"),
               ("pressure [MPa]", lambda r: float(r["pressure"]) / 1e6, "{:.4g}"),
               ("rho/rho0 - 1 [%]", lambda r: 100.0 * (float(r["density_ratio"]) - 1.0), "{:.3g}"),
               ("depth [mm]", lambda r: 1e3 * r["_depth"], "{:.3g}"),
               ("speed [m/s]", lambda r: float(r["speed"]), "{:.3g}")]
    for name, get, fmt in columns:
        q = quantiles([get(r) for r in rows])
        if q:
            lines.append(f"  {name:22s} median {fmt.format(q[1]):>9s}   range {fmt.format(q[0])} .. {fmt.format(q[2])}")
    tension = sum(1 for r in rows if math.isfinite(float(r["triaxiality"])) and float(r["triaxiality"]) > 1.0 / 3.0)
    lines.append(f"  failed in more tension than uniaxial (triaxiality > 1/3): {tension} of {len(rows)}")
    if rows and "surface" in rows[0]:  # eroded.csv since 2026-11-27
        surface = sum(1 for r in rows if r["surface"] == "1")
        inside = sum(1 for r in rows if r["surface"] == "0")
        lines.append(f"  on the solid's surface in their last step: {surface} of {len(rows)} ({inside} inside;"
                     f" eq. 35 took at most failure_surface_triaxiality on the surface)")
    return lines


def clustering(rows, radius, window):
    """Lines on how the removals cluster in space and time (docs/validation.md, "Not a cascade")."""
    import numpy as np  # the all-pairs count is O(n^2): in numpy, not in Python loops

    axes = [a for a in ("x", "y", "z") if a in rows[0]]
    order = sorted(range(len(rows)), key=lambda i: float(rows[i]["time"]))
    t = np.array([float(rows[i]["time"]) for i in order])
    x = np.array([[float(rows[i][a]) for a in axes] for i in order])
    n = len(t)
    close_pairs = sum(int(np.count_nonzero(np.linalg.norm(x[:i] - x[i], axis=1) < radius)) for i in range(1, n))
    close_share = close_pairs / (n * (n - 1) // 2) if n > 1 else 0.0
    following, within_1us, expected = 0, 0, 0.0
    for i in range(n):
        first = int(np.searchsorted(t, t[i] - window, side="left"))  # earlier removals within the window
        near = np.linalg.norm(x[first:i] - x[i], axis=1) < radius
        gaps = t[i] - t[first:i][near]
        following += gaps.size > 0
        within_1us += bool(np.any(gaps <= 1e-6))
        expected += 1.0 - (1.0 - close_share) ** (i - first)  # as many earlier ones, at random places
    return [f"clustering: {following} of {n} removals follow an earlier one within {radius * 1e3:g} mm and "
            f"{window * 1e6:g} us ({expected:.1f} would at random places: {100 * close_share:.0f} % of all pairs "
            f"lie that close), {within_1us} within 1 us"]


def main():
    require_numpy_and_matplotlib()  # with Debian's python3 if this one lacks numpy
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="a run's output folder (holding eroded.csv)")
    parser.add_argument("--bins", type=int, default=4, help="time windows to count the removals in")
    parser.add_argument("--surface", type=float, default=0.0, help="the specimen's initial top [m]")
    parser.add_argument("--radius", type=float, default=2e-4, help="clustering: distance to an earlier removal [m]")
    parser.add_argument("--window", type=float, default=2e-5, help="clustering: time since an earlier removal [s]")
    args = parser.parse_args()
    path = pathlib.Path(args.run) / "eroded.csv"
    if not path.is_file():
        sys.exit(f"erosion_summary: {path}: no such file (a run with solids writes it)")
    with path.open() as f:
        rows = list(csv.DictReader(f))
    up = "z" if rows and "z" in rows[0] else "y"
    for r in rows:
        r["_depth"] = args.surface - float(r[up])
    mass = sum(float(r["mass"]) for r in rows)
    print(f"{path}: {len(rows)} particles removed, {mass:.4g} kg{' per metre' if up == 'y' else ''}")
    if not rows:
        return
    for cause in sorted({r["cause"] for r in rows}):
        part = [r for r in rows if r["cause"] == cause]
        print(f"cause {cause}: {len(part)} particles, {sum(float(r['mass']) for r in part):.4g} kg")
        print("\n".join(describe(part)))
    times = [float(r["time"]) for r in rows]
    end = max(times)
    width = end / max(args.bins, 1)
    print("removals by time window:")
    for k in range(max(args.bins, 1)):
        lo, hi = k * width, (k + 1) * width
        part = [r for r in rows if lo < float(r["time"]) <= hi or (k == 0 and float(r["time"]) == 0.0)]
        print(f"  {lo * 1e3:8.4f} - {hi * 1e3:8.4f} ms: {len(part):5d} particles, "
              f"{sum(float(r['mass']) for r in part):.4g} kg")
    print("\n".join(clustering(rows, args.radius, args.window)))


if __name__ == "__main__":
    main()
