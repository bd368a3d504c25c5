"""Every kind of CSV file mechkit writes, read by pandas and numpy without options.

Run as `python3 tests/python/csv_readers.py MECHKIT` (the binary; `tests/run` passes the debug
build). Each command writes its CSV into a temporary directory; pandas.read_csv and
numpy.genfromtxt(names=True) must read it as it is: one header row, as many columns as the
header has names, the same numbers in both readers, and column names that pandas keeps
exactly; beside it, NAME.units.json gives a unit (or null) for every column of the header. numpy's name validation drops the `.` of a trajectory's `body.x` (the CLI contract
of docs/scenario.md §16); the test checks that this is all it changes.
"""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def run(binary, args, cwd):
    done = subprocess.run([binary, *args], cwd=cwd, capture_output=True, text=True)
    assert done.returncode == 0, f"mechkit {' '.join(args)}: {done.stderr}"


def cases(binary, tmp):
    """(kind, path) of every CSV kind, written by the binary into `tmp`."""
    run(binary, ["run", str(EXAMPLES / "feather.toml"), "--out", "run", "--no-plots"], tmp)
    yield "trajectory.csv (1 body)", tmp / "run/trajectory.csv"
    run(binary, ["run", str(EXAMPLES / "newtons_cradle.toml"), "--out", "cradle", "--no-plots"], tmp)
    yield "trajectory.csv (bodies, centre of mass)", tmp / "cradle/trajectory.csv"
    run(binary, ["sweep", str(EXAMPLES / "sweep/throw.toml"), "--set", "v0=0:5:11",
                 "--out", "sweep", "--no-plots", "-q"], tmp)
    yield "sweep.csv", tmp / "sweep/sweep.csv"
    run(binary, ["sweep", str(EXAMPLES / "sweep/throw.toml"), "--set", "v0=0:5:11",
                 "--shard", "2/3", "--out", "sweep", "--no-plots", "-q"], tmp)
    yield "sweep.partK.csv", tmp / "sweep/sweep.part2.csv"
    run(binary, ["derive", str(EXAMPLES / "data/fallingtennisball02.txt"), "--out", "derive",
                 "--no-plots"], tmp)
    yield "derived.csv", tmp / "derive/derived.csv"
    run(binary, ["work", str(EXAMPLES / "data/forcedata.d"), "--mass", "1", "--out", "work",
                 "--no-plots"], tmp)
    yield "work.csv", tmp / "work/work.csv"
    run(binary, ["impulse", str(EXAMPLES / "data/baseballforce.d"), "--out", "impulse",
                 "--no-plots"], tmp)
    yield "impulse.csv", tmp / "impulse/impulse.csv"
    run(binary, ["potential", "x^2", "--range=-1:1", "--mass", "1", "--x0", "0", "--v0", "1",
                 "--out", "potential", "--no-plots"], tmp)
    yield "potential.csv", tmp / "potential/potential.csv"
    run(binary, ["power", "--power", "20 kW", "--mass", "200 kg", "--at", "5 s",
                 "--out", "power", "--no-plots"], tmp)
    yield "power.csv", tmp / "power/power.csv"
    run(binary, ["friction", "--mass", "1 kg", "--mu-s", "0.6", "--mu-d", "0.4",
                 "--spring-k", "100", "--belt-speed", "0.1 m/s", "--t-max", "3 s",
                 "--out", "friction"], tmp)
    yield "stick_slip.csv", tmp / "friction/stick_slip.csv"
    run(binary, ["roll", "--body", "sphere", "--radius", "11 cm", "--mass", "0.45 kg",
                 "--slope", "20 deg", "--mu", "0.3", "--v0", "2 m/s", "--t-max", "3 s",
                 "--out", "roll"], tmp)
    yield "roll.csv", tmp / "roll/roll.csv"
    run(binary, ["bead", "--circle", "2 m", "--side", "outside", "--start", "0",
                 "--speed", "1 m/s", "--t-max", "3 s", "--out", "bead"], tmp)
    yield "path.csv", tmp / "bead/path.csv"
    run(binary, ["spin", "--moments", "1,2,3", "--omega", "0.01,1,0.01", "--t-max", "20",
                 "--out", "spin"], tmp)
    yield "spin.csv", tmp / "spin/spin.csv"
    run(binary, ["rocket", "--m0", "1000 kg", "--m1", "400 kg", "--mass-rate", "10 kg/s",
                 "--exhaust-speed", "2 km/s", "--g", "9.81", "-o", "rocket", "--no-plots"], tmp)
    yield "rocket.csv", tmp / "rocket/rocket.csv"
    run(binary, ["md", "--cells", "4", "--steps", "20", "--thermo-every", "5",
                 "--out", "md"], tmp)
    yield "thermo.csv", tmp / "md/thermo.csv"
    yield "rdf.csv", tmp / "md/rdf.csv"


def check(kind, path):
    text = path.read_text()
    header = text.splitlines()[0].split(",")
    assert not text.startswith("#"), f"{kind}: a comment line before the header"
    frame = pd.read_csv(path)
    assert list(frame.columns) == header, f"{kind}: pandas names {list(frame.columns)}"
    assert len(frame) == len(text.splitlines()) - 1, f"{kind}: pandas rows"
    table = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    table = np.atleast_1d(table)
    names = list(table.dtype.names)
    assert len(names) == len(header), f"{kind}: numpy reads {len(names)} of {len(header)} columns"
    assert names == [h.replace(".", "") for h in header], f"{kind}: numpy names {names}"
    assert len(table) == len(frame), f"{kind}: numpy rows"
    for name, numpy_name in zip(header, names):
        column = frame[name]
        if pd.api.types.is_numeric_dtype(column):
            left = column.to_numpy(dtype=float)
            right = np.asarray(table[numpy_name], dtype=float)
            same = (left == right) | (np.isnan(left) & np.isnan(right))
            assert same.all(), f"{kind}: column {name} differs between pandas and numpy"
    units_path = path.with_name(path.name[: -len(".csv")] + ".units.json")
    assert units_path.is_file(), f"{kind}: no units sidecar {units_path.name}"
    units = json.loads(units_path.read_text())
    assert list(units) == header, f"{kind}: the sidecar's columns {list(units)} are not the header's"
    for name, unit in units.items():
        assert unit is None or (isinstance(unit, str) and unit), f"{kind}: unit of {name} is {unit!r}"
    return len(frame), len(header)


def main():
    binary = str(Path(sys.argv[1]).resolve())
    with tempfile.TemporaryDirectory() as tmp:
        seen = 0
        for kind, path in cases(binary, Path(tmp)):
            rows, columns = check(kind, path)
            print(f"ok  {kind}: {rows} rows, {columns} columns")
            seen += 1
    print(f"{seen} CSV kinds read by pandas {pd.__version__} and numpy {np.__version__}")


if __name__ == "__main__":
    main()
