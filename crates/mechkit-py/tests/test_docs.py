"""The examples in the package's docstring and in its README run (from the repository's
root, where their paths point)."""

import doctest
import re

import mechkit
from conftest import ROOT


def test_package_docstring_examples(monkeypatch):
    monkeypatch.chdir(ROOT)
    result = doctest.testmod(mechkit, verbose=False)
    assert result.attempted >= 5
    assert result.failed == 0


def test_readme_quick_start_runs(monkeypatch, tmp_path):
    # in a scratch folder that sees the repository's examples: the blocks save files
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    readme = (ROOT / "crates" / "mechkit-py" / "README.md").read_text()
    # the blocks run in order, as a session typed from the top
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) >= 3
    names = {}
    for code in blocks:
        exec(compile(code, "README.md", "exec"), names)
    assert names["df"].shape == (len(names["run"]), len(names["run"].trajectory))


def test_model_docstring_example(monkeypatch):
    import mechkit._model

    monkeypatch.chdir(ROOT)
    result = doctest.testmod(mechkit._model, verbose=False)
    assert result.attempted >= 4
    assert result.failed == 0


def test_the_repository_readme_python_quick_start_runs(monkeypatch):
    monkeypatch.chdir(ROOT)
    readme = (ROOT / "README.md").read_text()
    (code,) = re.findall(r"```python\n(.*?)```", readme, re.S)
    names = {}
    exec(compile(code, "README.md", "exec"), names)
    # the hand-written loop fell for 1 s towards the terminal speed
    assert -0.5 < names["v"][0] < -0.45
    assert names["df"].shape[0] == len(names["run"])
