//! The fused step kernel against the general loop: the same scenarios run both ways give the
//! same bits (states, recorded samples, work, impulse, step range, counts), a chunk that goes
//! non-finite is handed back and diagnosed at the same step, and what cannot be fused is not.

use mechkit::prelude::*;
use mechkit::scenario::Scenario;
use mechkit::simulate::{Recorder, RunReport};

/// The system and initial state of a scenario (its own integrator settings are not used).
fn scenario(body: &str) -> Scenario {
    let text = if body.contains("[integrator]") {
        body.to_string()
    } else {
        format!("{body}\n[integrator]\nmethod = \"euler-cromer\"\ndt = \"1 ms\"\n")
    };
    Scenario::from_str("fused.toml", &text).unwrap()
}

fn run(sc: &Scenario, method: Method, dt: f64, t_max: f64, fuse: bool) -> (RunReport, Recorder) {
    let mut rec = Recorder::new(997);
    let report = Simulation::new(&sc.system, method, dt)
        .t_max(t_max)
        .fuse(fuse)
        .run(sc.initial.clone(), &mut [&mut rec])
        .unwrap();
    (report, rec)
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|v| v.to_bits()).collect()
}

/// Runs both ways and asserts the same bits everywhere; returns the fused report.
fn same_both_ways(sc: &Scenario, method: Method, dt: f64, t_max: f64) -> RunReport {
    let (general, rec_g) = run(sc, method, dt, t_max, false);
    let (fused, rec_f) = run(sc, method, dt, t_max, true);
    assert_eq!(general.fused_steps, 0);
    assert!(
        fused.fused_steps * 10 >= fused.steps * 9,
        "{method:?}: only {} of {} steps fused",
        fused.fused_steps,
        fused.steps
    );
    assert_eq!(general.steps, fused.steps);
    assert_eq!(general.evaluations, fused.evaluations);
    assert_eq!(general.stop_reason, fused.stop_reason);
    assert_eq!(
        general.final_state.t.to_bits(),
        fused.final_state.t.to_bits()
    );
    assert_eq!(bits(&general.final_state.y), bits(&fused.final_state.y));
    assert_eq!(
        bits(&[general.step_range.0, general.step_range.1]),
        bits(&[fused.step_range.0, fused.step_range.1])
    );
    assert_eq!(bits(general.ledger.work()), bits(fused.ledger.work()));
    for i in 0..sc.system.forces().len() {
        assert_eq!(
            bits(general.ledger.impulse(i)),
            bits(fused.ledger.impulse(i))
        );
    }
    assert_eq!(
        general.ledger.kinetic_end().to_bits(),
        fused.ledger.kinetic_end().to_bits()
    );
    assert_eq!(bits(&rec_g.t), bits(&rec_f.t));
    assert_eq!(rec_g.q.len(), rec_f.q.len());
    for (a, b) in rec_g.q.iter().zip(&rec_f.q) {
        assert_eq!(bits(a), bits(b));
    }
    for (a, b) in rec_g.v.iter().zip(&rec_f.v) {
        assert_eq!(bits(a), bits(b));
    }
    fused
}

const FEATHER: &str = r#"
dimensions = 1
[constants]
g = "9.8 m/s^2"
Dmg = "4.0 s^2/m^2"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
velocity = "0 m/s"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[force]]
name = "air"
kind = "expression"
F = "-m*g*Dmg*v*abs(v)"
[integrator]
method = "euler-cromer"
dt = "1 ms"
[stop]
t_max = "5 s"
"#;

#[test]
fn the_feather_gives_the_same_bits_fused_and_general() {
    let sc = scenario(FEATHER);
    for method in [Method::EulerCromer, Method::Euler] {
        let r = same_both_ways(&sc, method, 1e-4, 5.0);
        // and it is the right answer: terminal velocity 1/sqrt(Dmg) = 0.5 m/s
        let v = r.final_state.y[1];
        assert!((v + 0.5).abs() < 1e-6, "{method:?}: v = {v}");
    }
}

