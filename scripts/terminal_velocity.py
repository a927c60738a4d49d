#!/usr/bin/env python3
"""Terminal velocity of one grain settling in a fluid, from the drag laws of grit's coupling
(src/grit/coupling/drag_laws.hpp; docs/theory.md, "Fluid-grain coupling"), written here anew
from the papers' formulas so that the sedimentation cases have an independent reference.

The balance is (rho_p - rho_f) V g = c(v) v, with c = |F_d| / |u| of the law; every law is per unit
grain volume, so the value is the same for a sphere (3D) and a disc (2D). The approach from rest
follows rho_p V dv/dt = (rho_p - rho_f) V g - c(v) v (no added mass: the coupling has none).

  python3 scripts/terminal_velocity.py                      # the sedimentation cases' values
  python3 scripts/terminal_velocity.py --law di_felice --porosity 0.97 --diameter 5e-5
"""
import argparse
import math


def schiller_naumann(re):
    return 24.0 / re * (1.0 + 0.15 * re**0.687) if re < 1000.0 else 0.44


def drag_per_volume(law, u, eps, d, rho, mu):
    """|F_d| / (V u) [kg/(m^3 s)] for relative speed u > 0."""
    if law == "gidaspow":
        if eps < 0.8:  # Ergun
            return 150.0 * (1.0 - eps) * mu / (eps * d * d) + 1.75 * rho * u / d
        re = eps * rho * u * d / mu  # Wen-Yu
        return 0.75 * schiller_naumann(re) * eps * rho * u * eps**-2.65 / d
    if law == "di_felice":
        re = eps * rho * u * d / mu
        cd = (0.63 + 4.8 / math.sqrt(re)) ** 2
        chi = 3.7 - 0.65 * math.exp(-((1.5 - math.log10(re)) ** 2) / 2.0)
        return 0.5 * cd * rho * u * (1.5 / d) * eps ** (2.0 - chi)
    if law == "single_particle":
        re = rho * u * d / mu
        if re < 0.01:
            return 18.0 * mu / (d * d)
        return 1.5 / d * rho * u * (1.84 * re**-0.31 + 0.293 * re**0.06) ** 3.45
    raise ValueError(law)


def terminal_velocity(law, eps, d, rho_p, rho, mu, g):
    """Bisection on (rho_p - rho) g = k(u) u: the drag grows monotonically with u."""
    target = (rho_p - rho) * g
    lo, hi = 0.0, 1.0
    while drag_per_volume(law, hi, eps, d, rho, mu) * hi < target:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if drag_per_volume(law, mid, eps, d, rho, mu) * mid < target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def approach(law, eps, d, rho_p, rho, mu, g, times):
    """v(t) from rest, classical RK4 with 1e5 steps to the last time."""
    def rate(v):
        k = drag_per_volume(law, v, eps, d, rho, mu) if v > 0.0 else drag_per_volume(law, 1e-12, eps, d, rho, mu)
        return ((rho_p - rho) * g - k * v) / rho_p
    out, v, t = [], 0.0, 0.0
    n = 100000
    dt = times[-1] / n
    k = 0
    for target in times:
        while t < target - 0.5 * dt:
            a = rate(v)
            b = rate(v + 0.5 * dt * a)
            c = rate(v + 0.5 * dt * b)
            e = rate(v + dt * c)
            v += dt * (a + 2 * b + 2 * c + e) / 6.0
            t += dt
            k += 1
        out.append(v)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--law", default=None, help="gidaspow, di_felice or single_particle (default: all three)")
    p.add_argument("--porosity", type=float, default=1.0, help="eps at the grain (1: a lone grain)")
    p.add_argument("--diameter", type=float, default=1.0e-4)
    p.add_argument("--grain-density", type=float, default=2500.0)
    p.add_argument("--fluid-density", type=float, default=1000.0)
    p.add_argument("--viscosity", type=float, default=8.9e-4)
    p.add_argument("--gravity", type=float, default=9.81)
    a = p.parse_args()
    laws = [a.law] if a.law else ["gidaspow", "di_felice", "single_particle"]
    tau = a.grain_density * a.diameter**2 / (18.0 * a.viscosity)
    print(f"# d = {a.diameter} m, rho_p = {a.grain_density}, rho_f = {a.fluid_density}, mu = {a.viscosity}, "
          f"g = {a.gravity}, eps = {a.porosity}")
    stokes = (a.grain_density - a.fluid_density) * a.gravity * a.diameter**2 / (18.0 * a.viscosity)
    print(f"# Stokes terminal velocity {stokes:.6e} m/s, relaxation time rho_p d^2 / (18 mu) = {tau:.6e} s")
    times = [tau * k for k in (0.5, 1.0, 2.0, 3.0, 5.0)]
    print("# law  terminal_velocity[m/s]  Re  v/v_t at t/tau = 0.5 1 2 3 5")
    for law in laws:
        vt = terminal_velocity(law, a.porosity, a.diameter, a.grain_density, a.fluid_density, a.viscosity, a.gravity)
        re = a.fluid_density * vt * a.diameter / a.viscosity
        v = approach(law, a.porosity, a.diameter, a.grain_density, a.fluid_density, a.viscosity, a.gravity, times)
        print(f"{law} {vt:.6e} {re:.4f} " + " ".join(f"{x / vt:.4f}" for x in v))


if __name__ == "__main__":
    main()
