#!/usr/bin/env python3
"""Contact velocity of one grain carried by the water jet onto the wall, from the grain's one-way
equation of motion in the undisturbed jet (no reaction on the water, no displacement).

  grit run cases/awj_single_grain_wall_2d/jet_only.toml --out output/jet_only
  python3 scripts/single_grain_ode.py output/jet_only
  python3 scripts/single_grain_ode.py output/jet_only --radius 3.0 --porosity 1.0

It reads every snapshot of a grain-free run of the jet, and along the jet's axis (x = 0) evaluates what
grit's coupling evaluates at a grain (docs/theory.md, "Fluid-grain coupling"), written here anew: the
Shepard fluid velocity v_f and immersion S (eq. 46), and -grad p in the difference form
-sum_a V_a (p_a - p_i) grad_i W_ia, with the 2D cubic spline of h_c = R_c / 2. Then it integrates
m dv/dt = S [V (-grad p) + c(eps, |v_f - v|) (v_f - v)] (eqs. 42, 44) from the entry point at the entry
speed, interpolating the field linearly in time and height, until the grain's centre is one radius plus
half a spacing above the wall (where grit's penalty contact starts and `contact_velocity` is taken).

The porosity the drag law sees is an input: 1 is a lone grain, 0.81 is the Shepard porosity a 2D disc
gives itself at R_c = 2 d (grit's `grain_porosity`). The difference between this one-way value and the
coupled run's `contact_velocity` is what the two-way coupling adds. Uses Debian's python3-numpy.
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET

import numpy as np
from grit_vtu import read_vtu


def snapshots(run):
    """(time, file) of every entry of the run's particle .pvd."""
    pvd = [p for p in sorted(pathlib.Path(run).glob("*.pvd")) if not p.name.endswith("_grains.pvd")]
    if not pvd:
        raise FileNotFoundError(f"no .pvd in {run}")
    return [(float(e.get("timestep")), pathlib.Path(run) / e.get("file"))
            for e in ET.parse(pvd[0]).getroot().iter("DataSet")]


def cubic_spline_2d(h):
    """W(r) and (dW/dr)/r of the 2D cubic spline of smoothing length h (support 2h)."""
    a = 10.0 / (7.0 * np.pi * h * h)

    def w(r):
        q = r / h
        return a * np.where(q < 1.0, 1.0 - 1.5 * q * q + 0.75 * q**3, np.where(q < 2.0, 0.25 * (2.0 - q) ** 3, 0.0))

    def grad_over_r(r):
        q = r / h
        dw = a / h * np.where(q < 1.0, -3.0 * q + 2.25 * q * q, np.where(q < 2.0, -0.75 * (2.0 - q) ** 2, 0.0))
        return np.where(r > 0.0, dw / np.maximum(r, 1e-300), 0.0)

    return w, grad_over_r


def axis_field(path, heights, h):
    """Along x = 0: downward Shepard speed v_f, upward -dp/dy and the immersion S at each height."""
    f = read_vtu(path)
    fluid = f["phase"] == 0
    x = f["Points"][fluid][:, :2]
    vy = f["velocity"][fluid][:, 1]
    p = f["pressure"][fluid]
    vol = f["mass"][fluid] / f["density"][fluid]
    w, grad_over_r = cubic_spline_2d(h)
    speed, force, immersion = [], [], []
    for y in heights:
        d = np.array([0.0, y]) - x  # x_i - x_a
        r = np.hypot(d[:, 0], d[:, 1])
        vw = vol * w(r)
        s = vw.sum()
        immersion.append(s)
        if s <= 0.0:
            speed.append(0.0)
            force.append(0.0)
            continue
        speed.append(-(vw * vy).sum() / s)
        p_i = (vw * p).sum() / s
        force.append(-(vol * (p - p_i) * grad_over_r(r) * d[:, 1]).sum())
    return np.array(speed), np.array(force), np.array(immersion)


