//! The free flight after the body leaves the curve, by the one event driver
//! ([`run_to_event`]): `(x, y, vx, vy)` under gravity until the body meets the curve again.
//!
//! The body leaves tangentially, so its gap from the curve grows from zero (like τ³ where the
//! normal force fell through zero smoothly) and sits at rounding level at first. The landing is
//! therefore two terminal events in turn, both enclosed ([`Curve::enclose_gap`]): the gap opens
//! past `10⁻¹² ×` the curve's length scale, then falls back through zero.

use std::ops::ControlFlow;

use super::curve::{Curve, Side};
use super::error::ConstrainedError;
use super::run::{BeadOnCurve, BeadSample, Departure, Landing};
use crate::Real;
use crate::interval::Jet;
use crate::ode::{AdaptiveRk, EventEnd, OdeEvent, OdeSystem, Progress, State, run_to_event};

/// `(x, y, vx, vy)' = (vx, vy, 0, −g)`.
struct Flight {
    g: Real,
}

impl OdeSystem for Flight {
    fn dim(&self) -> usize {
        4
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[2];
        dydt[1] = y[3];
        dydt[2] = 0.0;
        dydt[3] = -self.g;
    }
}

/// The gap of the body from the curve less `offset`, as an event with its enclosure.
fn gap_event(curve: &Curve, side: Side, offset: Real) -> OdeEvent<'_> {
    OdeEvent::new(move |_, y| curve.gap([y[0], y[1]], side) - offset).bounded_by(
        move |_, y: &[Jet]| Some(curve.enclose_gap([y[0], y[1]], side)? - Jet::constant(offset)),
    )
}

impl BeadOnCurve {
    /// The free flight from the departure `d` to the landing (or `t_max`), integrated by `rk`
    /// (so its counters cover the whole run), appending a sample at every step.
    pub(super) fn fly(
        &self,
        rk: &mut AdaptiveRk,
        d: &Departure,
        t_max: Real,
        samples: &mut Vec<BeadSample>,
    ) -> Result<Option<Landing>, ConstrainedError> {
        let flight = Flight { g: self.g };
        let (p, v) = (d.position, d.velocity);
        let mut state = State::new(d.t, vec![p[0], p[1], v[0], v[1]]);
        let open = 1e-12 * self.curve.scale();
        let stages = [
            gap_event(&self.curve, self.side, open).rising().terminal(),
            gap_event(&self.curve, self.side, 0.0).falling().terminal(),
        ];
        rk.reset();
        for event in stages {
            let end = run_to_event(rk, &flight, &mut state, t_max, &[event], &mut |p| {
                if let Progress::Step(s) = p {
                    samples.push(BeadSample {
                        t: s.t,
                        position: [s.y[0], s.y[1]],
                        velocity: [s.y[2], s.y[3]],
                        normal_force: None,
                    });
                }
                ControlFlow::Continue(())
            })?;
            if end != (EventEnd::Terminal { event: 0 }) {
                return Ok(None);
            }
        }
        let (position, velocity) = ([state.y[0], state.y[1]], [state.y[2], state.y[3]]);
        let q = self.curve.coordinate_of(position);
        let (tangent, normal) = self.curve.frame(q);
        let dot = |a: [Real; 2], b: [Real; 2]| a[0] * b[0] + a[1] * b[1];
        Ok(Some(Landing {
            t: state.t,
            coordinate: q,
            position,
            velocity,
            tangential_speed: dot(velocity, tangent),
            normal_speed: (-self.side.sign() * dot(velocity, normal)).max(0.0),
        }))
    }
}
