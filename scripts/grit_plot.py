#!/usr/bin/python3
"""Plots of a grit run or sweep folder, as PNG files in FOLDER/plots/ (what `grit plot FOLDER` runs).

A run folder: a picture of the last output (2D: water, solids coloured by plastic strain, grains to
scale), the crater profile at several output times on one axis (2D cases with a crater analysis; from
crater_history.csv, or the snapshots of a run from before it), crater depth C_d and width C_w against time, eroded mass against time,
histograms of the impact speeds, angles and positions across x (impacts.csv), and where the removed solid particles were and
the state they failed in (eroded.csv), and (2D) the solid coloured by its damage at four output times
(damage.png, for runs whose solid is damaged: the rocks' cracks). A sweep folder (sweep.csv): C_d, C_w and
eroded mass against each swept parameter, and against time for each run (sweep_history.png).

Every figure is headed by the case, its title and its key parameters (plot_labels.py: the jet, the
abrasive, the specimen's material, the particle spacing, the --set); times are in µs, ms or s and masses
in kg, g, mg or µg as the values fit. Where nothing has been eroded yet, or there is no crater yet, the
plot says so instead of drawing a flat zero. In a sweep's plots a run whose crater is shallower than one
particle spacing (C_d < dx, below the resolution) is drawn with hollow markers.

usage: scripts/grit_plot.py FOLDER [--profiles N]
Uses Debian's python3-numpy and python3-matplotlib; run from another Python that lacks them, it runs
itself again with /usr/bin/python3.
"""
import argparse
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
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Patch  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from grit_vtu import read_vtu  # noqa: E402
from plot_labels import (BELOW, crater_scale, key_label, key_unit, key_value_text, length_text,  # noqa: E402
                         load_summary, mass_label, mass_scale, run_heading, sweep_heading, time_scale, time_text)

FLUID, SOLID, WALL = 0, 1, 2  # grit's phase codes of SPH particles
WATER, WATER_LIGHT, WALL_GREY, GRAIN_GREEN = "#4a90d9", "#b7d3ef", "0.6", "#2e8b57"


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


# --- figures --------------------------------------------------------------------------------------------

def figure(summary_heading, nrows=1, ncols=1, figsize=(7, 3.6), **kw):
    """A figure laid out for a report, headed by the case and its parameters."""
    fig, axes = plt.subplots(nrows, ncols, figsize=figsize, layout="constrained", **kw)
    if summary_heading:
        fig.suptitle(summary_heading, fontsize=9)
    return fig, axes


def save(fig, path):
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(path)


def say(ax, text, detail=None):
    """An axes that says why it shows nothing (no crater yet, nothing eroded yet) instead of a flat zero."""
    ax.text(0.5, 0.56, text, transform=ax.transAxes, ha="center", va="center", fontsize=12, color="0.2")
    if detail:
        ax.text(0.5, 0.40, detail, transform=ax.transAxes, ha="center", va="center", fontsize=8.5, color="0.4",
                wrap=True)
    ax.set_yticks([])
    ax.set_facecolor("0.97")


def time_limits(ax, t):
    """The x axis of a panel with nothing drawn spans the run's outputs (where there are two or more)."""
    if len(t) > 1 and t[-1] > t[0]:
        ax.set_xlim(t[0], t[-1])


def length_unit(extent):
    """(scale, unit) for the axes of a picture `extent` metres across: mm below 0.2 m, else m."""
    return (1e3, "mm") if extent < 0.2 else (1.0, "m")


def half_note(summary):
    """Where only the x >= 0 half is simulated (a symmetry plane): the words that say so."""
    return " (the x \u2265 0 half)" if summary.get("symmetry_plane") else ""


def marker_size(fig, ax, lo, hi, dx):
    """The scatter size [points^2] of a square marker one particle spacing wide on axes spanning lo..hi [m]
    (measured after the figure is laid out: call it once titles, labels and colour bars are in place),
    a fifth wider, so that neighbours overlap and no hairline gaps open between particles that moved."""
    fig.canvas.draw()
    bbox = ax.get_window_extent().transformed(fig.dpi_scale_trans.inverted())
    return (1.2 * bbox.width * 72.0 / (hi[0] - lo[0]) * dx) ** 2


def draw_water_and_walls(ax, x, phase, size, scale, water=WATER):
    for code, colour in ((WALL, WALL_GREY), (FLUID, water)):
        sel = phase == code
        ax.scatter(x[sel, 0] * scale, x[sel, 1] * scale, s=size, marker="s", c=colour, linewidths=0)


