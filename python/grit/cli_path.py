"""Where the grit command is, for ``python3 -m grit`` and grit.sweep."""
import os
import pathlib
import shutil


def cli() -> str:
    """The grit executable: $GRIT_EXECUTABLE, the build tree's (beside this package's build), the one in the
    install prefix's bin/, or the first on PATH. Raises FileNotFoundError when there is none."""
    if os.environ.get("GRIT_EXECUTABLE"):
        return os.environ["GRIT_EXECUTABLE"]
    try:
        from ._build_paths import cli as built
        if os.path.isfile(built):
            return built
    except ImportError:
        pass
    for parent in pathlib.Path(__file__).resolve().parents:
        candidate = parent / "bin" / "grit"
        if candidate.is_file():
            return str(candidate)
    found = shutil.which("grit")
    if found:
        return found
    raise FileNotFoundError("the grit executable was not found (set GRIT_EXECUTABLE)")
