"""Errors in a scenario: a ScenarioError (a MechkitError) whose str is the command line's
message, with the place in the file as attributes."""

import pytest

import mechkit
from conftest import mechkit as mechkit_cli

BAD_UNIT = """title = "a ball"
dimensions = 1

[[body]]
name     = "ball"
mass     = "1 kgz"
position = "0 m"

[[force]]
kind = "uniform-gravity"

[integrator]
method = "euler"
dt     = "1 ms"

[stop]
t_max = "1 s"
"""


def cli_message(path):
    out = mechkit_cli("run", path, check=False)
    assert out.returncode == 2
    assert out.stderr.startswith("error: ")
    return out.stderr[len("error: ") :].rstrip("\n")


def test_bad_unit_is_located(tmp_path):
    path = tmp_path / "ball.toml"
    path.write_text(BAD_UNIT)
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.Scenario.load(path)
    e = info.value
    assert isinstance(e, mechkit.MechkitError)
    assert str(e) == cli_message(path)
    assert e.file == str(path)
    assert e.line == 6
    line = BAD_UNIT.splitlines()[e.line - 1]
    assert "kgz" in line[e.column - 1 :]
    assert f"--> {path}:{e.line}:{e.column}" in str(e)
    assert e.kind == "unit"
    assert e.message in str(e) and e.message.splitlines() == [e.message]


def test_syntax_error_from_a_string():
    text = BAD_UNIT.replace('mass     = "1 kgz"', 'mass     = "1 kg')
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.Scenario.from_str(text, name="broken.toml")
    e = info.value
    assert e.kind == "syntax"
    assert e.file == "broken.toml" and e.line == 6
    assert "broken.toml:6:" in str(e)


def test_missing_file(tmp_path):
    path = tmp_path / "nowhere.toml"
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.Scenario.load(path)
    e = info.value
    assert e.kind == "io" and e.line is None and e.column is None
    assert str(e) == cli_message(path)


def test_the_classes():
    assert issubclass(mechkit.ScenarioError, mechkit.MechkitError)
    assert issubclass(mechkit.MechkitError, Exception)
    # raised from Python, the attributes are there, None
    e = mechkit.ScenarioError("made here")
    assert (e.line, e.column, e.file, e.hint) == (None, None, None, None)
