"""Opens a grit run in ParaView the way it reads best: each phase its own object (water, each solid
material, walls), solids coloured by plastic strain, water by speed, particles drawn one spacing wide,
grains as spheres of their radius, the simulated time in a corner, the camera on the specimen.

usage (ParaView's pvbatch or pvpython; Debian packages paraview and python3-paraview, and xvfb for a
machine without a display):
  pvbatch scripts/paraview_view.py OUT [--state OUT/grit_view.pvsm] [--screenshot OUT/view.png] [--time T]
                                       [--zoom Z] [--whole]

It writes a ParaView state file (default OUT/grit_view.pvsm): in the ParaView window, File > Load State
opens it with the pipeline above, and the time controls play the run. --screenshot also renders the
view at the last output (or at --time T, in seconds) to a PNG.

Without a display: Debian's ParaView renders only through X (its pvbatch has no off-screen or EGL
window; --force-offscreen-rendering still needs X). With no DISPLAY the script runs itself again under
`xvfb-run -a` (package xvfb) and says so; without xvfb-run it still writes the state (nothing needs
rendering) but stops with a one-line error for --screenshot. A ParaView built for EGL or OSMesa (the
paraview.org "egl"/"osmesa" binaries) renders with no display and is run as it is.

What it saves against opening OUT/CASE.pvd by hand: (1) a Threshold per phase and solid material, named
after the materials the snapshots list in their field data (material_names); (2) the Point Gaussian
representation, discs a little over a particle spacing wide (summary.json particle_spacing) that close
the gaps, instead of one-pixel points;
(3) a Glyph of spheres scaled by the grains' radius array, and the colour maps (plastic strain on the
solids, speed on the water), with units on their bars; (4) the time in us, ms or s (upper left);
(5) a camera framing the specimen (the solids, in 2D across the crater region, with room above for the
jet; --whole: everything), oblique in 3D. The state names the data files relative to its own folder
when it lies in the run folder: a run folder copied elsewhere opens with `cd OUT && paraview
--state=grit_view.pvsm`, or with File > Load State, "Search files under specified directory" (the
state's folder is the default), or pvpython's LoadState(STATE, data_directory=OUT).
"""
import argparse
import json
import math
import os
import pathlib
import re
import shutil
import sys
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape

from paraview import simple as pv  # noqa: E402  (ParaView's Python)

FLUID, SOLID, WALL = 0, 1, 2
SCREENSHOT_SIZE = [1200, 700]
XVFB_MARK = "GRIT_PARAVIEW_UNDER_XVFB"  # set when the script has run itself again under xvfb-run


# ---------------------------------------------------------------------------------------------------
# A display to render in


def renders_through_x():
    """Whether this ParaView's render window is an X window (Debian's), which needs a display even off
    screen; EGL and OSMesa builds render without one. Creating the window object opens nothing."""
    try:
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the platform's window class)
        from vtkmodules.vtkRenderingCore import vtkRenderWindow
    except ImportError:
        return False  # cannot tell: let ParaView try
    return vtkRenderWindow().GetClassName().startswith("vtkX")


def x_display_reachable():
    """DISPLAY is set and, for a local display (:N), its server's socket exists."""
    display = os.environ.get("DISPLAY", "")
    if not display:
        return False
    local = re.fullmatch(r"(?:unix)?:(\d+)(?:\.\d+)?", display)
    if not local:
        return True  # a remote display (ssh -X: localhost:10.0): trust it
    socket = f"/tmp/.X11-unix/X{local.group(1)}"
    if os.path.exists(socket):
        return True
    try:  # an abstract socket (a container without the host's /tmp)
        return socket in pathlib.Path("/proc/net/unix").read_text()
    except OSError:
        return False


def own_command_line():
    """The command line that started this process (pvbatch, its options, this script, its arguments)."""
    try:
        words = pathlib.Path("/proc/self/cmdline").read_bytes().split(b"\0")
    except OSError:
        return None
    return [os.fsdecode(w) for w in words if w] or None


