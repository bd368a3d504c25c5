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