def schiller_naumann(re):
    return 24.0 / re * (1.0 + 0.15 * re**0.687) if re < 1000.0 else 0.44


def gidaspow_per_volume(u, eps, d, rho, mu):
    """beta / (1 - eps) [kg/(m^3 s)]: Ergun below eps = 0.8, Wen-Yu above (eqs. 44, 47-49)."""
    if eps < 0.8:
        return 150.0 * (1.0 - eps) * mu / (eps * d * d) + 1.75 * rho * u / d
    re = eps * rho * u * d / mu
    return 0.75 * schiller_naumann(max(re, 1e-12)) * rho * u * eps**-1.65 / d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="output folder of a grain-free run of the jet (jet_only.toml)")
    ap.add_argument("--radius", type=float, default=2.0, help="coupling radius R_c in grain diameters [2.0]")
    ap.add_argument("--porosity", type=float, nargs="+", default=[1.0, 0.81], help="porosity in the drag law")
    ap.add_argument("--diameter", type=float, default=2.0e-4, help="grain diameter [m] (Table 4)")
    ap.add_argument("--grain-density", type=float, default=4120.0, help="[kg/m^3] (Table 4 garnet)")
    ap.add_argument("--fluid-density", type=float, default=1000.0, help="[kg/m^3]")
    ap.add_argument("--viscosity", type=float, default=1.0e-3, help="[Pa s] (Table 4)")
    ap.add_argument("--entry-time", type=float, default=3.0e-5, help="time the grain enters at the nozzle [s]")
    ap.add_argument("--entry-height", type=float, default=2.0e-3, help="nozzle height above the wall [m]")
    ap.add_argument("--speed", type=float, default=200.0, help="entry speed [m/s]")
    ap.add_argument("--spacing", type=float, default=5.0e-5, help="particle spacing d_ini [m]")
    a = ap.parse_args()

    d = a.diameter
    volume = np.pi * d * d / 4.0  # a disc, per metre
    mass = a.grain_density * volume
    h = 0.5 * a.radius * d
    contact_height = 0.5 * d + 0.5 * a.spacing
    heights = np.linspace(contact_height - a.spacing, a.entry_height + a.spacing, 200)
    frames = [(t, f) for t, f in snapshots(a.run) if t >= a.entry_time - 1.5e-6]
    if len(frames) < 2:
        sys.exit(f"{a.run}: no snapshots after the entry time {a.entry_time} s")
    times = np.array([t for t, _ in frames])
    fields = [axis_field(f, heights, h) for _, f in frames]
    print(f"R_c = {a.radius} d, h_c = {h:.3g} m, {len(frames)} snapshots from {times[0]:.3g} to {times[-1]:.3g} s")

    def at(t, y):
        k = int(np.clip(np.searchsorted(times, t) - 1, 0, len(times) - 2))
        s = np.clip((t - times[k]) / (times[k + 1] - times[k]), 0.0, 1.0)
        return [(1 - s) * np.interp(y, heights, f0) + s * np.interp(y, heights, f1)
                for f0, f1 in zip(fields[k], fields[k + 1])]

    for eps in a.porosity:
        y, v, t, dt = a.entry_height, a.speed, a.entry_time, 1.0e-9  # v: downward speed
        while y > contact_height:
            if t > times[-1]:
                sys.exit(f"the grain has not reached the wall by the run's last snapshot ({times[-1]:.3g} s)")
            fluid_speed, minus_grad_p, immersion = at(t, y)
            u = fluid_speed - v
            c = gidaspow_per_volume(abs(u), eps, d, a.fluid_density, a.viscosity) * volume
            force = min(immersion, 1.0) * (c * u - volume * minus_grad_p)
            v += force / mass * dt
            y -= v * dt
            t += dt
        print(f"porosity {eps:.3g}: contact velocity {v:.1f} m/s at t = {t * 1e6:.2f} us")
    return 0


if __name__ == "__main__":
    sys.exit(main())
