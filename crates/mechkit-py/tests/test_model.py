"""`scenario.model()`: the forces of a scenario at given states, for the loops students write.
A hand-written Euler-Cromer loop over it is the run, number for number (with the run's steps); many states at once
give what one state at a time gives; each force's value, power and potential are its law."""

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES


def test_a_hand_written_loop_is_the_run():
    feather = mechkit.Scenario.load(EXAMPLES / "feather.toml")
    run = feather.run()
    model = feather.model()
    assert model.coordinates == ["feather.x"]
    assert model.forces == ["gravity", "air"]
    x, v = model.initial
    dt = 1e-3
    t_rows = run.trajectory["t"]
    xs, vs = [x[0]], [v[0]]
    # the run stops at the landing, located inside its last step: compare the whole steps
    steps = int(round(t_rows[-2] / dt))
    for k in range(steps):
        # the run's steps end at t = k dt exactly: h = (k+1) dt - k dt, which a plain dt
        # matches only to the last bits (the loops would then part at the rounding level)
        h = (k + 1) * dt - k * dt
        v = v + h * model.accel(k * dt, x, v)
        x = x + h * v
        xs.append(x[0])
        vs.append(v[0])
    # the example keeps every 10th step ([output] every = 10), then the landing
    kept = len(run.trajectory["t"]) - 1
    np.testing.assert_array_equal(np.array(xs)[::10][:kept], run.trajectory["feather.x"][:kept])
    np.testing.assert_array_equal(np.array(vs)[::10][:kept], run.trajectory["feather.vx"][:kept])
    assert kept == steps // 10 + 1


def test_many_states_at_once_and_the_forces_laws():
    feather = mechkit.Scenario.load(EXAMPLES / "feather.toml")
    m, g, dmg = 1e-3, 9.8, 4.0
    q = np.linspace(0.0, 2.4, 7)[:, None]
    v = np.linspace(-0.6, 0.3, 7)[:, None]
    out = feather.model().evaluate(np.linspace(0, 1, 7), q, v)
    assert out["accel"].shape == (7, 1)
    np.testing.assert_array_equal(out["force"]["gravity"][:, 0], np.full(7, -m * g))
    np.testing.assert_allclose(
        out["force"]["air"][:, 0], -m * g * dmg * v[:, 0] * np.abs(v[:, 0]), rtol=1e-15
    )
    np.testing.assert_allclose(out["power"]["gravity"], -m * g * v[:, 0], rtol=1e-15)
    np.testing.assert_allclose(out["potential"]["gravity"], m * g * q[:, 0], rtol=1e-15)
    assert np.isnan(out["potential"]["air"]).all()
    # one state at a time gives the same
    for i in range(7):
        one = feather.model().evaluate(float(i) / 6, q[i], v[i])
        assert one["accel"].shape == (1,)
        assert one["accel"][0] == out["accel"][i, 0]


def test_constants_and_shapes():
    feather = mechkit.Scenario.load(EXAMPLES / "feather.toml")
    light = feather.model(Dmg="8 s^2/m^2").evaluate(0.0, [1.0], [-0.5])
    # falling at 0.5 m/s, the air pushes up: -m g Dmg v|v| > 0
    assert light["force"]["air"][0] == pytest.approx(1e-3 * 9.8 * 8 * 0.25, rel=1e-15)
    with pytest.raises(ValueError, match="feather.x"):
        feather.model().evaluate(0.0, [1.0, 2.0], [0.0])
    with pytest.raises(mechkit.ScenarioError, match="feather.x"):
        feather.model().evaluate(0.0, [1.0, 2.0], [0.0, 0.0])
