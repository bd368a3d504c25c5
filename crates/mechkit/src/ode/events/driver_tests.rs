//! Tests of `run_events` and `run_to_event`.

use mechkit_expr::interval::Jet;

use super::*;
use crate::ode::{AdaptiveConfig, Direction, Tableau};

/// `x' = v, v' = −x`.
struct Oscillator;
impl OdeSystem for Oscillator {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = -y[0];
    }
}

/// `y = [t, c − t²]`: integrated exactly by any pair, so its steps are as long as allowed.
struct Parabola;
impl OdeSystem for Parabola {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = 1.0;
        dydt[1] = -2.0 * y[0];
    }
}

fn rk(rtol: Real) -> AdaptiveRk {
    AdaptiveRk::new(Tableau::dop853(), AdaptiveConfig::from_rtol(rtol)).unwrap()
}

/// Runs and collects the hits and the steps.
fn collect<S: OdeSystem>(
    rk: &mut AdaptiveRk,
    sys: &S,
    state: &mut State,
    t_end: Real,
    events: &[OdeEvent<'_>],
) -> (EventEnd, Vec<(usize, Real)>, Vec<Real>) {
    let (mut hits, mut steps) = (Vec::new(), Vec::new());
    let end = run_to_event(rk, sys, state, t_end, events, &mut |p| {
        match p {
            Progress::Step(s) => steps.push(s.t),
            Progress::Event(h) => hits.push((h.event, h.t)),
        }
        ControlFlow::Continue(())
    })
    .unwrap();
    (end, hits, steps)
}

#[test]
fn a_short_excursion_that_eight_samples_miss_is_found() {
    // one step of length 1 over [−0.45, 0.55]; c − t² > 0 only for |t| < 1e-3, while the
    // nearest of the eight samples is at t = 0.05
    let run = |event: OdeEvent<'_>| {
        let config = AdaptiveConfig {
            h0: Some(1.0),
            h_max: 1.0,
            ..AdaptiveConfig::from_rtol(1e-10)
        };
        let mut rk = AdaptiveRk::new(Tableau::dop853(), config).unwrap();
        let mut state = State::new(-0.45, vec![-0.45, 1e-6 - 0.45 * 0.45]);
        let (end, hits, steps) = collect(&mut rk, &Parabola, &mut state, 0.55, &[event]);
        assert_eq!(end, EventEnd::TimeLimit);
        assert_eq!(steps, vec![0.55], "one step");
        hits
    };
    assert!(
        run(OdeEvent::new(|_, y| y[1])).is_empty(),
        "sampled: missed"
    );
    let hits = run(OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1])));
    assert_eq!(hits.len(), 2, "{hits:?}");
    for ((_, t), want) in hits.iter().zip([-1e-3, 1e-3]) {
        assert!((t - want).abs() < 1e-11, "{t} vs {want}");
    }
}

#[test]
fn recorded_events_come_in_time_order() {
    // x = cos t: zeros at π/2 (falling) and 3π/2 (rising), x = 0.5 at π/3 and 5π/3
    let mut rk = rk(1e-12);
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let bounded = |f: fn(Jet) -> Jet| move |_: Jet, y: &[Jet]| Some(f(y[0]));
    let events = [
        OdeEvent::new(|_, y| y[0]).bounded_by(bounded(|x| x)),
        OdeEvent::new(|_, y| y[0] - 0.5)
            .bounded_by(bounded(|x| x - Jet::constant(0.5)))
            .direction(Direction::Rising),
        OdeEvent::new(|t, _| t - 1.0),
    ];
    let (end, hits, steps) = collect(&mut rk, &Oscillator, &mut state, 6.0, &events);
    assert_eq!(end, EventEnd::TimeLimit);
    let pi = std::f64::consts::PI;
    let want = [(2, 1.0), (0, pi / 2.0), (0, 1.5 * pi), (1, 5.0 * pi / 3.0)];
    assert_eq!(hits.len(), want.len(), "{hits:?}");
    for ((e, t), (we, wt)) in hits.iter().zip(want) {
        assert_eq!(*e, we);
        assert!((t - wt).abs() < 1e-11, "{e}: {t} vs {wt}");
    }
    assert_eq!(*steps.last().unwrap(), 6.0);
    assert!(steps.windows(2).all(|w| w[0] < w[1]));
}