def draw_grains(ax, g, scale):
    if g is not None and len(g["Points"]):
        discs = [Circle((p[0] * scale, p[1] * scale), r * scale) for p, r in zip(g["Points"], g["radius"])]
        ax.add_collection(PatchCollection(discs, facecolor=GRAIN_GREEN, edgecolor="k", linewidth=0.4))


def phase_legend(ax, phase, grains, water=WATER, loc="upper right"):
    """A key to the picture's colours: water, walls, grains (those present)."""
    handles = []
    if (phase == FLUID).any():
        handles.append(Patch(color=water, label="water"))
    if (phase == WALL).any():
        handles.append(Patch(color=WALL_GREY, label="walls"))
    if grains:
        handles.append(Line2D([], [], ls="none", marker="o", mfc=GRAIN_GREEN, mec="k", label="grains (to scale)"))
    if handles:
        ax.legend(handles=handles, fontsize=7, loc=loc, framealpha=0.85)


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
    width = 5.4 * cols + 1.0
    fig, axes = figure(run_heading(summary, width), rows, cols, figsize=(width, 3.4 * rows + 0.8), squeeze=False)
    names = series.dtype.names or ()
    t_end = entries[-1][0]
    scale, unit = length_unit(float(np.ptp(frames[-1][1]["Points"][:, 0])))
    art = plt.cm.ScalarMappable(norm=matplotlib.colors.Normalize(0.0, 1.0), cmap="YlOrRd")
    fig.colorbar(art, ax=list(axes.flat), label="damage D [-] (1: failed)", shrink=0.8)
    boxes = []
    for ax, (time, v) in zip(axes.flat, frames):
        x, phase = v["Points"], v["phase"]
        solid = phase == SOLID
        lo, hi = x[:, :2].min(axis=0) - dx, x[:, :2].max(axis=0) + dx
        ax.set_xlim(lo[0] * scale, hi[0] * scale)
        ax.set_ylim(lo[1] * scale, hi[1] * scale)
        ax.set_aspect("equal")
        title = f"t = {time_text(time, t_end)}"
        if "damaged_area" in names and series.size:
            row = series[np.argmin(np.abs(series["time"] - time))]
            title += f": damaged {row['damaged_area'] * 1e6:.3g} mm\u00b2"
            if "crack_count" in names:
                title += f", {int(row['crack_count'])} cracks"
        title += f"; largest D {float(v['damage'][solid].max()):.2g}"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel(f"x [{unit}]")
        ax.set_ylabel(f"y [{unit}]")
        boxes.append((ax, time, v, lo, hi))
    phase_legend(axes.flat[0], frames[0][1]["phase"], bool(grains), water=WATER_LIGHT)
    for ax, time, v, lo, hi in boxes:
        x, phase = v["Points"], v["phase"]
        size = marker_size(fig, ax, lo, hi, dx)
        draw_water_and_walls(ax, x, phase, size, scale, water=WATER_LIGHT)
        solid = phase == SOLID
        ax.scatter(x[solid, 0] * scale, x[solid, 1] * scale, s=size, marker="s", c=v["damage"][solid],
                   cmap="YlOrRd", vmin=0.0, vmax=1.0, linewidths=0)
        draw_grains(ax, read_vtu(grains[time]) if time in grains else None, scale)
    save(fig, plots / "damage.png")


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
    lo, hi = x[:, :2].min(axis=0) - dx, x[:, :2].max(axis=0) + dx
    scale, unit = length_unit(float(hi[0] - lo[0]))
    grains = last_snapshot(folder / (summary["case"] + "_grains.pvd"))
    g = read_vtu(grains[1]) if grains else None
    fig, ax = figure(run_heading(summary, 8), figsize=(8, 4.8))
    ax.set_xlim(lo[0] * scale, hi[0] * scale)
    ax.set_ylim(lo[1] * scale, hi[1] * scale)
    ax.set_aspect("equal")
    solid = phase == SOLID
    strain = None
    if solid.any():
        strain = v["plastic_strain"][solid] if "plastic_strain" in v else np.zeros(int(solid.sum()))
        top = float(strain.max()) if strain.size and strain.max() > 0 else 1.0
        norm = matplotlib.colors.Normalize(0.0, top)
        fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="inferno"), ax=ax, label="plastic strain [-]", shrink=0.8)
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    what = "solid by plastic strain" if strain is not None else "the last output"
    ax.set_title(f"t = {time_text(time)}: {what}", fontsize=10)
    phase_legend(ax, phase, g is not None and len(g["Points"]) > 0)
    size = marker_size(fig, ax, lo, hi, dx)
    draw_water_and_walls(ax, x, phase, size, scale)
    if strain is not None:
        ax.scatter(x[solid, 0] * scale, x[solid, 1] * scale, s=size, marker="s", c=strain, cmap="inferno",
                   norm=norm, linewidths=0)
    draw_grains(ax, g, scale)
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


