"""The ``mechkit`` console script: the command line, run in this process."""

import os
import shutil
import signal
import sys

from . import _native


def main() -> None:
    """Runs ``mechkit ARGS...`` and exits with its status, as the ``mechkit`` binary does."""
    # Ctrl-C is the command's, as in the binary: `run`, `sweep` and `md` catch it to finish
    # their outputs (exit 130); the other commands end at once. Python's handler would only
    # note the signal until the command returned.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    # commands that run `mechkit` again (the gallery's scripts) start this script, not the
    # interpreter the command line runs in; by its absolute path, as they may run in another
    # folder than the one it was started from
    script = os.path.abspath(shutil.which(sys.argv[0]) or sys.argv[0])
    os.environ.setdefault("MECHKIT_EXE", script)
    sys.exit(_native.cli(sys.argv[1:]))
