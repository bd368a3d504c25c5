//! What a run keeps as it goes: samples on the output grid, the zeros of ω about the
//! intermediate axis (none missed: proven pieces of each step's interpolant, then Brent's
//! method), the largest deviations of
//! the conserved quantities at step ends, and the unwrapped precession angle.

use super::body::{Attitude, SpinningBody};
use super::driver::Driver;
use super::equations::{Formulation, SpinEquations};
use super::run::{Conservation, Crossing, SpinSample};
use crate::Real;
use crate::interval::Jet;
use crate::ode::{ProofOutcome, State, StepPolynomial, StepProof};

/// What is kept of the run as it goes.
pub(super) struct Record<'a> {
    body: &'a SpinningBody,
    formulation: Formulation,
    t_end: Real,
    intervals: usize,
    next_sample: usize,
    pub(super) samples: Vec<SpinSample>,
    pub(super) crossings: Vec<Crossing>,
    pub(super) conservation: Conservation,
    /// `(|L|, L_z, L₃, E, φ)` at the start.
    start: [Real; 5],
    e_scale: Real,
    /// The precession angle at the last step end, unwrapped.
    phi: Real,
    /// The intermediate axis (free bodies) and the smallest |ω| component taken as a sign.
    watch: Option<(usize, Real)>,
    /// ω about the watched axis at the last step end where it was not 0.
    g_end: Real,
    /// The step's interpolant, its proof and the sample fractions (reused).
    poly: StepPolynomial,
    proof: StepProof,
    fractions: Vec<Real>,
}

/// Evenly spaced intervals of a step whose proof ran out of bounds.
const FALLBACK_PARTS: usize = 8;

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
        let g_end = watch.map_or(0.0, |(k, _)| eq.omega_body(&y0)[k]);
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
            g_end,
            poly: StepPolynomial::default(),
            proof: StepProof::default(),
            fractions: Vec::new(),
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

    pub(super) fn after_step(
        &mut self,
        driver: &mut Driver,
        eq: &SpinEquations,
        t0: Real,
        end: &State,
    ) {
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
        if let Some((axis, noise)) = self.watch {
            self.locate_crossings(driver, eq, (t0, t1), axis, noise, y1);
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

    /// Zeros of ω about `axis` in `[t0, t1]`, none missed: ω is bounded over pieces of the
    /// step's interpolant ([`StepProof`], with `ω` enclosed through the rotation of the
    /// enclosed quaternion), evaluated at the ends of the pieces where it may change sign (at
    /// [`FALLBACK_PARTS`] evenly spaced points if the proof runs out of bounds), and each sign
    /// change between two of them larger than the noise is refined by Brent's method.
    fn locate_crossings(
        &mut self,
        driver: &mut Driver,
        eq: &SpinEquations,
        (t0, t1): (Real, Real),
        axis: usize,
        noise: Real,
        y1: &[Real],
    ) {
        let g0 = self.g_end;
        let g1 = eq.omega_body(y1)[axis];
        let h = t1 - t0;
        driver.step_polynomial(eq, &mut self.poly);
        let poly = &self.poly;
        let outcome = self.proof.cut(t0, h, &mut |s| {
            let y: [Jet; 7] = std::array::from_fn(|i| poly.enclose(i, s));
            Some(eq.omega_body_jet(&y)[axis])
        });
        self.fractions.clear();
        if outcome == ProofOutcome::Proven {
            self.proof.sample_fractions_into(&mut self.fractions);
        } else {
            self.fractions
                .extend((1..FALLBACK_PARTS).map(|j| j as Real / FALLBACK_PARTS as Real));
        }
        let mut y = [0.0; 7];
        let mut omega_at = |driver: &mut Driver, t: Real| {
            driver.interpolate(eq, t, &mut y);
            eq.omega_body(&y)[axis]
        };
        let (mut ta, mut ga) = (t0, g0);
        // the sample times: the fractions' times inside the step, then its end
        for s in &mut self.fractions {
            *s = t0 + *s * h;
        }
        self.fractions.retain(|t| *t > t0 && *t < t1);
        self.fractions.push(t1);
        for k in 0..self.fractions.len() {
            let tb = self.fractions[k];
            let gb = if tb == t1 { g1 } else { omega_at(driver, tb) };
            let significant = ga.abs().max(gb.abs()) > noise;
            if significant && ((ga < 0.0 && gb > 0.0) || (ga > 0.0 && gb < 0.0)) {
                let root = crate::roots::brent_with_values(
                    |t| omega_at(driver, t),
                    ta,
                    tb,
                    Some((ga, gb)),
                    4.0 * Real::EPSILON * tb.abs(),
                )
                .unwrap_or(tb);
                self.crossings.push(Crossing {
                    t: root,
                    rising: gb > 0.0,
                });
            }
            if gb != 0.0 {
                (ta, ga) = (tb, gb);
            }
        }
        if g1 != 0.0 {
            self.g_end = g1;
        }
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
