#!/usr/bin/python3
"""Plots of a grit run or sweep folder, as PNG files in FOLDER/plots/ (what `grit plot FOLDER` runs).

A run folder: a picture of the last output (2D: water, solids coloured by plastic strain, grains to
scale), the crater profile at several output times on one axis (2D cases with a crater analysis; from
crater_history.csv, or the snapshots of a run from before it), crater depth C_d and width C_w against time, eroded mass against time,
histograms of the impact speeds, angles and positions across x (impacts.csv), and where the removed solid particles were and
the state they failed in (eroded.csv), and (2D) the solid coloured by its damage at four output times
(damage.png, for runs whose solid is damaged: the rocks' cracks). A sweep folder (sweep.csv): C_d, C_w and
eroded mass against each swept parameter, and against time for each run (sweep_history.png).

usage: scripts/grit_plot.py FOLDER [--profiles N]
Uses Debian's python3-numpy and python3-matplotlib; run from another Python that lacks them, it runs
itself again with /usr/bin/python3.
"""
import argparse
import json
import pathlib
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from debian_python import require_numpy_and_matplotlib  # noqa: E402

require_numpy_and_matplotlib()
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from grit_vtu import read_vtu  # noqa: E402

FLUID, SOLID, WALL = 0, 1, 2  # grit's phase codes of SPH particles


def snapshots(pvd):
    """[(time, path)] of the datasets of a .pvd that exist, in its order ([] without the file)."""
    if not pvd.exists():
        return []
    entries = [(float(e.get("timestep")), pvd.parent / e.get("file")) for e in ET.parse(pvd).getroot().iter("DataSet")]
    return [e for e in entries if e[1].exists()]


def last_snapshot(pvd):
    """(time, path) of the last dataset of a .pvd that exists, or None."""
    entries = snapshots(pvd)
    return entries[-1] if entries else None


def marker_size(fig, ax, lo, hi, dx):
    """The scatter size [points^2] of a square marker one particle spacing wide on axes spanning lo..hi [m]."""
    fig.canvas.draw()
    bbox = ax.get_window_extent().transformed(fig.dpi_scale_trans.inverted())
    return (bbox.width * 72.0 / ((hi[0] - lo[0]) * 1e3) * dx * 1e3) ** 2


def draw_water_and_walls(ax, x, phase, size, water="#4a90d9"):
    for code, colour in ((WALL, "0.6"), (FLUID, water)):
        sel = phase == code
        ax.scatter(x[sel, 0] * 1e3, x[sel, 1] * 1e3, s=size, marker="s", c=colour, linewidths=0)


def draw_grains(ax, g):
    if g is not None and len(g["Points"]):
        discs = [Circle((p[0] * 1e3, p[1] * 1e3), r * 1e3) for p, r in zip(g["Points"], g["radius"])]
        ax.add_collection(PatchCollection(discs, facecolor="#2e8b57", edgecolor="k", linewidth=0.4))


