#!/usr/bin/python3
"""Compares the chute's wear map of a grit run with LIGGGHTS' for the same set-up.

Usage: /usr/bin/python3 compare_liggghts.py GRIT_OUTPUT_DIR LIGGGHTS_MESH.vtk [--bins N] [--plot FILE.png]

GRIT_OUTPUT_DIR: the output folder of `grit run cases/chute_wear_3d/case.toml` (its last walls/*.vtu).
LIGGGHTS_MESH.vtk: the last `dump mesh/gran/VTK ... wear` file of LIGGGHTS' chute_wear tutorial (bench/peers/README.md)
(post/mesh_100000.vtk), whose per-triangle `wear` is the removed mass per area [kg/m^2].
Prints the wear per area along the chute (triangles binned by their centroid's x, the downhill axis),
both totals and the correlation of the binned profiles. Needs python3-vtk9 and python3-numpy.
"""
import argparse
import glob
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def triangles(data):
    """Centroids and areas of the triangles of a VTK dataset."""
    centroids, areas = [], []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        p = np.array([data.GetPoint(ids.GetId(k)) for k in range(3)])
        centroids.append(p.mean(axis=0))
        areas.append(0.5 * np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0])))
    return np.array(centroids), np.array(areas)


def read_grit(folder):
    files = sorted(glob.glob(os.path.join(folder, "walls", "*.vtu")))
    if not files:
        sys.exit(f"error: no walls/*.vtu in {folder}")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    data = reader.GetOutput()
    centroids, areas = triangles(data)
    mass = vtk_to_numpy(data.GetCellData().GetArray("wear_mass"))
    return centroids, mass / areas, areas, files[-1]


def read_liggghts(path):
    reader = vtk.vtkPolyDataReader()
    reader.SetFileName(path)
    reader.ReadAllFieldsOn()
    reader.Update()
    data = reader.GetOutput()
    centroids, areas = triangles(data)
    wear = data.GetCellData().GetArray("wear")
    if wear is None:
        wear = data.GetFieldData().GetArray("wear")
    if wear is None:
        sys.exit(f"error: no 'wear' cell data in {path}")
    return centroids, vtk_to_numpy(wear), areas


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("grit_output")
    ap.add_argument("liggghts_vtk")
    ap.add_argument("--bins", type=int, default=12)
    ap.add_argument("--plot")
    a = ap.parse_args()
    gc, gw, ga, gfile = read_grit(a.grit_output)
    lc, lw, la = read_liggghts(a.liggghts_vtk)
    lo = min(gc[:, 0].min(), lc[:, 0].min())
    hi = max(gc[:, 0].max(), lc[:, 0].max())
    edges = np.linspace(lo, hi, a.bins + 1)

    def profile(c, w, area):  # area-weighted mean wear per area in each bin
        out = np.zeros(a.bins)
        for b in range(a.bins):
            sel = (c[:, 0] >= edges[b]) & (c[:, 0] <= edges[b + 1])
            out[b] = (w[sel] * area[sel]).sum() / max(area[sel].sum(), 1e-300)
        return out

    gp, lp = profile(gc, gw, ga), profile(lc, lw, la)
    print(f"grit: {gfile}; LIGGGHTS: {a.liggghts_vtk}")
    print("x from [m]  x to [m]   grit [kg/m^2]   LIGGGHTS [kg/m^2]   ratio")
    for b in range(a.bins):
        ratio = gp[b] / lp[b] if lp[b] > 0 else float("nan")
        print(f"{edges[b]:9.4f} {edges[b + 1]:9.4f}   {gp[b]:13.5g}   {lp[b]:17.5g}   {ratio:6.3f}")
    gtot, ltot = (gw * ga).sum(), (lw * la).sum()
    print(f"total wear mass: grit {gtot:.5g} kg, LIGGGHTS {ltot:.5g} kg, ratio {gtot / ltot:.3f}")
    print(f"correlation of the binned profiles: {np.corrcoef(gp, lp)[0, 1]:.3f}")
    gx, lx = (gc[:, 0] * gw * ga).sum() / gtot, (lc[:, 0] * lw * la).sum() / ltot
    print(f"wear-weighted mean x: grit {gx:.4f} m, LIGGGHTS {lx:.4f} m")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        mid = 0.5 * (edges[1:] + edges[:-1])
        plt.plot(mid, gp, "o-", label="grit")
        plt.plot(mid, lp, "s--", label="LIGGGHTS 3.8")
        plt.xlabel("x (downhill) [m]")
        plt.ylabel("wear per area [kg/m$^2$]")
        plt.legend()
        plt.title("chute_wear: wear along the chute after 1 s")
        plt.savefig(a.plot, dpi=120, bbox_inches="tight")


if __name__ == "__main__":
    main()
