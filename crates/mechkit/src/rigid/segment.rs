//! One regime of a piecewise-smooth motion, integrated with DOP853 until its event function
//! reaches zero: the switch is located inside the step by the dense output and Brent's
//! method, and the step is then redone up to exactly that time, so the next regime starts
//! from a state the integrator reached, not from an interpolated one.
//!
//! Shared by the stick-slip block ([`crate::rigid::friction::SpringBlock`]) and the rolling body
//! ([`crate::rigid::rolling`]).

use crate::Real;
use crate::ode::{AdaptiveError, AdaptiveRk, OdeSystem, State};

/// Interior points of each step at which the event function is sampled, so that a function
/// that touches zero and turns back inside one step is not missed.
const SAMPLES: u32 = 8;

/// How a segment ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SegmentEnd {
    /// The event function reached zero; the state is at that time.
    Event,
    /// The time limit was reached first.
    TimeLimit,
}

/// Integrates `sys` from `state` until `event(t, y)`, positive while the regime lasts, reaches
/// zero (arriving at zero counts; starting from zero does not), or until `t_end`. Calls
/// `on_step` after every accepted step, the final one included. The integrator is reset
/// first: the right-hand side changed with the regime.
pub(crate) fn run_segment<S: OdeSystem + ?Sized>(
    rk: &mut AdaptiveRk,
    sys: &S,
    state: &mut State,
    t_end: Real,
    event: &dyn Fn(Real, &[Real]) -> Real,
    on_step: &mut dyn FnMut(&State),
) -> Result<SegmentEnd, AdaptiveError> {
    rk.reset();
    let mut dense = vec![0.0; state.y.len()];
    // the last sample at which the event function was positive (None until one is seen)
    let mut armed = (event(state.t, &state.y) > 0.0).then_some(state.t);
    while state.t < t_end {
        let before = state.clone();
        rk.step(sys, state, t_end)?;
        let (a, b) = rk.last_step();
        let mut crossing = None;
        let mut prev = (a, armed.map_or(0.0, |_| event(a, &before.y)));
        for j in 1..=SAMPLES {
            let t = if j == SAMPLES {
                b
            } else {
                a + (b - a) * Real::from(j) / Real::from(SAMPLES)
            };
            let g = if j == SAMPLES {
                event(t, &state.y)
            } else {
                rk.dense_into(sys, t, &mut dense);
                event(t, &dense)
            };
            if g > 0.0 {
                armed = Some(t);
            } else if armed.is_some() && prev.1 > 0.0 {
                crossing = Some((prev, (t, g)));
                break;
            }
            prev = (t, g);
        }
        let Some(((ta, ga), (tb, gb))) = crossing else {
            on_step(state);
            continue;
        };
        let t_star = if gb == 0.0 {
            tb
        } else {
            let mut f = |t: Real| {
                rk.dense_into(sys, t, &mut dense);
                event(t, &dense)
            };
            crate::roots::brent_with_values(
                &mut f,
                ta,
                tb,
                Some((ga, gb)),
                4.0 * Real::EPSILON * tb.abs().max(tb - ta),
            )
            .expect("the event function changes sign in this bracket")
        };
        // redo the step up to exactly the switch
        *state = before;
        rk.reset();
        while state.t < t_star {
            rk.step(sys, state, t_star)?;
            if state.t < t_star {
                on_step(state);
            }
        }
        on_step(state);
        return Ok(SegmentEnd::Event);
    }
    Ok(SegmentEnd::TimeLimit)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::{AdaptiveConfig, Tableau, Tolerance};

    /// `x' = v, v' = −x`: the event `x = 0.5` (from above, starting at x = 1) is at
    /// `acos(0.5) = π/3`.
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

    fn rk() -> AdaptiveRk {
        let config = AdaptiveConfig {
            rtol: Tolerance::Scalar(1e-13),
            atol: Tolerance::Scalar(1e-15),
            ..AdaptiveConfig::default()
        };
        AdaptiveRk::new(Tableau::dop853(), config).unwrap()
    }

    #[test]
    fn locates_an_event_inside_a_step() {
        let mut rk = rk();
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let mut steps = 0;
        let end = run_segment(
            &mut rk,
            &Oscillator,
            &mut state,
            10.0,
            &|_, y| y[0] - 0.5,
            &mut |_| steps += 1,
        )
        .unwrap();
        assert_eq!(end, SegmentEnd::Event);
        let exact = std::f64::consts::FRAC_PI_3;
        assert!((state.t - exact).abs() < 1e-13, "{}", state.t - exact);
        assert!((state.y[0] - 0.5).abs() < 1e-13);
        assert!(steps >= 1);
    }

    #[test]
    fn starting_on_zero_does_not_fire_and_no_event_ends_at_the_limit() {
        // g = x starts at 0 (leaving); the next zero is at t = π
        let mut rk = rk();
        let mut state = State::new(0.0, vec![0.0, 1.0]);
        let end = run_segment(
            &mut rk,
            &Oscillator,
            &mut state,
            10.0,
            &|_, y| y[0],
            &mut |_| {},
        )
        .unwrap();
        assert_eq!(end, SegmentEnd::Event);
        assert!((state.t - std::f64::consts::PI).abs() < 1e-12);
        // an event that never happens: the segment ends at the time limit
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let end = run_segment(
            &mut rk,
            &Oscillator,
            &mut state,
            1.0,
            &|_, y| y[0] - 2.0,
            &mut |_| {},
        )
        .unwrap();
        assert_eq!(end, SegmentEnd::TimeLimit);
        assert_eq!(state.t, 1.0);
    }
}
