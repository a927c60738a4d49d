#!/usr/bin/python3
"""Plot columns of a grit series.csv against time, to a PNG.

usage: scripts/plot_series.py output/CASE/series.csv COLUMN [COLUMN ...] [-o plot.png]
Uses Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("series")
    parser.add_argument("columns", nargs="+")
    parser.add_argument("-o", "--output", default=None, help="PNG file (default: next to the series)")
    args = parser.parse_args()
    data = np.genfromtxt(args.series, delimiter=",", names=True)
    missing = [c for c in args.columns if c not in data.dtype.names]
    if missing:
        print(f"error: no column {', '.join(missing)} in {args.series} (has {', '.join(data.dtype.names)})",
              file=sys.stderr)
        return 2
    fig, axes = plt.subplots(len(args.columns), 1, sharex=True, figsize=(7, 2.4 * len(args.columns)), squeeze=False)
    for ax, column in zip(axes[:, 0], args.columns):
        ax.plot(data["time"], data[column])
        ax.set_ylabel(column)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    out = args.output or args.series.rsplit(".", 1)[0] + "_" + "_".join(args.columns) + ".png"
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