def damage_pictures(folder, summary, series, plots, panels=4):
    """A 2D run whose solid is damaged (the JH-2 rocks' cracks, a metal's failure damage): the solid
    coloured by its damage D at up to `panels` output times, evenly from the first output with damage to
    the last, as the paper's Figs. 22, 25 and 28 show it; each titled with that output's damaged area
    and crack count from series.csv."""
    if summary.get("dimension") != 2:
        return

    def damaged(v):
        solid = v["phase"] == SOLID
        return "damage" in v and bool((v["damage"][solid] > 0.0).any())

    entries = snapshots(folder / (summary["case"] + ".pvd"))
    if not entries:
        return
    last = len(entries) - 1
    kept = {last: read_vtu(entries[last][1])}  # the last and the first damaged output, each read once
    if not damaged(kept[last]):
        return
    scanned = ((k, kept[k] if k in kept else read_vtu(entries[k][1])) for k in range(last + 1))
    first, kept[first] = next((k, v) for k, v in scanned if damaged(v))  # lazily: earlier outputs are dropped
    picks = sorted(set(np.round(np.linspace(first, last, min(panels, last + 1 - first))).astype(int)))
    frames = [(entries[k][0], kept[k] if k in kept else read_vtu(entries[k][1])) for k in picks]
    grains = {t: p for t, p in snapshots(folder / (summary["case"] + "_grains.pvd"))}
    dx = summary["particle_spacing"]
    rows = 2 if len(frames) == 4 else 1
    cols = len(frames) // rows
    fig, axes = plt.subplots(rows, cols, figsize=(5.4 * cols + 1.0, 3.4 * rows + 0.4), squeeze=False,
                             layout="constrained")
    names = series.dtype.names or ()
    for ax, (time, v) in zip(axes.flat, frames):
        x, phase = v["Points"], v["phase"]
        lo, hi = x[:, :2].min(axis=0) - dx, x[:, :2].max(axis=0) + dx
        ax.set_xlim(lo[0] * 1e3, hi[0] * 1e3)
        ax.set_ylim(lo[1] * 1e3, hi[1] * 1e3)
        ax.set_aspect("equal")
        size = marker_size(fig, ax, lo, hi, dx)
        draw_water_and_walls(ax, x, phase, size, water="#b7d3ef")
        solid = phase == SOLID
        art = ax.scatter(x[solid, 0] * 1e3, x[solid, 1] * 1e3, s=size, marker="s", c=v["damage"][solid],
                         cmap="YlOrRd", vmin=0.0, vmax=1.0, linewidths=0)
        draw_grains(ax, read_vtu(grains[time]) if time in grains else None)
        title = f"t = {time * 1e6:.4g} us"
        if "damaged_area" in names and series.size:
            row = series[np.argmin(np.abs(series["time"] - time))]
            title += f": damaged {row['damaged_area'] * 1e6:.3g} mm^2"
            if "crack_count" in names:
                title += f", {int(row['crack_count'])} cracks"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
    fig.colorbar(art, ax=list(axes.flat), label="damage D [-]", shrink=0.8)
    fig.suptitle(f"{summary.get('case', '')}: damage (water light blue, grains green)", fontsize=10)
    fig.savefig(plots / "damage.png", dpi=120)
    plt.close(fig)
    print(plots / "damage.png")


def snapshot_picture(folder, summary, plots):
    """The last output of a 2D run as ParaView would show it: water blue, walls grey, solids coloured by
    plastic strain, grains as discs of their radius."""
    if summary.get("dimension") != 2:
        return
    last = last_snapshot(folder / (summary["case"] + ".pvd"))
    if last is None:
        return
    time, path = last
    v = read_vtu(path)
    x, phase = v["Points"], v["phase"]
    dx = summary["particle_spacing"]
    fig, ax = plt.subplots(figsize=(8, 4.4))
    lo, hi = x[:, :2].min(axis=0) - dx, x[:, :2].max(axis=0) + dx
    grains = last_snapshot(folder / (summary["case"] + "_grains.pvd"))
    g = read_vtu(grains[1]) if grains else None
    ax.set_xlim(lo[0] * 1e3, hi[0] * 1e3)
    ax.set_ylim(lo[1] * 1e3, hi[1] * 1e3)
    ax.set_aspect("equal")
    size = marker_size(fig, ax, lo, hi, dx)
    draw_water_and_walls(ax, x, phase, size)
    solid = phase == SOLID
    if solid.any():
        strain = v["plastic_strain"][solid] if "plastic_strain" in v else np.zeros(int(solid.sum()))
        art = ax.scatter(x[solid, 0] * 1e3, x[solid, 1] * 1e3, s=size, marker="s", c=strain, cmap="inferno",
                         vmin=0.0, linewidths=0)
        fig.colorbar(art, ax=ax, label="plastic strain [-]", shrink=0.8)
    draw_grains(ax, g)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"{summary.get('case', '')} at t = {time * 1e6:.4g} us (grains green)")
    save(fig, plots / "snapshot.png")


