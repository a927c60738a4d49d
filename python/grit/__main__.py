"""``python3 -m grit ARGS``: the ``grit`` command with the same arguments (run, check, sweep, plot, ...)."""
import os
import pathlib
import shutil
import sys


def _cli() -> str:
    """The grit executable: $GRIT_EXECUTABLE, the build tree's (beside this package's build), the one in
    the install prefix's bin/, or the first on PATH."""
    if os.environ.get("GRIT_EXECUTABLE"):
        return os.environ["GRIT_EXECUTABLE"]
    try:
        from ._build_paths import cli
        if os.path.isfile(cli):
            return cli
    except ImportError:
        pass
    here = pathlib.Path(__file__).resolve()
    for parent in here.parents:
        candidate = parent / "bin" / "grit"
        if candidate.is_file():
            return str(candidate)
    found = shutil.which("grit")
    if found:
        return found
    sys.exit("grit: the grit executable was not found (set GRIT_EXECUTABLE)")


if __name__ == "__main__":
    cli = _cli()
    os.execv(cli, [cli] + sys.argv[1:])
