#!/usr/bin/python3
"""Velocity profile of a plane Poiseuille run (cases/poiseuille_periodic_2d) against the analytic one.

usage: scripts/poiseuille_profile.py output/poiseuille_periodic_2d [--height H] [--nu NU] [--g G] [-o profile.png]

Reads the last snapshot of the run (snapshots/*.vtu, raw appended data as grit writes it), compares
the fluid particles' u_x with the start-up series solution at the snapshot's time (Morris, Fox & Zhu
1997, eq. 21; the parabola u(y) = g / (2 nu) y (H - y) once steady), prints the largest and rms
errors in % of u_max = g H^2 / (8 nu), and plots the profile to a PNG. Walls at y = 0 and y = H.
Uses Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from grit_vtu import read_vtu  # noqa: E402


def last_snapshot(run: pathlib.Path):
    """(time, file) of the last entry of the run's .pvd."""
    pvd = sorted(run.glob("*.pvd"))
    pvd = [p for p in pvd if not p.name.endswith("_grains.pvd")]
    if not pvd:
        raise FileNotFoundError(f"no .pvd in {run}")
    entries = ET.parse(pvd[0]).getroot().iter("DataSet")
    last = list(entries)[-1]
    return float(last.get("timestep")), run / last.get("file")


def series_velocity(y, t, height, nu, g):
    u = g / (2.0 * nu) * y * (height - y)
    for n in range(400):
        k = 2 * n + 1
        u -= (4.0 * g * height**2 / (nu * np.pi**3 * k**3) * np.sin(np.pi * y * k / height)
              * np.exp(-k * k * np.pi**2 * nu * t / height**2))
    return u


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", type=pathlib.Path, help="the run's output folder")
    parser.add_argument("--height", type=float, default=1.0e-3, help="channel height H [m]")
    parser.add_argument("--nu", type=float, default=1.0e-6, help="kinematic viscosity [m^2/s]")
    parser.add_argument("--g", type=float, default=8.0e-3, help="body force along x [m/s^2]")
    parser.add_argument("-o", "--output", default=None, help="PNG file (default: RUN/profile.png)")
    args = parser.parse_args()
    try:
        t, snapshot = last_snapshot(args.run)
    except (FileNotFoundError, IndexError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    points = read_vtu(snapshot)
    fluid = points["phase"] == 0
    y = points["Points"][fluid, 1]
    u = points["velocity"][fluid, 0]
    u_max = args.g * args.height**2 / (8.0 * args.nu)
    exact = series_velocity(y, t, args.height, args.nu, args.g)
    error = np.abs(u - exact) / u_max
    print(f"t = {t:.6g} s, {fluid.sum()} fluid particles: max |u - u_exact| = {100 * error.max():.3f} % of "
          f"u_max = {u_max:.6g} m/s, rms {100 * np.sqrt(np.mean(error**2)):.3f} %; max u = {u.max():.6g} m/s")
    yy = np.linspace(0.0, args.height, 200)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(u * 1e3, y * 1e3, ".", ms=2, label="grit (fluid particles)")
    ax.plot(series_velocity(yy, t, args.height, args.nu, args.g) * 1e3, yy * 1e3, "-", label=f"series, t = {t:.3g} s")
    ax.plot(args.g / (2 * args.nu) * yy * (args.height - yy) * 1e3, yy * 1e3, "--", lw=0.8, label="steady parabola")
    ax.set_xlabel("u_x [mm/s]")
    ax.set_ylabel("y [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    out = args.output or str(args.run / "profile.png")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
