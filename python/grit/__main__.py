"""``python3 -m grit ARGS``: the ``grit`` command with the same arguments (run, check, sweep, plot, ...)."""
import os
import sys

from .cli_path import cli

if __name__ == "__main__":
    try:
        executable = cli()
    except FileNotFoundError as e:
        sys.exit(f"grit: {e}")
    os.execv(executable, [executable] + sys.argv[1:])
