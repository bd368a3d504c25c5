"""mechkit.md and mechkit.sweep: the same library calls as `mechkit md` and `mechkit sweep`,
so the same numbers. Each result is compared with what the console script writes for the
same input (thermo.csv, rdf.csv, trajectory.xyz, sweep.csv and its sidecars, the overlay
plot, the --json report), and the errors with the command's words; plus the physics of the
examples: the Lennard-Jones dimer turns at r = 1.5 and r = 1.0154323 with E = U(1.5), and a
ball thrown up with v0 rises to x_max = 1 m + (vT^2/2g) ln(1 + v0^2/vT^2)."""

import _thread
import json
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES, mechkit as cli, read_csv

# the report's timings differ from run to run
TIMINGS = ("seconds", "atom_steps_per_second")

LJ_PAIR = EXAMPLES / "md" / "lj_pair.csv"
SPRING_CHAIN = EXAMPLES / "md" / "spring_chain.csv"
THROW = EXAMPLES / "sweep" / "throw.toml"


def untimed(report):
    return {k: v for k, v in report.items() if k not in TIMINGS}


def cli_md(tmp_path, *args):
    """`mechkit md ARGS -o DIR --json`: (report, thermo columns, rdf columns, units, DIR)."""
    out_dir = tmp_path / "md"
    done = cli("md", *args, "-o", out_dir, "--json")
    report = json.loads(done.stdout)
    _, thermo = read_csv(out_dir / "thermo.csv")
    _, rdf = read_csv(out_dir / "rdf.csv")
    units = json.loads((out_dir / "thermo.units.json").read_text())
    return report, thermo, rdf, units, out_dir


def assert_columns_equal(ours, theirs):
    assert list(ours) == list(theirs)
    for name, column in theirs.items():
        np.testing.assert_array_equal(ours[name], column, err_msg=name)


def read_xyz(path):
    """The positions of each frame of an extended-XYZ file, (F, N, 3)."""
    lines = Path(path).read_text().splitlines()
    frames = []
    while lines:
        n = int(lines[0])
        frames.append([[float(x) for x in line.split()[1:4]] for line in lines[2 : 2 + n]])
        lines = lines[2 + n :]
    return np.array(frames)


# --- md ---------------------------------------------------------------------------------


def test_md_lj_dimer_equals_the_command_and_turns_where_it_should(tmp_path):
    flags = ["--boundary", "open", "--dt", "1e-4", "--steps", "20000"]
    flags += ["--thermo-every", "1000", "--xyz-every", "500"]
    report, thermo, rdf, units, out_dir = cli_md(tmp_path, "--positions", LJ_PAIR, *flags)
    dimer = mechkit.md(
        positions=str(LJ_PAIR),
        boundary="open",
        dt=1e-4,
        steps=20000,
        thermo_every=1000,
        xyz_every=500,
    )
    assert untimed(dimer.report) == untimed(report)
    assert dimer.report["start"] == f"2 particles from {LJ_PAIR}"
    assert_columns_equal(dimer.thermo, thermo)
    assert dimer.thermo["step"].dtype.kind in "iu"
    assert_columns_equal(dimer.rdf, rdf)
    assert dimer.thermo_units == units
    assert not dimer.failed and dimer.divergence is None
    # the frames are trajectory.xyz's positions (written to 8 decimals)
    frames = dimer.frames
    assert frames.shape == (41, 2, 3)
    np.testing.assert_array_equal(dimer.frame_steps, np.arange(0, 20001, 500))
    np.testing.assert_allclose(frames, read_xyz(out_dir / "trajectory.xyz"), rtol=0, atol=6e-9)
    # physics: E = U(1.5) per atom-pair throughout, the separation between the turning points
    u0 = 4 * (1.5**-12 - 1.5**-6)
    np.testing.assert_allclose(dimer.thermo["total"], u0, rtol=0, atol=1e-6)
    r = np.abs(frames[:, 1, 0] - frames[:, 0, 0])
    assert r.max() <= 1.5 + 1e-9 and r.min() >= 1.0154323 - 1e-6
    assert dimer.positions.shape == (2, 3) and dimer.velocities.shape == (2, 3)
    np.testing.assert_array_equal(dimer.positions, frames[-1])


