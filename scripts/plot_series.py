#!/usr/bin/python3
"""Plots of a grit run's CSV files, to PNG, with units.

usage:
  scripts/plot_series.py OUT/series.csv COLUMN [COLUMN ...] [-o plot.png]
      columns of series.csv against time (time in s, ms or µs, lengths in mm, pressures in MPa ...)
  scripts/plot_series.py OUT/crater.csv [-o plot.png]
      the crater profile of the last output: the solid's top surface against x, in mm (3D: against y,
      the section across the traverse through the deepest cell)
  scripts/plot_series.py OUT/series.csv --dambreak [--column-width 0.2] [--reference CSV] [-o plot.png]
      the dam break's surge front in Martin & Moyce's axes, Z = front / a against T = t sqrt(2 g / a),
      with their measurements (cases/dambreak_2d/reference/martin_moyce_1952.csv)

Each plot is headed by the case and its key parameters where the CSV's folder holds the run's
summary.json (plot_labels.py). Uses Debian's python3-numpy and python3-matplotlib; run from another
Python that lacks them, it runs itself again with /usr/bin/python3.
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from debian_python import require_numpy_and_matplotlib  # noqa: E402

require_numpy_and_matplotlib()
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_labels import MU, crater_scale, load_summary, mass_scale, run_heading, time_text  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
MARTIN_MOYCE = ROOT / "cases" / "dambreak_2d" / "reference" / "martin_moyce_1952.csv"

# Column -> (label, unit, scale from SI). Columns not listed are plotted as written (SI units).
UNITS = {
    "crater_depth": ("crater depth C_d", "mm", 1e3),
    "crater_width": ("crater width C_w", "mm", 1e3),
    "crater_rim_width": ("crater rim to rim", "mm", 1e3),
    "crater_lip_height": ("crater lip height", "mm", 1e3),
    "crater_area": ("crater section's area", "mm\u00b2", 1e6),
    "crater_shape_factor": ("crater shape factor area / (C_d C_w): V 0.5, semicircle 0.785", "-", 1.0),
    "front": ("front", "m", 1.0),
    "height": ("height", "m", 1.0),
    "dt": ("time step", "ns", 1e9),
    "max_velocity": ("largest speed", "m/s", 1.0),
    "kinetic_energy": ("kinetic energy", "J (per m in 2D)", 1.0),
    "internal_energy": ("internal energy", "J (per m in 2D)", 1.0),
    "mass_total": ("mass", "kg (per m in 2D)", 1.0),
    "mass_in": ("mass in", "kg (per m in 2D)", 1.0),
    "mass_out": ("mass out", "kg (per m in 2D)", 1.0),
    "eroded_mass": ("eroded mass", "g (per m in 2D)", 1e3),
    "max_plastic_strain": ("largest plastic strain", "-", 1.0),
    "damaged_area": ("damaged area", "mm\u00b2 (mm\u00b3 in 3D)", 1e6),
    "crack_count": ("cracks", "-", 1.0),
    "p_stagnation": ("stagnation pressure", "MPa", 1e-6),
    "grain_kinetic_energy": ("grain kinetic energy", "J (per m in 2D)", 1.0),
    "fluid_in_solid": ("fluid particles inside solids", "-", 1.0),
}


# Columns that stay 0 until something happens: the words a plot of nothing but zeros gives instead.
NOTHING_YET = {
    "eroded_mass": "nothing eroded yet",
    "crater_depth": "no crater yet",
    "crater_width": "no crater width yet",
    "crater_rim_width": "no crater yet",
    "crater_area": "no crater yet",
    "damaged_area": "no damage yet",
    "crack_count": "no cracks yet",
}


def unit_for(column, values, dimension):
    """(label, unit, scale) of a column: UNITS's, with '(per m in 2D)' settled by the run's dimension
    (summary.json) and masses in kg, g, mg or µg as the values fit."""
    label, unit, scale = UNITS.get(column, (column, "SI", 1.0))
    if dimension in (2, 3):
        unit = unit.replace(" (per m in 2D)", "/m" if dimension == 2 else "")
        unit = unit.replace(" (mm\u00b3 in 3D)", "") if dimension == 2 else unit.replace("mm\u00b2 (mm\u00b3 in 3D)", "mm\u00b3")
    if column in ("eroded_mass", "mass_total", "mass_in", "mass_out"):
        largest = float(np.nanmax(np.abs(values))) if len(values) else 0.0
        scale, base = mass_scale(largest, dimension if dimension in (2, 3) else 3)
        unit = base if dimension in (2, 3) else base + " (per m in 2D)"
    elif unit == "mm" and column.startswith("crater"):
        scale, unit = crater_scale(float(np.nanmax(np.abs(values))) if len(values) else 0.0)
    return label, unit, scale


def time_axis(t):
    """Scale and unit for a time axis that ends at max(t)."""
    end = float(np.nanmax(t)) if len(t) else 1.0
    if end < 1e-3:
        return 1e6, MU + "s"
    if end < 1.0:
        return 1e3, "ms"
    return 1.0, "s"


def read(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    return np.atleast_1d(data)


def figure(summary, nrows=1, figsize=(7, 3.2), **kw):
    """A figure laid out for a report, headed by the run's case and parameters where they are known."""
    fig, axes = plt.subplots(nrows, 1, figsize=(figsize[0], figsize[1] + (0.5 if summary else 0.0)),
                             layout="constrained", **kw)
    if summary:
        fig.suptitle(run_heading(summary, figsize[0]), fontsize=9)
    return fig, axes