def read_csv(path):
    data = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8", deletechars="")
    return np.atleast_1d(data)


def read_log(path):
    """A run's CSV log, or an empty array when it is missing, empty or unreadable (rows of another grit
    version appended by a restart: warned about, not plotted)."""
    if not path.exists() or path.stat().st_size == 0:
        return np.empty(0)
    try:
        return read_csv(path)
    except ValueError as e:
        print(f"warning: {path} not plotted: {str(e).splitlines()[0]}", file=sys.stderr)
        return np.empty(0)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(path)


def crater_profiles(folder, summary, plots, count):
    """Top of the solid in bins of one spacing over the crater region, at `count` output times: the rule
    of grit's crater analysis (src/grit/analysis/crater.cpp), each particle counted in every bin within a
    quarter spacing of it, so that the curves show the C_d and C_w that series.csv gives."""
    region = summary.get("crater_region")
    if not region:
        return
    history = folder / "crater_history.csv"
    if history.exists():  # grit's own profiles of every output (since 2026-11-27): no snapshots needed
        data = np.genfromtxt(history, delimiter=",", names=True)
        data = np.atleast_1d(data)
        times = np.unique(data["time"])
        if len(times) < 2:
            return
        picks = sorted({round(k) for k in np.linspace(1, len(times) - 1, min(count, len(times) - 1))})
        if "y" in data.dtype.names:  # 3D: the map of cells over x and y
            crater_sections_3d(data, times, picks, region, plots)
            return
        fig, ax = plt.subplots(figsize=(7, 3.6))
        for k in picks:
            rows = data[data["time"] == times[k]]
            ax.plot(rows["x"] * 1e3, (rows["surface"] - region["surface"]) * 1e3, label=time_label(times[k]))
        finish_profiles(fig, ax, plots)
        return
    if "y_min" in region:  # 3D without crater_history.csv: no profiles
        return
    pvd = folder / (summary["case"] + ".pvd")
    if not pvd.exists():
        return
    entries = [(float(e.get("timestep")), folder / e.get("file")) for e in ET.parse(pvd).getroot().iter("DataSet")]
    entries = [e for e in entries if e[1].exists()]
    if len(entries) < 2:
        return
    picks = sorted({round(k) for k in np.linspace(1, len(entries) - 1, min(count, len(entries) - 1))})
    dx = summary["particle_spacing"]
    edges = np.arange(region["x_min"], region["x_max"] + 0.5 * dx, dx)
    centres = 0.5 * (edges[:-1] + edges[1:])
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for k in picks:
        time, path = entries[k]
        v = read_vtu(path)
        solid = v["phase"] == SOLID
        x, y = v["Points"][solid, 0], v["Points"][solid, 1] + 0.5 * dx
        if region.get("mirror"):  # the x >= 0 half on a symmetry plane: its mirror image is the other half
            x, y = np.concatenate([x, -x]), np.concatenate([y, y])
        top = np.full(len(centres), np.nan)
        u = (x - region["x_min"]) / dx
        for margin in (-0.25, 0.25):
            index = np.floor(u + margin).astype(int)
            inside = (index >= 0) & (index < len(centres))
            for b, h in zip(index[inside], y[inside]):
                if np.isnan(top[b]) or h > top[b]:
                    top[b] = h
        ax.plot(centres * 1e3, (top - region["surface"]) * 1e3, label=time_label(time))
    finish_profiles(fig, ax, plots)