#[test]
fn projectiles_with_drag_wind_and_formula_forces_give_the_same_bits() {
    let sc = scenario(
        r#"
dimensions = 2
[constants]
c = "0.0002 kg/m"
w = "3 1/s"
q = "0.01 N/m"
[[body]]
name = "ball"
mass = "0.145 kg"
position = ["0 m", "1 m"]
velocity = ["30 m/s", "20 m/s"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[force]]
name = "air"
kind = "quadratic-drag"
D = "0.0013 kg/m"
wind = ["-3 m/s", "0.5 m/s"]
[[force]]
name = "magnus"
kind = "expression"
F = ["c*vy*speed", "-c*vx*speed + q*sin(w*t)*r"]
[[force]]
name = "viscous"
kind = "linear-drag"
b = "0.001 kg/s"
[[force]]
name = "thrust"
kind = "constant"
F = ["0.1 N", "0 N"]
"#,
    );
    for method in [Method::EulerCromer, Method::Euler] {
        same_both_ways(&sc, method, 1e-4, 3.0);
    }
}

#[test]
fn springs_and_gravitation_give_the_same_bits() {
    let springs = scenario(
        r#"
dimensions = 3
[[body]]
name = "a"
mass = "1 kg"
position = ["0.1 m", "0 m", "0 m"]
velocity = ["0 m/s", "0.3 m/s", "0 m/s"]
[[body]]
name = "b"
mass = "2 kg"
position = ["1.3 m", "0.2 m", "0 m"]
velocity = ["0 m/s", "0 m/s", "0.2 m/s"]
[[force]]
name = "anchor"
kind = "spring"
k = "40 N/m"
rest_length = "0.5 m"
on = "a"
anchor = ["0 m", "0 m", "1 m"]
[[force]]
name = "coupling"
kind = "spring"
k = "25 N/m"
rest_length = "1 m"
between = ["a", "b"]
"#,
    );
    same_both_ways(&springs, Method::EulerCromer, 1e-4, 4.0);
    let orbit = scenario(
        r#"
dimensions = 2
[[body]]
name = "planet"
mass = "1 kg"
position = ["1 m", "0 m"]
velocity = ["0 m/s", "1.2 m/s"]
[[force]]
name = "sun"
kind = "newtonian-gravity"
GM = "1 m^3/s^2"
"#,
    );
    same_both_ways(&orbit, Method::EulerCromer, 1e-4, 10.0);
    let three = scenario(
        r#"
dimensions = 2
[[body]]
name = "a"
mass = "1 kg"
position = ["1 m", "0 m"]
velocity = ["0 m/s", "0.5 m/s"]
[[body]]
name = "b"
mass = "1 kg"
position = ["-1 m", "0 m"]
velocity = ["0 m/s", "-0.5 m/s"]
[[body]]
name = "c"
mass = "0.1 kg"
position = ["0 m", "2 m"]
velocity = ["0.3 m/s", "0 m/s"]
[[force]]
name = "gravity"
kind = "newtonian-gravity"
between = ["a", "b", "c"]
G = "1 m^3/(kg*s^2)"
"#,
    );
    same_both_ways(&three, Method::EulerCromer, 1e-4, 5.0);
}

