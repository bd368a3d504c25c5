//! Which events are armed again after a state change.
//!
//! An event that fires and changes the state leaves its function at zero (to rounding, on
//! either side). Leaving zero afterwards is not a crossing, unless the change **turned the
//! function back**: a bounce sends `g = x` from falling to rising, so the next arrival at zero
//! (the next bounce) must fire even when the excursion above zero is too short for any sample
//! point of the next step to see it (late bounces near the accumulation point, long fixed
//! steps). The direction the function takes after the change is its rate along the new state's
//! flow, `ġ ≈ (g(t + δ, y + δ ẏ) − g(t, y)) / δ`, with `δ = √ε · max(|t|, typical step)`.
//! A change that leaves the function at zero with no rate (a bounce of a body at rest on the
//! floor) leaves it as at the start of a run ([`Side::StartZero`]): if the flow then takes it
//! across the way it fired, it fires again at once, and the run stops on the Zeno diagnosis
//! rather than pass through the wall; if it stays at zero, nothing fires.

use super::event::{Event, Trigger};
use super::probe::Probe;
use super::run::sample_of;
use crate::Real;
use crate::ode::State;
use crate::ode::events::find::{self, Side};
use crate::particles::{Evaluation, ParticleSystem, SampleKind};

/// The values of the functions of the `fired` events a moment `δ` along the flow of `state`
/// (whose accelerations are in `eval`), in `out` (the other entries are left alone); `probe`
/// is scratch space.
#[allow(clippy::too_many_arguments)]
pub(super) fn values_ahead(
    (events, fired): (&[Event], &[usize]),
    sys: &ParticleSystem,
    (state, eval, work): (&State, &Evaluation, &[Real]),
    scale: Real,
    step: u64,
    probe: &mut Probe,
    evaluations: &mut u64,
    out: &mut [Real],
) {
    let n = state.y.len() / 2;
    let mut delta = Real::EPSILON.sqrt() * state.t.abs().max(scale.abs());
    if !(delta.is_finite() && delta > 0.0) {
        delta = Real::EPSILON.sqrt();
    }
    probe.state.t = state.t + delta;
    probe.state.y.resize(2 * n, 0.0);
    for k in 0..n {
        probe.state.y[k] = state.y[k] + delta * state.y[n + k];
        probe.state.y[n + k] = state.y[n + k] + delta * eval.a.get(k).copied().unwrap_or(0.0);
    }
    let eval_ahead = if fired.iter().any(|&i| events[i].needs_forces()) {
        let (q, v) = probe.state.qv();
        sys.evaluate(probe.state.t, q, v, &mut probe.eval, &mut probe.scratch);
        *evaluations += 1;
        &probe.eval
    } else {
        eval
    };
    let s = sample_of(step, &probe.state, eval_ahead, work, SampleKind::Event);
    for &i in fired {
        out[i] = events[i].condition().value(&s, sys);
    }
}

/// The sides of the events right after a state change ([`sides_after_change`] of the one
/// event finder, with the particles' events' origins: a stop condition is never armed).
pub(super) fn sides_after_change(
    events: &[Event],
    fired: &[usize],
    before: &[Side],
    values: (&[Real], &[Real], &[Real]),
    out: &mut [Side],
) {
    let origin = |i: usize| match events[i].trigger {
        Trigger::Crossing(d) => d.origin(before[i]),
        Trigger::Holds { .. } => Side::Zero,
    };
    find::sides_after_change(fired, &origin, before, values, out);
    // a change that leaves its function at zero with no rate at all (a bounce `vy -> -e vy`
    // of a body at rest on the floor: `vy` stays 0) has not turned it back, and has not sent
    // it on either; as at the start of a run, leaving zero the way it fired fires it again
    // (at once: the Zeno diagnosis) instead of passing through the wall unseen, while staying
    // at zero (two balls at rest in contact after a Newton's cradle's impact) fires nothing
    let (g_pre, g_post, g_ahead) = values;
    for &i in fired {
        let in_place = g_post[i] == g_pre[i] || g_post[i] == 0.0;
        if out[i] == Side::Zero
            && events[i].state_change().is_some()
            && in_place
            && g_post[i] == 0.0
            && g_ahead[i] == g_post[i]
        {
            out[i] = Side::StartZero;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::events::Direction;

    #[test]
    fn a_bounce_is_armed_again_and_a_kick_is_not() {
        let falling = [Event::new("g", |_, _| 0.0).direction(Direction::Falling)];
        let mut out = [Side::Unknown];
        let b = [-1e-30];
        // slightly below zero after the change (where it was located), rising: armed above
        sides_after_change(&falling, &[0], &[Side::Pos], (&b, &b, &[1e-20]), &mut out);
        assert_eq!(out, [Side::Pos]);
        // still falling after the change (a kick along): at zero
        sides_after_change(&falling, &[0], &[Side::Pos], (&b, &b, &[-1e-20]), &mut out);
        assert_eq!(out, [Side::Zero]);
        // moved well below and rising (a jump elsewhere): at zero, its side follows the samples
        sides_after_change(
            &falling,
            &[0],
            &[Side::Pos],
            (&b, &[-1.0], &[-0.9]),
            &mut out,
        );
        assert_eq!(out, [Side::Zero]);
        let rising = [Event::new("g", |_, _| 0.0).direction(Direction::Rising)];
        sides_after_change(
            &rising,
            &[0],
            &[Side::Neg],
            (&[0.0], &[0.0], &[-1.0]),
            &mut out,
        );
        assert_eq!(out, [Side::Neg]);
        // not fired: its own side
        sides_after_change(
            &rising,
            &[],
            &[Side::Neg],
            (&[2.0], &[2.0], &[3.0]),
            &mut out,
        );
        assert_eq!(out, [Side::Pos]);
    }

    #[test]
    fn a_change_leaving_its_function_at_zero_without_rate_is_as_at_the_start() {
        let bounce = [Event::new("g", |_, _| 0.0)
            .direction(Direction::Falling)
            .set(|_, _, y| y[1] *= -0.9)];
        let mut out = [Side::Unknown];
        let zero = [0.0];
        // a bounce at rest on the floor: still at zero a moment later, as at the start
        sides_after_change(&bounce, &[0], &[Side::Pos], (&zero, &zero, &zero), &mut out);
        assert_eq!(out, [Side::StartZero]);
        // the same without a state change (a recording event): at zero
        let record = [Event::new("g", |_, _| 0.0).direction(Direction::Falling)];
        sides_after_change(&record, &[0], &[Side::Pos], (&zero, &zero, &zero), &mut out);
        assert_eq!(out, [Side::Zero]);
        // a kick along: at zero
        sides_after_change(
            &bounce,
            &[0],
            &[Side::Pos],
            (&zero, &zero, &[-1e-20]),
            &mut out,
        );
        assert_eq!(out, [Side::Zero]);
    }
}
