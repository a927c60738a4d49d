#!/usr/bin/python3
# Checks .vtu files (or every .vtu of a .pvd) with VTK's own XML reader: no reader error,
# one VTK_VERTEX cell per point, and the required point-data arrays present.
"""Usage:
  /usr/bin/python3 check_vtu_with_vtk.py FILE.vtu [required_array ...]
  /usr/bin/python3 check_vtu_with_vtk.py --pvd FILE.pvd [required_array ...]

Needs python3-vtk9 (Debian), hence /usr/bin/python3 rather than another python3 on PATH.
Prints "N points, arrays: a, b, ...[; field data: name=[v, ...]]" (per dataset in --pvd mode)
and exits 0; on any
problem prints a message starting with "error:" to stderr and exits 1 (2 for bad usage).
In --pvd mode the .pvd is parsed with xml.etree and each referenced .vtu (relative to the
.pvd's directory) is checked like a single file, with the same required arrays.
"""

import os
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
except ImportError as exc:  # environment problem, not a file problem
    sys.stderr.write(f"error: cannot import vtk ({exc}); run with /usr/bin/python3 "
                     "and install python3-vtk9\n")
    sys.exit(1)

VTK_VERTEX = 1


class CheckError(Exception):
    """A problem with the checked file."""


class ErrorCollector:
    """Collects VTK error and warning messages.

    Messages raised on an observed object (the reader) arrive as ErrorEvent/WarningEvent;
    messages from objects without observers (e.g. the reader's internal XML parser) go to
    the global vtkOutputWindow, which is replaced by a vtkStringOutputWindow to capture them.
    """

    def __init__(self):
        self.messages = []
        self.consumed = 0  # length of the output-window text already reported
        self.window = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(self.window)
        # vtkLogger would print the same errors again, in colour, to stderr.
        vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_OFF)

    def observe(self, obj):
        for event in ("ErrorEvent", "WarningEvent"):
            def callback(caller, ev, call_data=None):
                self.messages.append(f"{ev}: {str(call_data).strip()}")
            callback.CallDataType = vtk.VTK_STRING
            obj.AddObserver(event, callback)

    def take(self):
        """Returns and clears everything collected so far."""
        out = list(self.messages)
        full = self.window.GetOutput()
        text = full[self.consumed:].strip()
        self.consumed = len(full)
        if text:
            out.append(text)
        self.messages.clear()
        return out


COLLECTOR = None


def check_vtu(path, required):
    """Reads `path` with vtkXMLUnstructuredGridReader and returns the summary line."""
    global COLLECTOR
    if COLLECTOR is None:
        COLLECTOR = ErrorCollector()
    COLLECTOR.take()

    if not os.path.isfile(path):
        raise CheckError(f"{path}: no such file")
    reader = vtk.vtkXMLUnstructuredGridReader()
    COLLECTOR.observe(reader)
    if not reader.CanReadFile(path):
        raise CheckError(f"{path}: vtkXMLUnstructuredGridReader cannot read this file "
                         "(not a VTK XML UnstructuredGrid?)")
    reader.SetFileName(path)
    reader.Update()

    messages = COLLECTOR.take()
    if messages:
        raise CheckError(f"{path}: VTK reported problems:\n  " + "\n  ".join(messages))
    code = reader.GetErrorCode()
    if code != 0:
        raise CheckError(f"{path}: reader error code {code} "
                         f"({vtk.vtkErrorCode.GetStringFromErrorCode(code)})")

    grid = reader.GetOutput()
    if grid is None:
        raise CheckError(f"{path}: reader produced no output")
    n_points = grid.GetNumberOfPoints()
    n_cells = grid.GetNumberOfCells()
    if n_points != n_cells:
        raise CheckError(f"{path}: {n_points} points but {n_cells} cells "
                         "(expected one VTK_VERTEX cell per point)")
    if n_cells > 0:
        lo, hi = grid.GetCellTypesArray().GetRange()
        if lo != VTK_VERTEX or hi != VTK_VERTEX:
            raise CheckError(f"{path}: cell types range over [{lo:g}, {hi:g}], "
                             f"expected all VTK_VERTEX ({VTK_VERTEX})")

    pd = grid.GetPointData()
    names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
    for i, name in enumerate(names):
        tuples = pd.GetArray(i).GetNumberOfTuples()
        if tuples != n_points:
            raise CheckError(f"{path}: array '{name}' has {tuples} tuples, "
                             f"expected {n_points}")
    missing = [r for r in required if r not in names]
    if missing:
        raise CheckError(f"{path}: missing required array(s) {', '.join(missing)}; "
                         f"present: {', '.join(names) or '(none)'}")

    fd = grid.GetFieldData()
    lists = []
    for i in range(fd.GetNumberOfArrays()):
        a = fd.GetAbstractArray(i)
        values = [str(a.GetValue(k)) for k in range(a.GetNumberOfValues())]
        lists.append(f"{a.GetName()}=[{', '.join(values)}]")

    line = f"{n_points} points, arrays: {', '.join(names) if names else '(none)'}"
    return line + (f"; field data: {'; '.join(lists)}" if lists else "")


def check_pvd(path, required):
    """Parses the .pvd with xml.etree, checks every referenced .vtu, returns report lines."""
    if not os.path.isfile(path):
        raise CheckError(f"{path}: no such file")
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as exc:
        raise CheckError(f"{path}: not well-formed XML ({exc})") from exc
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise CheckError(f"{path}: not a VTKFile of type Collection")
    collection = root.find("Collection")
    if collection is None:
        raise CheckError(f"{path}: no <Collection> element")
    datasets = collection.findall("DataSet")
    if not datasets:
        raise CheckError(f"{path}: the collection lists no datasets")
    base = os.path.dirname(os.path.abspath(path))
    lines = []
    previous = None
    for k, ds in enumerate(datasets):
        rel = ds.get("file")
        if not rel:
            raise CheckError(f"{path}: DataSet {k} has no file attribute")
        try:
            t = float(ds.get("timestep", ""))
        except ValueError as exc:
            raise CheckError(f"{path}: DataSet {k} ({rel}) has a bad timestep "
                             f"{ds.get('timestep')!r}") from exc
        if previous is not None and t < previous:
            raise CheckError(f"{path}: timesteps decrease at DataSet {k} ({previous} -> {t})")
        previous = t
        try:
            summary = check_vtu(os.path.join(base, rel), required)
        except CheckError as exc:
            raise CheckError(f"{exc}\n  (DataSet {k} of {path})") from exc
        lines.append(f"t={t!r} {rel}: {summary}")
    lines.append(f"{len(datasets)} datasets")
    return lines


def main(argv):
    args = argv[1:]
    if not args or args[0] in ("-h", "--help"):
        sys.stderr.write(__doc__)
        return 2
    try:
        if args[0] == "--pvd":
            if len(args) < 2:
                sys.stderr.write(__doc__)
                return 2
            for line in check_pvd(args[1], args[2:]):
                print(line)
        else:
            print(check_vtu(args[0], args[1:]))
    except CheckError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