/// Contact laws (Hertz with Hunt-Crossley damping, a linear dashpot), walls and a pair
/// potential with a cut-off: the kernel selects each contact's force to zero while it is apart,
/// the general loop skips it, and the bits are the same.
#[test]
fn contacts_and_pair_potentials_give_the_same_bits() {
    for (model, stiffness, damping) in [("hertz", "1e6", "0.5"), ("spring", "2e4", "3")] {
        let sc = scenario(&format!(
            r#"
dimensions = 2
[constants]
w = "0.2 m"
E0 = "0.01 J"
[[body]]
name = "a"
mass = "0.2 kg"
radius = "0.1 m"
position = ["0 m", "0.3 m"]
velocity = ["0.4 m/s", "0 m/s"]
[[body]]
name = "b"
mass = "0.1 kg"
radius = "0.08 m"
position = ["0.5 m", "0.5 m"]
velocity = ["-0.6 m/s", "0.2 m/s"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[force]]
name = "glue"
kind = "pair"
between = ["a", "b"]
U = "-E0*exp(-(r/w)^2)"
cutoff = "0.5 m"
[[wall]]
name = "floor"
point = ["0 m", "0 m"]
normal = [0, 1]
[[wall]]
name = "side"
point = ["1 m", "0 m"]
normal = [-1, 0]
[contact]
model = "{model}"
stiffness = {stiffness}
damping = {damping}
"#
        ));
        let forces: Vec<&str> = sc
            .system
            .forces()
            .iter()
            .map(mechkit::forces::Force::name)
            .collect();
        assert_eq!(forces, ["gravity", "glue", "contact", "contact_damping"]);
        let r = same_both_ways(&sc, Method::EulerCromer, 1e-5, 1.0);
        // the balls bounced: the contact did work and the damper took energy
        assert!(r.ledger.work_of("contact_damping").unwrap() < -1e-4);
        same_both_ways(&sc, Method::Euler, 1e-5, 0.3);
    }
}

#[test]
fn a_chunk_that_diverges_is_rerun_and_diagnosed_at_the_same_step() {
    // F = sqrt(x) is NaN once the body has crossed x = 0
    let sc = scenario(
        r#"
dimensions = 1
[[body]]
name = "probe"
mass = "1 kg"
position = "1 m"
velocity = "-1 m/s"
[[force]]
name = "pull"
kind = "expression"
F = "1e-6*sqrt(x)"
"#,
    );
    let (general, rec_g) = run(&sc, Method::EulerCromer, 1.0 / 1024.0, 10.0, false);
    let (fused, rec_f) = run(&sc, Method::EulerCromer, 1.0 / 1024.0, 10.0, true);
    assert_eq!(general.stop_reason, StopReason::Diverged);
    assert_eq!(fused.stop_reason, StopReason::Diverged);
    assert_eq!(general.steps, fused.steps);
    assert_eq!(bits(&general.final_state.y), bits(&fused.final_state.y));
    assert_eq!(
        general.divergence.as_ref().unwrap().message,
        fused.divergence.as_ref().unwrap().message
    );
    assert_eq!(bits(&rec_g.t), bits(&rec_f.t));
    assert!(
        fused.fused_steps > 0,
        "the steps before the chunk were fused"
    );
}

#[test]
fn runs_that_cannot_be_fused_take_the_general_loop() {
    let sc = scenario(FEATHER);
    // an observer that wants every step
    let mut rec = Recorder::new(1);
    let r = Simulation::new(&sc.system, Method::EulerCromer, 1e-3)
        .t_max(1.0)
        .fuse(true)
        .run(sc.initial.clone(), &mut [&mut rec])
        .unwrap();
    assert_eq!(r.fused_steps, 0);
    // a method the kernel does not have
    let r = Simulation::new(&sc.system, Method::Rk4, 1e-3)
        .t_max(1.0)
        .fuse(true)
        .run(sc.initial.clone(), &mut [])
        .unwrap();
    assert_eq!(r.fused_steps, 0);
    // an event
    let r = Simulation::new(&sc.system, Method::EulerCromer, 1e-3)
        .t_max(1.0)
        .fuse(true)
        .stop_when(Condition::below(0, 0, 0.0))
        .run(sc.initial.clone(), &mut [])
        .unwrap();
    assert_eq!(r.fused_steps, 0);
    // short runs are not compiled unless asked
    let r = Simulation::new(&sc.system, Method::EulerCromer, 1e-3)
        .t_max(1.0)
        .run(sc.initial.clone(), &mut [])
        .unwrap();
    assert_eq!(r.fused_steps, 0);
    // without observers and with no limits in the way almost every step is fused
    let r = Simulation::new(&sc.system, Method::EulerCromer, 1e-5)
        .t_max(1.0)
        .run(sc.initial.clone(), &mut [])
        .unwrap();
    assert_eq!(r.steps, 100_000);
    assert!(r.fused_steps >= 99_990, "{}", r.fused_steps);
}
