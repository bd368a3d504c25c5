//! A run that hits a singularity stops with a diagnosis naming the time, the quantity and the
//! force, and keeps every sample computed before it.

use mechkit::prelude::*;
use mechkit::simulate::Recorder;

/// F = -k/x² towards the origin (a body falling into a 1/r potential) with the step landing
/// exactly on x = 0.
#[derive(Debug)]
struct InverseSquare;

impl Force for InverseSquare {
    fn name(&self) -> &'static str {
        "pull"
    }
    fn add_forces(&self, k: &mechkit::particles::Kinematics<'_>, out: &mut [f64]) {
        out[0] -= 1.0 / (k.x[0] * k.x[0]);
    }
    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

#[test]
fn force_singularity_is_diagnosed() {
    // no force until x = 0 would be reached: a body moving at -1 m/s from x = 1 with an
    // inverse-square pull is far too fast for dt = 0.25, and lands on x = 0 exactly.
    let sys = ParticleSystem::builder(1)
        .body("probe", 1e30)
        .force(InverseSquare)
        .build()
        .unwrap();
    let mut rec = Recorder::new(1);
    let r = Simulation::new(&sys, Method::EulerCromer, 0.25)
        .t_max(10.0)
        .run(State::from_qv(0.0, &[1.0], &[-1.0]), &mut [&mut rec])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::Diverged);
    let d = r.divergence.unwrap();
    assert!(d.quantity.contains("pull"), "{}", d.quantity);
    assert!(d.message.contains("t = 1 s"), "{}", d.message);
    // everything up to and including the singular (but finite) state was observed
    assert_eq!(rec.t, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    assert!(r.final_state.is_finite());
    assert_eq!(r.final_state.t, 1.0);
}

/// F = sqrt(x): finite for x ≥ 0, NaN below.
#[derive(Debug)]
struct RootOfX;

impl Force for RootOfX {
    fn name(&self) -> &'static str {
        "root"
    }
    fn add_forces(&self, k: &mechkit::particles::Kinematics<'_>, out: &mut [f64]) {
        out[0] += k.x[0].sqrt();
    }
    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

#[test]
fn a_stage_outside_the_domain_names_the_coordinate() {
    // RK4's stages at x = 0.01 - 0.05 leave the domain of sqrt although both ends of the
    // previous steps were fine.
    let sys = ParticleSystem::builder(1)
        .body("b", 1.0)
        .force(RootOfX)
        .build()
        .unwrap();
    let r = Simulation::new(&sys, Method::Rk4, 0.1)
        .t_max(10.0)
        .run(State::from_qv(0.0, &[0.01], &[-1.0]), &mut [])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::Diverged);
    let d = r.divergence.unwrap();
    assert!(d.quantity.starts_with("b."), "{}", d.quantity);
    assert!(d.message.contains("try a smaller dt"), "{}", d.message);
    assert_eq!(r.final_state.t, 0.0);
    assert!(r.final_state.is_finite());
}
