"""Shared by the plot scripts: run the calling script again with Debian's /usr/bin/python3 when the Python
that started it lacks numpy or matplotlib (python3-numpy, python3-matplotlib)."""
import os
import sys


def require_numpy_and_matplotlib():
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as missing:
        debian = "/usr/bin/python3"
        if os.path.exists(debian) and os.path.realpath(sys.executable) != os.path.realpath(debian):
            os.execv(debian, [debian, *sys.argv])
        sys.exit(f"error: {missing}; install Debian's python3-numpy and python3-matplotlib")
