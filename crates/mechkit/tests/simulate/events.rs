//! Stop conditions: the crossing is located between steps on the step's cubic Hermite
//! interpolant, to rounding when the motion is a polynomial of degree three or less
//! (projectile: exact), and the last step before it is reported too.

use mechkit::particles::Sample;
use mechkit::prelude::*;
use mechkit::simulate::{Observer, ObserverError};

fn projectile() -> ParticleSystem {
    ParticleSystem::builder(2)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .build()
        .unwrap()
}

#[test]
fn landing_of_a_projectile_is_located_to_rounding() {
    let sys = projectile();
    let (vx, vy) = (3.0, 7.0);
    for method in Method::ALL {
        let r = if method.kind() == MethodKind::Implicit {
            Simulation::adaptive(&sys, method, AdaptiveConfig::default())
        } else {
            Simulation::new(&sys, method, 0.013)
        };
        let r = r
            .t_max(10.0)
            .stop_when(Condition::below(0, 1, 0.0))
            .run(State::from_qv(0.0, &[0.0, 0.0], &[vx, vy]), &mut [])
            .unwrap();
        let e = r.event.as_ref().unwrap();
        let exact = 2.0 * vy / 9.81;
        // methods of order >= 2 are exact for constant acceleration; BDF starts with steps of
        // order 1 (backward Euler), whose error is held to the tolerance (rtol 1e-6)
        let tol = if method == Method::Bdf {
            1e-6
        } else if method.order() >= 2 {
            1e-12
        } else {
            0.02
        };
        assert!((e.t - exact).abs() < tol, "{method}: {} vs {exact}", e.t);
        assert!(e.last_step.t < e.t && e.t <= e.crossing_step.t);
        assert!(e.last_step.q[1] >= 0.0 && e.crossing_step.q[1] < 0.0);
        assert_eq!(r.final_state.t, e.t);
        assert_eq!(r.stop_reason, StopReason::Event);
    }
}

#[test]
fn crossing_exactly_on_a_step_is_reported_once_at_that_step() {
    // x = 1 - t with dt = 0.25: x is exactly 0 at t = 1 (a step), below 0 after.
    let sys = ParticleSystem::builder(1).body("b", 1.0).build().unwrap();
    let r = Simulation::new(&sys, Method::Rk4, 0.25)
        .t_max(5.0)
        .stop_when(Condition::below(0, 0, 0.0))
        .run(State::from_qv(0.0, &[1.0], &[-1.0]), &mut [])
        .unwrap();
    let e = r.event.unwrap();
    assert!((e.t - 1.0).abs() < 1e-12, "{}", e.t);
    assert_eq!(e.last_step.t, 1.0);
    assert_eq!(e.crossing_step.t, 1.25);
}

#[test]
fn condition_true_at_the_start_stops_at_once_with_a_warning() {
    let sys = ParticleSystem::builder(1).body("b", 1.0).build().unwrap();
    let r = Simulation::new(&sys, Method::Euler, 0.1)
        .t_max(1.0)
        .stop_when(Condition::below(0, 0, 0.0))
        .run(State::from_qv(0.0, &[-1.0], &[0.0]), &mut [])
        .unwrap();
    assert_eq!(r.steps, 0);
    assert_eq!(r.event.unwrap().t, 0.0);
    assert!(r.warnings.iter().any(|w| w.contains("already holds")));
}

#[test]
fn t_max_is_hit_exactly_and_missing_t_max_is_bounded() {
    let sys = projectile();
    let r = Simulation::new(&sys, Method::Rk4, 0.3)
        .t_max(1.0)
        .run(State::from_qv(0.0, &[0.0, 0.0], &[1.0, 1.0]), &mut [])
        .unwrap();
    assert_eq!(r.final_state.t, 1.0);
    assert_eq!(r.steps, 4);
    assert_eq!(r.stop_reason, StopReason::TMax);

    let r = Simulation::new(&sys, Method::Euler, 1.0)
        .stop_when(Condition::below(0, 1, -1e300))
        .run(State::from_qv(0.0, &[0.0, 0.0], &[0.0, 0.0]), &mut [])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::MaxSteps);
    assert_eq!(r.steps, mechkit::simulate::DEFAULT_MAX_STEPS);
    assert!(r.warnings.iter().any(|w| w.contains("t_max")));
}

/// Counts samples and remembers which were located events.
#[derive(Default)]
struct Log {
    located: Vec<bool>,
    finished: Option<f64>,
}

impl Observer for Log {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        self.located
            .push(s.kind == mechkit::particles::SampleKind::Event);
        Ok(())
    }
    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        self.finished = Some(s.t);
        Ok(())
    }
}

#[test]
fn observers_see_the_located_event_instead_of_the_crossing_step() {
    let sys = projectile();
    let mut log = Log::default();
    let r = Simulation::new(&sys, Method::Rk4, 0.01)
        .t_max(10.0)
        .stop_when(Condition::below(0, 1, 0.0))
        .run(
            State::from_qv(0.0, &[0.0, 0.0], &[1.0, 5.0]),
            &mut [&mut log],
        )
        .unwrap();
    assert_eq!(log.located.len() as u64, r.steps + 1);
    assert_eq!(log.located.iter().filter(|l| **l).count(), 1);
    assert!(*log.located.last().unwrap());
    assert_eq!(log.finished, Some(r.event.unwrap().t));
}
