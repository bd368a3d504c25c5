//! Bodies landing on a contact surface with Coulomb friction: the impact is an inelastic
//! impulse whose tangential part is bounded by friction, and after it the contact sticks only
//! if static friction can hold it. A block dropped onto a slope steeper than its friction
//! angle slides on with a = g (sin α − μₖ cos α); a cylinder dropped onto a slope where
//! μ < tan α / 3 slides and rolls with a = g (sin α − μ cos α), its friction μN. Once, both
//! stuck for good after landing (friction above μₛN, the `slips` event never crossing zero).

use mechkit::scenario::{Scenario, Summary};

use crate::util::workspace;

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap()
        .run()
        .unwrap()
        .summary
}

fn example(path: &str) -> String {
    std::fs::read_to_string(workspace().join("examples").join(path)).unwrap()
}

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

const G: f64 = 9.81;

#[test]
fn a_block_dropped_onto_a_steep_slope_slides_with_kinetic_friction() {
    let slope = 30f64.to_radians();
    let text = example("friction/incline.toml")
        .replace(
            "position = [\"0 m\", \"0 m\"]",
            "position = [\"0 m\", \"0.05 m\"]",
        )
        .replace(
            "[observe]",
            "[observe]\na_along = \"final(block.ax*cos(slope) - block.ay*sin(slope))\"",
        );
    let s = run_text(&text);
    assert!(s.events.iter().any(|e| e.name == "incline touches"));
    close(
        s.observables["a_along"],
        G * (slope.sin() - 0.4 * slope.cos()),
        1e-6,
    );
    let (n, f) = (s.observables["normal"], s.observables["friction"]);
    close(n, G * slope.cos(), 1e-6);
    close(f.abs(), 0.4 * n, 1e-6);
    // it covers at least what sliding from rest after landing gives (the impact keeps
    // part of its speed along the slope)
    let t_land = (2.0 * 0.05 / G).sqrt();
    let from_rest = 0.5 * G * (slope.sin() - 0.4 * slope.cos()) * (2.0 - t_land).powi(2);
    assert!(
        s.observables["distance"] > from_rest,
        "{}",
        s.observables["distance"]
    );
}

#[test]
fn a_block_dropped_onto_a_gentle_slope_sticks() {
    // tan 20° = 0.36 < μₛ = 0.5: it lands and stays, friction below μₛ N
    let text = example("friction/incline.toml")
        .replace("slope = \"30 deg\"", "slope = \"20 deg\"")
        .replace(
            "position = [\"0 m\", \"0 m\"]",
            "position = [\"0 m\", \"0.05 m\"]",
        );
    let s = run_text(&text);
    let (n, f) = (s.observables["normal"], s.observables["friction"]);
    close(f.abs(), G * 20f64.to_radians().sin(), 1e-6);
    assert!(f.abs() <= 0.5 * n);
    let distance = s.observables["distance"];
    let after_landing = s.bodies["block"].speed;
    assert!(after_landing < 1e-6, "{after_landing}");
    assert!(distance < 0.05, "{distance}");
}

#[test]
fn a_cylinder_dropped_onto_a_slippery_slope_slides_and_rolls() {
    let slope = 30f64.to_radians();
    for mu in [0.1, 0.15] {
        let text = example("rigid/rolling_incline.toml")
            .replace(
                "position = [\"R*sin(slope)\", \"R*cos(slope)\"]",
                "position = [\"R*sin(slope)\", \"R*cos(slope) + R/2\"]",
            )
            .replace("mu    = 0.5", &format!("mu    = {mu}"));
        let s = run_text(&text);
        close(
            s.observables["a_cm"],
            G * (slope.sin() - mu * slope.cos()),
            1e-6,
        );
        let (n, f) = (s.observables["normal"], s.observables["friction"]);
        close(f.abs(), mu * n, 1e-6);
        assert!(s.observables["slip_speed"] > 0.1);
    }
    // enough friction (μ ≥ tan α / 3): it lands and rolls without slipping
    let text = example("rigid/rolling_incline.toml").replace(
        "position = [\"R*sin(slope)\", \"R*cos(slope)\"]",
        "position = [\"R*sin(slope)\", \"R*cos(slope) + R/2\"]",
    );
    let s = run_text(&text);
    close(s.observables["a_cm"], 2.0 / 3.0 * G * slope.sin(), 1e-6);
    close(s.observables["slip_speed"], 0.0, 1e-6);
}
