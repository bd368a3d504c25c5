"""The feather of examples/feather.toml (Euler-Cromer, dt = 1 ms, quadratic drag): the
Python run gives the command line's summary and trajectory number for number, and the
course's answers (landing between steps at t = 4.8354 s, terminal speed 0.5 m/s)."""

import json
import math

import numpy as np

import mechkit
from conftest import cli_run, without_files


def test_feather_matches_the_command_line(feather_path, tmp_path):
    run = mechkit.Scenario.load(feather_path).run()
    summary, header, columns = cli_run(feather_path, tmp_path)

    # the same columns in the same order, the same rows, every number equal
    assert list(run.trajectory) == header
    assert len(run) == len(columns["t"]) > 100
    for name in header:
        np.testing.assert_array_equal(run.trajectory[name], columns[name], err_msg=name)
    last = [run.trajectory[name][-1] for name in header]
    assert last == [columns[name][-1] for name in header]

    # the summary is summary.json's, less the files the command wrote
    assert without_files(run.summary) == without_files(summary)
    assert summary["files"]["trajectory"] == "trajectory.csv"

    # the units are those of trajectory.units.json
    units = json.loads((tmp_path / "trajectory.units.json").read_text())
    assert list(run.units.items()) == list(units.items())


def test_feather_lands_where_the_course_says(feather_path):
    run = mechkit.Scenario.load(feather_path).run()
    landing = run.events[0]
    # the continuous answer (4.8354 s) and the loop's last step before the floor (4.834 s)
    assert abs(landing["t"] - 4.8354) < 1e-3
    assert math.isclose(landing["last_step"]["t"], 4.834, abs_tol=1e-9)
    # terminal speed 1/sqrt(Dmg) = 0.5 m/s, reached long before landing
    v = run.trajectory["feather.vx"]
    assert abs(v[-1] + 0.5) < 1e-4
    assert v.min() >= -0.5 - 1e-9
    assert run.summary["stop_reason"] == "event"
    assert not run.failed
    # [observe] t_land = final(t), the last row's time
    assert run.observables["t_land"] == run.trajectory["t"][-1]
