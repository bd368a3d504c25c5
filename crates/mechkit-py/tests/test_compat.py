"""The package keeps its promise of CPython 3.9 or later (pyproject's requires-python): its
Python files use nothing newer than 3.9 (checked by vermin, which reads the syntax and the
standard library's names), and the extension is one abi3 module, built for the stable ABI of
3.9, so the same wheel loads on every later CPython."""

import pathlib
import subprocess
import sys

import mechkit
import mechkit._native as native


PACKAGE = pathlib.Path(mechkit.__file__).parent
# the console script pip installed beside this interpreter
VERMIN = str(pathlib.Path(sys.executable).parent / "vermin")


def test_python_files_need_no_more_than_3_9():
    files = sorted(str(p) for p in PACKAGE.glob("*.py")) + sorted(
        str(p) for p in PACKAGE.glob("*.pyi")
    )
    assert len(files) >= 4
    done = subprocess.run(
        [VERMIN, "--no-tips", "--violations", "-t=3.9-", *files],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_vermin_would_catch_a_3_10_feature(tmp_path):
    newer = tmp_path / "newer.py"
    newer.write_text("def f(x: int | None):\n    match x:\n        case 1:\n            pass\n")
    done = subprocess.run(
        [VERMIN, "--no-tips", "--violations", "-t=3.9-", str(newer)],
        capture_output=True,
        text=True,
    )
    assert done.returncode != 0


def test_the_extension_is_one_abi3_module():
    name = pathlib.Path(native.__file__).name
    assert ".abi3." in name, name