# --- crater profiles ------------------------------------------------------------------------------------

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
            crater_sections_3d(data, times, picks, region, summary, plots)
            return
        curves = []
        for k in picks:
            rows = data[data["time"] == times[k]]
            curves.append((times[k], rows["x"], rows["surface"] - region["surface"]))
        finish_profiles(curves, summary, plots)
        return
    if "y_min" in region:  # 3D without crater_history.csv: no profiles
        return
    entries = snapshots(folder / (summary["case"] + ".pvd"))
    if len(entries) < 2:
        return
    picks = sorted({round(k) for k in np.linspace(1, len(entries) - 1, min(count, len(entries) - 1))})
    dx = summary["particle_spacing"]
    edges = np.arange(region["x_min"], region["x_max"] + 0.5 * dx, dx)
    centres = 0.5 * (edges[:-1] + edges[1:])
    curves = []
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
        curves.append((time, centres, top - region["surface"]))
    finish_profiles(curves, summary, plots)


def flat(values, dx):
    """True where a surface (or several) lies within a thousandth of a spacing of where it started."""
    values = np.asarray(values, float)
    values = values[np.isfinite(values)]
    return values.size == 0 or float(np.abs(values).max()) < 1e-3 * dx


def spacing_line(ax, dx, scale, sign=1.0, largest=None, words=True, what="largest"):
    """A dotted line at one particle spacing (the resolution), in the legend; where everything drawn is
    under a quarter of it (a line that would squash the curves flat), only the legend's words (or,
    words=False, nothing: the legend says it otherwise)."""
    if largest is None or largest >= 0.25 * dx:
        ax.axhline(sign * dx * scale, color="0.45", lw=0.9, ls=":", label=f"one particle spacing ({length_text(dx)})")
    elif words:
        ax.plot([], [], ls="none", label=f"{what} {length_text(largest)}: {BELOW} ({length_text(dx)})")


def finish_profiles(curves, summary, plots, xlabel="x [mm]", title="crater profile: the top of the solid"):
    """crater_profile.png: [(time, x [m], surface - original [m])], or the words 'no crater yet'."""
    dx = summary.get("particle_spacing", 0.0)
    t_end = max(t for t, _, _ in curves)
    fig, ax = figure(run_heading(summary, 7), figsize=(7, 4.0))
    ax.set_xlabel(xlabel)
    ax.set_title(title, fontsize=10)
    if flat(np.concatenate([s for _, _, s in curves]), dx):
        say(ax, f"no crater yet by t = {time_text(t_end)}", "the surface is where it started at every output drawn")
        lo = min(float(np.nanmin(x)) for _, x, _ in curves)
        hi = max(float(np.nanmax(x)) for _, x, _ in curves)
        ax.set_xlim(lo * 1e3, hi * 1e3)
    else:
        profile_curves(ax, curves, [f"t = {time_text(time, t_end)}" for time, _, _ in curves], dx)
    save(fig, plots / "crater_profile.png")