def say(ax, text, detail=None):
    """An axes that says why it shows nothing instead of a flat zero."""
    ax.text(0.5, 0.58, text, transform=ax.transAxes, ha="center", va="center", fontsize=11, color="0.2")
    if detail:
        ax.text(0.5, 0.36, detail, transform=ax.transAxes, ha="center", va="center", fontsize=8, color="0.4")
    ax.set_yticks([])
    ax.set_facecolor("0.97")


def plot_columns(data, path, columns, out):
    missing = [c for c in columns if c not in data.dtype.names]
    if missing:
        print(f"error: no column {', '.join(missing)} in {path} (has {', '.join(data.dtype.names)})", file=sys.stderr)
        return 2
    summary = load_summary(pathlib.Path(path).parent)
    scale_t, unit_t = time_axis(data["time"])
    t_end = float(np.nanmax(data["time"])) if len(data) else 0.0
    fig, axes = figure(summary, len(columns), figsize=(7, 2.4 * len(columns)), sharex=True, squeeze=False)
    for ax, column in zip(axes[:, 0], columns):
        values = data[column]
        label, unit, scale = unit_for(column, values, summary.get("dimension"))
        if column in NOTHING_YET and not np.any(np.nan_to_num(values) != 0):
            say(ax, f"{label}: {NOTHING_YET[column]} by t = {time_text(t_end)}", "0 at every output")
            ax.set_xlim(float(data["time"][0]) * scale_t, t_end * scale_t)
            continue
        ax.plot(data["time"] * scale_t, values * scale)
        ax.set_ylabel(f"{label} [{unit}]")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(f"time [{unit_t}]")
    save(fig, out or str(path).rsplit(".", 1)[0] + "_" + "_".join(columns) + ".png")
    return 0


