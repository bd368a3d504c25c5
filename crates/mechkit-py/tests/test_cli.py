"""The `mechkit` console script runs the command line in this package: its version, its exit
statuses (0, 2) and its outputs."""

import json

import mechkit
from conftest import EXAMPLES, mechkit as mechkit_cli


def test_version():
    out = mechkit_cli("--version")
    assert out.stdout.strip() == f"mechkit {mechkit.__version__}"
    assert mechkit.__version__.count(".") == 2


def test_usage_error_exits_2():
    out = mechkit_cli("no-such-command", check=False)
    assert out.returncode == 2
    assert "no-such-command" in out.stderr and out.stdout == ""


def test_help_exits_0():
    out = mechkit_cli("run", "--help")
    assert "Usage: mechkit run" in out.stdout


def test_json_output_of_a_run():
    out = mechkit_cli("run", EXAMPLES / "feather.toml", "--json")
    summary = json.loads(out.stdout)
    run = mechkit.Scenario.load(EXAMPLES / "feather.toml").run()
    assert summary["events"] == run.summary["events"]
    assert summary["t_end"] == run.summary["t_end"]


def test_gallery_scripts_run_the_console_script(tmp_path):
    # a gallery case written as a script of `mechkit` commands: they start this console
    # script again (MECHKIT_EXE), not the interpreter the command line runs in
    out = mechkit_cli("gallery", "c05-B27", "--json", cwd=tmp_path)
    [case] = json.loads(out.stdout)
    assert case["error"] is None, case
    assert case["checks"] and all(c["pass"] for c in case["checks"]), case
