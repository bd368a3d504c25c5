#!/usr/bin/env bash
# Builds the mechkit Python package into a fresh virtual environment and runs its pytest suite.
#
#   bash crates/mechkit-py/tests/run.sh [PYTEST ARGS...]
#
# The package is built by pip through maturin (a release build) in the workspace's target
# directory, shared with cargo: $CARGO_TARGET_DIR, or target/ when unset. The environment is
# $CARGO_TARGET_DIR/py-venv (target/py-venv), made anew each time. Needs python3 (3.9 or
# later) with venv and pip, and PyPI for maturin, numpy, pandas, pytest, scipy (the peer the
# tests compare with), nbclient, nbformat and ipykernel (to run the example notebooks) and
# vermin (to check that the Python files need nothing newer than 3.9), and dask[distributed]
# (for `mechkit.sweep(..., client=...)` on a LocalCluster).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
cd "$root"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}"
venv="$CARGO_TARGET_DIR/py-venv"

rm -rf "$venv"
python3 -m venv "$venv"
echo "run.sh: building and installing ./crates/mechkit-py[pandas] into $venv (a release build)"
start=$SECONDS
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check "./crates/mechkit-py[pandas]" pytest scipy nbclient nbformat ipykernel vermin "dask[distributed]"
echo "run.sh: pip install took $((SECONDS - start)) s"

export PYTHONDONTWRITEBYTECODE=1
# from the tests' folder, so that `import mechkit` finds the installed package only
cd crates/mechkit-py/tests
exec "$venv/bin/python" -m pytest -p no:cacheprovider "$@" .