def profile_curves(ax, curves, labels, dx):
    """The surfaces of `curves` (time, position [m], surface change [m]) against position in mm, one
    label each, with the original surface and one particle spacing `dx` below the deepest point."""
    deepest = -min(float(np.nanmin(s)) for _, _, s in curves)
    scale, unit = crater_scale(max(deepest, max(float(np.nanmax(np.abs(s))) for _, _, s in curves)))
    for (_, position, surface), label in zip(curves, labels):
        ax.plot(position * 1e3, surface * scale, label=label)
    ax.axhline(0.0, color="0.3", lw=0.6)
    if dx:
        spacing_line(ax, dx, scale, -1.0, deepest, what="deepest")
    ax.set_ylabel(f"surface \u2212 original surface [{unit}]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7.5, loc="lower right")


def crater_sections_3d(data, times, picks, region, summary, plots):
    """3D: the section across the traverse (along y) through each picked output's deepest cell, the one
    grit's C_w is measured on (crater_profile.png), and the last output's map of the surface
    (crater_map.png)."""
    curves = []
    where = []
    for k in picks:
        rows = data[data["time"] == times[k]]
        if not np.any(np.isfinite(rows["surface"])):
            continue
        deepest = rows[np.nanargmin(rows["surface"])]
        section = rows[rows["x"] == deepest["x"]]
        curves.append((times[k], section["y"], section["surface"] - region["surface"]))
        where.append(deepest["x"])
    if curves:
        finish_sections(curves, where, summary, plots)
    rows = data[data["time"] == times[-1]]
    xs, ys = np.unique(rows["x"]), np.unique(rows["y"])
    depth = np.full((len(ys), len(xs)), np.nan)
    change = rows["surface"] - region["surface"]
    scale, unit = crater_scale(np.nanmax(np.abs(change)) if np.any(np.isfinite(change)) else 0.0)
    depth[np.searchsorted(ys, rows["y"]), np.searchsorted(xs, rows["x"])] = change * scale
    fig, ax = figure(run_heading(summary, 7), figsize=(7, 4.2))
    mesh = ax.pcolormesh(xs * 1e3, ys * 1e3, depth, shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=f"surface \u2212 original surface [{unit}]", shrink=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (along the traverse) [mm]")
    ax.set_ylabel("y [mm]")
    title = f"the specimen's top at t = {time_text(times[-1])}"
    if flat(change, summary.get("particle_spacing", 0.0) or 1e-3):
        title += ": no crater yet"
    ax.set_title(title, fontsize=10)
    save(fig, plots / "crater_map.png")


def finish_sections(curves, where, summary, plots):
    dx = summary.get("particle_spacing", 0.0)
    t_end = max(t for t, _, _ in curves)
    fig, ax = figure(run_heading(summary, 7), figsize=(7, 4.0))
    ax.set_xlabel("y (across the traverse) [mm]")
    ax.set_title("crater section across the traverse through the deepest cell", fontsize=10)
    if flat(np.concatenate([s for _, _, s in curves]), dx):
        say(ax, f"no crater yet by t = {time_text(t_end)}", "the surface is where it started at every output drawn")
    else:
        labels = [f"t = {time_text(time, t_end)}, x = {x * 1e3:.2f} mm" for (time, _, _), x in zip(curves, where)]
        profile_curves(ax, curves, labels, dx)
    save(fig, plots / "crater_profile.png")


def shape_levels(ax):
    """The shape factor's landmarks: a V 0.5, a semicircle pi/4, a box 1 (named inside the axes)."""
    for level, name in ((0.5, "V (triangle) 0.5"), (np.pi / 4, "semicircle 0.785"), (1.0, "box 1")):
        ax.axhline(level, color="0.6", lw=0.8, ls=":")
        ax.text(0.01, level, name, transform=ax.get_yaxis_transform(), va="bottom", fontsize=7, color="0.4")


# --- a run ----------------------------------------------------------------------------------------------

def run_plots(folder, plots, profiles):
    summary = load_summary(folder)
    series = read_csv(folder / "series.csv")
    names = series.dtype.names
    t_end = float(series["time"][-1]) if series.size else 0.0
    scale, unit = time_scale(t_end)
    t = series["time"] * scale
    dx = summary.get("particle_spacing")
    dim = summary.get("dimension", 2)
    heading = run_heading(summary, 7)
    if "crater_depth" in names:
        depth, width = series["crater_depth"], series["crater_width"]
        crater = bool(np.any(depth > 0) or np.any(width > 0))
        shape = "crater_shape_factor" in names and crater
        if shape:  # a second panel: V or U (area / (C_d C_w))
            fig, (ax, ax_shape) = figure(heading, 2, 1, figsize=(7, 6.2), sharex=True,
                                         gridspec_kw={"height_ratios": (3, 2)})
        else:
            fig, ax = figure(heading, figsize=(7, 4.0))
        ax.set_title("crater depth C_d and width C_w", fontsize=10)
        if crater:
            lines = [("crater_depth", "-", "C_d (depth)"), ("crater_width", "-", "C_w (width)"),
                     ("crater_rim_width", "--", "rim to rim (lips' crests)")]
            largest = max(float(np.nanmax(series[c])) for c, _, _ in lines if c in names)
            c_scale, c_unit = crater_scale(largest)
            for col, style, label in lines:
                if col in names:
                    zero = not np.any(series[col] > 0)
                    ax.plot(t, series[col] * c_scale, style, label=label + (": 0 at every output" if zero else ""))
            if dx:
                spacing_line(ax, dx, c_scale, 1.0, largest)
            ax.set_ylabel(f"length [{c_unit}]")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8)
        else:
            say(ax, f"no crater yet by t = {time_text(t_end)}", "C_d = C_w = 0 at every output")
            time_limits(ax, t)
        if shape:
            f = np.where(width > 0, series["crater_shape_factor"], np.nan)
            if np.any(np.isfinite(f)):
                ax_shape.plot(t, f, ".", markersize=5, color="C3")
                shape_levels(ax_shape)
                ax_shape.set_ylim(0.3, 1.1)
                ax_shape.set_ylabel("area / (C_d C_w) [-]")
                ax_shape.grid(True, alpha=0.3)
            else:
                say(ax_shape, "shape factor: no crater width yet", "C_w = 0 at every output")
            ax_shape.set_title("crater shape factor", fontsize=10)
            ax_shape.set_xlabel(f"time [{unit}]")
        else:
            ax.set_xlabel(f"time [{unit}]")
        save(fig, plots / "crater_size.png")
    if "eroded_mass" in names:
        fig, ax = figure(heading, figsize=(7, 3.8))
        mass = series["eroded_mass"]
        ax.set_title("eroded mass" + half_note(summary), fontsize=10)
        if np.any(mass > 0):
            m_scale, m_unit = mass_scale(float(mass.max()), dim)
            ax.plot(t, mass * m_scale, "o-" if t.size <= 60 else "-", ms=3, label="eroded mass at each output")
            first = summary.get("first_removal_time")
            if isinstance(first, (int, float)):
                ax.axvline(first * scale, color="0.5", lw=0.8, ls="--",
                           label=f"first removal, t = {time_text(first, t_end)}")
                ax.legend(fontsize=8)
            ax.set_ylabel(f"{mass_label(dim)} [{m_unit}]")
            ax.grid(True, alpha=0.3)
        else:
            say(ax, f"nothing eroded yet by t = {time_text(t_end)}", "eroded mass 0 at every output")
            time_limits(ax, t)
        ax.set_xlabel(f"time [{unit}]")
        save(fig, plots / "eroded_mass.png")
    impact_histograms(folder, summary, plots, t_end)
    erosion_picture(folder, summary, plots)
    if summary:
        snapshot_picture(folder, summary, plots)
        damage_pictures(folder, summary, series, plots)
        crater_profiles(folder, summary, plots, profiles)


def impact_histograms(folder, summary, plots, t_end):
    """impacts.csv: histograms of the grains' impact speeds, angles and positions across x."""
    data = read_log(folder / "impacts.csv")
    if data.size == 0 or "speed" not in (data.dtype.names or ()):
        return
    where = "x" in data.dtype.names  # the grain's position at contact (since 2026-11-27)
    width = 13 if where else 9
    heading = "\n".join(filter(None, [run_heading(summary, width), f"{data.size} impacts by t = {time_text(t_end)}"]))
    fig, axes = figure(heading, 1, 3 if where else 2, figsize=(width, 4.1))
    axes[0].hist(data["speed"], bins=20)
    axes[0].set_xlabel("impact speed [m/s]")
    axes[0].set_title("speed at first contact", fontsize=10)
    axes[1].hist(data["angle"], bins=18, range=(0, 90))
    axes[1].set_xlabel("impact angle [\u00b0] (90\u00b0: normal to the surface)")
    axes[1].set_title("angle to the surface", fontsize=10)
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
        axes[2].set_title("position across the jet" + half_note(summary), fontsize=10)
    for ax in axes:
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_ylabel("impacts [count]")
        ax.grid(True, axis="y", alpha=0.3)
    save(fig, plots / "impacts.png")


def erosion_picture(folder, summary, plots):
    """eroded.csv: where the removed solid particles were (coloured by the time they went) and the
    state they failed in (plastic strain against triaxiality -p/sigma_vm, by cause)."""
    data = read_log(folder / "eroded.csv")
    if data.size == 0 or "cause" not in (data.dtype.names or ()):
        return
    up = "z" if "z" in data.dtype.names else "y"
    fig, axes = figure(run_heading(summary, 10.5), 1, 2, figsize=(10.5, 4.4))
    t_scale, t_unit = time_scale(float(np.max(data["time"])))
    dots = axes[0].scatter(data["x"] * 1e3, data[up] * 1e3, c=data["time"] * t_scale, s=8, cmap="viridis")
    fig.colorbar(dots, ax=axes[0], label=f"removed at t [{t_unit}]")
    axes[0].set_xlabel("x [mm]")
    axes[0].set_ylabel(f"{up} [mm]")
    axes[0].set_aspect("equal", adjustable="datalim")
    axes[0].xaxis.set_major_locator(MaxNLocator(5))
    axes[0].set_title(f"{data.size} particles removed, where they were", fontsize=10)
    axes[0].grid(True, alpha=0.3)
    ductile = data["cause"] == "failed"
    if ductile.any():  # metals: the stress state of failure, eq. (35)
        axes[1].scatter(data["triaxiality"][ductile], data["plastic_strain"][ductile], s=8, label="failed (D = 1)")
        axes[1].axvline(1.0 / 3.0, color="0.6", lw=0.8, ls="--", label="1/3: uniaxial tension")
        axes[1].set_xlabel("triaxiality \u2212p/\u03c3_vm at failure [-]")
        axes[1].set_ylabel("plastic strain at failure [-]")
        axes[1].set_title("the state they failed in", fontsize=10)
    else:  # rock: fractured particles go as fragments or as dilated rubble; how deep, how dilated
        for cause in sorted(set(data["cause"])):
            sel = data["cause"] == cause
            axes[1].scatter(-data[up][sel] * 1e3, data["density_ratio"][sel], s=8, label=cause)
        axes[1].set_xlabel(f"depth below {up} = 0 [mm]")
        axes[1].set_ylabel("\u03c1/\u03c1\u2080 when removed [-]")
        axes[1].set_title("how deep, how dilated", fontsize=10)
    axes[1].legend(fontsize=7)
    axes[1].grid(True, alpha=0.3)
    save(fig, plots / "erosion.png")


# --- a sweep --------------------------------------------------------------------------------------------

def column(data, name, rows):
    """A sweep.csv column as floats (nan where empty) for the given rows."""
    if name not in data.dtype.names:
        return np.full(int(np.sum(rows)) if rows.dtype == bool else len(rows), np.nan)
    values = data[name][rows]
    try:
        return values.astype(float)
    except ValueError:
        return np.array([float(v) if str(v).strip() else np.nan for v in values])


def spacings(data, swept, summaries):
    """The particle spacing of each run [m]: sweep.csv's column where it has one (swept or written),
    else the run's summary.json."""
    for name in ("particle_spacing", "numerics.particle_spacing"):
        if name in data.dtype.names:
            return column(data, name, np.ones(data.size, bool))
    return np.array([float(s.get("particle_spacing", np.nan)) if s else np.nan for s in summaries])


def sweep_plots(folder, plots):
    data = read_csv(folder / "sweep.csv")
    names = list(data.dtype.names)
    swept = names[: names.index("crater_depth")]
    summaries = [load_summary(folder / str(f)) for f in data["folder"]]
    done = data["status"] == "completed"
    dx_all = spacings(data, swept, summaries)
    ends = [float(s["end_time"]) for s, d in zip(summaries, done) if d and isinstance(s.get("end_time"), (int, float))]
    t_end = max(ends) if ends else float("nan")
    dims = {s.get("dimension") for s in summaries if s}
    dim = dims.pop() if len(dims) == 1 else 2
    values = {k: sorted({v.item() if hasattr(v, "item") else v for v in data[k]}) for k in swept}
    missing = int((~done).sum())
    extra = f"  ({missing} run{'s' if missing > 1 else ''} not finished, left out)" if missing else ""
    if not done.any():
        print(f"warning: no completed run in {folder / 'sweep.csv'}: no sweep_<key>.png", file=sys.stderr)
    for key in swept if done.any() else []:
        x_unit, x_scale = key_unit(key, values[key])
        raw = data[key][done]
        numeric = raw.dtype.kind in "iuf"
        if numeric:
            x = raw.astype(float) * x_scale
        else:  # a swept name (a material): one tick per value
            categories = sorted(set(raw.tolist()))
            x = np.array([categories.index(v) for v in raw.tolist()], float)
        others = [k for k in swept if k != key]
        depth = column(data, "crater_depth", done)
        dx = dx_all[done]
        below = np.isfinite(depth) & np.isfinite(dx) & (depth < dx)
        shape = "crater_shape_factor" in names
        sizes = np.concatenate([column(data, c, done) for c in ("crater_depth", "crater_width")])
        largest = float(np.nanmax(sizes)) if np.any(np.isfinite(sizes)) else 0.0
        c_scale, c_unit = crater_scale(largest)
        panels = [("crater_depth", "crater depth C_d", f"C_d [{c_unit}]", c_scale),
                  ("crater_width", "crater width C_w", f"C_w [{c_unit}]", c_scale)]
        mass = column(data, "eroded_mass", done)
        m_scale, m_unit = mass_scale(np.nanmax(mass) if np.any(mass > 0) else 0.0, dim)
        panels.append(("eroded_mass", "eroded mass", f"{mass_label(dim)} [{m_unit}]", m_scale))
        if shape:
            panels.append(("crater_shape_factor", "crater shape factor", "area / (C_d C_w) [-]", 1.0))
        rows, cols = (2, 2) if shape else (1, 3)
        width = 11.5 if shape else 13
        heading = sweep_heading([s for s, d in zip(summaries, done) if d], {k: values[k] for k in swept},
                                width, extra)
        fig, axes = figure(heading, rows, cols, figsize=(width, 7.4 if shape else 4.2), squeeze=False)
        axes = list(axes.flat)
        # One line per combination of the other swept values.
        groups = sorted({tuple(data[k][done][i].item() for k in others) for i in range(int(done.sum()))}) or [()]
        empty = {}
        for ax, (col, title, ylabel, factor) in zip(axes, panels):
            ax.set_title(title, fontsize=10)
            y_all = column(data, col, done)
            if col == "crater_shape_factor":
                y_all = np.where(column(data, "crater_width", done) > 0, y_all, np.nan)
            if not np.any(np.nan_to_num(y_all) > 0):
                empty[col] = True
                what = {"crater_depth": "no crater yet", "crater_width": "no crater width yet",
                        "eroded_mass": "nothing eroded yet", "crater_shape_factor": "no crater width yet"}[col]
                detail = {"crater_depth": "C_d = 0 in every run", "crater_width": "C_w = 0 in every run",
                          "eroded_mass": "eroded mass 0 in every run",
                          "crater_shape_factor": "the shape factor needs C_w > 0"}[col]
                say(ax, f"{what} by t = {time_text(t_end)}", detail)
                pad = 0.05 * (x.max() - x.min()) if x.max() > x.min() else 0.5
                ax.set_xlim(x.min() - pad, x.max() + pad)
            else:
                ax.set_ylabel(ylabel)
                ax.grid(True, alpha=0.3)
            for n, g in enumerate(groups):
                sel = np.ones(int(done.sum()), bool)
                for k, v in zip(others, g):
                    sel &= data[k][done] == v
                order = np.argsort(x[sel])
                xs, ys, low = x[sel][order], y_all[sel][order] * factor, below[sel][order]
                colour = f"C{n % 10}"
                if col in empty:
                    continue
                label = "; ".join(key_value_text(k, v, values[k]) for k, v in zip(others, g)) or None
                ax.plot(xs, ys, "-", color=colour, label=label)
                ax.plot(xs[~low], ys[~low], "o", color=colour)
                ax.plot(xs[low], ys[low], "o", mfc="white", mec=colour, mew=1.5)
                if col == "crater_width" and "crater_rim_width" in names:
                    rim = column(data, "crater_rim_width", done)[sel][order] * c_scale
                    ax.plot(xs, rim, "--", color=colour, alpha=0.7)
        if "crater_depth" not in empty:
            unique_dx = np.unique(dx[np.isfinite(dx)])
            if len(unique_dx) == 1:
                spacing_line(axes[0], unique_dx[0], c_scale, 1.0, float(np.nanmax(depth)), words=False)
            elif key in ("numerics.particle_spacing", "particle_spacing"):
                order = np.argsort(x)
                axes[0].plot(x[order], dx[order] * c_scale, ":", color="0.45", label="one particle spacing")
        if "crater_shape_factor" in names and "crater_shape_factor" not in empty:
            shape_levels(axes[3])
            axes[3].set_ylim(0.3, 1.1)
        handles, labels = axes[0].get_legend_handles_labels()
        if below.any():
            handles.append(Line2D([], [], ls="none", marker="o", mfc="white", mec="0.3", mew=1.5))
            unique_dx = np.unique(dx[below])
            labels.append(f"{BELOW} (C_d < {length_text(unique_dx[0])})" if len(unique_dx) == 1 else BELOW)
        if handles:
            axes[0].legend(handles, labels, fontsize=7)
        if "crater_width" not in empty and "crater_rim_width" in names:
            axes[1].legend([Line2D([], [], color="0.3", marker="o"), Line2D([], [], color="0.3", ls="--")],
                           ["C_w", "rim to rim (lips' crests)"], fontsize=7)
        ticks = np.unique(x)
        for ax in axes:
            ax.set_xlabel(key_label(key, values[key]) if numeric else key_label(key).rsplit(" [", 1)[0])
            if not numeric:
                ax.set_xticks(range(len(categories)), [str(v).replace("_", " ") for v in categories])
                ax.set_xlim(-0.5, len(categories) - 0.5)
            elif len(ticks) <= 8:  # the swept values themselves
                ax.set_xticks(ticks, [f"{v:.4g}" for v in ticks])
        save(fig, plots / f"sweep_{key}.png")
    sweep_history(folder, data, swept, summaries, values, dx_all, plots, extra)


def value_text(value):
    """A swept value as the sweep's folder names it: 2e8, not 200000000.0."""
    return f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)


