"""grit from Python: set up a case, run it in this process, and read its results as numpy arrays.

    import grit
    case = grit.Case.load("cases/dambreak_2d/case.toml").set("time.end", 0.05)
    run = grit.run(case, out="output/dambreak", threads=2)   # the files `grit run` writes
    run.series["kinetic_energy"], run.summary["steps"]

    sim = grit.Simulation(case)        # in memory, stepped by the caller
    sim.advance(0.01)
    water = sim.fields("fluid")        # {"position": (n, dim), "velocity": ..., "pressure": ...}

The module links the library the ``grit`` command is built from, so a case gives the same results, bit
for bit. Case keys, their validation and their messages are those of ``grit run --set``
(docs/case_files.md); a refused value raises grit.CaseError naming the key, the value and the reason.
"""
import os
import pathlib
import sys
from typing import Any, Callable, Dict, Iterable, Optional, Union

from . import _grit
from .case_values import override
from .run_folder import Run
from .sweep import sweep

__all__ = ["Case", "CaseError", "BlowUp", "Interrupted", "Simulation", "Run", "run", "sweep", "version"]

CaseError = _grit.CaseError
"""A case refused (a ValueError): the message names the key, the value and the reason."""
BlowUp = _grit.BlowUp
"""A run that blew up (a RuntimeError): the message names the step and the particle."""
Interrupted = _grit.Interrupted
"""A run stopped by SIGTERM or SIGUSR1 after writing its checkpoint (SIGINT raises KeyboardInterrupt)."""

version = _grit.version


class Case:
    """A case file (or its text) and the overrides set on it, validated as ``grit check`` validates.

    ``Case.load(path)`` or ``Case.from_string(text)``; ``case.set("jet.velocity", 400.0)`` overrides a value
    as ``--set jet.velocity=400.0`` does (and returns the case, so calls chain); ``case.check()`` builds the
    particles as ``grit check`` does. A case is a value: ``set`` on a copy (``case.copy()``) leaves the
    original as it was."""

    def __init__(self, file: Union[str, os.PathLike], text: Optional[str] = None, overrides: Iterable[str] = ()):
        self._file = str(file)
        self._text = text
        self._overrides = list(overrides)
        self._info = _grit.check_case(self._file, self._text, self._overrides, False)

    @classmethod
    def load(cls, path: Union[str, os.PathLike]) -> "Case":
        """The case in the TOML file ``path`` (relative paths inside it, such as meshes, start from its folder)."""
        return cls(pathlib.Path(path))

    @classmethod
    def from_string(cls, text: str, name: str = "case", folder: Union[str, os.PathLike] = ".") -> "Case":
        """The case whose TOML text is ``text``; ``name`` names its run (as a file's stem does) and relative
        paths inside it start from ``folder``."""
        return cls(pathlib.Path(folder) / f"{name}.toml", text=text)

    def set(self, key: str, value: Any) -> "Case":
        """Overrides ``key`` (a dotted name: ``"jet.velocity"``, ``"grains[0].diameter"``) with ``value`` and
        validates the case at once: a bad key or value raises CaseError and leaves the case unchanged."""
        overrides = self._overrides + [override(key, value)]
        self._info = _grit.check_case(self._file, self._text, overrides, False)
        self._overrides = overrides
        return self

    def copy(self) -> "Case":
        """The same case, to set on without changing this one."""
        return Case(self._file, self._text, self._overrides)

    def check(self) -> Dict[str, Any]:
        """Validates the case and builds its particles, as ``grit check`` does; returns its name, title,
        dimension, end time, output interval and ``grit check``'s estimate (steps, particles, wall time)."""
        return dict(_grit.check_case(self._file, self._text, self._overrides, True))

    @property
    def name(self) -> str:
        """The run's name: the file's stem, or its folder's name for a file named case.toml."""
        return self._info["name"]

    @property
    def dimension(self) -> int:
        return self._info["dimension"]

    @property
    def end_time(self) -> float:
        """time.end [s]."""
        return self._info["end_time"]

    @property
    def overrides(self) -> list:
        """The overrides set, as ``--set`` takes them."""
        return list(self._overrides)

    @property
    def file(self) -> str:
        return self._file

    def _source(self):
        return self._file, self._text, self._overrides

    def __repr__(self) -> str:
        sets = "".join(f" --set {o}" for o in self._overrides)
        return f"grit.Case('{self._file}'{' (text)' if self._text is not None else ''}{sets})"


def _case_of(case: Union[Case, str, os.PathLike]) -> Case:
    return case if isinstance(case, Case) else Case.load(case)


def _one_process() -> None:
    """Refuses to run under an MPI launcher with more than one process: each would run the whole case."""
    for variable in ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"):
        size = os.environ.get(variable, "1")
        if size.isdigit() and int(size) > 1:
            raise RuntimeError(f"grit's Python module runs a case in one process, and this process is one of {size} "
                               f"that an MPI launcher started ({variable} = {size}): each would run the whole case. "
                               f"Run the script without mpirun, or with -np 1")


