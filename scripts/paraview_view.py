"""Opens a grit run in ParaView the way it reads best: each phase its own object (water, each solid
material, walls), solids coloured by plastic strain, water by speed, particles drawn one spacing wide,
grains as spheres of their radius.

usage (ParaView's pvbatch or pvpython; Debian packages paraview and python3-paraview; pvbatch needs a
display, e.g. xvfb-run on a machine without one):
  pvbatch scripts/paraview_view.py OUT [--state OUT/grit_view.pvsm] [--screenshot OUT/view.png] [--time T] [--zoom Z]

It writes a ParaView state file (default OUT/grit_view.pvsm): in the ParaView window, File > Load State
opens it with the pipeline above, and the time controls play the run. --screenshot also renders the
view at the last output (or at --time T, in seconds) to a PNG.

What it saves against opening OUT/CASE.pvd by hand: (1) a Threshold per phase and solid material, named
after the materials the snapshots list in their field data (material_names); (2) the Point Gaussian
representation, discs a little over a particle spacing wide (summary.json particle_spacing) that close
the gaps, instead of one-pixel points;
(3) a Glyph of spheres scaled by the grains' radius array, and the colour maps (plastic strain on the
solids, speed on the water).
"""
import argparse
import json
import pathlib
import re
import sys
import xml.etree.ElementTree as ET

from paraview import simple as pv  # noqa: E402  (ParaView's Python)

FLUID, SOLID, WALL = 0, 1, 2


def material_names(first_vtu):
    """The material_names field data of a grit snapshot (strings written as byte values, 0-terminated)."""
    header = first_vtu.read_bytes().split(b"<AppendedData", 1)[0].decode("utf-8", "replace")
    found = re.search(r'<Array type="String" Name="material_names"[^>]*>([^<]*)</Array>', header)
    if not found:
        return []
    return [bytes(int(c) for c in word.split()).decode("utf-8") for word in found.group(1).split(" 0")[:-1]]


def threshold(source, array, value, name):
    t = pv.Threshold(registrationName=name, Input=source)
    t.Scalars = ["POINTS", array]
    t.LowerThreshold = value
    t.UpperThreshold = value
    return t


def point_gaussian(source, view, radius):
    d = pv.Show(source, view)
    d.SetRepresentationType("Point Gaussian")
    d.GaussianRadius = radius
    d.ShaderPreset = "Plain circle"
    return d


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path, help="a grit output folder (summary.json, CASE.pvd)")
    parser.add_argument("--state", type=pathlib.Path, default=None, help="state file (default FOLDER/grit_view.pvsm)")
    parser.add_argument("--screenshot", type=pathlib.Path, default=None, help="also render the view to this PNG")
    parser.add_argument("--time", type=float, default=None, help="time of the screenshot [s] (default: last)")
    parser.add_argument("--zoom", type=float, default=1.0, help="camera zoom of the screenshot (1: the whole run)")
    args = parser.parse_args()

    folder = args.folder.resolve()
    summary_file = folder / "summary.json"
    if not summary_file.exists():
        sys.exit(f"error: {folder} has no summary.json (not a grit run folder?)")
    summary = json.loads(summary_file.read_text())
    case, dx = summary["case"], summary["particle_spacing"]
    pvd = folder / f"{case}.pvd"
    if not pvd.exists():
        sys.exit(f"error: {pvd} is missing (a run without SPH particles, or output.snapshots = false)")
    datasets = [folder / e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]
    names = material_names(datasets[0]) if datasets else []

    view = pv.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 1
    particles = pv.PVDReader(registrationName=case, FileName=str(pvd))
    pv.Hide(particles, view)

    # Water (and any fluid), walls, and one object per solid material.
    fluid = threshold(particles, "phase", FLUID, "fluid")
    walls = threshold(particles, "phase", WALL, "walls")
    solids = threshold(particles, "phase", SOLID, "solids")
    pv.Hide(solids, view)

    d = point_gaussian(fluid, view, 0.6 * dx)
    pv.ColorBy(d, ("POINTS", "velocity", "Magnitude"))
    d.LookupTable = pv.GetColorTransferFunction("velocity")
    d.LookupTable.ApplyPreset("Cool to Warm", True)
    d.SetScalarBarVisibility(view, True)

    d = point_gaussian(walls, view, 0.6 * dx)
    d.ColorArrayName = ["POINTS", ""]
    d.AmbientColor = d.DiffuseColor = [0.6, 0.6, 0.6]

    strain = pv.GetColorTransferFunction("plastic_strain")
    strain.ApplyPreset("Inferno (matplotlib)", True)
    first = list(particles.TimestepValues)[0] if hasattr(particles.TimestepValues, "__len__") else 0.0
    solid_objects = []
    for m, name in enumerate(names):
        solid = threshold(solids, "material", m, name)
        solid.UpdatePipeline(first)
        if solid.GetDataInformation().GetNumberOfPoints() == 0:  # a fluid's material
            pv.Delete(solid)
            continue
        d = point_gaussian(solid, view, 0.6 * dx)
        pv.ColorBy(d, ("POINTS", "plastic_strain"))
        d.LookupTable = strain
        d.SetScalarBarVisibility(view, True)
        solid_objects.append(solid)

    grains_pvd = folder / f"{case}_grains.pvd"
    if grains_pvd.exists():
        grains = pv.PVDReader(registrationName="grains", FileName=str(grains_pvd))
        pv.Hide(grains, view)
        glyph = pv.Glyph(registrationName="grain spheres", Input=grains, GlyphType="Sphere")
        glyph.ScaleArray = ["POINTS", "radius"]
        glyph.ScaleFactor = 2.0  # the sphere source has radius 0.5: diameter 1 x 2 r
        glyph.GlyphMode = "All Points"
        d = pv.Show(glyph, view)
        d.ColorArrayName = ["POINTS", ""]
        d.AmbientColor = d.DiffuseColor = [0.18, 0.55, 0.34]

    if summary.get("dimension") == 2:
        view.InteractionMode = "2D"
    pv.ResetCamera(view)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    times = list(particles.TimestepValues) if hasattr(particles.TimestepValues, "__len__") else [particles.TimestepValues]
    at = args.time if args.time is not None else (times[-1] if times else 0.0)
    scene.AnimationTime = at
    view.ViewTime = at
    # Colour ranges of the shown time (they were set at the first output, where all is at rest).
    for source in (fluid, *solid_objects):
        pv.GetDisplayProperties(source, view).RescaleTransferFunctionToDataRange(False, True)

    state = args.state or folder / "grit_view.pvsm"
    pv.SaveState(str(state))
    print(state)
    if args.screenshot:
        view.ViewSize = [1200, 700]
        pv.ResetCamera(view)
        pv.GetActiveCamera().Zoom(args.zoom)
        pv.SaveScreenshot(str(args.screenshot), view, ImageResolution=[1200, 700])
        print(args.screenshot)


if __name__ == "__main__":
    main()
