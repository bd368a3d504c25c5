"""Sampled data: mechkit.trapz, cumtrapz and simpson are the sample rules of `mechkit work`
(the same numbers as its --json for the same file) and agree with NumPy's and SciPy's rules to
1e-12; mechkit.derive is `mechkit derive`, on a data file or on arrays. Bad samples raise
MechkitError naming the array."""

import json

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES
from conftest import mechkit as mechkit_cli

FORCEDATA = EXAMPLES / "data" / "forcedata.d"
TENNISBALL = EXAMPLES / "data" / "fallingtennisball02.txt"


def cli_json(*args):
    return json.loads(mechkit_cli(*args, "--json").stdout)


def without_arrays(d):
    """The derive dict less its numpy arrays (the command's JSON has none)."""
    d = dict(d)
    d.pop("t")
    d["columns"] = [{k: v for k, v in c.items() if k not in ("x", "v", "a")} for c in d["columns"]]
    return d


def cli_error(*args):
    out = mechkit_cli(*args, check=False)
    assert out.returncode == 2, out
    return out.stderr[len("error: ") :].rstrip("\n")


def uneven(n, seed=1):
    """n increasing samples on [0, 2], unevenly spaced, and y = sin(x) + x."""
    rng = np.random.default_rng(seed)
    x = np.sort(rng.uniform(0.0, 2.0, n))
    return x, np.sin(x) + x


# exact answers


def test_exact_values():
    assert mechkit.trapz([0.0, 1.0, 4.0], x=[0.0, 1.0, 2.0]) == 3.0
    assert mechkit.trapz([1, 2, 3]) == 4.0  # ints, dx = 1
    assert mechkit.trapz([1, 2, 3], dx=0.5) == 2.0
    # Simpson is exact for a parabola on any spacing, with an odd number of intervals too
    for n in (7, 8):
        x, _ = uneven(n)
        x = np.concatenate([[0.0], x, [2.0]])
        assert mechkit.simpson(x**2, x) == pytest.approx(8 / 3, rel=1e-14)
    # two samples: the trapezoid
    assert mechkit.simpson([2.0, 4.0], [1.0, 3.0]) == 6.0
    c = mechkit.cumtrapz([1.0, 1.0, 3.0], [0.0, 1.0, 2.0])
    assert isinstance(c, np.ndarray) and c.dtype == np.float64
    assert c.tolist() == [0.0, 1.0, 3.0]
    assert mechkit.cumtrapz([1.0, 1.0, 3.0], initial=None).tolist() == [1.0, 3.0]
    assert mechkit.cumtrapz([1.0, 1.0, 3.0], initial=5.0).tolist() == [5.0, 6.0, 8.0]


def test_arrays_of_any_layout():
    x, y = uneven(41)
    whole = mechkit.trapz(y, x)
    assert mechkit.trapz(y.tolist(), x.tolist()) == whole
    # a strided view and another dtype are converted
    assert mechkit.trapz(y[::2], x[::2]) == mechkit.trapz(y[::2].copy(), x[::2].copy())
    assert mechkit.trapz(y.astype(np.float32), x) == mechkit.trapz(
        y.astype(np.float32).astype(np.float64), x
    )


# the rules of `mechkit work`


def test_the_same_numbers_as_mechkit_work():
    x, f = np.loadtxt(FORCEDATA, comments="%", unpack=True)
    work = cli_json("work", FORCEDATA)
    assert mechkit.cumtrapz(f, x).tolist() == work["cumulative"]
    # the command's integral is the running sum's end; trapz sums pairwise: rounding apart
    assert mechkit.trapz(f, x) == pytest.approx(work["integral"], rel=1e-14, abs=0)
    simpson = cli_json("work", FORCEDATA, "--method", "simpson")
    assert mechkit.simpson(f, x) == pytest.approx(simpson["integral"], rel=1e-14, abs=0)
    # F = -sin(2 pi x), from 0 to 1/4: -1/(2 pi)
    assert mechkit.simpson(f, x) == pytest.approx(-1 / (2 * np.pi), rel=1e-8)


# NumPy and SciPy