#[test]
fn the_redone_step_ends_exactly_at_the_event() {
    // x = cos t falls through 0.5 at π/3; the time mark at 0.5 is recorded first, the one
    // at 2 never
    let mut rk = rk(1e-13);
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let events = [
        OdeEvent::new(|t, _| t - 2.0),
        OdeEvent::new(|_, y| y[0] - 0.5)
            .bounded_by(|_, y: &[Jet]| Some(y[0] - Jet::constant(0.5)))
            .falling()
            .terminal(),
        OdeEvent::new(|t, _| t - 0.5),
    ];
    let (mut order, mut last_step) = (Vec::new(), 0.0);
    let end = run_to_event(&mut rk, &Oscillator, &mut state, 10.0, &events, &mut |p| {
        match p {
            Progress::Step(s) => {
                order.push(("step", s.t));
                last_step = s.t;
            }
            Progress::Event(h) => order.push(("event", h.t)),
        }
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(end, EventEnd::Terminal { event: 1 });
    let exact = std::f64::consts::FRAC_PI_3;
    assert!((state.t - exact).abs() < 1e-13, "{}", state.t - exact);
    assert!((state.y[0] - 0.5).abs() < 1e-13);
    // the integrator reached the event time exactly: the last step ends there
    assert_eq!(last_step, state.t);
    assert_eq!(rk.last_step().1, state.t);
    assert!(order.iter().any(|(k, t)| *k == "event" && *t == 0.5));
    assert!(order.windows(2).all(|w| w[0].1 <= w[1].1), "{order:?}");
}

#[test]
fn starting_on_zero_does_not_fire_and_no_event_ends_at_the_limit() {
    // g = x starts at 0 (leaving); the next zero is at t = π
    let mut rk = rk(1e-13);
    let mut state = State::new(0.0, vec![0.0, 1.0]);
    let events = [OdeEvent::new(|_, y| y[0]).terminal()];
    let (end, _, _) = collect(&mut rk, &Oscillator, &mut state, 10.0, &events);
    assert_eq!(end, EventEnd::Terminal { event: 0 });
    assert!((state.t - std::f64::consts::PI).abs() < 1e-12);
    // an event that never happens: the run ends at the time limit
    rk.reset();
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let events = [OdeEvent::new(|_, y| y[0] - 2.0).terminal()];
    let (end, _, _) = collect(&mut rk, &Oscillator, &mut state, 1.0, &events);
    assert_eq!(end, EventEnd::TimeLimit);
    assert_eq!(state.t, 1.0);
}

#[test]
fn the_caller_can_halt_the_run() {
    let mut rk = rk(1e-10);
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let mut steps = 0;
    let end = run_to_event(&mut rk, &Oscillator, &mut state, 10.0, &[], &mut |_| {
        steps += 1;
        if steps == 3 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })
    .unwrap();
    assert_eq!(end, EventEnd::Halted);
    assert_eq!(steps, 3);
    assert!(state.t < 10.0);
}

/// `x' = v, v' = −g`.
struct Fall;
impl OdeSystem for Fall {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = -9.81;
    }
}

fn floor(e: Real) -> OdeEvent<'static> {
    OdeEvent::new(|_, y| y[0])
        .bounded_by(|_, y: &[Jet]| Some(y[0]))
        .falling()
        .action(move |_, y| y[1] *= -e)
}

