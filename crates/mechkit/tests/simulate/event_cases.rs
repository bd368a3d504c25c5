//! Events through the simulation loop: located on the step's interpolant, never missed inside a
//! step, once at step boundaries and at the start, in time order, with state changes (a
//! bouncing ball) and a diagnosis when they accumulate (Zeno). SciPy's known failures are the
//! test list: #9228 (two roots inside one step missed), #17066 and #19418 (a root exactly on a
//! step boundary reported twice, or breaking the output).

use mechkit::forces::Force;
use mechkit::particles::{Kinematics, Sample, SampleKind};
use mechkit::prelude::*;
use mechkit::simulate::{EventRecord, Observer, ObserverError, ZENO_LIMIT};

const G: f64 = 9.81;

fn ball(dim: usize) -> ParticleSystem {
    ParticleSystem::builder(dim)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], G))
        .build()
        .unwrap()
}

fn dopri5() -> Stepping {
    Stepping::Adaptive {
        method: Method::Dopri5,
        config: AdaptiveConfig::default(),
    }
}

/// Times and kinds of every sample.
#[derive(Default)]
struct Times(Vec<(f64, SampleKind)>);

impl Observer for Times {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        self.0.push((s.t, s.kind));
        Ok(())
    }
}

fn named<'r>(r: &'r [EventRecord], name: &str) -> Vec<&'r EventRecord> {
    r.iter().filter(|e| e.name == name).collect()
}

/// A ball dropped from 1 m bounces with restitution 0.9: each apex is 0.81 of the one before,
/// to 1e-9, for 20 bounces, with adaptive and with fixed steps (the motion between bounces is
/// a parabola, which both the dense output and the Hermite interpolant reproduce).
#[test]
fn bouncing_ball_apex_heights_follow_e_squared() {
    let sys = ball(1);
    let e = 0.9;
    for stepping in [
        dopri5(),
        Stepping::Fixed {
            method: Method::Rk4,
            dt: 0.01,
        },
    ] {
        let bounce = Event::new("bounce", |s, _| s.q[0])
            .direction(Direction::Falling)
            .set(move |_, _, y| y[1] *= -e);
        let apex = Event::new("apex", |s, _| s.v[0]).direction(Direction::Falling);
        let mut times = Times::default();
        let r = Simulation::with_stepping(&sys, stepping.clone())
            .t_max(8.0)
            .event(bounce)
            .event(apex)
            .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [&mut times])
            .unwrap();
        assert_eq!(r.stop_reason, StopReason::TMax, "{stepping:?}");
        // the start (at rest at 1 m) is an apex too: leaving vy = 0 downwards
        let apexes = named(&r.events, "apex");
        assert_eq!(apexes[0].t, 0.0);
        let apexes = &apexes[1..];
        assert!(apexes.len() >= 20, "{} apexes", apexes.len());
        let mut worst: f64 = 0.0;
        let mut previous = 1.0;
        for a in apexes.iter().take(20) {
            let ratio = a.state.q[0] / previous;
            worst = worst.max((ratio - e * e).abs() / (e * e));
            previous = a.state.q[0];
        }
        println!(
            "{:?}: worst relative error of the apex ratio {worst:e}",
            stepping.method()
        );
        assert!(worst < 1e-9, "{worst:e}");
        // bounce times: t1 = sqrt(2/g), then flights of 2 e^k v1/g
        let bounces = named(&r.events, "bounce");
        let v1 = (2.0 * G).sqrt();
        let mut t = (2.0 / G).sqrt();
        for (k, b) in bounces.iter().take(20).enumerate() {
            assert!((b.t - t).abs() < 1e-9 * t, "bounce {k}: {} vs {t}", b.t);
            let after = b.after.as_ref().expect("state change recorded");
            assert!((after.v[0] + e * b.state.v[0]).abs() < 1e-12);
            t += 2.0 * e.powi(k as i32 + 1) * v1 / G;
        }
        // the energy lost at the bounces is booked as jumps, not as work
        assert!(
            r.ledger.work_energy_residual().abs() < 1e-9,
            "{}",
            r.ledger.work_energy_residual()
        );
        assert!(r.ledger.jump_kinetic() < 0.0);
        // time never goes backwards in the output
        assert!(times.0.windows(2).all(|w| w[0].0 <= w[1].0));
    }
}

/// The bounces accumulate at T = t1 (1 + 2e/(1 - e)): running past it must stop with a Zeno
/// diagnosis after a bounded number of occurrences, keeping the state there.
#[test]
fn accumulating_bounces_stop_with_a_zeno_diagnosis() {
    let sys = ball(1);
    let e = 0.9;
    let bounce = Event::new("bounce", |s, _| s.q[0])
        .direction(Direction::Falling)
        .set(move |_, _, y| y[1] *= -e);
    let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(100.0)
        .event(bounce)
        .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
        .unwrap();
    let last: Vec<(f64, f64)> = r
        .events
        .iter()
        .rev()
        .take(5)
        .map(|e| (e.t, e.state.v[0]))
        .collect();
    println!(
        "{} bounces, final t {}, last {last:?}",
        r.events.len(),
        r.final_state.t
    );
    assert_eq!(r.stop_reason, StopReason::Zeno);
    let d = r.divergence.as_ref().unwrap();
    assert!(d.message.contains("Zeno"), "{}", d.message);
    let t1 = (2.0 / G).sqrt();
    let t_inf = t1 * (1.0 + 2.0 * e / (1.0 - e));
    assert!(
        (r.final_state.t - t_inf).abs() < 1e-6,
        "{} vs {t_inf}",
        r.final_state.t
    );
    assert!(r.events.len() < 400, "{} bounces", r.events.len());
    assert!(r.events.len() as u32 > ZENO_LIMIT);
}

