#!/usr/bin/env python3
"""The figures docs/validation.md compares for the sloshing tank with sand (cases/sloshing_tank_sand_3d),
read from one run's output folder: the water front along the floor at 0.12 s, when the water first
reaches the right wall, where the grains are at the end, the impacts on the tank, the wear (total, on the
floor, on the right wall) and the run's steps and wall time.

  python3 scripts/sloshing_summary.py output/sloshing_tank_sand_3d
  python3 scripts/sloshing_summary.py /tmp/isph /tmp/wcsph        # two runs, one column each
"""
import csv
import glob
import json
import pathlib
import re
import sys

from debian_python import require_numpy_and_matplotlib

TANK_LENGTH = 0.245   # [m] the right wall's plane (x)
FRONT_TIME = 0.12     # [s]
FLOOR_LAYER = 0.02    # [m] water below this height counts towards the front along the floor
AT_WALL = 0.240       # [m] water beyond this x has reached the right wall
NEAR_WALL = 0.02      # [m] grains this close to the right wall count as at it when lifted


def times_of(pvd):
    """(time, file) of each entry of a .pvd collection, in order."""
    text = pathlib.Path(pvd).read_text()
    return [(float(t), pathlib.Path(pvd).parent / f)
            for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


def summary(out):
    import numpy as np
    from grit_vtu import read_vtu

    out = pathlib.Path(out)
    run = json.loads((out / "summary.json").read_text())
    pvds = sorted(glob.glob(str(out / "*.pvd")))
    fluid_pvd = next(p for p in pvds if not p.endswith(("_grains.pvd", "_walls.pvd")))
    rows = {}
    front, reached = None, None
    for t, f in times_of(fluid_pvd):
        d = read_vtu(f)
        water = d["phase"] == 0
        x, z = d["Points"][water, 0], d["Points"][water, 2]
        if abs(t - FRONT_TIME) < 1e-9:
            front = x[z < FLOOR_LAYER].max()
        if reached is None and x.max() > AT_WALL:
            reached = t
    rows["water front along the floor at 0.12 s [m]"] = "-" if front is None else f"{front:.3f}"
    rows["water at the right wall [s]"] = "-" if reached is None else f"{reached:.2f}"
    grain_outputs = times_of(str(out / (pathlib.Path(fluid_pvd).stem + "_grains.pvd")))
    first = next((t for t, f in grain_outputs if read_vtu(f)["Points"][:, 0].max() > AT_WALL), None)
    rows["first grain at the right wall (x > 0.240 m) [s]"] = "-" if first is None else f"{first:.2f}"
    # The paper's picture (sec. 3.1): grains near the right wall "lifted up to the top before they have
    # contact with the wall", then "moving back to the left": how high grains near the wall rise, and whether
    # the sand's mean x falls back after its largest value.
    high, high_at, mean_x = 0.0, None, []
    for t, f in grain_outputs:
        p = read_vtu(f)["Points"]
        near = p[:, 0] > TANK_LENGTH - NEAR_WALL
        if near.any() and p[near, 2].max() > high:
            high, high_at = p[near, 2].max(), t
        mean_x.append((t, p[:, 0].mean()))
    rows[f"highest grain within {1e3 * NEAR_WALL:.0f} mm of the right wall [mm] / at [s]"] = (
        f"{1e3 * high:.1f} / {high_at:.2f}" if high_at is not None else "-")
    peak_t, peak_x = max(mean_x, key=lambda e: e[1])
    rows["grains' mean x: largest [m] / at [s] / at the end [m]"] = (
        f"{peak_x:.3f} / {peak_t:.2f} / {mean_x[-1][1]:.3f}")
    grains = read_vtu(grain_outputs[-1][1])
    rows["grains' mean height at the end [mm]"] = f"{1e3 * grains['Points'][:, 2].mean():.1f}"
    rows["farthest grain at the end, x [m]"] = f"{grains['Points'][:, 0].max():.3f}"
    with open(out / "impacts.csv") as f:
        impacts = list(csv.DictReader(f))
    angle = np.array([float(r["angle"]) for r in impacts]) if impacts else np.zeros(1)
    speed = np.array([float(r["speed"]) for r in impacts]) if impacts else np.zeros(1)
    rows["impacts / mean angle [deg] / mean speed [m/s]"] = (
        f"{len(impacts)} / {angle.mean():.1f} / {speed.mean():.2f}")
    wall_outputs = times_of(str(out / (pathlib.Path(fluid_pvd).stem + "_walls.pvd")))
    walls = read_vtu(wall_outputs[-1][1])
    centre = walls["Points"][walls["connectivity"].reshape(-1, 3)].mean(axis=1)
    wear = walls["wear_mass"]
    floor = np.abs(centre[:, 2]) < 1e-9
    right = np.abs(centre[:, 0] - TANK_LENGTH) < 1e-9
    rows["wear at the end: total / floor / right wall [kg]"] = (
        f"{wear.sum():.3g} / {wear[floor].sum():.3g} / {wear[right].sum():.3g}")
    # Where on the right wall (the paper's maps, Figs. 6-7): its wear in height bands, and how high the
    # grains hit it. Meaningful with a fine mesh (tank_fine.stl: 5 mm squares).
    z = centre[right, 2]
    worn = wear[right] > 0.0
    bands = [0.0, 0.01, 0.02, 0.05, 0.1001]
    share = [wear[right][(z >= a) & (z < b)].sum() / wear[right].sum() if worn.any() else 0.0
             for a, b in zip(bands, bands[1:])]
    rows["right wall's wear at 0-1 / 1-2 / 2-5 / 5-10 cm height [%]"] = (
        " / ".join(f"{100 * v:.0f}" for v in share) if worn.any() else "-")
    rows["right wall: impacts / highest worn square's centre [mm]"] = (
        f"{int(walls['impact_count'][right].sum())} / " + (f"{1e3 * z[worn].max():.1f}" if worn.any() else "-"))
    rows["steps / wall time [s]"] = f"{run['steps']} / {run['wall_time_s']:.0f}"
    return rows


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        sys.exit(__doc__)
    require_numpy_and_matplotlib()
    columns = [summary(out) for out in sys.argv[1:]]
    width = max(len(k) for k in columns[0])
    print(" " * width, *(f"{pathlib.Path(o).name:>28}" for o in sys.argv[1:]))
    for key in columns[0]:
        print(key.ljust(width), *(f"{c[key]:>28}" for c in columns))


if __name__ == "__main__":
    main()