def _quiet(quiet: Optional[bool]) -> bool:
    """The progress line: shown on a terminal unless quiet=True, as the command line shows it."""
    return (not sys.stderr.isatty()) if quiet is None else bool(quiet)


def _check_threads(threads: Optional[int]) -> Optional[int]:
    if threads is not None and (not isinstance(threads, int) or isinstance(threads, bool) or threads < 1):
        raise CaseError(f"threads={threads!r}: must be a positive whole number")
    return threads


class _Threads:
    """The OpenMP thread count ``threads`` while the block runs (None: as it is), then as it was."""

    def __init__(self, threads: Optional[int]):
        self.threads = threads

    def __enter__(self):
        self.before = _grit.max_threads()
        if self.threads is not None:
            _grit.set_threads(self.threads)

    def __exit__(self, *exc):
        _grit.set_threads(self.before)
        return False


class Simulation:
    """A case built in this process and stepped by the caller, writing no files.

    ``sim = grit.Simulation(case)``; ``sim.advance(t)`` runs to time ``t`` [s]; ``sim.time``, ``sim.step``;
    ``sim.fields("fluid")`` ("solid", "wall", "grains") gives the particles' arrays; ``sim.outputs()`` the
    values series.csv would hold now; ``sim.checkpoint(path)`` writes a checkpoint, and
    ``grit.Simulation(case, checkpoint=path)`` continues from it, bit for bit."""

    def __init__(self, case: Union[Case, str, os.PathLike], threads: Optional[int] = None,
                 checkpoint: Optional[Union[str, os.PathLike]] = None):
        """``threads``: the OpenMP threads while it builds and advances (default: as the command line)."""
        _one_process()
        self.case = _case_of(case)
        self.threads = _check_threads(threads)
        with _Threads(self.threads):
            self._handle = _grit.SimulationHandle(*self.case._source(), "" if checkpoint is None else str(checkpoint))

    @property
    def time(self) -> float:
        """The simulated time [s]."""
        return self._handle.time

    @property
    def step(self) -> int:
        """Steps taken."""
        return self._handle.step

    @property
    def dt(self) -> float:
        """The next step's length [s]."""
        return self._handle.dt

    def advance(self, time: float) -> "Simulation":
        """Runs to ``time`` [s] (absolute, not an increment). Steps land on every output time on the way, as
        ``grit run`` does, so advancing to output times in pieces gives a run's states bit for bit. Ctrl-C stops
        it after the step it is in (within 0.2 s) with KeyboardInterrupt; the state is then that step's."""
        with _Threads(self.threads):
            self._handle.advance(float(time))
        return self

    def fields(self, phase: str = "fluid") -> Dict[str, Any]:
        """The particles of ``phase`` ("fluid", "solid", "wall" or "grains") as numpy arrays (copies):
        ``position`` (n x dim) and every array a snapshot holds (``velocity``, ``pressure``, ``id``, ...)."""
        return self._handle.fields(phase)

    def outputs(self) -> Dict[str, float]:
        """The output values now, named as series.csv and summary.json name them (probes as "probes.NAME")."""
        return self._handle.outputs()

    def checkpoint(self, path: Union[str, os.PathLike]) -> None:
        """Writes a checkpoint of the state now (``grit.Simulation(case, checkpoint=path)`` continues it)."""
        self._handle.checkpoint(str(path))

    def __repr__(self) -> str:
        return f"grit.Simulation({self.case!r}, t = {self.time:g} s, step {self.step})"


def run(case: Union[Case, str, os.PathLike], out: Optional[Union[str, os.PathLike]] = None,
        threads: Optional[int] = None, quiet: Optional[bool] = None, overwrite: bool = False,
        progress: Optional[Callable[[float, int], Any]] = None) -> Union[Run, Dict[str, Any]]:
    """Runs ``case`` to its time.end, as ``grit run CASE --out OUT`` does.

    With ``out``, the run writes the files ``grit run`` writes there and returns them as a grit.Run; a folder
    that holds an earlier run is refused unless ``overwrite=True``. Without ``out`` nothing is written and
    the run's summary (status, steps, final output values) is returned as a dict. ``threads``: the OpenMP
    threads for this run (default: as the command line: OMP_NUM_THREADS, else the cores this process may
    use). The command line's progress line is shown when standard error is a terminal (``quiet`` True or
    False decides instead); ``progress(time, step)``, if given, is called after every output. An exception
    it raises ends the run there. Ctrl-C stops the run with a checkpoint, then raises KeyboardInterrupt."""
    _one_process()
    case = _case_of(case)
    with _Threads(_check_threads(threads)):
        summary = _grit.run(*case._source(), None if out is None else str(out), _quiet(quiet), overwrite, progress)
    return summary if out is None else Run(out)
