"""grit.sweep: a case over the product of parameter lists, as ``grit sweep`` runs it."""
import os
import pathlib
import subprocess
import tempfile
from typing import Any, Dict, Iterable, Optional, Union

from . import _grit
from .case_values import toml_value
from .cli_path import cli
from .run_folder import _read_table


def _values_text(key: str, values: Iterable[Any]) -> str:
    """``key=v1,v2,...`` as --param takes it; a value with a comma in its TOML (a list) cannot be swept."""
    texts = [toml_value(v) for v in values]
    if not texts:
        raise ValueError(f"sweep parameter '{key}': give at least one value")
    for t in texts:
        if "," in t:
            raise TypeError(f"sweep parameter '{key}': {t} has a comma; sweep numbers, strings or booleans")
    return f"{key}={','.join(texts)}"


def sweep(case, parameters: Dict[str, Iterable[Any]], out: Optional[Union[str, os.PathLike]] = None,
          jobs: int = 1, threads: Optional[int] = None, quiet: bool = True):
    """Runs ``case`` over the product of ``parameters`` (``{"jet.pressure": [1.5e8, 2e8], "abrasive.seed":
    [1, 2]}``: the first key varies slowest), as ``grit sweep CASE --param ...`` does: each point a run of
    the grit command in a child process, ``jobs`` at once, sharing ``threads`` (default: all cores).

    Returns sweep.csv (one row per point: the swept values, the crater and erosion figures, status and
    folder) as a pandas DataFrame when pandas is installed, else a dict of numpy arrays. With ``out`` the
    runs' folders and sweep.csv stay there (finished runs of the same case and overrides are kept, not
    run again); without it they go to a temporary folder that is removed."""
    from . import Case, _one_process  # the package's, after it is imported

    _one_process()
    case = case if isinstance(case, Case) else Case.load(case)
    if case._text is not None:
        raise _grit.CaseError("grit.sweep runs the grit command on a case file: save the text to a file and "
                              "use Case.load")
    if not isinstance(jobs, int) or jobs < 1:
        raise _grit.CaseError(f"jobs={jobs!r}: must be a positive whole number")
    args = [cli(), "sweep", case.file]
    for key, values in parameters.items():
        args += ["--param", _values_text(key, values)]
    for o in case.overrides:
        args += ["--set", o]
    args += ["--jobs", str(jobs)]
    if threads is not None:
        args += ["--threads", str(threads)]
    if quiet:
        args.append("--quiet")

    def run_in(folder: pathlib.Path):
        r = subprocess.run(args + ["--out", str(folder)], stdout=subprocess.PIPE if quiet else None,
                           stderr=subprocess.PIPE, text=True)
        if r.returncode == 2:
            raise _grit.CaseError(r.stderr.strip().removeprefix("grit: error: "))
        if r.returncode not in (0, 3):  # 3: some points did not complete (their status says why)
            raise RuntimeError(f"grit sweep exited with {r.returncode}: {r.stderr.strip()}")
        table = _read_table(folder / "sweep.csv")
        try:
            import pandas
        except ImportError:
            return table
        return pandas.DataFrame(table)

    if out is not None:
        return run_in(pathlib.Path(out))
    with tempfile.TemporaryDirectory(prefix="grit_sweep_") as tmp:
        return run_in(pathlib.Path(tmp) / "sweep")