def plot_crater(data, path, out):
    summary = load_summary(pathlib.Path(path).parent)
    fig, ax = figure(summary, figsize=(7, 3.4))
    time = data["time"][0] if len(data) else float("nan")
    scale_t, unit_t = time_axis(np.array([time]))
    across = "x"
    if "y" in data.dtype.names and np.any(np.isfinite(data["surface"])):
        # 3D: the map's section across the traverse through its deepest cell (where C_w is measured).
        data = data[data["x"] == data["x"][np.nanargmin(data["surface"])]]
        across = "y"
    ax.set_xlabel(f"{across} [mm]")
    ax.set_title("crater profile (top of the solid; gaps: no solid left)", fontsize=10)
    region = summary.get("crater_region") or {}
    surface = region.get("surface")
    dx = summary.get("particle_spacing") or 0.0
    change = data["surface"] - surface if surface is not None else None
    if change is not None and np.all(np.abs(change[np.isfinite(change)]) < 1e-3 * (dx or 1e-4)):
        say(ax, f"no crater yet by t = {time * scale_t:.4g} {unit_t}", "the surface is where it started")
        if len(data):
            ax.set_xlim(float(np.min(data[across])) * 1e3, float(np.max(data[across])) * 1e3)
    else:
        scale, unit = crater_scale(np.nanmax(np.abs(change))) if change is not None else (1e3, "mm")
        heights = change if change is not None else data["surface"]
        ax.plot(data[across] * 1e3, heights * scale, drawstyle="steps-mid", label=f"t = {time * scale_t:.4g} {unit_t}")
        ax.set_ylabel(f"surface \u2212 original surface [{unit}]" if change is not None else "surface height [mm]")
        ax.grid(True, alpha=0.3)
        ax.legend()
    save(fig, out or str(path).rsplit(".", 1)[0] + "_profile.png")
    return 0


def plot_dambreak(data, path, width, gravity, reference, out):
    if "front" not in data.dtype.names:
        print(f"error: {path} has no 'front' column (the dam break case's probe)", file=sys.stderr)
        return 2
    T = data["time"] * np.sqrt(2.0 * gravity / width)
    Z = data["front"] / width
    fig, ax = figure(load_summary(pathlib.Path(path).parent), figsize=(6, 4))
    ax.plot(T, Z, label="grit")
    if reference.exists():
        lines = [line for line in reference.read_text().splitlines() if line and not line.startswith("#")]
        ref = np.genfromtxt(lines, delimiter=",", names=True)
        ax.plot(ref["T"], ref["Z"], "o", mfc="none", label="Martin & Moyce (1952)")
    else:
        print(f"warning: no reference {reference}", file=sys.stderr)
    ax.set_xlabel("T = t \u221a(2 g / a) [-]")
    ax.set_ylabel("Z = front / a [-]")
    ax.set_title(f"dam break surge front, a = {width:g} m", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, out or str(path).rsplit(".", 1)[0] + "_dambreak_front.png")
    return 0


def save(fig, path):
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(path)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0], usage=__doc__.split("\n\n")[1])
    parser.add_argument("csv", help="series.csv or crater.csv of a run")
    parser.add_argument("columns", nargs="*", help="series.csv columns to plot against time")
    parser.add_argument("-o", "--output", default=None, help="PNG file (default: next to the CSV)")
    parser.add_argument("--dambreak", action="store_true", help="the surge front in Martin & Moyce's Z-T axes")
    parser.add_argument("--column-width", type=float, default=0.2, help="the dam break column's width a [m]")
    parser.add_argument("--gravity", type=float, default=9.81, help="g [m/s^2]")
    parser.add_argument("--reference", type=pathlib.Path, default=MARTIN_MOYCE, help="Martin & Moyce's T,Z data")
    args = parser.parse_args()
    data = read(args.csv)
    names = data.dtype.names or ()
    if args.dambreak:
        return plot_dambreak(data, args.csv, args.column_width, args.gravity, args.reference, args.output)
    if {"x", "surface"} <= set(names):
        return plot_crater(data, args.csv, args.output)
    if not args.columns:
        print(f"error: name the columns to plot (has {', '.join(names)})", file=sys.stderr)
        return 2
    return plot_columns(data, args.csv, args.columns, args.output)


if __name__ == "__main__":
    sys.exit(main())