def crater_sections_3d(data, times, picks, region, plots):
    """3D: the section across the traverse (along y) through each picked output's deepest cell, the one
    grit's C_w is measured on (crater_profile.png), and the last output's map of the surface
    (crater_map.png)."""
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for k in picks:
        rows = data[data["time"] == times[k]]
        if not np.any(np.isfinite(rows["surface"])):
            continue
        deepest = rows[np.nanargmin(rows["surface"])]
        section = rows[rows["x"] == deepest["x"]]
        ax.plot(section["y"] * 1e3, (section["surface"] - region["surface"]) * 1e3,
                label=f"{time_label(times[k])}, x = {deepest['x'] * 1e3:.2f} mm")
    finish_profiles(fig, ax, plots, "y (across the traverse) [mm]", "crater section through the deepest cell")
    rows = data[data["time"] == times[-1]]
    xs, ys = np.unique(rows["x"]), np.unique(rows["y"])
    depth = np.full((len(ys), len(xs)), np.nan)
    depth[np.searchsorted(ys, rows["y"]), np.searchsorted(xs, rows["x"])] = (rows["surface"] - region["surface"]) * 1e3
    fig, ax = plt.subplots(figsize=(7, 3.6))
    mesh = ax.pcolormesh(xs * 1e3, ys * 1e3, depth, shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="surface - original [mm]")
    ax.set_aspect("equal")
    ax.set_xlabel("x (along the traverse) [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"surface at {time_label(times[-1])}")
    save(fig, plots / "crater_map.png")


def time_label(time):
    return f"{time * 1e3:.3g} ms" if time >= 1e-3 else f"{time * 1e6:.3g} us"


def finish_profiles(fig, ax, plots, xlabel="x [mm]", title="crater profile"):
    ax.set_xlabel(xlabel)
    ax.set_ylabel("surface - original [mm]")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, plots / "crater_profile.png")


def run_plots(folder, plots, profiles):
    summary = json.loads((folder / "summary.json").read_text()) if (folder / "summary.json").exists() else {}
    series = read_csv(folder / "series.csv")
    t = series["time"] * 1e6
    names = series.dtype.names
    if "crater_depth" in names:
        shape = "crater_shape_factor" in names
        if shape:  # a second panel: V or U (area / (C_d C_w))
            fig, (ax, ax_shape) = plt.subplots(2, 1, figsize=(7, 6), sharex=True, gridspec_kw={"height_ratios": (3, 2)})
        else:
            fig, ax = plt.subplots(figsize=(7, 3.6))
        ax.plot(t, series["crater_depth"] * 1e3, label="C_d (depth)")
        ax.plot(t, series["crater_width"] * 1e3, label="C_w (width)")
        if "crater_rim_width" in names:
            ax.plot(t, series["crater_rim_width"] * 1e3, "--", label="rim to rim (lips' crests)")
        ax.set_ylabel("[mm]")
        ax.set_title("crater size")
        ax.grid(True, alpha=0.3)
        ax.legend()
        if shape:
            f = np.where(series["crater_width"] > 0, series["crater_shape_factor"], np.nan)
            ax_shape.plot(t, f, ".", markersize=3, color="C3")
            for level, name in ((0.5, "V (triangle)"), (np.pi / 4, "semicircle"), (1.0, "box")):
                ax_shape.axhline(level, color="0.6", lw=0.8, ls=":")
                ax_shape.text(t[-1], level, f" {name}", va="center", fontsize=7, color="0.4")
            ax_shape.set_ylim(0.3, 1.1)
            ax_shape.set_ylabel("area / (C_d C_w)")
            ax_shape.grid(True, alpha=0.3)
            ax_shape.set_xlabel("time [us]")
        else:
            ax.set_xlabel("time [us]")
        save(fig, plots / "crater_size.png")
    if "eroded_mass" in names:
        fig, ax = plt.subplots(figsize=(7, 3.2))
        per = "kg/m" if summary.get("dimension", 2) == 2 else "kg"
        ax.plot(t, series["eroded_mass"])
        ax.set_xlabel("time [us]")
        ax.set_ylabel(f"eroded mass [{per}]")
        ax.grid(True, alpha=0.3)
        save(fig, plots / "eroded_mass.png")
    data = read_log(folder / "impacts.csv")
    if data.size > 0 and "speed" in (data.dtype.names or ()):
        where = "x" in data.dtype.names  # the grain's position at contact (since 2026-11-27)
        fig, axes = plt.subplots(1, 3 if where else 2, figsize=(13 if where else 9, 3.4))
        axes[0].hist(data["speed"], bins=20)
        axes[0].set_xlabel("impact speed [m/s]")
        axes[0].set_ylabel("impacts")
        axes[1].hist(data["angle"], bins=18, range=(0, 90))
        axes[1].set_xlabel("impact angle [deg] (90: normal)")
        if where:  # across the jet: how far the grains spread the impacts (the crater's width)
            x = data["x"] * 1e3
            if "grain_collisions" in data.dtype.names:  # since 2026-11-27: deflected by another grain?
                hit = data["grain_collisions"] > 0
                axes[2].hist([x[~hit], x[hit]], bins=40, stacked=True,
                             label=["no grain met before", "met another grain before"])
                axes[2].legend(fontsize=8)
            else:
                axes[2].hist(x, bins=40)
            axes[2].set_xlabel("where the grain hit: x [mm]")
        save(fig, plots / "impacts.png")
    erosion_picture(folder, summary, plots)
    if summary:
        snapshot_picture(folder, summary, plots)
        damage_pictures(folder, summary, series, plots)
        crater_profiles(folder, summary, plots, profiles)


