"""mechkit.md(..., export_lammps=DIR): the same LAMMPS export as `mechkit md --export-lammps
DIR` (the same files, byte for byte), and, where Debian's LAMMPS (`lmp`) is on the PATH,
LAMMPS continuing the run: its potential and total energy per atom at every thermo row equal
mechkit's to 1e-6."""

import os
import shutil
import subprocess

import numpy as np
import pytest

import mechkit
from conftest import mechkit as cli

MELT = dict(cells=4, temperature=1.44, steps=50, thermo_every=10)


def lammps_thermo(directory):
    """LAMMPS's thermo rows (step temp pe ke etotal press) on the export in `directory`."""
    done = subprocess.run(
        ["lmp", "-in", "in.lammps", "-log", "none", "-nocite"],
        cwd=directory,
        capture_output=True,
        text=True,
        check=True,
    )
    lines = done.stdout.splitlines()
    start = next(i for i, l in enumerate(lines) if l.split()[:2] == ["Step", "Temp"])
    rows = []
    for line in lines[start + 1 :]:
        if line.startswith("Loop time"):
            break
        rows.append([float(w) for w in line.split()])
    return np.array(rows)


def test_export_lammps_writes_the_commands_files(tmp_path):
    melt = mechkit.md(**MELT, export_lammps=tmp_path / "py")
    assert melt.report["lammps_export"] == str(tmp_path / "py")
    cli("md", "--cells", "4", "--temperature", "1.44", "--steps", "50", "--thermo-every",
        "10", "--export-lammps", tmp_path / "cli", "-q")
    for name in ("in.lammps", "data.lammps"):
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text()
    assert "\n256 atoms\n" in (tmp_path / "py" / "data.lammps").read_text()
    assert "lammps_export" not in mechkit.md(cells=4, steps=1).report


@pytest.mark.skipif(
    shutil.which("lmp") is None and not os.environ.get("CI"),
    reason="no LAMMPS (`lmp`) on the PATH; CI installs it",
)
def test_lammps_continues_the_run(tmp_path):
    melt = mechkit.md(**MELT, export_lammps=str(tmp_path))
    theirs = lammps_thermo(tmp_path)
    ours = melt.report["thermo"]
    assert theirs[:, 0].tolist() == [row["step"] for row in ours]
    pe = np.array([row["potential_per_atom"] for row in ours])
    total = np.array([row["total_per_atom"] for row in ours])
    assert np.max(np.abs(theirs[:, 2] - pe)) < 1e-6
    assert np.max(np.abs(theirs[:, 4] - total)) < 1e-6


def test_export_lammps_errors(tmp_path):
    with pytest.raises(TypeError, match="export_lammps: a int"):
        mechkit.md(cells=4, steps=1, export_lammps=5)
    taken = tmp_path / "taken"
    taken.write_text("a file")
    with pytest.raises(mechkit.MechkitError, match="export_lammps: cannot write"):
        mechkit.md(cells=4, steps=1, export_lammps=taken)
