"""Ctrl-C during a long run: the run stops after its current step (through its cancellation
handle) and KeyboardInterrupt is raised; the GIL is free while Rust computes; the console
script, like the binary, finishes its outputs and exits with 130."""

import _thread
import json
import signal
import subprocess
import threading
import time

import pytest

import mechkit
from conftest import MECHKIT

# a feather that falls for 10^10 steps (a minute or two: a run that Ctrl-C did not stop ends
# the test with a failure, not a hang), keeping a row every 10^5
ENDLESS = """
title = "a long fall"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
kind = "uniform-gravity"
[[force]]
name = "air"
kind = "expression"
F = "-0.04*v*abs(v)"
[integrator]
method = "euler-cromer"
dt = "1 us"
[stop]
t_max = "1e3 s"
[output]
every = 100000
"""


def interrupted_after(delay, interrupt):
    scenario = mechkit.Scenario.from_str(ENDLESS)
    timer = threading.Timer(delay, interrupt)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            scenario.run()
    finally:
        timer.cancel()
    return time.monotonic() - start, scenario


@pytest.mark.parametrize(
    "interrupt",
    [_thread.interrupt_main, lambda: signal.raise_signal(signal.SIGINT)],
    ids=["interrupt_main", "SIGINT"],
)
def test_ctrl_c_stops_a_run(interrupt):
    elapsed, scenario = interrupted_after(0.5, interrupt)
    assert 0.5 <= elapsed < 5.0
    # the next run of the same scenario has a handle of its own, not the raised one
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        scenario.run()
    assert time.monotonic() - start >= 0.3


def test_the_gil_is_released_while_rust_runs():
    scenario = mechkit.Scenario.from_str(ENDLESS.replace('t_max = "1e3 s"', 't_max = "100 s"'))
    worker = threading.Thread(target=scenario.run)
    counted = 0
    worker.start()
    start = time.monotonic()
    # pure Python work, which needs the GIL, while the run computes on the other thread
    while worker.is_alive() and time.monotonic() - start < 10:
        counted += 1
    worker.join()
    assert time.monotonic() - start > 0.2
    assert counted > 10_000


def test_console_script_finishes_its_outputs_on_ctrl_c(tmp_path):
    (tmp_path / "endless.toml").write_text(ENDLESS)
    child = subprocess.Popen(
        [str(MECHKIT), "run", "endless.toml", "-o", "out", "--no-plots"],
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    partial = tmp_path / "out" / "trajectory.csv.partial"
    start = time.monotonic()
    while not partial.exists() and time.monotonic() - start < 60:
        time.sleep(0.02)
    time.sleep(0.3)
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=30)
    assert child.returncode == 130, stderr
    assert "interrupted at t = " in stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["stop_reason"] == "interrupted"
    assert (tmp_path / "out" / "trajectory.csv").exists()
