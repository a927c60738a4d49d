"""A finished (or interrupted) run's folder, read back as arrays: grit.Run."""
import csv
import json
import pathlib
import re
from typing import Dict, List, Optional

import numpy as np

from ._vtu import read_vtu


def _read_table(path: pathlib.Path) -> Dict[str, np.ndarray]:
    """A CSV grit wrote (a header row, then rows) as one array per column: numbers as float64 (an empty
    cell, a value a run does not have, as NaN), a column with text in it as strings."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty, not a table grit wrote")
    head, body = rows[0], rows[1:]
    for n, row in enumerate(body, start=2):
        if len(row) != len(head):
            raise ValueError(f"{path} line {n}: {len(row)} values for {len(head)} columns")
    out = {}
    for k, name in enumerate(head):
        column = [row[k] for row in body]
        try:
            out[name] = np.array([float(v) if v != "" else np.nan for v in column], dtype=np.float64)
        except ValueError:
            out[name] = np.array(column, dtype=str)
    return out


def _pvd_entries(path: pathlib.Path) -> List[tuple]:
    """(time, file) of each dataset a .pvd collection lists, in its order."""
    text = path.read_text()
    return [(float(t), path.parent / f) for t, f in re.findall(r'<DataSet timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


class Run:
    """The files of one run (``grit run --out DIR`` or ``grit.run(case, out=DIR)``), read back as arrays.

    ``Run.open(folder)``; then ``series`` (series.csv: a dict of arrays, or a pandas DataFrame when pandas is
    installed), ``summary`` (summary.json as a dict), ``crater()``, ``impacts``, ``snapshot(i)``,
    ``checkpoints``."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        if not (self.folder / "series.csv").is_file():
            raise FileNotFoundError(f"{self.folder}: no series.csv, not a grit run folder")

    @classmethod
    def open(cls, folder) -> "Run":
        """The run whose files lie in ``folder``."""
        return cls(folder)

    @property
    def summary(self) -> dict:
        """summary.json: the run's status, totals and final output values."""
        return json.loads((self.folder / "summary.json").read_text())

    @property
    def name(self) -> str:
        """The case's name (the prefix of its snapshot files)."""
        return self.summary["case"]

    @property
    def series(self):
        """series.csv, one row per output: a pandas DataFrame when pandas is installed, else a dict of
        numpy arrays (``run.series["crater_depth"]``)."""
        table = _read_table(self.folder / "series.csv")
        try:
            import pandas  # noqa: F401 (optional)
        except ImportError:
            return table
        return pandas.DataFrame(table)

    def crater(self) -> Optional[Dict[str, np.ndarray]]:
        """The last crater profile (crater.csv: x, surface [m]), or None for a run without a crater."""
        path = self.folder / "crater.csv"
        return _read_table(path) if path.is_file() else None

    @property
    def impacts(self) -> Optional[Dict[str, np.ndarray]]:
        """impacts.csv (every first contact of a grain with a target: time, grain id, target, speed, angle,
        position), or None for a run without grains. Grain ids are exact (int64)."""
        path = self.folder / "impacts.csv"
        if not path.is_file():
            return None
        table = _read_table(path)
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
        k = rows[0].index("grain")
        table["grain"] = np.array([int(r[k]) for r in rows[1:]], dtype=np.int64)
        return table

    def snapshot_times(self, phase: str = "particles") -> List[float]:
        """The times of the snapshots written (``phase``: "particles" or "grains")."""
        return [t for t, _ in _pvd_entries(self._pvd(phase))]

    def snapshot(self, i: int, phase: str = "particles") -> Dict[str, np.ndarray]:
        """Snapshot ``i`` (negative counts from the last) as arrays: ``Points`` and every point array
        (``phase``: "particles" for the SPH particles, "grains" for the grains)."""
        entries = _pvd_entries(self._pvd(phase))
        if not entries:
            raise IndexError(f"{self.folder}: no {phase} snapshots")
        return read_vtu(entries[i][1])

    @property
    def checkpoints(self) -> List[pathlib.Path]:
        """The checkpoint files, oldest first (``grit run --restart`` continues from the last)."""
        return sorted((self.folder / "checkpoints").glob("*.h5"))

    def restart(self, end_time: Optional[float] = None, case=None, threads: Optional[int] = None,
                quiet: Optional[bool] = None) -> "Run":
        """Continues the run from its latest checkpoint into its own files, as ``grit run CASE --restart DIR``
        does, bit for bit with a run that never stopped. ``end_time`` [s] extends it (time.end); ``case`` (a
        grit.Case or a path) is read again with its overrides after the checkpointed run's, as the command
        line's restart reads it; without it, the case the checkpoint holds (its text and overrides) is used.
        A run already at its end time runs nothing (``summary["status"]`` stays)."""
        from . import Case, _check_threads, _grit, _one_process, _quiet, _Threads

        _one_process()
        if end_time is not None and not end_time > 0.0:
            raise _grit.CaseError(f"end_time={end_time!r}: must be a time after the start [s]")
        if case is not None and not isinstance(case, Case):
            case = Case.load(case)
        source = (None, None, []) if case is None else case._source()
        with _Threads(_check_threads(threads)):
            _grit.restart(str(self.folder), *source, end_time or 0.0, _quiet(quiet))
        return self

    def _pvd(self, phase: str) -> pathlib.Path:
        suffix = {"particles": "", "grains": "_grains"}.get(phase)
        if suffix is None:
            raise ValueError(f"phase '{phase}': the snapshots are of 'particles' or 'grains'")
        return self.folder / f"{self.name}{suffix}.pvd"

    def __repr__(self) -> str:
        return f"grit.Run('{self.folder}')"
