#!/usr/bin/env python3
"""Where and how the grains hit, from a run's impacts.csv: per target, the impacts of grains that had met
another grain before (grain_collisions > 0: deflected, the widening mechanism of the first seed paper's
Figs. 14 and 21) against those that had not, with how far from the jet's axis they landed (median and
90th percentile of |x - axis|), their speed and angle (medians), and by time window.

  python3 scripts/impact_summary.py output/awj_copper_2d [--axis 0.0] [--bins 4]

Uses the standard library only.
"""
import argparse
import csv
import pathlib
import statistics
import sys


def percentile(values, q):
    s = sorted(values)
    if not s:
        return float("nan")
    k = min(len(s) - 1, max(0, round(q * (len(s) - 1))))
    return s[k]


def describe(rows, axis):
    if not rows:
        return "none"
    off = [abs(float(r["x"]) - axis) * 1e3 for r in rows]
    speed = [float(r["speed"]) for r in rows]
    angle = [float(r["angle"]) for r in rows]
    return (f"{len(rows):5d} | |x| median {statistics.median(off):.3g} mm, 90 % within {percentile(off, 0.9):.3g} mm"
            f" | speed {statistics.median(speed):.3g} m/s | angle {statistics.median(angle):.3g} deg")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", type=pathlib.Path, help="a run's output folder (holds impacts.csv)")
    ap.add_argument("--axis", type=float, default=0.0, help="the jet's axis, x [m] (0 in the AWJ cases)")
    ap.add_argument("--bins", type=int, default=4, help="time windows")
    args = ap.parse_args()
    path = args.run / "impacts.csv"
    try:
        with open(path) as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"error: {e}")
    if rows and "grain_collisions" not in rows[0]:
        sys.exit(f"error: {path} has no grain_collisions column (written by grit before 2026-11-27)")
    print(f"{path}: {len(rows)} impacts")
    for target in sorted({r["target"] for r in rows}):
        hits = [r for r in rows if r["target"] == target]
        met = [r for r in hits if int(r["grain_collisions"]) > 0]
        alone = [r for r in hits if int(r["grain_collisions"]) == 0]
        print(f"\ntarget {target}: {len(hits)} impacts, {len(met)} ({100.0 * len(met) / len(hits):.0f} %) "
              "by grains that had met another grain")
        print(f"  met a grain before: {describe(met, args.axis)}")
        print(f"  met none:           {describe(alone, args.axis)}")
        times = [float(r["time"]) for r in hits]
        t0, t1 = min(times), max(times)
        width = (t1 - t0) / args.bins if t1 > t0 else 1.0
        for b in range(args.bins):
            lo, hi = t0 + b * width, t0 + (b + 1) * width
            window = [r for r in hits if lo <= float(r["time"]) < hi or (b == args.bins - 1 and float(r["time"]) == hi)]
            share = [r for r in window if int(r["grain_collisions"]) > 0]
            print(f"  {lo * 1e3:.3g}-{hi * 1e3:.3g} ms: {len(window)} impacts, {len(share)} after meeting a grain;"
                  f" met: {describe(share, args.axis)}; none: "
                  f"{describe([r for r in window if int(r['grain_collisions']) == 0], args.axis)}")


if __name__ == "__main__":
    main()
