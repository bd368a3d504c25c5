"""The example notebooks (examples/notebooks/*.ipynb) run from top to bottom in a fresh
kernel of this Python, in their own folder, as a student would open them: every cell must
run, and their own checks (asserts on the physics) must hold. Their outputs are not
committed (a notebook with outputs fails here too, so the repository stays clean)."""

from pathlib import Path

import pytest

from conftest import ROOT

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

NOTEBOOKS = sorted((ROOT / "examples" / "notebooks").glob("*.ipynb"))


def test_the_examples_have_notebooks():
    names = {p.stem for p in NOTEBOOKS}
    assert {"work_and_energy", "collisions"} <= names, names


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path: Path, tmp_path):
    nb = nbformat.read(path, as_version=4)
    with_outputs = [i for i, c in enumerate(nb.cells) if c.cell_type == "code" and c.get("outputs")]
    assert not with_outputs, f"{path.name}: cells {with_outputs} have outputs; clear them before committing"
    client = nbclient.NotebookClient(
        nb,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    client.execute()
    # each plot a notebook shows is displayed as an image (SVG or PNG), not as a repr
    shown = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    errors = [o for o in shown if o.get("output_type") == "error"]
    assert not errors, errors
    images = [o for o in shown if "image/svg+xml" in o.get("data", {}) or "image/png" in o.get("data", {})]
    assert images, f"{path.name} shows no plot"