def erosion_picture(folder, summary, plots):
    """eroded.csv: where the removed solid particles were (coloured by the time they went) and the
    state they failed in (plastic strain against triaxiality -p/sigma_vm, by cause)."""
    data = read_log(folder / "eroded.csv")
    if data.size == 0 or "cause" not in (data.dtype.names or ()):
        return
    up = "z" if "z" in data.dtype.names else "y"
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    dots = axes[0].scatter(data["x"] * 1e3, data[up] * 1e3, c=data["time"] * 1e6, s=8, cmap="viridis")
    fig.colorbar(dots, ax=axes[0], label="removed at [us]")
    axes[0].set_xlabel("x [mm]")
    axes[0].set_ylabel(f"{up} [mm]")
    axes[0].set_aspect("equal", adjustable="datalim")
    axes[0].set_title(f"{data.size} particles removed", fontsize=9)
    ductile = data["cause"] == "failed"
    if ductile.any():  # metals: the stress state of failure, eq. (35)
        axes[1].scatter(data["triaxiality"][ductile], data["plastic_strain"][ductile], s=8, label="failed (D = 1)")
        axes[1].axvline(1.0 / 3.0, color="0.6", lw=0.8, ls="--")
        axes[1].set_xlabel("triaxiality -p/sigma_vm at failure (1/3: uniaxial tension)")
        axes[1].set_ylabel("plastic strain")
    else:  # rock: fractured particles go as fragments or as dilated rubble; how deep, how dilated
        for cause in sorted(set(data["cause"])):
            sel = data["cause"] == cause
            axes[1].scatter(-data[up][sel] * 1e3, data["density_ratio"][sel], s=8, label=cause)
        axes[1].set_xlabel(f"depth below {up} = 0 [mm]")
        axes[1].set_ylabel("rho / rho0 when removed")
    axes[1].legend(fontsize=7)
    axes[1].grid(True, alpha=0.3)
    save(fig, plots / "erosion.png")


