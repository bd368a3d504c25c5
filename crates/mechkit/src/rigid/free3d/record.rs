//! What a run keeps as it goes: samples on the output grid, the zeros of ω about the
//! intermediate axis (found as events by the loop: `model.rs`), the largest deviations of the
//! conserved quantities at step ends, and the unwrapped precession angle.

use super::body::{Attitude, SpinningBody};
use super::driver::Driver;
use super::equations::{Formulation, SpinEquations};
use super::run::{Conservation, Crossing, SpinSample};
use crate::Real;
use crate::ode::State;

/// What is kept of the run as it goes.
pub(super) struct Record<'a> {
    body: &'a SpinningBody,
    formulation: Formulation,
    t_end: Real,
    intervals: usize,
    next_sample: usize,
    pub(super) samples: Vec<SpinSample>,
    /// The zeros of ω about the intermediate axis (found by the run's events).
    pub(super) crossings: Vec<Crossing>,
    pub(super) conservation: Conservation,
    /// `(|L|, L_z, L₃, E, φ)` at the start.
    start: [Real; 5],
    e_scale: Real,
    /// The precession angle at the last step end, unwrapped.
    phi: Real,
    /// The intermediate axis (free bodies) and the noise level of ω about it: below it a
    /// change of sign is rounding, not a crossing.
    pub(super) watch: Option<(usize, Real)>,
}

/// `x` wrapped to `(−π, π]`.
fn wrap(x: Real) -> Real {
    use std::f64::consts::{PI, TAU};
    x - TAU * ((x + PI) / TAU).floor()
}

impl<'a> Record<'a> {
    pub(super) fn new(
        eq: &SpinEquations<'a>,
        start: &Attitude,
        t_end: Real,
        intervals: usize,
    ) -> Self {
        let body = eq.body();
        let y0 = eq.formulation().to_state(start);
        let invariants = eq.invariants(&y0);
        let omega = body.omega_body(start);
        let watch = body
            .pivot()
            .is_none()
            .then(|| (body.body().intermediate_axis(), 1e-12 * omega.norm()));
        let mut r = Record {
            body,
            formulation: eq.formulation(),
            t_end,
            intervals: intervals.max(1),
            next_sample: 0,
            samples: Vec::with_capacity(intervals.max(1) + 1),
            crossings: Vec::new(),
            conservation: Conservation::default(),
            start: invariants,
            e_scale: invariants[3].abs().max(body.kinetic_energy(start)),
            phi: invariants[4],
            watch,
        };
        r.sample(0.0, &y0);
        r
    }

    fn sample(&mut self, t: Real, y: &[Real]) {
        let a = self.formulation.attitude(y);
        let phi = self.phi + wrap(a.euler_angles().0 - self.phi);
        self.samples.push(SpinSample {
            t,
            attitude: a,
            omega_body: self.body.omega_body(&a),
            kinetic: self.body.kinetic_energy(&a),
            potential: self.body.potential_energy(&a.q),
            precession: phi,
        });
        self.next_sample += 1;
    }

    pub(super) fn after_step(&mut self, driver: &mut Driver, eq: &SpinEquations, end: &State) {
        let y1 = &end.y;
        let t1 = end.t;
        let mut y = [0.0; 7];
        while self.next_sample <= self.intervals {
            let k = self.next_sample;
            let t = if k == self.intervals {
                self.t_end
            } else {
                self.t_end * k as Real / self.intervals as Real
            };
            if t > t1 {
                break;
            }
            if t == t1 {
                self.sample(t, y1);
            } else {
                driver.interpolate(eq, t, &mut y);
                self.sample(t, &y);
            }
        }
        let c = &mut self.conservation;
        let qn = (y1[0] * y1[0] + y1[1] * y1[1] + y1[2] * y1[2] + y1[3] * y1[3]).sqrt();
        c.quaternion_norm = c.quaternion_norm.max((qn - 1.0).abs());
        let [l_norm, l_z, l_3, e, phi] = eq.invariants(y1);
        let [l0, lz0, l30, e0, _] = self.start;
        let scale = l0.max(Real::MIN_POSITIVE);
        c.l_norm = c.l_norm.max((l_norm - l0).abs() / scale);
        c.l_z = c.l_z.max((l_z - lz0).abs() / scale);
        c.l_3 = c.l_3.max((l_3 - l30).abs() / scale);
        c.energy = c
            .energy
            .max((e - e0).abs() / self.e_scale.max(Real::MIN_POSITIVE));
        self.phi += wrap(phi - self.phi);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_is_in_minus_pi_pi() {
        for x in [3.5, -3.5, 10.0, 0.0, -7.0] {
            let w = wrap(x);
            assert!(w > -std::f64::consts::PI && w <= std::f64::consts::PI);
            assert!(((x - w) / std::f64::consts::TAU).fract().abs() < 1e-12);
        }
    }
}