def test_md_lattice_melt_equals_the_command(tmp_path):
    flags = ["--cells", "4", "--steps", "40", "--thermo-every", "10", "--threads", "2"]
    report, thermo, rdf, units, _ = cli_md(tmp_path, *flags)
    melt = mechkit.md(cells=4, steps=40, thermo_every=10, threads=2)
    assert untimed(melt.report) == untimed(report)
    assert melt.report["start"] == "fcc lattice" and melt.report["atoms"] == 256
    assert_columns_equal(melt.thermo, thermo)
    assert_columns_equal(melt.rdf, rdf)
    assert melt.thermo_units == units
    assert melt.frames is None and melt.frame_steps is None
    # the velocities start at T = 1.44 (k_B = 1, zero total momentum)
    assert abs(melt.thermo["temperature"][0] - 1.44) < 1e-12
    df = melt.to_pandas()
    assert list(df.columns) == list(thermo) and df.attrs["units"] == units


def test_md_lammps_list_policy_equals_the_command(tmp_path):
    # LAMMPS's bench/in.lj: the list checked every 20 steps, rebuilt whether needed or not
    flags = ["--cells", "4", "--steps", "40", "--neigh-every", "20", "--neigh-check", "no"]
    report, thermo, _, _, _ = cli_md(tmp_path, *flags)
    melt = mechkit.md(cells=4, steps=40, neigh_every=20, neigh_check=False)
    assert untimed(melt.report) == untimed(report)
    assert melt.report["list_builds"] == 3
    assert melt.report["dangerous_builds"] >= 1
    assert_columns_equal(melt.thermo, thermo)
    checked = mechkit.md(cells=4, steps=40)
    assert checked.report["dangerous_builds"] == 0


def test_md_positions_as_an_array_equal_the_file(tmp_path):
    flags = ["--box", "16", "--potential", "spring", "--k", "1", "--rest-length", "1"]
    flags += ["--cutoff", "1.5", "--dt", "0.008051636", "--steps", "2000"]
    flags += ["--thermo-every", "100"]
    report, thermo, _, _, _ = cli_md(tmp_path, "--positions", SPRING_CHAIN, *flags)
    lines = SPRING_CHAIN.read_text().splitlines()
    x = np.array([[float(v)] for v in lines if v and v[0] not in "#x"])
    assert x.shape == (16, 1)
    ring = mechkit.md(
        positions=x,
        box=16,
        potential="spring",
        k=1,
        rest_length=1,
        cutoff=1.5,
        dt=0.008051636,
        steps=2000,
        thermo_every=100,
    )
    assert ring.report["start"] == "16 particles from an array"
    assert untimed(ring.report) == {**untimed(report), "start": ring.report["start"]}
    assert_columns_equal(ring.thermo, thermo)
    # one period of the lowest mode (T = 16.10327) brings every atom back to its start
    np.testing.assert_allclose(ring.positions, x, rtol=0, atol=2e-5)


def cli_error(*args):
    out = cli(*args, check=False)
    assert out.returncode == 2, out.stderr
    return out.stderr.removeprefix("error: ").rstrip("\n")


@pytest.mark.parametrize(
    "kwargs, flags, key",
    [
        ({"density": -1.0, "cells": 2}, ["--density", "-1", "--cells", "2"], "density"),
        ({"dt": 0.0}, ["--dt", "0"], "dt"),
        ({"threads": 0, "cells": 4}, ["--threads", "0", "--cells", "4"], "threads"),
        (
            {"rest_length": -1.0, "potential": "spring"},
            ["--rest-length", "-1", "--potential", "spring"],
            "rest_length",
        ),
        ({"cells": 0}, ["--cells", "0"], "cells"),
        ({"thermo_every": 0}, ["--thermo-every", "0"], "thermo_every"),
        ({"neigh_every": 0}, ["--neigh-every", "0"], "neigh_every"),
        ({"lattice": "bcc"}, ["--lattice", "bcc"], "lattice"),
        ({"potential": "morse"}, ["--potential", "morse"], "potential"),
    ],
)
def test_md_errors_name_the_argument_in_the_commands_words(kwargs, flags, key):
    with pytest.raises(mechkit.MechkitError) as info:
        mechkit.md(steps=1, **kwargs)
    flag = "--" + key.replace("_", "-")
    assert str(info.value) == cli_error("md", "--steps", "1", *flags).replace(flag, key, 1)
    assert str(info.value).startswith(f"{key}: ")