/// x(t) = (t + 6)(t + 2)(t - 2) from t = -8 to 4 (SciPy #9228: the solver's first long step
/// jumps over two of the roots). The motion is a cubic, which Dormand-Prince integrates
/// exactly, so its steps grow as large as they like; every root must still be found.
#[derive(Debug)]
struct CubicPush;

impl Force for CubicPush {
    fn name(&self) -> &'static str {
        "push"
    }
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [f64]) {
        out[0] += 6.0 * k.t + 12.0;
    }
    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

#[test]
fn two_roots_inside_one_step_are_both_found() {
    let sys = ParticleSystem::builder(1)
        .body("p", 1.0)
        .force(CubicPush)
        .build()
        .unwrap();
    let x0 = State::from_qv(-8.0, &[-120.0], &[92.0]);
    for direction in [Direction::Both, Direction::Rising, Direction::Falling] {
        let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
            .t_max(4.0)
            .event(Event::new("zero", |s, _| s.q[0]).direction(direction))
            .run(x0.clone(), &mut [])
            .unwrap();
        let found: Vec<f64> = r.events.iter().map(|e| e.t).collect();
        let want: &[f64] = match direction {
            Direction::Both => &[-6.0, -2.0, 2.0],
            Direction::Rising => &[-6.0, 2.0],
            Direction::Falling => &[-2.0],
        };
        assert!(r.steps < 12, "the steps should be long: {}", r.steps);
        assert_eq!(found.len(), want.len(), "{direction:?}: {found:?}");
        for (t, w) in found.iter().zip(want) {
            assert!((t - w).abs() < 1e-12, "{t} vs {w}");
        }
    }
}

/// Uniform motion with steps of exactly 0.25 s: roots at t = 0.5 (a step boundary) and at
/// t = 0 (the start).
fn boundary_run(stepping: Stepping, events: Vec<Event>) -> (mechkit::simulate::RunReport, Times) {
    let sys = ParticleSystem::builder(1).body("p", 1.0).build().unwrap();
    let mut times = Times::default();
    let mut sim = Simulation::with_stepping(&sys, stepping).t_max(1.0);
    for e in events {
        sim = sim.event(e);
    }
    let r = sim
        .run(State::from_qv(0.0, &[0.0], &[1.0]), &mut [&mut times])
        .unwrap();
    (r, times)
}

#[test]
fn a_root_on_a_step_boundary_fires_once() {
    let fixed = Stepping::Fixed {
        method: Method::Rk4,
        dt: 0.25,
    };
    let adaptive = Stepping::Adaptive {
        method: Method::Dopri5,
        config: AdaptiveConfig {
            h0: Some(0.25),
            h_max: 0.25,
            ..AdaptiveConfig::default()
        },
    };
    for stepping in [fixed, adaptive] {
        let (r, times) = boundary_run(
            stepping.clone(),
            vec![
                Event::new("half", |s, _| s.t - 0.5),
                Event::new("x half", |s, _| s.q[0] - 0.5),
            ],
        );
        assert_eq!(r.steps, 4, "{stepping:?}");
        let t: Vec<f64> = r.events.iter().map(|e| e.t).collect();
        assert_eq!(t, vec![0.5, 0.5], "{stepping:?}");
        // one sample per instant, marked as the event
        let at_half: Vec<_> = times.0.iter().filter(|(t, _)| *t == 0.5).collect();
        assert_eq!(at_half.len(), 1, "{:?}", times.0);
        assert_eq!(at_half[0].1, SampleKind::Event);
        assert!(times.0.windows(2).all(|w| w[0].0 < w[1].0));
    }
}

#[test]
fn a_root_at_the_start_counts_when_left_in_its_direction() {
    let fixed = Stepping::Fixed {
        method: Method::Rk4,
        dt: 0.25,
    };
    let (r, _) = boundary_run(
        fixed.clone(),
        vec![
            Event::new("rising x", |s, _| s.q[0]).direction(Direction::Rising),
            Event::new("falling x", |s, _| s.q[0]).direction(Direction::Falling),
        ],
    );
    let names: Vec<(&str, f64)> = r.events.iter().map(|e| (e.name.as_str(), e.t)).collect();
    assert_eq!(names, vec![("rising x", 0.0)]);
    // a terminal event at the start ends the run there
    let (r, _) = boundary_run(fixed, vec![Event::new("x", |s, _| s.q[0]).stop()]);
    assert_eq!(r.stop_reason, StopReason::Event);
    assert_eq!(r.final_state.t, 0.0);
}

