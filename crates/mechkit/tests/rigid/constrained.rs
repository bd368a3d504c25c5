//! A body constrained to a curve under gravity, no friction: the normal force
//! N = m(v²κ + g cos β) along the way, the departure where N = 0 located inside the step,
//! the free flight to the landing. Checked against the closed forms: a particle sliding off a
//! cylinder from the top leaves at cos φ = (2 + v₀²/gR)/3 (2/3 from rest), inside a loop it
//! leaves at cos φ = (v₀²/gR − 2)/3 (so the release height must be at least 5R/2), a bead on a
//! circle is a pendulum with the exact period 4K(sin(θ₀/2))/ω₀, and the energy is conserved
//! on the curve.

use mechkit::ode::reference::Pendulum;
use mechkit::ode::{AdaptiveConfig, Tolerance};
use mechkit::rigid::constrained::{BeadOnCurve, Curve, Side, Start, StopReason};

const G: f64 = 9.81;

fn config(rtol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(rtol * 1e-2),
        h_max: 0.01,
        ..AdaptiveConfig::default()
    }
}

fn circle(r: f64, side: Side) -> BeadOnCurve {
    BeadOnCurve::new(Curve::circle(r).unwrap(), side, 1.0, G).unwrap()
}

/// From near the top of a cylinder: measured |cos φ − exact| ≤ 1.9e-12 at rtol 1e-11 for
/// v₀ = 0.01, 0.5, 1, 2 m/s (R = 1.5 m), and |N| at the departure ≤ 6e-11 N.
#[test]
fn sliding_off_a_cylinder_leaves_at_cos_two_thirds_plus_v0_squared() {
    let r = 1.5;
    let body = circle(r, Side::Outer);
    for v0 in [0.01, 0.5, 1.0, 2.0] {
        let run = body
            .simulate(
                Start {
                    coordinate: 0.0,
                    speed: v0,
                },
                20.0,
                &config(1e-11),
            )
            .unwrap();
        let d = run.departure.expect("it leaves the cylinder");
        let exact = (2.0 + v0 * v0 / (G * r)) / 3.0;
        let err = (d.coordinate.cos() - exact).abs();
        println!(
            "v0 = {v0}: |cos φ − exact| = {err:.1e}, N = {:.1e}",
            d.normal_force
        );
        assert!(
            err < 2e-11,
            "v0 = {v0}: cos φ = {} vs {exact}",
            d.coordinate.cos()
        );
        assert!(d.normal_force.abs() < 1e-9, "N = {}", d.normal_force);
        // v² = g R cos φ at the departure
        let v2 = d.velocity[0].powi(2) + d.velocity[1].powi(2);
        assert!((v2 - G * r * exact).abs() < 1e-9);
        assert!(run.energy_drift < 1e-9, "drift {}", run.energy_drift);
        // it lands on the cylinder's surface? no: outside a cylinder the flight never meets it
        // again above the ground, which a circle does not have, so it falls past it
        assert_eq!(run.stop, StopReason::TimeLimit);
        assert!(run.samples.iter().all(|s| s.t <= 20.0));
    }
}

/// The same hill as a graph y = sqrt(R² − x²) (the x parametrisation, symbolic y', y''):
/// it leaves at x = R sin φ with cos φ = 2/3 + v₀²/(3gR), measured error ≤ 1e-10.
#[test]
fn a_semicircle_graph_agrees_with_the_circle() {
    let r = 1.0;
    let curve = Curve::graph("sqrt(R^2 - x^2)", &[("R".into(), r)]).unwrap();
    let body = BeadOnCurve::new(curve, Side::Outer, 2.0, G).unwrap();
    let v0 = 1.0;
    let run = body
        .simulate(
            Start {
                coordinate: 0.0,
                speed: v0,
            },
            5.0,
            &config(1e-11),
        )
        .unwrap();
    let d = run.departure.unwrap();
    let cos = (2.0 + v0 * v0 / (G * r)) / 3.0;
    assert!(
        (d.position[0] - r * (1.0 - cos * cos).sqrt()).abs() < 1e-10,
        "{d:?}"
    );
    assert!((d.position[1] - r * cos).abs() < 1e-10);
}

