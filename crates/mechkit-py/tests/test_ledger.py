"""The energy ledger of the feather (gravity and quadratic drag, Euler-Cromer): the
work-energy residual W_net - dK is the summary's own sums, and it vanishes at first order
as the step shrinks, as does the error of gravity's work against m g x0; the trajectory's
work and kinetic-energy columns agree with the summary and with K = m v^2/2."""

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES

M, G, X0 = 1e-3, 9.8, 2.4


@pytest.fixture(scope="module")
def feather():
    # the example with its step as a constant, h, so that run(h=...) can change it
    text = (EXAMPLES / "feather.toml").read_text()
    text = text.replace('dt     = "1 ms"', 'dt     = "h"')
    text = text.replace('Dmg = "4.0 s^2/m^2"', 'Dmg = "4.0 s^2/m^2"\nh   = "1 ms"')
    assert text.count('"h"') == 1
    return mechkit.Scenario.from_str(text, name="feather_h.toml")


def test_residual_is_the_summarys_own_sums(feather):
    s = feather.run().summary
    work = s["work"]
    assert set(work) == {"gravity", "air"}
    dk = s["kinetic_energy"]["end"] - s["kinetic_energy"]["start"]
    assert abs(s["work_energy_residual"] - (sum(work.values()) - dk)) < 1e-15
    # the air took almost all that gravity gave
    assert work["air"] < 0 and abs(work["air"] + work["gravity"]) < 0.01 * work["gravity"]
    # dE = W_nc, to the size of the residual
    e = s["energy"]
    assert abs(e["change"] - e["non_conservative_work"]) < abs(s["work_energy_residual"])


def test_ledger_errors_are_first_order_in_the_step(feather):
    runs = [feather.run(h=h).summary for h in ("1 ms", "0.5 ms", "0.25 ms")]
    residual = [abs(s["work_energy_residual"]) for s in runs]
    gravity = [abs(s["work"]["gravity"] - M * G * X0) for s in runs]
    assert residual[0] < 1e-4 * M * G * X0
    for errors in (residual, gravity):
        for coarse, fine in zip(errors, errors[1:]):
            assert 1.8 < coarse / fine < 2.2, errors


def test_trajectory_columns_agree_with_the_summary(feather):
    run = feather.run()
    t, s = run.trajectory, run.summary
    assert t["work.gravity"][-1] == s["work"]["gravity"]
    assert t["work.air"][-1] == s["work"]["air"]
    np.testing.assert_allclose(t["K"], 0.5 * M * t["feather.vx"] ** 2, rtol=1e-14, atol=0)
    np.testing.assert_allclose(t["E"], t["K"] + t["U"], rtol=1e-14, atol=1e-18)
    assert t["K"][-1] == s["kinetic_energy"]["end"]