#[test]
fn events_in_one_step_are_reported_in_time_order() {
    let (r, times) = boundary_run(
        Stepping::Fixed {
            method: Method::Rk4,
            dt: 0.5,
        },
        vec![
            Event::new("late", |s, _| s.q[0] - 0.3),
            Event::new("early", |s, _| s.q[0] - 0.2),
            Event::new("same time", |s, _| s.t - 0.2),
        ],
    );
    let got: Vec<(&str, f64)> = r.events.iter().map(|e| (e.name.as_str(), e.t)).collect();
    assert_eq!(got.len(), 3);
    assert_eq!(got[0].0, "early");
    assert_eq!(got[1].0, "same time");
    assert_eq!(got[2].0, "late");
    for (_, t) in &got[..2] {
        assert!((t - 0.2).abs() < 1e-15);
    }
    assert!((got[2].1 - 0.3).abs() < 1e-15);
    assert!(times.0.windows(2).all(|w| w[0].0 <= w[1].0));
}

#[test]
fn max_count_and_stop_at() {
    let sys = ParticleSystem::builder(1)
        .body("p", 1.0)
        .force(Spring::new(
            "spring",
            1.0,
            0.0,
            SpringEnds::Anchor {
                bodies: vec![0],
                anchor: vec![0.0],
            },
        ))
        .build()
        .unwrap();
    // x = cos t crosses zero at π/2 + kπ
    let run = |e: Event| {
        Simulation::adaptive(&sys, Method::Dop853, AdaptiveConfig::default())
            .t_max(20.0)
            .event(e)
            .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
            .unwrap()
    };
    let r = run(Event::new("zero", |s, _| s.q[0]).max_count(3));
    assert_eq!(r.events.len(), 3);
    assert_eq!(r.stop_reason, StopReason::TMax);
    let r = run(Event::new("zero", |s, _| s.q[0]).stop_at(4));
    assert_eq!(r.events.len(), 4);
    assert_eq!(r.stop_reason, StopReason::Event);
    let want = 3.5 * std::f64::consts::PI;
    // located to rounding on the interpolant; the solution itself is good to about rtol
    assert!((r.final_state.t - want).abs() < 1e-6, "{}", r.final_state.t);
    assert!(r.event.as_ref().unwrap().terminal);
}

/// Output times are interpolated without changing the steps: the same steps and final state
/// with and without them.
#[test]
fn output_times_do_not_affect_the_steps() {
    let sys = ball(2);
    let x0 = State::from_qv(0.0, &[0.0, 0.0], &[3.0, 7.0]);
    let plain = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(1.0)
        .run(x0.clone(), &mut [])
        .unwrap();
    let mut times = Times::default();
    let sampled = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(1.0)
        .output_interval(0.1)
        .run(x0, &mut [&mut times])
        .unwrap();
    assert_eq!(plain.steps, sampled.steps);
    assert_eq!(plain.final_state.y, sampled.final_state.y);
    let grid: Vec<f64> = times
        .0
        .iter()
        .filter(|(_, k)| *k == SampleKind::Grid)
        .map(|(t, _)| *t)
        .collect();
    assert_eq!(grid.len(), 10, "{grid:?}");
    for (k, t) in grid.iter().enumerate() {
        assert!((t - 0.1 * (k + 1) as f64).abs() < 1e-15);
    }
}

/// Keeps the output-time samples: time and height.
#[derive(Default)]
struct Grid(Vec<(f64, f64)>);

impl Observer for Grid {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if s.kind == SampleKind::Grid {
            self.0.push((s.t, s.q[1]));
        }
        Ok(())
    }
}

/// `t_eval`: the state at listed times, exact for a parabola on any interpolant.
#[test]
fn output_at_listed_times() {
    let sys = ball(2);
    for stepping in [
        dopri5(),
        Stepping::Fixed {
            method: Method::Rk4,
            dt: 0.3,
        },
    ] {
        let mut grid = Grid::default();
        Simulation::with_stepping(&sys, stepping)
            .t_max(1.0)
            .output_times(vec![0.0, 0.25, 0.5, 0.9, 2.0])
            .run(
                State::from_qv(0.0, &[0.0, 0.0], &[3.0, 7.0]),
                &mut [&mut grid],
            )
            .unwrap();
        let t: Vec<f64> = grid.0.iter().map(|p| p.0).collect();
        assert_eq!(t, vec![0.25, 0.5, 0.9]);
        for (t, y) in grid.0 {
            assert!((y - (7.0 * t - 0.5 * G * t * t)).abs() < 1e-12, "{t}: {y}");
        }
    }
    let err = Simulation::new(&sys, Method::Rk4, 0.1)
        .output_times(vec![0.5, 0.2])
        .run(State::from_qv(0.0, &[0.0, 0.0], &[3.0, 7.0]), &mut [])
        .unwrap_err();
    assert!(err.to_string().contains("increasing"), "{err}");
}