def ensure_display(need_render):
    """Returns whether rendering works here. Without a display, runs the script again under
    `xvfb-run -a` (this process is replaced) when xvfb-run is installed; without it, a state alone is
    still written (nothing renders), and a screenshot stops with an error naming xvfb-run."""
    if not renders_through_x() or x_display_reachable():
        return True
    display = os.environ.get("DISPLAY")
    why = f"DISPLAY={display} does not answer" if display else "DISPLAY unset"
    xvfb = shutil.which("xvfb-run")
    command = own_command_line()
    ranks = max(int(os.environ.get(k) or 1) for k in ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"))
    if os.environ.get(XVFB_MARK):
        sys.exit(f"error: xvfb-run gave no usable X display ({why})")
    if xvfb and command and ranks == 1:
        print(f"paraview_view: no X display ({why}) and this ParaView renders only through X: "
              "running again under xvfb-run -a", flush=True)
        sys.stderr.flush()
        env = dict(os.environ, **{XVFB_MARK: "1"})
        # -noreset: Xvfb resets when its last client leaves, and ParaView's OpenGL probe is one; its
        # render window then found no server in about one run of 15 here
        os.execve(xvfb, [xvfb, "-a", "-s", "-screen 0 1920x1080x24 -noreset", *command], env)
    if xvfb:  # under MPI (or without /proc): one xvfb-run around the whole job
        hint = "run it as xvfb-run -a -s -noreset [mpiexec ...] pvbatch ..."
    else:
        hint = "no xvfb-run: apt-get install xvfb, and the script runs itself under xvfb-run"
    if need_render:
        sys.exit(f"error: no X display to render the screenshot in ({why}); {hint}")
    print(f"paraview_view: no X display ({why}); writing the state only, nothing rendered ({hint})",
          flush=True)
    return False


# ---------------------------------------------------------------------------------------------------
# The pipeline


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


def colour_bar(lut, view, title):
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""  # not "Magnitude"
    bar.RangeLabelFormat = "%.3g"
    return bar


def time_unit(times):
    """The unit of the time label: us up to 2 ms of run, ms up to 2 s, then s."""
    end = max(times) if times else 0.0
    if end <= 2e-3:
        return "\u00b5s", 1e6
    if end <= 2.0:
        return "ms", 1e3
    return "s", 1.0


def time_decimals(values):
    """Decimals that tell the given times (in the label's unit) apart and show each as it is, at most 3."""
    decimals = 0
    for v in values:
        while decimals < 3 and abs(round(v, decimals) - v) > 1e-6 * max(1.0, abs(v)):
            decimals += 1
    return decimals


def time_label(source, view, times, at):
    unit, scale = time_unit(times)
    steps = [t * scale for t in times] + [at * scale]
    label = pv.AnnotateTimeFilter(registrationName="time", Input=source)
    label.Format = "t = {time:.%df} %s" % (time_decimals(steps), unit)
    label.Scale = scale
    d = pv.Show(label, view)
    d.WindowLocation = "Upper Left Corner"
    d.FontSize = 22
    return d


def screenshot_font(texts, bars):
    """DejaVu Sans for the screenshot's text where it is installed: the "Arial" that Debian's ParaView
    ships draws [ ] as ( ). The state keeps ParaView's own font (a font file need not exist where it
    is opened)."""
    font = next((f for f in ("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                             "/usr/share/fonts/TTF/DejaVuSans.ttf",
                             "/usr/share/fonts/dejavu/DejaVuSans.ttf") if os.path.exists(f)), None)
    if font is None:
        return
    for text in texts:
        text.FontFamily, text.FontFile = "File", font
    for bar in bars:
        bar.TitleFontFamily = bar.LabelFontFamily = "File"
        bar.TitleFontFile = bar.LabelFontFile = font


# ---------------------------------------------------------------------------------------------------
# The camera


def bounds_of(sources, time):
    """The union of the sources' bounds at a time, or None when they hold no points."""
    box = None
    for s in sources:
        s.UpdatePipeline(time)
        info = s.GetDataInformation()
        if info.GetNumberOfPoints() == 0:
            continue
        b = list(info.GetBounds())
        box = b if box is None else [min(box[i], b[i]) if i % 2 == 0 else max(box[i], b[i]) for i in range(6)]
    return box


def specimen_box(solid_box, summary, dimension):
    """The solids' box, in 2D narrowed to the crater region's width where that is under two thirds
    of the solids' (a wide plate), raised above the surface to show the jet and the splash (the up
    axis: y in 2D, z in 3D)."""
    box = list(solid_box)
    region = summary.get("crater_region") or {}
    if dimension == 2 and "x_min" in region and "x_max" in region:
        lo, hi = max(box[0], region["x_min"]), min(box[1], region["x_max"])
        if 0 < hi - lo < 2.0 / 3.0 * (box[1] - box[0]):
            box[0], box[1] = lo, hi
    up = 2 if dimension == 3 else 1
    spans = [box[2 * i + 1] - box[2 * i] for i in range(dimension)]
    box[2 * up + 1] += max(0.3 * spans[up], 0.1 * max(spans))
    return box


def frame_2d(view, box, aspect, bars):
    """Looks along -z at the box, parallel projection, the box's bottom near the view's bottom (the
    room the box's width leaves goes above it, to the jet), the right `bars` share of the width left
    to the colour bars."""
    width, height = box[1] - box[0], box[3] - box[2]
    visible = max(height, width / (aspect * (1.0 - bars)), 1e-12) * 1.05
    cx = 0.5 * (box[0] + box[1]) + 0.5 * bars * visible * aspect
    cy = box[2] - 0.025 * visible + 0.5 * visible
    cz = 0.5 * (box[4] + box[5])
    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = [cx, cy, cz]
    view.CameraPosition = [cx, cy, cz + 10 * visible]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 0.5 * visible
    view.CenterOfRotation = [cx, cy, cz]


def frame_3d(view, box, aspect, bars):
    """An oblique view (from the front right, 30 degrees above the surface, z up) that fits the box
    into the view less the right `bars` share of its width (the colour bars)."""
    def unit(v):
        n = math.sqrt(sum(c * c for c in v))
        return [c / n for c in v]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def dot(a, b):
        return sum(x * y for x, y in zip(a, b))

    azimuth, elevation = math.radians(30.0), math.radians(30.0)
    back = unit([math.sin(azimuth) * math.cos(elevation), -math.cos(azimuth) * math.cos(elevation),
                 math.sin(elevation)])  # from the focal point towards the camera
    right = unit(cross([-c for c in back], [0.0, 0.0, 1.0]))
    up = cross(right, [-c for c in back])
    centre = [0.5 * (box[2 * i] + box[2 * i + 1]) for i in range(3)]
    corners = [[box[i], box[2 + j], box[4 + k]] for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    rel = [[p[i] - centre[i] for i in range(3)] for p in corners]
    u, v = [dot(r, right) for r in rel], [dot(r, up) for r in rel]
    # centre the box's picture, then step back until every corner is inside the view's cone
    shift = [0.5 * (max(u) + min(u)) * right[i] + 0.5 * (max(v) + min(v)) * up[i] for i in range(3)]
    focal = [centre[i] + shift[i] for i in range(3)]
    rel = [[p[i] - focal[i] for i in range(3)] for p in corners]
    angle = 30.0
    t = math.tan(math.radians(0.5 * angle)) / 1.05
    wide = aspect * (1.0 - bars)
    distance = max(max(dot(r, back) + abs(dot(r, right)) / (wide * t), dot(r, back) + abs(dot(r, up)) / t)
                   for r in rel)
    distance = max(distance, 1e-9)
    # move the picture left, off the colour bars: the focal point right by half the bars' share of the
    # view's width there (2 distance tan(angle / 2) aspect)
    offset = bars * distance * math.tan(math.radians(0.5 * angle)) * aspect
    focal = [focal[i] + offset * right[i] for i in range(3)]
    view.InteractionMode = "3D"
    view.CameraParallelProjection = 0
    view.CameraViewAngle = angle
    view.CameraFocalPoint = focal
    view.CameraPosition = [focal[i] + distance * back[i] for i in range(3)]
    view.CameraViewUp = up
    view.CenterOfRotation = focal


def zoom(view, factor):
    if factor == 1.0:
        return
    if view.CameraParallelProjection:
        view.CameraParallelScale = view.CameraParallelScale / factor
    else:
        f, p = list(view.CameraFocalPoint), list(view.CameraPosition)
        view.CameraPosition = [f[i] + (p[i] - f[i]) / factor for i in range(3)]


# ---------------------------------------------------------------------------------------------------
# The state's file names


def relative_file_names(state, folder):
    """Rewrites the state's file names under the run folder relative to the state's folder (ParaView
    writes them absolute), when the state lies in the run folder. Returns how many it rewrote."""
    state_dir = state.resolve().parent
    if state_dir != folder and folder not in state_dir.parents:
        return 0
    to_folder = os.path.relpath(folder, state_dir)
    prefix = escape(str(folder) + os.sep, {'"': "&quot;"})
    new = "" if to_folder == "." else escape(to_folder + "/", {'"': "&quot;"})
    text = state.read_text(encoding="utf-8")
    text, count = re.subn(r'(value=")' + re.escape(prefix), lambda m: m.group(1) + new, text)
    state.write_text(text, encoding="utf-8")
    return count


# ---------------------------------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path, help="a grit output folder (summary.json, CASE.pvd)")
    parser.add_argument("--state", type=pathlib.Path, default=None, help="state file (default FOLDER/grit_view.pvsm)")
    parser.add_argument("--screenshot", type=pathlib.Path, default=None, help="also render the view to this PNG")
    parser.add_argument("--time", type=float, default=None, help="time of the screenshot [s] (default: last)")
    parser.add_argument("--zoom", type=float, default=1.0,
                        help="camera zoom of the screenshot (1: the specimen, or with --whole the whole run)")
    parser.add_argument("--whole", action="store_true",
                        help="frame the whole run (water, grains, walls), not the specimen")
    args = parser.parse_args()

    folder = args.folder.resolve()
    summary_file = folder / "summary.json"
    if not summary_file.exists():
        sys.exit(f"error: {folder} has no summary.json (not a grit run folder?)")
    summary = json.loads(summary_file.read_text())
    case, dx = summary["case"], summary["particle_spacing"]
    dimension = summary.get("dimension", 3)
    pvd = folder / f"{case}.pvd"
    if not pvd.exists():
        sys.exit(f"error: {pvd} is missing (a run without SPH particles, or output.snapshots = false)")
    datasets = [folder / e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]
    names = material_names(datasets[0]) if datasets else []
    can_render = ensure_display(need_render=args.screenshot is not None)

    view = pv.GetActiveViewOrCreate("RenderView")
    view.SuppressRendering = 0 if can_render else 1  # no display: the animation scene must not render
    view.OrientationAxesVisibility = 1
    particles = pv.PVDReader(registrationName=case, FileName=str(pvd))
    pv.Hide(particles, view)
    steps = particles.TimestepValues
    times = list(steps) if hasattr(steps, "__len__") else [steps]
    first = times[0] if times else 0.0
    at = args.time if args.time is not None else (times[-1] if times else 0.0)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = at
    view.ViewTime = at

    # Water (and any fluid), walls, and one object per solid material.
    fluid = threshold(particles, "phase", FLUID, "fluid")
    walls = threshold(particles, "phase", WALL, "walls")
    solids = threshold(particles, "phase", SOLID, "solids")
    pv.Hide(solids, view)

    d = point_gaussian(fluid, view, 0.6 * dx)
    pv.ColorBy(d, ("POINTS", "velocity", "Magnitude"))
    speed = d.LookupTable = pv.GetColorTransferFunction("velocity")
    speed.ApplyPreset("Cool to Warm", True)
    d.SetScalarBarVisibility(view, True)
    bars = [colour_bar(speed, view, "speed [m/s]")]

    d = point_gaussian(walls, view, 0.6 * dx)
    d.ColorArrayName = ["POINTS", ""]
    d.AmbientColor = d.DiffuseColor = [0.6, 0.6, 0.6]
    if dimension == 3:
        d.Opacity = 0.2  # a tank's walls would hide the water

    strain = pv.GetColorTransferFunction("plastic_strain")
    strain.ApplyPreset("Inferno (matplotlib)", True)
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
    if solid_objects:
        bars.append(colour_bar(strain, view, "plastic strain [-]"))

    shown = [fluid, walls, *solid_objects]
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
        shown.append(glyph)

    label = time_label(particles, view, times, at)

    # Colour ranges of the shown time (the first output is at rest), from 0; no speed bar without water.
    ranges = ((speed, "velocity", -1, [fluid], 1.0), (strain, "plastic_strain", 0, solid_objects, 0.01))
    for lut, array, component, sources, floor in ranges:
        tops = []
        for source in sources:
            source.UpdatePipeline(at)
            info = source.GetDataInformation()
            found = info.GetPointDataInformation().GetArrayInformation(array)
            if found is not None and info.GetNumberOfPoints() > 0:
                tops.append(found.GetComponentRange(component)[1])
        if tops:
            lut.RescaleTransferFunction(0.0, max(max(tops), floor))
    if bounds_of([fluid], at) is None and bounds_of([fluid], times[-1] if times else at) is None:
        pv.GetDisplayProperties(fluid, view).SetScalarBarVisibility(view, False)

    # The camera: the specimen (the solids), or everything when asked or when there are no solids;
    # the particles' discs reach 0.6 dx beyond their centres.
    box = None if args.whole else bounds_of(solid_objects, at)
    box = specimen_box(box, summary, dimension) if box else bounds_of(shown, at)
    if box is None:
        box = [-1.0, 1.0, -1.0, 1.0, -1.0, 1.0]
    box = [b + (0.6 * dx if i % 2 else -0.6 * dx) for i, b in enumerate(box)]
    aspect = SCREENSHOT_SIZE[0] / SCREENSHOT_SIZE[1]
    share = 0.1  # the colour bars' share of the width, on the right
    if dimension == 2:
        frame_2d(view, box, aspect, share)
    else:
        frame_3d(view, box, aspect, share)

    state = (args.state or folder / "grit_view.pvsm").resolve()
    view.SuppressRendering = 0
    pv.SaveState(str(state))
    relative_file_names(state, folder)
    print(state)
    if args.screenshot and can_render:
        view.ViewSize = SCREENSHOT_SIZE
        zoom(view, args.zoom)
        screenshot_font([label], bars)
        pv.SaveScreenshot(str(args.screenshot), view, ImageResolution=SCREENSHOT_SIZE)
        print(args.screenshot)


if __name__ == "__main__":
    main()
