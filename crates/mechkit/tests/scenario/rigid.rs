//! Scenarios of rigid bodies hinged to the world (`[[rigid_body]]`, `[[torque]]`): the
//! examples against their closed forms, and located errors.

use std::f64::consts::PI;

use mechkit::rigid::fixed_axis::pendulum::elliptic_k;
use mechkit::scenario::{Scenario, ScenarioError};

use crate::util::workspace;

fn run(name: &str) -> mechkit::scenario::Summary {
    let path = workspace().join("examples/rigid").join(name);
    Scenario::load(&path).unwrap().run().unwrap().summary
}

/// The rod hinged at its end released from 120°: successive upswings are one period apart,
/// 4 √(I/(m g d)) K(sin 60°), to 1e-9 (DOP853 at rtol 1e-12); I = m L²/3; energy conserved.
#[test]
fn physical_pendulum_period_through_a_scenario() {
    let s = run("physical_pendulum.toml");
    assert_eq!(s.coordinates, Some("angle"));
    let (l, m, g) = (1.2, 0.7, 9.81);
    assert!((s.observables["I_pivot"] - m * l * l / 3.0).abs() < 1e-14);
    let up: Vec<f64> = s.events.iter().map(|e| e.t).collect();
    assert_eq!(up.len(), 2, "{up:?}");
    let exact = 4.0 * (l * l / 3.0 / (g * l / 2.0)).sqrt() * elliptic_k((PI / 3.0).sin()).unwrap();
    assert!(
        ((up[1] - up[0]) - exact).abs() < 1e-9 * exact,
        "{up:?} vs {exact}"
    );
    assert!(s.observables["energy_drift"].abs() < 1e-11);
    assert!((s.observables["theta_max"] - 2.0 * PI / 3.0).abs() < 1e-15);
}

/// Atwood machine with a 2 kg disk pulley: a = (m1 - m2) g/(m1 + m2 + M/2), and the weights'
/// potential energy is the kinetic energy of the three bodies (RK4 is exact for constant α).
#[test]
fn atwood_machine_through_a_scenario() {
    let s = run("atwood_massive_pulley.toml");
    let a = 2.0 * 9.81 / 5.0;
    assert!(
        (s.observables["a"] - a).abs() < 1e-12,
        "{}",
        s.observables["a"]
    );
    assert!((s.observables["drop"] - 0.5 * a).abs() < 1e-12);
    assert!(s.energy.end.abs() < 1e-9, "{}", s.energy.end);
}

/// Flywheel coasting against dry and viscous bearing friction: I ω' = -τ₀ - b ω stops it at
/// t = (I/b) ln(1 + b ω₀/τ₀), located by the automatic `stopped` event; the heat of both
/// frictions is the kinetic energy it had.
#[test]
fn flywheel_stops_at_the_closed_form_time() {
    let s = run("flywheel_spin_down.toml");
    let i = 0.5 * 40.0 * 0.25 * 0.25;
    let (tau, b, w0): (f64, f64, f64) = (0.8, 2e-4, 314.159_265);
    let t_stop = i / b * (1.0 + b * w0 / tau).ln();
    assert_eq!(s.stop_reason, "event");
    let t = s.observables["spin_down_time"];
    assert!((t - t_stop).abs() < 1e-8 * t_stop, "{t} vs {t_stop}");
    let heat = s.observables["heat_bearing"] + s.observables["heat_air"];
    assert!((heat - 0.5 * i * w0 * w0).abs() < 1e-8 * heat);
    // dry friction: the bearing's heat is τ₀ times the angle turned
    let turned = s.observables["revolutions"] * 2.0 * PI;
    assert!((s.observables["heat_bearing"] - tau * turned).abs() < 1e-8 * tau * turned);
}

const BASE: &str = r#"
[[rigid_body]]
name = "wheel"
theta = "10 deg"
  [[rigid_body.part]]
  shape = "disk"
  radius = "20 cm"
  mass = "1 kg"
  position = ["0 m", "-0.2 m"]

[[torque]]
kind = "gravity"

[integrator]
method = "rk4"
dt = "1 ms"

[stop]
t_max = "1 s"
"#;

fn error(text: &str) -> ScenarioError {
    Scenario::from_str("test.toml", text).expect_err("the scenario should be rejected")
}

fn with(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

#[test]
fn rigid_body_errors_are_located() {
    if let Err(e) = Scenario::from_str("test.toml", BASE) {
        panic!("{e}");
    }
    // an axis through a rod along its length: no moment of inertia
    let e = error(
        &with(
            "shape = \"disk\"\n  radius = \"20 cm\"",
            "shape = \"rod\"\n  length = \"20 cm\"",
        )
        .replace("position = [\"0 m\", \"-0.2 m\"]", ""),
    );
    assert!(e.to_string().contains("no moment of inertia"), "{e}");
    let e = error(&with("kind = \"gravity\"", "kind = \"gravty\""));
    assert!(e.to_string().contains("did you mean `gravity`"), "{e}");
    let e = error(&with(
        "kind = \"gravity\"",
        "kind = \"torsion-spring\"\nkappa = \"-2 N*m\"",
    ));
    assert!(e.to_string().contains("must not be negative"), "{e}");
    let e = error(&with(
        "kind = \"gravity\"",
        "kind = \"friction\"\ntorque = \"1 N*m\"",
    ));
    assert!(e.to_string().contains("starts at rest"), "{e}");
    let e = error(&with(
        "kind = \"gravity\"",
        "kind = \"applied\"\ntorque = \"omega*theta\"",
    ));
    assert!(e.to_string().contains("torque"), "{e}");
    let e = error(&format!("{BASE}\n[[body]]\nmass = \"1 kg\"\n"));
    assert!(e.to_string().contains("cannot also have `body`"), "{e}");
    let e = error(&with("theta = \"10 deg\"", "theta = \"10 m\""));
    assert!(e.to_string().contains("test.toml:"), "{e}");
    let e = error("[[torque]]\nkind = \"gravity\"\n[[body]]\nmass = \"1 kg\"\n");
    assert!(e.to_string().contains("no [[rigid_body]]"), "{e}");
}

/// A torque formula of the state: a damping torque -c omega written by hand equals the
/// built-in viscous friction, step for step.
#[test]
fn torque_formula_equals_the_built_in_friction() {
    let formula = with(
        "[[torque]]\nkind = \"gravity\"",
        "[[torque]]\nkind = \"gravity\"\n[[torque]]\nname = \"damper\"\nkind = \"applied\"\ntorque = \"-c*omega\"",
    );
    let built_in = with(
        "[[torque]]\nkind = \"gravity\"",
        "[[torque]]\nkind = \"gravity\"\n[[torque]]\nname = \"damper\"\nkind = \"friction\"\nb = \"0.05 N*m*s\"",
    );
    let formula = format!("[constants]\nc = \"0.05 N*m*s\"\n{formula}");
    let a = Scenario::from_str("a.toml", &formula)
        .unwrap()
        .run()
        .unwrap()
        .summary;
    let b = Scenario::from_str("b.toml", &built_in)
        .unwrap()
        .run()
        .unwrap()
        .summary;
    assert_eq!(a.bodies["wheel"].position, b.bodies["wheel"].position);
    assert!(a.work["damper"] < 0.0);
    assert!((a.work["damper"] - b.work["damper"]).abs() < 1e-15);
}
