#!/usr/bin/python3
"""Crater depth against jet pressure on the coarse AWJ on copper (cases/awj_copper_2d), from Python.

    PYTHONPATH=build/python /usr/bin/python3 examples/awj_study.py [--end-time 3e-5] [--threads 2]

Runs the case at four jet pressures (the jet speed follows from eq. 52), each in memory, and plots the crater
depth C_d and width C_w against the pressure into output/awj_study/crater_vs_pressure.png. At the case's
30 us, each run takes about a minute on 2 cores. Where each grain lands is chaotic, so a single run per
pressure shows the trend, not its spread: average over seeds (`abrasive.seed`) to compare settings.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import grit  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--end-time", type=float, default=None, help="simulated time per run [s] (default: the case's)")
    parser.add_argument("--threads", type=int, default=None, help="OpenMP threads")
    parser.add_argument("--out", default=str(ROOT / "output" / "awj_study"), help="folder for the figure")
    args = parser.parse_args()

    base = grit.Case.load(ROOT / "cases" / "awj_copper_2d" / "case.toml")
    if args.end_time is not None:
        base.set("time.end", args.end_time)
    pressures = [1.5e8, 2.0e8, 2.55e8, 3.0e8]  # [Pa]; 2.55e8 is the case's 500 m/s
    depth, width = [], []
    for p in pressures:
        case = base.copy().set("jet.pressure", p)
        values = grit.run(case, threads=args.threads)["values"]
        depth.append(1e3 * values["crater_depth"])
        width.append(1e3 * values["crater_width"])
        print(f"p = {p / 1e6:.0f} MPa: C_d = {depth[-1]:.3f} mm, C_w = {width[-1]:.3f} mm", flush=True)

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(5, 3.5))
    mpa = [p / 1e6 for p in pressures]
    ax.plot(mpa, depth, "o-", label="depth $C_d$")
    ax.plot(mpa, width, "s--", label="width $C_w$")
    ax.set_xlabel("jet pressure [MPa]")
    ax.set_ylabel("crater [mm]")
    ax.set_title(f"AWJ on copper, {base.end_time * 1e6:g} us")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "crater_vs_pressure.png", dpi=120)
    print(f"-> {out / 'crater_vs_pressure.png'}")


if __name__ == "__main__":
    main()