def test_md_argument_errors(tmp_path):
    with pytest.raises(TypeError, match="keyword argument `density_`; did you mean `density`"):
        mechkit.md(density_=0.8)
    with pytest.raises(TypeError, match="cells is a float"):
        mechkit.md(cells=1.5)
    with pytest.raises(mechkit.MechkitError, match=r"cells: `-2` is not a whole number ≥ 0"):
        mechkit.md(cells=-2)
    with pytest.raises(TypeError, match="shift is a int"):
        mechkit.md(shift=1)
    with pytest.raises(mechkit.MechkitError, match="box goes with positions"):
        mechkit.md(box=10)
    with pytest.raises(mechkit.MechkitError, match="temperature and velocities cannot both"):
        mechkit.md(positions=LJ_PAIR, velocities=LJ_PAIR, temperature=1.0, box=10)
    with pytest.raises(mechkit.MechkitError, match="box: a periodic box needs its edge lengths"):
        mechkit.md(positions=LJ_PAIR)
    with pytest.raises(mechkit.MechkitError, match=r"box: 2 lengths for 3-D positions; give 1"):
        mechkit.md(positions=LJ_PAIR, box=[10, 10])
    with pytest.raises(mechkit.MechkitError, match=r"positions: an array of shape \(2, 4\)"):
        mechkit.md(positions=np.zeros((2, 4)), boundary="open")
    bad = tmp_path / "bad.csv"
    bad.write_text("0,0\n1,x\n")
    with pytest.raises(mechkit.MechkitError) as info:
        mechkit.md(positions=bad, boundary="open")
    assert str(info.value) == cli_error("md", "--positions", bad, "--boundary", "open").replace(
        "--positions", "positions"
    )
    with pytest.raises(mechkit.MechkitError, match="positions: cannot read"):
        mechkit.md(positions=tmp_path / "missing.csv", boundary="open")


def test_md_divergence_is_reported_as_the_command_does():
    # a 2-D lattice where atoms overlap hard, and a huge step
    flags = ["--lattice", "square", "--cells", "12", "--density", "3", "--dt", "1", "--steps", "50"]
    out = cli("md", *flags, check=False)
    assert out.returncode == 1
    blown = mechkit.md(lattice="square", cells=12, density=3, dt=1, steps=50)
    assert blown.failed
    assert f"error: {blown.divergence}" in out.stderr.splitlines()
    assert blown.divergence.startswith("the run diverged at step ")


def test_ctrl_c_stops_md():
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            mechkit.md(cells=6, steps=10**8, thermo_every=10**7)
    finally:
        timer.cancel()
    assert 0.5 <= time.monotonic() - start < 5.0


# --- sweep ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def throws(tmp_path_factory):
    """`mechkit sweep throw.toml --set v0=0:5:51 -o DIR` and mechkit.sweep of the same."""
    out_dir = tmp_path_factory.mktemp("sweep")
    done = cli("sweep", THROW, "--set", "v0=0:5:51", "--threads", "2", "-o", out_dir, "--json")
    ours = mechkit.sweep(THROW, "v0=0:5:51", threads=2)
    return ours, out_dir, json.loads(done.stdout)


def test_sweep_table_equals_sweep_csv(throws):
    ours, out_dir, done = throws
    text = (out_dir / "sweep.csv").read_text()
    assert ours.to_csv() == text
    assert len(ours) == done["rows"] == 51 and ours.runs == 51
    header = text.splitlines()[0].split(",")
    assert list(ours.table) == header
    rows = [line.split(",") for line in text.splitlines()[1:]]
    for i, name in enumerate(header):
        column = [r[i] for r in rows]
        if name == "stop_reason":
            assert list(ours.table[name]) == column
        else:
            expected = np.array([float(c) if c else np.nan for c in column])
            np.testing.assert_array_equal(ours.table[name], expected, err_msg=name)
    assert ours.units == json.loads((out_dir / "sweep.units.json").read_text())
    assert ours.manifest == json.loads((out_dir / "sweep.manifest.json").read_text())
    assert ours.params == ["v0"] and ours.observables == ["x_max", "v_land"]


def test_sweep_rows_are_the_runs_summaries(throws):
    ours, _, _ = throws
    table = ours.table
    for i, row in enumerate(ours.rows):
        assert row["index"] == i
        assert row["values"] == [table["v0"][i]]
        assert row["stop_reason"] == table["stop_reason"][i] == "event"
        assert row["steps"] == table["steps"][i]
        assert row["observables"] == [table["x_max"][i], table["v_land"][i]]
        assert row["energy_end"] == table["E_end"][i]
    # physics: x_max = 1 m + (vT^2 / 2g) ln(1 + v0^2/vT^2) with vT = 2 m/s (RK4, 1 ms)
    v0 = table["v0"]
    exact = 1.0 + 4.0 / 19.6 * np.log1p(v0**2 / 4.0)
    np.testing.assert_allclose(table["x_max"], exact, rtol=0, atol=5e-6)