def sweep_plots(folder, plots):
    data = read_csv(folder / "sweep.csv")
    names = list(data.dtype.names)
    swept = names[: names.index("crater_depth")]
    done = data["status"] == "completed"
    for key in swept:
        x = data[key][done].astype(float)
        others = [k for k in swept if k != key]
        shape = "crater_shape_factor" in names  # a third panel: V (0.5) or U (pi/4 and above)
        fig, axes = plt.subplots(1, 3 if shape else 2, figsize=(13 if shape else 9, 3.4))
        # One line per combination of the other swept values.
        groups = {tuple(data[k][done][i] for k in others) for i in range(int(done.sum()))} or {()}
        for g in sorted(groups):
            sel = np.ones(int(done.sum()), bool)
            for k, v in zip(others, g):
                sel &= data[k][done] == v
            order = np.argsort(x[sel])
            label = ", ".join(f"{k}={v}" for k, v in zip(others, g)) or None
            for ax, col in zip(axes, ("crater_depth", "crater_width")):
                y = data[col][done].astype(float)[sel][order] * 1e3
                line = ax.plot(x[sel][order], y, "o-", label=label)[0]
                if col == "crater_width" and "crater_rim_width" in names:
                    rim = data["crater_rim_width"][done].astype(float)[sel][order] * 1e3
                    ax.plot(x[sel][order], rim, "s--", color=line.get_color(), alpha=0.7)
            if shape:
                f = data["crater_shape_factor"][done].astype(float)[sel][order]
                axes[2].plot(x[sel][order], f, "o-", color=line.get_color())
        labels = ["C_d [mm]", "C_w [mm] (dashed: rim to rim)" if "crater_rim_width" in names else "C_w [mm]"]
        if shape:
            labels.append("shape factor area / (C_d C_w)")
            for level in (0.5, np.pi / 4, 1.0):
                axes[2].axhline(level, color="0.6", lw=0.8, ls=":")
        for ax, col in zip(axes, labels):
            ax.set_xlabel(key)
            ax.set_ylabel(col)
            ax.grid(True, alpha=0.3)
        if others:
            axes[0].legend(fontsize=7)
        save(fig, plots / f"sweep_{key}.png")
    sweep_history(folder, data, swept, plots)


def value_text(value):
    """A swept value as the sweep's folder names it: 2e8, not 200000000.0."""
    return f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)


def sweep_history(folder, data, swept, plots):
    """C_d, C_w and the eroded mass against time, one line per run of the sweep (from its series.csv,
    finished or not): Fig. 13(b)'s curves for each jet velocity or flow rate side by side."""
    runs = []
    for i in range(data.size):
        series = read_log(folder / str(data["folder"][i]) / "series.csv")
        if series.size < 2 or "crater_depth" not in (series.dtype.names or ()):
            continue
        label = ", ".join(f"{k}={value_text(data[k][i])}" for k in swept)
        if data["status"][i] != "completed":
            label += " (running or stopped)"
        runs.append((label, series))
    if not runs:
        return
    t_end = max(float(s["time"][-1]) for _, s in runs)
    scale, unit = (1e3, "ms") if t_end >= 1e-3 else (1e6, "us")
    columns = [("crater_depth", "C_d [mm]", 1e3), ("crater_width", "C_w [mm]", 1e3), ("eroded_mass", "eroded mass [kg/m in 2D, kg in 3D]", 1.0)]
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
    for label, series in runs:
        t = series["time"] * scale
        for ax, (col, _, factor) in zip(axes, columns):
            if col in series.dtype.names:
                ax.plot(t, series[col] * factor, label=label)
    for ax, (_, name, _) in zip(axes, columns):
        ax.set_xlabel(f"time [{unit}]")
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    save(fig, plots / "sweep_history.png")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--profiles", type=int, default=6, help="crater profiles drawn (output times)")
    args = parser.parse_args()
    folder = pathlib.Path(args.folder)
    plots = folder / "plots"
    if (folder / "sweep.csv").exists():
        plots.mkdir(exist_ok=True)
        sweep_plots(folder, plots)
        return 0
    if not (folder / "series.csv").exists():
        print(f"error: {folder} holds neither series.csv (a run) nor sweep.csv (a sweep)", file=sys.stderr)
        return 2
    plots.mkdir(exist_ok=True)
    run_plots(folder, plots, args.profiles)
    return 0


if __name__ == "__main__":
    sys.exit(main())