def test_trapz_is_numpys():
    trapezoid = getattr(np, "trapezoid", None) or np.trapz
    for n in (2, 3, 50, 1001):
        x, y = uneven(n)
        assert mechkit.trapz(y, x) == pytest.approx(trapezoid(y, x), rel=1e-12, abs=0)
        assert mechkit.trapz(y, dx=0.1) == pytest.approx(trapezoid(y, dx=0.1), rel=1e-12, abs=0)


def test_scipys_rules():
    integrate = pytest.importorskip("scipy.integrate")
    import scipy

    version = tuple(int(p) for p in scipy.__version__.split(".")[:2])
    for n in (2, 3, 4, 11, 12, 1000, 1001):
        x, y = uneven(n, seed=n)
        got = mechkit.cumtrapz(y, x)
        want = integrate.cumulative_trapezoid(y, x, initial=0)
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=0)
        got = mechkit.cumtrapz(y, dx=0.25, initial=None)
        np.testing.assert_allclose(got, integrate.cumulative_trapezoid(y, dx=0.25), rtol=1e-12)
        if version >= (1, 11) and n > 2:  # the last interval as SciPy 1.11 and later
            assert mechkit.simpson(y, x) == pytest.approx(integrate.simpson(y, x=x), rel=1e-12)
            assert mechkit.simpson(y, dx=0.5) == pytest.approx(
                integrate.simpson(y, dx=0.5), rel=1e-12
            )


# bad samples


@pytest.mark.parametrize("rule", [mechkit.trapz, mechkit.cumtrapz, mechkit.simpson])
def test_bad_samples(rule):
    with pytest.raises(mechkit.MechkitError, match=r"^x has 3 samples but y has 2$"):
        rule([1.0, 2.0], [0.0, 1.0, 2.0])
    with pytest.raises(mechkit.MechkitError, match=r"^at least 2 samples are needed, not 1$"):
        rule([1.0])
    with pytest.raises(mechkit.MechkitError, match=r"^y\[1\] is NaN: the samples must be finite"):
        rule([1.0, np.nan, 2.0])
    with pytest.raises(mechkit.MechkitError, match=r"^x\[2\] is inf"):
        rule([1.0, 1.0, 2.0], [0.0, 1.0, np.inf])
    with pytest.raises(mechkit.MechkitError) as e:
        rule([1.0, 1.0, 2.0], [0.0, 1.0, 1.0])
    assert str(e.value) == (
        "x must increase strictly, but x[2] = 1 follows x[1] = 1; sort the samples by x and "
        "remove or average repeated values"
    )
    with pytest.raises(mechkit.MechkitError, match=r"^x must increase strictly, but x\[1\] = 0"):
        rule([1.0, 1.0], [1.0, 0.0])
    with pytest.raises(mechkit.MechkitError, match=r"^dx must be a positive finite number, not 0"):
        rule([1.0, 1.0], dx=0.0)
    with pytest.raises(mechkit.MechkitError, match=r"^y must be a 1-D array, not one of shape"):
        rule([[1.0, 2.0], [3.0, 4.0]])


# derive


def test_derive_a_file_as_the_command_does():
    d = mechkit.derive(str(TENNISBALL), smooth=(21, 2))
    assert without_arrays(d) == cli_json("derive", TENNISBALL, "--smooth", "21:2")
    # a path-like object, and the command line's spelling of the filter
    for smooth in ("21:2", [21, 2]):
        assert without_arrays(mechkit.derive(TENNISBALL, smooth=smooth)) == without_arrays(d)
    t, x = np.loadtxt(TENNISBALL, unpack=True)
    np.testing.assert_array_equal(d["t"], t)
    (column,) = d["columns"]
    xs, v, a = column["x"], column["v"], column["a"]
    np.testing.assert_array_equal(xs, x)
    assert v.shape == a.shape == t.shape and v.dtype == np.float64
    # the arrays are those the summaries describe
    assert np.median(a) == pytest.approx(column["acceleration"]["median"], rel=1e-15)
    assert (v[0], v[-1], a.max()) == (
        column["velocity"]["first"],
        column["velocity"]["last"],
        column["acceleration"]["max"],
    )
    # a falling ball: about -9.8 m/s^2 most of the time
    assert -9.9 < np.median(a) < -9.7


