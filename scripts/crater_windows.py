#!/usr/bin/env python3
"""A run's crater sizes averaged over windows of time, for several runs side by side (a markdown table
per quantity). One output's C_d can move by a grain's dent and its C_w by half a millimetre when a lip
joins the crater; the mean over the outputs of a window is what to compare between runs and with a
paper's figure at one time.

  python3 scripts/crater_windows.py RUN [RUN ...] [--edges 0,1,2.5,5,7.5,10] [--columns crater_depth,crater_width]

RUN: a run's output folder (its series.csv), or a sweep's (each run in it, finished or not). --edges: the windows'
bounds in ms; a window (a, b] holds the outputs with a < t <= b. --columns: series.csv's columns to
average (lengths shown in mm, areas in mm^2); the default is C_d, C_w, the rim width and the shape
factor. Outputs where a column is nan (no crater yet) are left out of its mean; a window without any
prints '-'. The eroded mass at the end of each window (its last output) follows, in g/m in 2D and mg in
3D, the whole specimen's: a finished run of the half (summary.json's "symmetry_plane") is doubled, a run
still going is not. Uses the standard library only.
"""
import argparse
import csv
import json
import math
import pathlib
import sys

DEFAULT_COLUMNS = "crater_depth,crater_width,crater_rim_width,crater_shape_factor"
# How each column is shown: (unit, factor from series.csv's SI value).
UNITS = {"crater_area": ("mm^2", 1e6), "crater_shape_factor": ("", 1.0), "crater_length": ("mm", 1e3)}


def fail(message):
    """Bad input: one line naming it, exit 2 (as grit's own input errors)."""
    print(f"crater_windows.py: {message}", file=sys.stderr)
    sys.exit(2)


def unit_of(column):
    if column in UNITS:
        return UNITS[column]
    if column.startswith("crater_"):
        return "mm", 1e3
    return "", 1.0


def run_folders(paths):
    """Each run folder named, and the runs of each sweep folder named (its sub-folders with a series.csv,
    in name order; a sweep still going has them before its sweep.csv)."""
    runs = []
    for path in map(pathlib.Path, paths):
        if (path / "series.csv").is_file():
            runs.append(path)
            continue
        children = sorted(p for p in path.iterdir() if (p / "series.csv").is_file()) if path.is_dir() else []
        if not children:
            fail(f"{path}: no series.csv (not a run's output folder), nor a sweep's runs in it")
        runs.extend(children)
    return runs


def read_series(folder):
    with open(folder / "series.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(f"{folder}/series.csv has no outputs")
    return rows


def summary_of(folder):
    """summary.json's keys, or {} for a run still going (it writes summary.json at its end)."""
    path = folder / "summary.json"
    if not path.is_file():
        return {}
    with open(path) as f:
        return json.load(f)


def dimension(folder, rows):
    """2 or 3, from summary.json when the run wrote one, else from series.csv's columns."""
    dim = summary_of(folder).get("dimension")
    if dim in (2, 3):
        return dim
    return 3 if "crater_length" in rows[0] else 2


def whole_factor(folder):
    """2 for a run of the half on a symmetry plane (its masses are the half's), else 1. A run still going
    has no summary.json yet: its case file's jet.symmetric or domain.symmetry is not read here, so such a
    run's mass is the half's, as series.csv gives it."""
    return 2.0 if summary_of(folder).get("symmetry_plane") else 1.0


def window_means(rows, column, edges):
    means = []
    for a, b in zip(edges, edges[1:]):
        values = [float(r[column]) for r in rows if a < float(r["time"]) <= b]
        values = [v for v in values if math.isfinite(v)]
        means.append(sum(values) / len(values) if values else None)
    return means


def last_in_window(rows, column, edges):
    out = []
    for a, b in zip(edges, edges[1:]):
        inside = [r for r in rows if a < float(r["time"]) <= b]
        out.append(float(inside[-1][column]) if inside else None)
    return out


def table(title, names, edges_ms, values, fmt):
    head = "| " + title + " | " + " | ".join(f"{a:g}-{b:g} ms" for a, b in zip(edges_ms, edges_ms[1:])) + " |"
    lines = [head, "|" + "---|" * (len(edges_ms))]
    for name, row in zip(names, values):
        cells = ["-" if v is None else fmt.format(v) for v in row]
        lines.append("| " + name + " | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run or sweep output folders")
    parser.add_argument("--edges", default=None,
                        help="window bounds in ms, comma-separated (default: 5 windows over the longest run)")
    parser.add_argument("--columns", default=DEFAULT_COLUMNS, help="series.csv columns to average")
    args = parser.parse_args()

    runs = run_folders(args.runs)
    series = {run: read_series(run) for run in runs}
    if args.edges:
        try:
            edges_ms = [float(e) for e in args.edges.split(",")]
        except ValueError:
            fail(f"--edges '{args.edges}': expected numbers in ms separated by commas")
        if len(edges_ms) < 2 or any(b <= a for a, b in zip(edges_ms, edges_ms[1:])):
            fail(f"--edges '{args.edges}': at least two bounds, increasing")
    else:
        end = max(float(rows[-1]["time"]) for rows in series.values()) * 1e3
        edges_ms = [end * k / 5 for k in range(6)]
    edges = [e * 1e-3 for e in edges_ms]
    # A run still going has no summary.json: it is marked, and its masses are as series.csv gives them.
    names = [run.name + ("" if summary_of(run) else " (running)") for run in runs]

    columns = [c.strip() for c in args.columns.split(",") if c.strip()]
    for run, rows in series.items():
        missing = [c for c in columns if c not in rows[0]]
        if missing:
            fail(f"{run}/series.csv has no column {', '.join(missing)} "
                     f"(a run without [crater], or one made before the column existed: `grit crater {run}` "
                     "measures it again into crater_measures.csv)")
    for column in columns:
        unit, factor = unit_of(column)
        values = [[None if v is None else v * factor for v in window_means(series[run], column, edges)]
                  for run in runs]
        title = f"{column} [{unit}], mean" if unit else f"{column}, mean"
        print(table(title, names, edges_ms, values, "{:.3g}" if not unit else "{:.3f}"))
        print()

    if all("eroded_mass" in rows[0] for rows in series.values()):
        dims = {run: dimension(run, series[run]) for run in runs}
        values = [[None if v is None else v * whole_factor(run) * (1e3 if dims[run] == 2 else 1e6)
                   for v in last_in_window(series[run], "eroded_mass", edges)] for run in runs]
        unit = "g/m" if all(d == 2 for d in dims.values()) else ("mg" if all(d == 3 for d in dims.values())
                                                                  else "g/m in 2D, mg in 3D")
        print(table(f"eroded_mass [{unit}] at the window's end (a half's doubled)", names, edges_ms, values,
                    "{:.3g}"))


if __name__ == "__main__":
    main()
