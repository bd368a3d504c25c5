"""Shared helpers: the repository's examples, and the `mechkit` command installed with the
package (the same command line, run in-process by the console script)."""

import csv
import json
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"
# the console script pip put beside this Python
MECHKIT = Path(sys.executable).parent / "mechkit"


def mechkit(*args, cwd=None, check=True):
    """Runs the `mechkit` console script; returns the completed process (text output)."""
    out = subprocess.run(
        [str(MECHKIT), *map(str, args)],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=300,
    )
    if check and out.returncode != 0:
        raise AssertionError(f"mechkit {args} exited {out.returncode}: {out.stderr}")
    return out


def read_csv(path):
    """A CSV file as (header, dict of float64 columns)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    columns = {name: np.array([float(r[i]) for r in body]) for i, name in enumerate(header)}
    return header, columns


def cli_run(scenario, out_dir, *extra):
    """`mechkit run SCENARIO -o OUT_DIR --no-plots EXTRA...`: (summary dict, header, columns)."""
    mechkit("run", scenario, "-o", out_dir, "--no-plots", "--quiet", *extra)
    summary = json.loads((Path(out_dir) / "summary.json").read_text())
    header, columns = read_csv(Path(out_dir) / "trajectory.csv")
    return summary, header, columns


def without_files(summary):
    """The summary less `files` (which says what the command wrote; a Python run writes
    nothing)."""
    return {k: v for k, v in summary.items() if k != "files"}


@pytest.fixture
def feather_path():
    return EXAMPLES / "feather.toml"


@pytest.fixture(autouse=True)
def ctrl_c_raises_keyboard_interrupt():
    """Ctrl-C is Python's KeyboardInterrupt in every test, as in a terminal or a notebook,
    even where the suite was started with SIGINT ignored (a shell's background job: Python
    then keeps the signal ignored, and `_thread.interrupt_main` does nothing)."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)
