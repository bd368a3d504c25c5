"""mechkit.sweep(..., client=...) on a dask.distributed LocalCluster of two worker processes:
the sweep is split into shards run on the workers from the scenario's text, and the parts
merged by the library's merge give exactly the numbers of `mechkit sweep ... -o DIR` (the
bytes of sweep.csv, every float to the bit) and of the sweep without a client, for a grid of
two parameters and for a random sample; a run that fails on a worker comes back as the
command's error naming the run. Skipped where dask.distributed is not installed."""

import _thread
import json
import sys
import threading
import time

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES, mechkit as cli

distributed = pytest.importorskip("distributed")

THROW = EXAMPLES / "sweep" / "throw.toml"
# 40 points of a grid of two parameters
GRID = {"v0": "0:5:10", "Dmg": [0.1, 0.2, 0.25, 0.5]}
GRID_FLAGS = ("--set", "v0=0:5:10", "--set", "Dmg=0.1,0.2,0.25,0.5")

# a scenario whose mass is a constant: a negative one is an invalid run
NEGATIVE_MASS = """\
dimensions = 1
[constants]
m = "1 kg"
v0 = "1 m/s"
[[body]]
name = "ball"
mass = "m"
velocity = "v0"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.8 m/s^2"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
when = "x < 0"
t_max = "1 s"
"""


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        silence_logs=40,
    )
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def exactly_equal(a, b):
    """Two SweepResults with the same columns, every float equal to the bit."""
    assert list(a.table) == list(b.table)
    for name, column in a.table.items():
        other = b.table[name]
        if column.dtype == np.float64:
            assert np.array_equal(column.view(np.uint64), other.view(np.uint64)), name
        else:
            assert column.tolist() == other.tolist(), name


def test_a_grid_on_two_workers_is_the_commands_sweep_csv(client, tmp_path):
    out_dir = tmp_path / "cli"
    cli("sweep", THROW, *GRID_FLAGS, "-o", out_dir, "-q")
    start = time.perf_counter()
    with distributed.get_task_stream(client) as tasks:
        ours = mechkit.sweep(THROW, GRID, client=client)
    took = time.perf_counter() - start
    # 4 shards per worker thread, spread over both workers
    assert len(tasks.data) == 8
    assert len({t["worker"] for t in tasks.data}) == 2
    assert len(ours) == ours.runs == 40
    assert ours.to_csv() == (out_dir / "sweep.csv").read_text()
    assert ours.manifest == json.loads((out_dir / "sweep.manifest.json").read_text())
    assert ours.units == json.loads((out_dir / "sweep.units.json").read_text())
    local = mechkit.sweep(THROW, GRID, threads=2)
    exactly_equal(ours, local)
    assert ours.rows == local.rows
    # the overlay of the runs' plots travelled with the parts
    assert ours.plot().svg == local.plot().svg
    print("dask sweep of 40 runs: {:.2f} s".format(took), file=sys.stderr)


def test_a_random_sample_and_a_scenario_object_on_the_cluster(client, tmp_path):
    scenario = mechkit.Scenario.load(THROW)
    ours = mechkit.sweep(
        scenario, v0="0:5:51", Dmg="0.1:0.5:5", random=25, seed=7, plot=False, client=client
    )
    done = cli(
        "sweep", THROW, "--set", "v0=0:5:51", "--set", "Dmg=0.1:0.5:5",
        "--random", "25", "--seed", "7", "--no-plots", "-o", tmp_path, "-q",
    )
    assert done.returncode == 0
    assert ours.to_csv() == (tmp_path / "sweep.csv").read_text()
    exactly_equal(ours, mechkit.sweep(scenario, ["v0=0:5:51", "Dmg=0.1:0.5:5"], random=25,
                                      seed=7, plot=False))
    with pytest.raises(mechkit.MechkitError, match="the sweep recorded no plot"):
        ours.plot()
    # fewer runs than shards: one shard per run
    few = mechkit.sweep(THROW, v0=[1, 2], client=client)
    assert few.to_csv() == mechkit.sweep(THROW, v0=[1, 2]).to_csv()


def test_a_run_that_fails_on_a_worker_is_the_commands_error(client, tmp_path):
    path = tmp_path / "negative.toml"
    path.write_text(NEGATIVE_MASS)
    done = cli("sweep", path, "--set", "m=1,-1,2", "--set", "v0=1,2", "-o", tmp_path / "o",
               check=False)
    assert done.returncode == 2
    with pytest.raises(mechkit.MechkitError) as info:
        mechkit.sweep(path, {"m": [1, -1, 2], "v0": [1, 2]}, client=client)
    # the first shard to fail names its run: run 2 or run 3, both with m = -1; the rest of
    # the message is the command's
    message = str(info.value)
    expected = done.stderr.strip().removeprefix("error: ")
    assert expected.startswith("run 2 (m=-1, v0=1): the mass of `ball` must be positive")
    run, rest = message.split(": ", 1)
    assert run in ("run 2 (m=-1, v0=1)", "run 3 (m=-1, v0=2)")
    assert rest == expected.split(": ", 1)[1]
    # the cluster is still of use after it
    assert len(mechkit.sweep(path, m=[1, 2], client=client)) == 2


def test_arguments_that_a_cluster_decides_are_refused(client):
    with pytest.raises(mechkit.MechkitError, match="shard goes without client"):
        mechkit.sweep(THROW, v0="1,2", shard="1/2", client=client)
    with pytest.raises(mechkit.MechkitError, match="threads goes without client"):
        mechkit.sweep(THROW, v0="1,2", threads=2, client=client)
    with pytest.raises(TypeError, match="client is a str: give a dask.distributed.Client"):
        mechkit.sweep(THROW, v0="1,2", client="tcp://127.0.0.1:8786")
    # the arguments are checked here, before any shard is sent
    with pytest.raises(mechkit.MechkitError, match="a sweep needs at least one --set"):
        mechkit.sweep(THROW, client=client)


def test_a_client_without_dask_installed_is_a_clear_error(monkeypatch):
    # as if dask.distributed were not installed: its import fails
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(mechkit.MechkitError, match=r"pip install 'mechkit\[dask\]'"):
        mechkit.sweep(THROW, v0="1,2", client=object())


def test_ctrl_c_cancels_the_shards(client, tmp_path):
    # 1e5 steps a run, 400 runs in 8 shards: seconds of work that Ctrl-C cuts short
    path = tmp_path / "long.toml"
    path.write_text(NEGATIVE_MASS.replace('when = "x < 0"\n', "").replace("1 s", "100 s"))
    timer = threading.Timer(0.5, _thread.interrupt_main)
    with distributed.get_task_stream(client) as tasks:
        start = time.perf_counter()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            mechkit.sweep(path, m="1:2:400", plot=False, client=client)
        took = time.perf_counter() - start
        timer.join()
        # the shards not started are dropped: the workers are soon idle
        deadline = time.monotonic() + 30
        while any(client.processing().values()) and time.monotonic() < deadline:
            time.sleep(0.05)
    assert took < 1.5, took
    assert not any(client.processing().values())
    assert len(tasks.data) < 8
