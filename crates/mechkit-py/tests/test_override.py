"""Keyword arguments of run() override [constants] as the command line's --set does: a block
of mass m on a spring k = 8 N/m released at x0 = 0.1 m turns back (v = 0, rising) after half
a period, t = pi sqrt(m/k): pi/sqrt(8) s for the file's m = 1 kg, pi/2 s for m = 2 kg."""

import math

import numpy as np
import pytest

import mechkit
from conftest import cli_run, mechkit as mechkit_cli, without_files

SPRING = """
title = "block on a spring"
dimensions = 1

[constants]
m  = "1 kg"
k  = "8 N/m"
x0 = "0.1 m"

[[body]]
name     = "block"
mass     = "m"
position = "x0"

[[force]]
name        = "spring"
kind        = "spring"
k           = "k"
rest_length = "0 m"
anchor      = "0 m"

[[event]]
name      = "turn"
function  = "v"
direction = "rising"

[integrator]
method = "rk4"
dt     = "1 ms"

[stop]
t_max = "2 s"
"""


@pytest.fixture
def spring(tmp_path):
    path = tmp_path / "spring.toml"
    path.write_text(SPRING)
    return path


def turn_time(run):
    (turn,) = run.events
    return turn["t"]


def test_the_files_constants(spring):
    scenario = mechkit.Scenario.load(spring)
    assert scenario.constants == {"m": 1.0, "k": 8.0, "x0": 0.1}
    assert abs(turn_time(scenario.run()) - math.pi / math.sqrt(8)) < 1e-6


def test_override_with_units_and_in_si_match_set(spring, tmp_path):
    scenario = mechkit.Scenario.load(spring)
    with_units = scenario.run(m="2 kg")
    in_si = scenario.run(m=2.0)
    in_grams = scenario.run(m="2000 g")
    assert abs(turn_time(with_units) - math.pi / 2) < 1e-6

    summary, header, columns = cli_run(spring, tmp_path / "out", "--set", "m=2kg")
    for run in (with_units, in_si, in_grams):
        assert without_files(run.summary) == without_files(summary)
        assert list(run.trajectory) == header
        for name in header:
            np.testing.assert_array_equal(run.trajectory[name], columns[name], err_msg=name)
    # the scenario itself is unchanged
    assert abs(turn_time(scenario.run()) - math.pi / math.sqrt(8)) < 1e-6


def test_several_overrides_and_formulas(spring):
    # a formula of pi, in SI
    run = mechkit.Scenario.load(spring).run(m="2 kg", k="2*pi^2")
    # omega = sqrt(k/m) = pi: the turn at t = 1 s
    assert abs(turn_time(run) - 1.0) < 1e-6


def cli_error(spring, set_text):
    out = mechkit_cli("run", spring, "--set", set_text, check=False)
    assert out.returncode == 2
    assert out.stderr.startswith("error: ")
    return out.stderr[len("error: ") :].rstrip("\n")


def test_unknown_constant_is_the_command_lines_error(spring):
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.Scenario.load(spring).run(mass=2.0)
    e = info.value
    assert isinstance(e, mechkit.MechkitError)
    assert str(e) == cli_error(spring, "mass=2")
    assert "`mass`" in e.message and e.kind == "unknown_key"
    assert e.line is None and e.column is None and e.file is None


def test_wrong_dimension_is_the_command_lines_error(spring):
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.Scenario.load(spring).run(m="2 m")
    assert str(info.value) == cli_error(spring, "m=2 m")
    assert info.value.kind == "dimension"
    assert info.value.hint is not None


def test_values_that_are_not_numbers(spring):
    scenario = mechkit.Scenario.load(spring)
    with pytest.raises(TypeError):
        scenario.run(m=[2.0])
    with pytest.raises(TypeError):
        scenario.run(m=True)
    with pytest.raises(mechkit.ScenarioError):
        scenario.run(m=float("nan"))
    with pytest.raises(mechkit.ScenarioError) as info:
        scenario.run(m="2 kgg")
    assert str(info.value) == cli_error(spring, "m=2 kgg")