/// Inside a loop of radius R, started at the bottom with v₀² = 2gh: the departure angle from
/// the top is cos φ = (2h/R − 2)/3 (measured error ≤ 5.5e-12), the landing lies on the
/// circle, and the least height that completes the loop, found by bisection on "did it
/// leave", is 5R/2 to 4.7e-10 R (a dip of N below zero at the top narrower than a step is
/// found: N is enclosed inside every step).
#[test]
fn loop_the_loop_needs_five_halves_r() {
    let r = 1.0;
    let body = circle(r, Side::Inner);
    let launch = |h: f64| Start {
        coordinate: std::f64::consts::PI,
        speed: -(2.0 * G * h).sqrt(),
    };
    for h in [2.0, 2.3, 2.49] {
        let run = body.simulate(launch(h), 5.0, &config(1e-11)).unwrap();
        let d = run.departure.expect("below 5R/2 it leaves the track");
        let exact = (2.0 * h / r - 2.0) / 3.0;
        println!("h = {h}: cos φ error {:.1e}", d.coordinate.cos() - exact);
        assert!((d.coordinate.cos() - exact).abs() < 1e-10, "h = {h}: {d:?}");
        let land = run.landing.expect("it falls back onto the track");
        assert_eq!(run.stop, StopReason::Landed);
        let p = land.position;
        assert!((p[0].hypot(p[1]) - r).abs() < 1e-12, "{land:?}");
        assert!(land.normal_speed > 0.0 && land.t > d.t);
    }
    let leaves = |h: f64| {
        body.simulate(launch(h), 3.0, &config(1e-12))
            .unwrap()
            .departure
            .is_some()
    };
    let (mut lo, mut hi) = (2.0, 3.0);
    for _ in 0..30 {
        let mid = 0.5 * (lo + hi);
        if leaves(mid) { lo = mid } else { hi = mid }
    }
    println!("h_min − 5R/2 = {:.1e}", 0.5 * (lo + hi) - 2.5 * r);
    assert!(
        (0.5 * (lo + hi) - 2.5 * r).abs() < 1e-8,
        "h_min = {lo}..{hi}"
    );
}

/// A bead threaded on a circle is a pendulum: released from rest at θ₀ from the bottom, the
/// turning points come every half period; measured relative period error 4e-14, 1.7e-12,
/// 3.7e-11 for θ₀ = 10°, 90°, 170° (exact: the arithmetic-geometric mean) at rtol 1e-12,
/// energy drift ≤ 8e-11 J/kg.
#[test]
fn a_bead_on_a_circle_is_a_pendulum() {
    let r = 0.8;
    let body = circle(r, Side::Bead);
    for theta0_deg in [10.0_f64, 90.0, 170.0] {
        let theta0 = theta0_deg.to_radians();
        let exact = Pendulum {
            omega0: (G / r).sqrt(),
            theta0,
        }
        .period();
        let start = Start {
            coordinate: std::f64::consts::PI - theta0,
            speed: 0.0,
        };
        let run = body.simulate(start, 2.2 * exact, &config(1e-12)).unwrap();
        assert!(run.departure.is_none());
        let t = &run.turning_times;
        assert!(t.len() >= 4, "{t:?}");
        let period = t[3] - t[1];
        println!(
            "θ0 = {theta0_deg}°: period rel. error {:.1e}, drift {:.1e}",
            period / exact - 1.0,
            run.energy_drift
        );
        assert!(
            (period / exact - 1.0).abs() < 1e-10,
            "{theta0_deg}°: {period} vs {exact}"
        );
        assert!((2.0 * t[0] / exact - 1.0).abs() < 1e-10);
        assert!(run.energy_drift < 1e-9, "{}", run.energy_drift);
    }
}

/// A bead on the parabola y = x²/2 released from rest at x = 1: it turns at x = −1 and back
/// (energy: to 1e-9 m), and the normal force at the bottom is m(g + v²κ) with κ = 1 there.
#[test]
fn a_bead_in_a_parabolic_bowl_conserves_energy() {
    let curve = Curve::graph("x^2/2", &[]).unwrap();
    let body = BeadOnCurve::new(curve, Side::Outer, 0.5, G).unwrap();
    let run = body
        .simulate(
            Start {
                coordinate: 1.0,
                speed: 0.0,
            },
            6.0,
            &config(1e-12),
        )
        .unwrap();
    assert!(run.departure.is_none(), "a bowl holds the body");
    assert!(run.energy_drift < 1e-9, "{}", run.energy_drift);
    let v_bottom2 = 2.0 * G * 0.5;
    let n_bottom = body.normal_force(0.0, v_bottom2.sqrt());
    assert!((n_bottom - 0.5 * (G + v_bottom2)).abs() < 1e-12);
    for s in &run.samples {
        assert!(s.position[0].abs() <= 1.0 + 1e-9, "{s:?}");
    }
    assert!(run.turning_times.len() >= 2);
}

/// Bad input: a zero radius, a negative mass, a curve with an unknown name, a start where
/// the graph is vertical.
#[test]
fn bad_curves_and_starts_are_errors() {
    assert!(Curve::circle(0.0).is_err());
    assert!(BeadOnCurve::new(Curve::circle(1.0).unwrap(), Side::Bead, -1.0, G).is_err());
    let e = Curve::graph("a*x^2", &[]).unwrap_err().to_string();
    assert!(e.contains("--set a="), "{e}");
    let body = BeadOnCurve::new(
        Curve::graph("sqrt(1 - x^2)", &[]).unwrap(),
        Side::Outer,
        1.0,
        G,
    )
    .unwrap();
    let e = body
        .simulate(
            Start {
                coordinate: 2.0,
                speed: 0.0,
            },
            1.0,
            &config(1e-8),
        )
        .unwrap_err()
        .to_string();
    assert!(e.contains("undefined or vertical at x = 2"), "{e}");
}
