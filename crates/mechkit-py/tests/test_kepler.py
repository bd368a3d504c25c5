"""Kepler orbit with an event: a planet started at perihelion r_p = a(1 - e) with
v_p = sqrt(GM(1 + e)/r_p) (GM = 1 m^3/s^2, a = 1 m, e = 0.5) reaches aphelion
r_a = a(1 + e) on the negative x axis after half a period, T/2 = pi sqrt(a^3/GM) = pi s,
where y crosses zero falling; its energy stays E = -GM m/(2a)."""

import math

import numpy as np

import mechkit

KEPLER = """
title = "Kepler orbit, e = 0.5, in units where GM = 1"
dimensions = 2

[constants]
GM = "1 m^3/s^2"
e  = 0.5
rp = "0.5 m"
vp = "sqrt(GM*(1 + e)/rp)"

[[body]]
name     = "planet"
mass     = "1 kg"
position = ["rp", "0 m"]
velocity = ["0 m/s", "vp"]

[[force]]
name   = "sun"
kind   = "newtonian-gravity"
GM     = "GM"
center = ["0 m", "0 m"]

[[event]]
name      = "aphelion"
function  = "y"
direction = "falling"

[integrator]
method = "rk4"
dt     = "1 ms"

[stop]
t_max = "6 s"
"""


def test_kepler_event_at_half_a_period():
    run = mechkit.Scenario.from_str(KEPLER, name="kepler.toml").run()
    assert not run.failed
    events = run.events
    assert [e["name"] for e in events] == ["aphelion"]
    aphelion = events[0]
    assert abs(aphelion["t"] - math.pi) < 1e-6
    x, y = aphelion["state"]["planet"]["position"]
    assert abs(x + 1.5) < 1e-6 and abs(y) < 1e-6
    vx, vy = aphelion["state"]["planet"]["velocity"]
    # moving back along -y at v_a = sqrt(GM (1 - e)/r_a)
    assert abs(vx) < 1e-6 and abs(vy + math.sqrt(0.5 / 1.5)) < 1e-6
    # the event is a row of the trajectory, between the steps around it
    t = run.trajectory["t"]
    assert np.any(t == aphelion["t"])


def test_kepler_energy_and_radius_from_the_arrays():
    run = mechkit.Scenario.from_str(KEPLER).run()
    x = run.trajectory["planet.x"]
    y = run.trajectory["planet.y"]
    vx = run.trajectory["planet.vx"]
    vy = run.trajectory["planet.vy"]
    r = np.hypot(x, y)
    energy = 0.5 * (vx**2 + vy**2) - 1.0 / r
    np.testing.assert_allclose(energy, -0.5, rtol=0, atol=1e-9)
    assert abs(r.min() - 0.5) < 1e-9 and abs(r.max() - 1.5) < 1e-6
    assert abs(run.summary["energy"]["start"] + 0.5) < 1e-12