def sweep_history(folder, data, swept, summaries, values, dx_all, plots, extra=""):
    """C_d, C_w and the eroded mass against time, one line per run of the sweep (from its series.csv,
    finished or not): Fig. 13(b)'s curves for each jet velocity or flow rate side by side."""
    runs = []
    for i in range(data.size):
        series = read_log(folder / str(data["folder"][i]) / "series.csv")
        if series.size < 2 or "crater_depth" not in (series.dtype.names or ()):
            continue
        label = "; ".join(key_value_text(k, data[k][i].item(), values[k]) for k in swept)
        if data["status"][i] != "completed":
            label += " (running or stopped)"
        runs.append((label, series, summaries[i]))
    if not runs:
        return
    t_end = max(float(s["time"][-1]) for _, s, _ in runs)
    scale, unit = time_scale(t_end)
    dims = {s.get("dimension") for _, _, s in runs if s}
    dim = dims.pop() if len(dims) == 1 else 2
    largest = max(float(np.nanmax(s["eroded_mass"])) if "eroded_mass" in s.dtype.names else 0.0 for _, s, _ in runs)
    m_scale, m_unit = mass_scale(largest, dim)
    deepest = max(float(np.nanmax(s["crater_depth"])) for _, s, _ in runs)
    widest = max((float(np.nanmax(s["crater_width"])) for _, s, _ in runs if "crater_width" in s.dtype.names),
                 default=0.0)
    c_scale, c_unit = crater_scale(max(deepest, widest))
    columns = [("crater_depth", "crater depth C_d", f"C_d [{c_unit}]", c_scale, "no crater yet", "C_d = 0 in every run"),
               ("crater_width", "crater width C_w", f"C_w [{c_unit}]", c_scale, "no crater width yet",
                "C_w = 0 in every run"),
               ("eroded_mass", "eroded mass", f"{mass_label(dim)} [{m_unit}]", m_scale, "nothing eroded yet",
                "eroded mass 0 in every run")]
    heading = sweep_heading([s for _, _, s in runs], {k: values[k] for k in swept}, 13, extra)
    fig, axes = figure(heading, 1, 3, figsize=(13, 4.4))
    for ax, (col, title, name, factor, nothing, detail) in zip(axes, columns):
        ax.set_title(title, fontsize=10)
        ax.set_xlabel(f"time [{unit}]")
        present = [s for _, s, _ in runs if col in s.dtype.names]
        if not any(np.any(s[col] > 0) for s in present):
            say(ax, f"{nothing} by t = {time_text(t_end)}", detail)
            ax.set_xlim(0.0, t_end * scale)
            continue
        for n, (label, series, _) in enumerate(runs):
            if col in series.dtype.names:
                ax.plot(series["time"] * scale, series[col] * factor, color=f"C{n % 10}", label=label)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    unique_dx = np.unique(dx_all[np.isfinite(dx_all)])
    if len(unique_dx) == 1 and axes[0].lines:
        spacing_line(axes[0], unique_dx[0], c_scale, 1.0, deepest)
    target = next((ax for ax in axes if ax.lines), None)
    if target is not None:
        target.legend(fontsize=7)
    else:  # nothing drawn anywhere: the runs named in a key beside the panels
        handles = [Line2D([], [], color=f"C{n % 10}") for n in range(len(runs))]
        axes[0].legend(handles, [label for label, _, _ in runs], fontsize=7, loc="upper left")
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
