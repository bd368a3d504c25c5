//! For a variable mass `d(mv)/dt` is not the external force: in free space the rocket's
//! momentum grows from 0 to `m1 v1` with no force at all. What is conserved is the momentum of
//! rocket and exhaust together: the mass `ṁ dt` leaves at the ground-frame velocity `v − u`,
//! so `m1 v1 + ∫₀ᵀ ṁ (v − u) dt = m0 v0 = 0`. The integral is taken by Simpson's rule on the
//! simulated samples (one per step).

use mechkit::quad::{simpson, trapz};

use super::{config, rocket};

#[test]
fn rocket_and_exhaust_momentum_is_conserved_in_free_space() {
    let r = rocket();
    let run = r.simulate(&config(1e-12), false).unwrap();
    let (t, v): (Vec<f64>, Vec<f64>) = run.samples.iter().map(|s| (s.0, s.2)).unzip();
    let rate = r.mass_rate;
    let u = r.exhaust_speed;
    let exhaust: Vec<f64> = v.iter().map(|v| rate * (v - u)).collect();
    // Simpson on the integrator's own steps (about a hundred); the trapezoid's O(h²) error is
    // far above 1e-8 on so few samples
    let p_exhaust = simpson(&t, &exhaust);
    let p_trapz = trapz(&t, &exhaust);
    let (_, _, v1) = run.burnout;
    let p_rocket = r.m1 * v1;
    let p_start = 0.0; // m0 v0: the rocket starts from rest
    let residual = (p_rocket + p_exhaust - p_start).abs() / p_rocket;
    println!(
        "momentum: rocket {p_rocket} kg m/s, exhaust {p_exhaust} kg m/s, relative residual {residual:e} over {} samples (trapezoid: {:e})",
        t.len(),
        (p_rocket + p_trapz - p_start).abs() / p_rocket
    );
    assert!(residual < 1e-8, "{residual:e}");
    // the rocket's own momentum is not conserved: it gained m1 v1 with no external force
    assert!(p_rocket > 0.5 * r.m1 * r.delta_v());
}

/// The momentum ledger of a scenario's rocket (`examples/rocket.toml`, launched vertically
/// until burnout): the ejected mass carries away `ṁ v` per second, booked as the impulse of
/// `exhaust`. Without it the residual was −606,675 kg·m/s (ṁ times the height gained), 87 % of
/// the final momentum, on a trajectory exact to 1e-11; now it is the trapezoidal rule's error
/// over the run's steps.
#[test]
fn a_scenario_rockets_momentum_ledger_books_what_the_exhaust_carries_away() {
    let path = crate::util::workspace().join("examples/rocket.toml");
    let out = mechkit::scenario::Scenario::load(&path)
        .unwrap()
        .run()
        .unwrap();
    let p = &out.summary.momentum;
    let residual = p.residual[0].abs() / p.end[0].abs();
    assert!(residual < 1e-3, "{p:?}");
    // the exhaust's impulse is ṁ times the height gained (ṁ = −10 kg/s)
    let height = out.summary.bodies["rocket"].position[0];
    let exhaust = out.summary.impulse["exhaust"][0];
    assert!(
        (exhaust + 10.0 * height).abs() < 1e-3 * (10.0 * height),
        "{exhaust} vs {height}"
    );
}
