"""The trajectory's arrays: float64, one value per row, no NaN, handed over from Rust without
a copy (numpy holds the Rust vector's memory), and the pandas view of them."""

import numpy as np
import pytest

import mechkit


@pytest.fixture(scope="module")
def run():
    from conftest import EXAMPLES

    return mechkit.Scenario.load(EXAMPLES / "feather.toml").run()


def test_arrays_are_float64_columns_of_equal_length(run):
    rows = len(run)
    # the feather lands at 4.8354 s; every 10th of 1 ms steps, plus the first and last rows
    assert 480 < rows < 490
    for name, a in run.trajectory.items():
        assert isinstance(a, np.ndarray), name
        assert a.dtype == np.float64 and a.ndim == 1 and a.shape == (rows,), name
        assert not np.isnan(a).any(), name
        assert a.flags.c_contiguous
    t = run.trajectory["t"]
    assert t[0] == 0.0 and np.all(np.diff(t) > 0)


def test_arrays_are_moved_not_copied(run):
    a = run.trajectory["feather.x"]
    # numpy does not own the buffer: the Rust Vec does, kept alive by the array's base
    assert not a.flags.owndata
    assert type(a.base).__name__ == "PySliceContainer"
    # the same array each time
    assert run.trajectory["feather.x"] is a


def test_units(run):
    assert run.units["t"] == "s"
    assert run.units["feather.x"] == "m"
    assert run.units["feather.vx"] == "m/s"
    assert list(run.units) == list(run.trajectory)


def test_to_pandas(run):
    pd = pytest.importorskip("pandas")
    df = run.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == list(run.trajectory)
    assert len(df) == len(run)
    for name, a in run.trajectory.items():
        np.testing.assert_array_equal(df[name].to_numpy(), a)
    assert df.attrs["units"] == run.units
