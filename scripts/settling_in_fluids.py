#!/usr/bin/env python3
"""The sedimentation_3d grain (glass, d = 100 um) settling in five fluids, against the isolated sphere's
terminal velocity (Schiller-Naumann, the Wen-Yu law at eps = 1: scripts/terminal_velocity.py).

Each fluid runs cases/sedimentation_3d with its density and viscosity, in a column `--width` wide
(default 7 mm = 70 grain diameters, where the periodic images change the Stokes drag by about 2 %),
to max(8 tau, 2 h^2 / nu) (at most 30 ms): tau = rho_p d^2 / (18 mu) is the grain's relaxation time,
h^2 / nu the time the flow the grain drags along takes to spread over the coupling kernel. The
settling velocity is averaged over the last quarter of the run (the column's sound waves shake the
slow grains of the viscous fluids).

Fluids (20 C unless said): water at 20 C and 80 C (IAPWS: 998.2 / 971.8 kg/m^3, 1.002 / 0.355 mPa s);
glycerol-water at 60 and 80 % glycerol by mass (Segur & Oberstar 1951, Ind. Eng. Chem. 43: 1153.8 /
1208.5 kg/m^3, 10.8 / 60.1 mPa s); an ISO VG 32 mineral oil at 40 C (ISO 3448: 32 mm^2/s; 860 kg/m^3,
27.5 mPa s). Viscosity spans a factor 170, density a factor 1.41.

  python3 scripts/settling_in_fluids.py [--grit build/grit] [--width 7e-3] [--threads 2]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from terminal_velocity import terminal_velocity  # noqa: E402

FLUIDS = [  # name, density [kg/m^3], dynamic viscosity [Pa s]
    ("water, 80 C", 971.8, 0.355e-3),
    ("water, 20 C", 998.2, 1.002e-3),
    ("glycerol-water 60 %", 1153.8, 10.8e-3),
    ("glycerol-water 80 %", 1208.5, 60.1e-3),
    ("ISO VG 32 oil, 40 C", 860.0, 27.5e-3),
]
DIAMETER, GRAIN_DENSITY, GRAVITY = 1.0e-4, 2500.0, 9.81
SMOOTHING_LENGTH = 1.25 * 2.0e-4  # h of the case (dx = 2 d)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p.add_argument("--grit", default=os.path.join(root, "build", "grit"))
    p.add_argument("--case", default=os.path.join(root, "cases", "sedimentation_3d", "case.toml"))
    p.add_argument("--width", type=float, default=7.0e-3, help="the column's period along x and y [m]")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--set", action="append", default=[], help="further overrides, as grit run --set")
    a = p.parse_args()
    w = a.width
    print(f"{'fluid':22s} {'Re':>8s} {'v_t [m/s]':>10s} {'grit / v_t':>10s}  (column {w * 1e3:g} mm)")
    with tempfile.TemporaryDirectory() as tmp:
        for name, rho, mu in FLUIDS:
            vt = terminal_velocity("gidaspow", 1.0, DIAMETER, GRAIN_DENSITY, rho, mu, GRAVITY)
            tau = GRAIN_DENSITY * DIAMETER**2 / (18.0 * mu)
            end = min(max(8.0 * tau, 2.0 * SMOOTHING_LENGTH**2 * rho / mu), 0.03)
            out = os.path.join(tmp, "run")
            cmd = [a.grit, "run", a.case, "--out", out, "--overwrite", "--quiet", "--threads", str(a.threads),
                   "--set", f"materials.water.reference_density={rho}",
                   "--set", f"materials.water.dynamic_viscosity={mu}",
                   "--set", f"time.end={end}", "--set", f"output.interval={end / 40}",
                   "--set", "output.snapshots=false",
                   "--set", f"fluid[0].max=[{w}, {w}, 4.0e-3]", "--set", f"wall[0].max=[{w}, {w}, 0.0]",
                   "--set", f"domain.max=[{w}, {w}, 6.0e-3]",
                   "--set", f"grains[0].position=[{w / 2}, {w / 2}, 3.0e-3]"]
            for s in a.set:
                cmd += ["--set", s]
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"{name}: grit run failed ({r.returncode}): {r.stderr.strip()}")
            series = np.genfromtxt(os.path.join(out, "series.csv"), delimiter=",", names=True)
            v = np.abs(series["settling_velocity"])
            late = v[3 * len(v) // 4:].mean()
            print(f"{name:22s} {rho * vt * DIAMETER / mu:8.3g} {vt:10.4e} {late / vt:10.3f}", flush=True)


if __name__ == "__main__":
    main()