#[test]
fn fixed_steps_find_every_crossing_on_the_hermite_interpolant() {
    // x = cos t with rk4 at dt = 0.01: zeros at π/2 + kπ, none missed, each to the
    // interpolant's accuracy
    let mut rk4 = crate::ode::Rk4::default();
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let events = [OdeEvent::new(|_, y| y[0]).bounded_by(|_, y: &[Jet]| Some(y[0]))];
    let mut hits = Vec::new();
    let fixed = Integrator::Fixed {
        stepper: &mut rk4,
        dt: 0.01,
    };
    let end = run_events(fixed, &Oscillator, &mut state, 10.0, &events, &mut |p| {
        if let Progress::Event(h) = p {
            hits.push(h.t);
        }
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(end, EventEnd::TimeLimit);
    assert_eq!(state.t, 10.0);
    let pi = std::f64::consts::PI;
    assert_eq!(hits.len(), 3, "{hits:?}");
    for (k, t) in hits.iter().enumerate() {
        assert!((t - (0.5 + k as Real) * pi).abs() < 1e-8, "{t}");
    }
    // one step of length 1 over [−0.45, 0.55]: c − t² > 0 only for |t| < 1e-3
    let mut rk4 = crate::ode::Rk4::default();
    let mut state = State::new(-0.45, vec![-0.45, 1e-6 - 0.45 * 0.45]);
    let events = [OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1]))];
    let mut hits = Vec::new();
    let fixed = Integrator::Fixed {
        stepper: &mut rk4,
        dt: 1.0,
    };
    run_events(fixed, &Parabola, &mut state, 0.55, &events, &mut |p| {
        if let Progress::Event(h) = p {
            hits.push(h.t);
        }
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!((hits[0] + 1e-3).abs() < 1e-12 && (hits[1] - 1e-3).abs() < 1e-12);
}

#[test]
fn an_action_cuts_the_step_and_the_fixed_steps_restart_there() {
    let mut rk4 = crate::ode::Rk4::default();
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let mut order = Vec::new();
    let fixed = Integrator::Fixed {
        stepper: &mut rk4,
        dt: 0.01,
    };
    let end = run_events(fixed, &Fall, &mut state, 0.5, &[floor(0.8)], &mut |p| {
        order.push(match p {
            Progress::Step(s) => ("step", s.t, s.y[1]),
            Progress::Event(h) => ("event", h.t, h.y[1]),
        });
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(end, EventEnd::TimeLimit);
    let t1 = (2.0 / 9.81 as Real).sqrt();
    let at = order.iter().position(|o| o.0 == "event").unwrap();
    let (_, te, v_before) = order[at];
    assert!((te - t1).abs() < 1e-13 && v_before < 0.0);
    // the step reached the event, the new state follows at the same time, then the
    // fixed steps count from the event
    assert_eq!((order[at + 1].0, order[at + 1].1), ("step", te));
    assert_eq!((order[at + 2].0, order[at + 2].1), ("step", te));
    assert!((order[at + 2].2 + 0.8 * v_before).abs() < 1e-12);
    assert_eq!(order[at + 3].1, te + 0.01);
}

#[test]
fn bounces_that_accumulate_end_the_run_as_zeno() {
    // restitution 0.5: the bounces accumulate at t∞ = t₁ (1 + e)/(1 − e) = 3 t₁
    let mut rk = rk(1e-12);
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let mut bounces = 0;
    let end = run_events(
        Integrator::Adaptive(&mut rk),
        &Fall,
        &mut state,
        10.0,
        &[floor(0.5)],
        &mut |p| {
            if let Progress::Event(_) = p {
                bounces += 1;
            }
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    assert_eq!(end, EventEnd::Zeno { event: 0 });
    let t_inf = 3.0 * (2.0 / 9.81 as Real).sqrt();
    assert!((state.t - t_inf).abs() < 1e-12, "{} vs {t_inf}", state.t);
    assert!(bounces > 30, "{bounces}");
}

#[test]
fn a_bad_fixed_step_is_refused() {
    let mut rk4 = crate::ode::Rk4::default();
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    for dt in [0.0, -1.0, Real::NAN, Real::INFINITY] {
        let fixed = Integrator::Fixed {
            stepper: &mut rk4,
            dt,
        };
        let err = run_events(fixed, &Oscillator, &mut state, 1.0, &[], &mut |_| {
            ControlFlow::Continue(())
        });
        assert!(matches!(err, Err(RunError::Fixed(_))), "{dt}: {err:?}");
    }
}
