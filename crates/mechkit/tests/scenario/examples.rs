//! The example scenarios reproduce their analytic answers.

use mechkit::scenario::Scenario;

use crate::util::workspace;

fn run(name: &str) -> mechkit::scenario::Summary {
    let path = workspace().join("examples").join(name);
    Scenario::load(&path).unwrap().run().unwrap().summary
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

#[test]
fn feather_matches_the_textbook_loop() {
    let s = run("feather.toml");
    let e = &s.events[0];
    assert!((e.last_step.t - 4.834).abs() < 1e-9);
    assert!((e.last_step.state["feather"].position[0] - 2.8e-4).abs() < 1e-5);
    assert!((e.t - 4.8354).abs() < 1e-3);
    assert!(
        (s.bodies["feather"].velocity[0] + 0.5).abs() < 1e-6,
        "terminal speed"
    );
}

#[test]
fn projectile_range_height_and_time() {
    let s = run("projectile.toml");
    let (v0, th, g) = (20.0_f64, 30f64.to_radians(), 9.81);
    assert!(close(
        s.observables["range"],
        v0 * v0 * (2.0 * th).sin() / g,
        1e-10
    ));
    assert!(close(
        s.observables["flight_time"],
        2.0 * v0 * th.sin() / g,
        1e-10
    ));
    // the peak is sampled at steps: within (v0y dt)² of the top
    assert!(close(
        s.observables["peak_height"],
        (v0 * th.sin()).powi(2) / (2.0 * g),
        1e-6
    ));
}

#[test]
fn drag_and_headwind_shorten_the_flight() {
    let s = run("projectile_drag.toml");
    let range = s.observables["range"];
    assert!(range < 0.6 * s.observables["vacuum_range"]);
    assert!(
        s.observables["impact_angle"] < -45.0,
        "steeper descent than ascent (35°)"
    );
    assert!(s.work["air"] < 0.0);
    assert!(close(s.work["air"], s.energy.change, 1e-6));
}

#[test]
fn hanging_spring_oscillates_about_equilibrium() {
    let s = run("spring_block.toml");
    let (m, g, k, l) = (0.5, 9.81, 20.0, 0.3);
    assert!(close(s.observables["lowest"], -(l + 2.0 * m * g / k), 1e-6));
    assert!(close(s.observables["amplitude"], m * g / k, 1e-5));
    assert!(s.observables["energy_drift"].abs() < 1e-5);
}

#[test]
fn kepler_orbit_keeps_its_shape() {
    let s = run("kepler.toml");
    assert!(close(s.observables["perihelion_AU"], 0.5, 1e-6));
    assert!(close(s.observables["aphelion_AU"], 1.5, 1e-6));
    assert!(close(s.observables["eccentricity"], 0.5, 1e-6));
    assert!(s.observables["relative_drift"].abs() < 1e-8);
}

#[test]
fn the_readme_scenario_says_what_the_readme_says() {
    let readme = std::fs::read_to_string(workspace().join("README.md")).unwrap();
    let start = readme.find("```toml\n").unwrap() + 8;
    let end = start + readme[start..].find("```").unwrap();
    let s = Scenario::from_str("README.md", &readme[start..end])
        .unwrap()
        .run()
        .unwrap()
        .summary;
    let e = &s.events[0];
    assert!((e.last_step.t - 4.834).abs() < 1e-9);
    assert!((e.last_step.state["feather"].position[0] - 2.8e-4).abs() < 1e-6);
    assert!((e.t - 4.8346).abs() < 5e-5);
    assert!((s.work["gravity"] - 0.02352).abs() < 1e-5);
    assert!((s.work["air"] + 0.02339).abs() < 1e-5);
}

/// Apex heights of the bouncing ball example shrink by e² = 0.81 per bounce, to 1e-9.
#[test]
fn bouncing_ball_apexes_and_energy_booking() {
    let s = run("bouncing_ball.toml");
    let apexes: Vec<f64> = s
        .events
        .iter()
        .filter(|e| e.name == "apex" && e.t > 0.0)
        .map(|e| e.state["ball"].position[1])
        .collect();
    assert!(apexes.len() >= 10, "{apexes:?}");
    let mut previous = 1.0;
    for h in &apexes {
        assert!(
            (h / previous - 0.81).abs() < 1e-9 * 0.81,
            "{h} after {previous}"
        );
        previous = *h;
    }
    // the bounces take the energy, not a force; no drift from the method
    assert!(s.energy.events_change < 0.0);
    assert!(s.energy.relative_drift.unwrap().abs() < 1e-12);
    assert!(s.work_energy_residual.abs() < 1e-12);
    let bounce = s.events.iter().find(|e| e.name == "bounce").unwrap();
    let after = bounce.after.as_ref().unwrap();
    assert!((after["ball"].velocity[1] + 0.9 * bounce.state["ball"].velocity[1]).abs() < 1e-12);
    assert_eq!(s.step_control.mode, "adaptive");
    assert_eq!(s.step_control.rtol, Some(1e-10));
}

/// Yoshida 4 over 10⁶ steps of a Kepler orbit: energy error bounded by 2.1e-5.
#[test]
fn kepler_symplectic_keeps_its_energy() {
    let s = run("kepler_symplectic.toml");
    assert_eq!(s.steps, 1_000_000);
    assert!(s.energy.relative_drift.unwrap().abs() < 2.1e-5);
    assert!((s.observables["eccentricity"] - 0.5).abs() < 1e-4);
}

/// The comparison of methods on the feather: the error ranks the methods by order, and the
/// landing time of each is compared with the reference's.
#[test]
fn comparing_methods_on_the_feather() {
    use mechkit::ode::Method;
    use mechkit::scenario::CompareSettings;
    let path = workspace().join("examples/feather.toml");
    let scenario = Scenario::load(&path).unwrap();
    let methods = [
        Method::Euler,
        Method::VelocityVerlet,
        Method::Rk4,
        Method::Dopri5,
        Method::Yoshida4,
    ];
    let c = scenario
        .compare(&methods, &CompareSettings::default())
        .unwrap();
    assert!((c.reference_event_t.unwrap() - 4.835_364_652).abs() < 1e-8);
    let err = |i: usize| c.methods[i].max_position_error.unwrap();
    assert!(
        err(0) > 1e-5 && err(1) < 1e-5 && err(2) < 1e-9,
        "{}",
        c.to_text()
    );
    assert!(c.methods[3].event_error.unwrap().abs() < 1e-6);
    // drag: the symplectic method cannot run, and says why
    assert!(
        c.methods[4]
            .error
            .as_ref()
            .unwrap()
            .contains("velocity-dependent")
    );
    assert_eq!(c.plots.len(), 2);
    assert!(c.to_text().contains("event Δt"));
}
