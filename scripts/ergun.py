#!/usr/bin/env python3
"""Superficial velocity through a packed bed from Ergun's equation (Ergun 1952):

  dp/dx = 150 mu (1 - eps)^2 U / (eps^3 d^2) + 1.75 (1 - eps) rho U^2 / (eps^3 d)

solved for U given the pressure gradient. For a bed driven by a body force g on the fluid (periodic
along the flow, cases/packed_bed_2d), the equivalent pressure gradient is rho g (docs/validation.md).

  python3 scripts/ergun.py                          # cases/packed_bed_2d at g = 1 and 10 m/s^2
  python3 scripts/ergun.py --gradient 2500 --porosity 0.45 --diameter 5e-4
"""
import argparse
import math


def ergun_velocity(gradient, eps, d, rho, mu):
    a = 1.75 * (1.0 - eps) * rho / (eps**3 * d)            # U^2 coefficient
    b = 150.0 * mu * (1.0 - eps) ** 2 / (eps**3 * d * d)  # U coefficient
    u = (-b + math.sqrt(b * b + 4.0 * a * gradient)) / (2.0 * a)
    return u, b * u / gradient, a * u * u / gradient


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--gradient", type=float, action="append", help="pressure gradient [Pa/m] (repeatable)")
    p.add_argument("--porosity", type=float, default=1.0 - math.pi / (4.0 * 1.4**2),
                   help="bed porosity (default: discs of d on a square lattice of 1.4 d)")
    p.add_argument("--diameter", type=float, default=1.0e-3)
    p.add_argument("--density", type=float, default=1000.0)
    p.add_argument("--viscosity", type=float, default=1.0e-3)
    a = p.parse_args()
    gradients = a.gradient or [a.density * 1.0, a.density * 10.0]
    print(f"# eps = {a.porosity:.6f}, d = {a.diameter} m, rho = {a.density}, mu = {a.viscosity}")
    print("# pressure_gradient[Pa/m]  superficial_velocity[m/s]  viscous_share  inertial_share")
    for g in gradients:
        u, viscous, inertial = ergun_velocity(g, a.porosity, a.diameter, a.density, a.viscosity)
        print(f"{g:.6g} {u:.6e} {viscous:.4f} {inertial:.4f}")


if __name__ == "__main__":
    main()