def test_derive_arrays_as_a_file_of_them(tmp_path):
    t = np.linspace(0.0, 1.0, 101)
    x = 2.0 - 4.9 * t**2
    d = mechkit.derive(t, x)
    np.testing.assert_allclose(d["columns"][0]["a"], -9.8, rtol=1e-9)
    np.testing.assert_allclose(d["columns"][0]["v"], -9.8 * t, atol=1e-12)
    # the same numbers written to a file with a header: the command's answer
    path = tmp_path / "fall.csv"
    np.savetxt(path, np.column_stack([t, x]), delimiter=",", header="t,x", comments="",
               fmt="%.17g")  # fmt: skip
    cli = cli_json("derive", path)
    assert d["file"] == "<arrays>"
    assert {**without_arrays(d), "file": cli["file"]} == cli


def test_derive_arrays_with_units_and_several_columns():
    t_ms = np.arange(0.0, 50.0, 1.0)
    y_cm = 100.0 * 0.5 * (t_ms / 1000.0) ** 2 * 3.0  # a = 3 m/s^2
    d = mechkit.derive(t_ms, {"y [cm]": y_cm, "z": 2 * t_ms}, t="t [ms]", method="forward")
    assert d["time"] == "t" and d["time_unit"] == "s" and d["method"] == "forward"
    y, z = d["columns"]
    assert (y["name"], z["name"]) == ("y", "z")
    assert y["units"] == {"position": "m", "velocity": "m/s", "acceleration": "m/s^2"}
    assert z["units"] == {"position": None, "velocity": None, "acceleration": None}
    np.testing.assert_allclose(d["t"], t_ms / 1000.0)
    assert y["acceleration"]["median"] == pytest.approx(3.0, rel=1e-9)


def test_derive_columns_by_name_and_number(tmp_path):
    path = tmp_path / "two.csv"
    path.write_text("x [m], time [s], y [m]\n0, 0, 0\n1, 1, 2\n4, 2, 4\n9, 3, 6\n")
    d = mechkit.derive(path, ["y", 1], t="time")
    assert [c["name"] for c in d["columns"]] == ["y", "x"]
    assert d["columns"][1]["acceleration"]["median"] == pytest.approx(2.0)
    assert without_arrays(d) == cli_json("derive", path, "--x", "y,1", "--t", "time")


def test_derive_errors(tmp_path):
    with pytest.raises(mechkit.MechkitError) as e:
        mechkit.derive(TENNISBALL, smooth=20)
    assert "--" + str(e.value) == cli_error("derive", TENNISBALL, "--smooth", "20")
    with pytest.raises(mechkit.MechkitError) as e:
        mechkit.derive(TENNISBALL, t="nope")
    assert "--" + str(e.value) == cli_error("derive", TENNISBALL, "--t", "nope")
    with pytest.raises(mechkit.MechkitError) as e:
        mechkit.derive(TENNISBALL, method="sideways")
    assert "--" + str(e.value) == cli_error("derive", TENNISBALL, "--method", "sideways")
    missing = tmp_path / "nowhere.txt"
    with pytest.raises(mechkit.MechkitError) as e:
        mechkit.derive(missing)
    assert str(e.value) == cli_error("derive", missing)

    t = np.array([0.0, 1.0, 1.0, 2.0])
    with pytest.raises(mechkit.MechkitError, match=r"^t must increase strictly, but t\[2\] = 1"):
        mechkit.derive(t, t)
    with pytest.raises(mechkit.MechkitError, match=r"^x has 3 samples but t has 4$"):
        mechkit.derive(np.arange(4.0), np.arange(3.0))
    with pytest.raises(mechkit.MechkitError, match=r"^x\[0\] is NaN"):
        mechkit.derive(np.arange(4.0), [np.nan, 1, 2, 3])
    with pytest.raises(mechkit.MechkitError, match=r"^x: give the positions"):
        mechkit.derive(np.arange(4.0))
    with pytest.raises(mechkit.MechkitError, match="not both"):
        mechkit.derive(TENNISBALL, method="central", smooth=21)
    with pytest.raises(mechkit.MechkitError, match=r"^smooth 21:x: the window and the polynomial"):
        mechkit.derive(TENNISBALL, smooth="21:x")
    # Savitzky-Golay needs evenly spaced times
    with pytest.raises(mechkit.MechkitError, match="not evenly spaced"):
        mechkit.derive([0.0, 1.0, 3.0, 4.0, 5.0], [0.0, 1.0, 2.0, 3.0, 4.0], smooth=3)
