"""The `mechkit` console script runs the command line in this package: its version, its exit
statuses (0, 2) and its outputs."""

import json
import os
import subprocess

import mechkit
from conftest import EXAMPLES, MECHKIT, mechkit as mechkit_cli


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


def test_gallery_scripts_find_a_console_script_started_by_a_relative_path():
    # `target/py-venv/bin/mechkit gallery` (CI's way): the case's script runs in another
    # folder, where that relative path names nothing
    venv = MECHKIT.parent.parent
    out = subprocess.run(
        [os.path.join("bin", MECHKIT.name), "gallery", "c05-B27", "--json"],
        cwd=venv,
        capture_output=True,
        text=True,
        timeout=300,
        env={k: v for k, v in os.environ.items() if k != "MECHKIT_EXE"},
    )
    assert out.returncode == 0, out.stderr
    [case] = json.loads(out.stdout)
    assert case["error"] is None, case