def test_sweep_overlay_plot_is_the_commands(throws):
    ours, out_dir, done = throws
    plot = ours.plot()
    assert Path(done["plot"]).name == "sweep_v_x.svg"
    assert plot.svg == (out_dir / "sweep_v_x.svg").read_text()
    assert plot.title == "51 runs, v0=0:5:51"


def test_sweep_to_pandas(throws):
    pd = pytest.importorskip("pandas")
    ours, out_dir, _ = throws
    df = ours.to_pandas()
    expected = pd.read_csv(out_dir / "sweep.csv")
    pd.testing.assert_frame_equal(df, expected, check_dtype=False)


def test_sweep_arguments_as_keywords_a_scenario_and_shards(tmp_path):
    out_dir = tmp_path / "parts"
    flags = ["--set", "v0=1:4:4", "--set", "Dmg=0.25,0.5", "--shard", "2/3", "--no-plots"]
    cli("sweep", THROW, *flags, "-o", out_dir, "-q")
    scenario = mechkit.Scenario.load(THROW)
    part = mechkit.sweep(scenario, v0="1:4:4", Dmg=[0.25, 0.5], shard="2/3", threads=1, plot=False)
    assert part.to_csv() == (out_dir / "sweep.part2.csv").read_text()
    assert part.manifest == json.loads((out_dir / "sweep.part2.manifest.json").read_text())
    assert len(part) == 3 and part.runs == 8
    with pytest.raises(mechkit.MechkitError, match="the sweep recorded no plot"):
        part.plot()
    # the --set texts and the keyword forms are one sweep
    a = mechkit.sweep(THROW, ["v0=1,2", "Dmg=0.25"], plot=False)
    b = mechkit.sweep(THROW, v0=[1, 2], Dmg=0.25, plot=False)
    assert a.to_csv() == b.to_csv()
    # a random sample, seeded
    c = mechkit.sweep(THROW, v0="0:5:51", random=4, seed=3, plot=False)
    d = cli("sweep", THROW, "--set", "v0=0:5:51", "--random", "4", "--seed", "3", "--no-plots")
    assert c.to_csv() == d.stdout


@pytest.mark.parametrize(
    "sets, flags",
    [
        (["v0=1:2"], ["--set", "v0=1:2"]),
        (["v0=1,2", "v0=3"], ["--set", "v0=1,2", "--set", "v0=3"]),
        (["zz=1,2"], ["--set", "zz=1,2"]),
    ],
)
def test_sweep_errors_are_the_commands(sets, flags):
    with pytest.raises(mechkit.MechkitError) as info:
        mechkit.sweep(THROW, sets, plot=False)
    assert str(info.value) == cli_error("sweep", THROW, *flags, "--no-plots")


def test_sweep_argument_errors():
    with pytest.raises(mechkit.MechkitError, match="a sweep needs at least one --set"):
        mechkit.sweep(THROW)
    with pytest.raises(mechkit.MechkitError, match="threads must be at least 1"):
        mechkit.sweep(THROW, v0="1,2", threads=0)
    with pytest.raises(mechkit.MechkitError) as info:
        mechkit.sweep(THROW, v0="1,2", plot="w(t)")
    assert str(info.value) == cli_error("sweep", THROW, "--set", "v0=1,2", "--plot", "w(t)")
    with pytest.raises(TypeError, match="v0 is a bool"):
        mechkit.sweep(THROW, v0=True)
    with pytest.raises(TypeError, match="scenario is a int"):
        mechkit.sweep(3, v0=1)
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.sweep(THROW.with_name("missing.toml"), v0=1)
    assert info.value.kind == "io"


def test_ctrl_c_stops_a_sweep():
    long_throw = THROW.read_text().replace('dt     = "1 ms"', 'dt     = "1 us"')
    scenario = mechkit.Scenario.from_str(long_throw, name="throw.toml")
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            mechkit.sweep(scenario, v0="0:5:200", threads=2)
    finally:
        timer.cancel()
    assert 0.5 <= time.monotonic() - start < 5.0


def test_the_gil_is_released_during_a_sweep():
    counted = 0
    worker = threading.Thread(
        target=lambda: mechkit.sweep(THROW, v0="0:5:200", threads=1, plot=False)
    )
    worker.start()
    # pure Python work, which needs the GIL, while the sweep computes on the other thread
    while worker.is_alive():
        counted += 1
    worker.join()
    assert counted > 10_000
