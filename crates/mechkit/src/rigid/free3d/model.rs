//! The spinning body on the one event-aware loop ([`crate::ode::events::drive`]): each turn
//! one step of its integrator, the samples and the conservation record at the step's end, the
//! zeros of ω about the intermediate axis as events through the one event finder (none
//! missed: ω is bounded over pieces of the step as one polynomial of the step with the sign
//! of ω, [`SpinEquations::omega_numerator`], so that a body spinning steadily, whose ω about
//! the axis is constant, is proven so at once), and the quaternion renormalised between
//! steps.

use mechkit_expr::interval::{Interval, Jet};

use super::driver::Driver;
use super::equations::SpinEquations;
use super::error::Free3dError;
use super::record::Record;
use super::run::Crossing;
use crate::Real;
use crate::ode::events::Direction;
use crate::ode::events::drive::{AfterFiring, Model};
use crate::ode::events::find::{Bounds, Finder, Fired, Rules, Side};
use crate::ode::{Series, State, StepPolynomial};

/// A run of a spinning body under way.
pub(super) struct SpinModel<'r, 'a> {
    pub eq: &'r SpinEquations<'a>,
    pub driver: Driver,
    pub state: State,
    pub t_end: Real,
    pub record: Record<'a>,
    pub renormalise: bool,
    pub steps: u64,
    pub evaluations: u64,
    /// The watched axis and the noise level of ω about it (free bodies).
    pub watch: Option<(usize, Real)>,
    pub finder: Finder,
    /// Steps whose proof ran out of enclosures (ω sampled evenly there).
    pub unproven_steps: u64,
    /// The side of ω about the watched axis, at its last sample.
    pub side: [Side; 1],
    /// ω about the watched axis at the start and at the end of the step, and where the scan
    /// has reached.
    pub g: (Real, Real, Real),
    pub t0: Real,
    pub done: bool,
}

impl SpinModel<'_, '_> {
    /// ω about `axis` at the state `y`.
    fn omega(&self, y: &[Real], axis: usize) -> Real {
        self.eq.omega_body(y)[axis]
    }

    /// The watched axis and the side and value of ω about it at the start.
    pub fn watching(mut self, watch: Option<(usize, Real)>) -> Self {
        self.watch = watch;
        if let Some((axis, _)) = watch {
            let g = self.omega(&self.state.y, axis);
            self.g = (g, g, g);
            self.side = [Side::of(g).unwrap_or(Side::Unknown)];
        }
        self
    }
}

/// ω about the watched axis, bounded over pieces of the step and evaluated on it.
struct Omega<'m, 'r, 'a> {
    eq: &'r SpinEquations<'a>,
    driver: &'m mut Driver,
    axis: usize,
    noise: Real,
    /// A polynomial of the step with the sign of ω about the axis, where there is one, and
    /// the noise level in its units.
    numerator: Option<&'m (Series, Real)>,
}

impl Bounds for Omega<'_, '_, '_> {
    fn count(&self) -> usize {
        1
    }

    fn enabled(&self, _: usize) -> bool {
        true
    }

    fn provable(&self, _: usize) -> bool {
        true
    }

    /// ω's noise level, in the numerator's units where it is enclosed: `|ω| = |n|/|q|²`, so
    /// `|n| ≤ noise · min |q|²` keeps ω within the noise.
    fn noise(&self, _: usize) -> Real {
        self.numerator.map_or(self.noise, |(_, noise)| *noise)
    }

    /// The numerator's enclosure where there is one (it has ω's sign, so its sign-definite
    /// and monotone pieces are ω's), else ω's from the state's enclosures.
    fn enclose(&mut self, _: usize, poly: &StepPolynomial, s: Interval) -> Option<Jet> {
        if let Some((numerator, _)) = self.numerator {
            return Some(numerator.enclose(poly, s));
        }
        let y: [Jet; 7] = std::array::from_fn(|i| poly.enclose(i, s));
        Some(self.eq.omega_body_jet(&y)[self.axis])
    }
}

impl Rules for Omega<'_, '_, '_> {
    fn count(&self) -> usize {
        1
    }

    fn enabled(&self, _: usize) -> bool {
        true
    }

    fn fires(&self, _: usize, from: Side, to: Side) -> bool {
        Direction::Both.fires(from, to)
    }

    fn values(&mut self, _: &StepPolynomial, t: Real, out: &mut [Real]) {
        let mut y = [0.0; 7];
        self.driver.interpolate(self.eq, t, &mut y);
        out[0] = self.eq.omega_body(&y)[self.axis];
    }

    /// Both samples at rounding level about zero: jitter, not a crossing.
    fn significant(&self, _: usize, g_prev: Real, g: Real) -> bool {
        g_prev.abs().max(g.abs()) > self.noise
    }
}

impl Model for SpinModel<'_, '_> {
    type Error = Free3dError;

    fn ended(&self) -> bool {
        self.done
    }

    fn stops_before_step(&mut self) -> bool {
        self.done = self.state.t >= self.t_end;
        self.done
    }

    fn advance(&mut self) -> Result<bool, Free3dError> {
        self.t0 = self.state.t;
        self.evaluations += self.driver.step(self.eq, &mut self.state, self.t_end)?;
        self.steps += 1;
        self.record
            .after_step(&mut self.driver, self.eq, &self.state);
        if let Some((axis, _)) = self.watch {
            self.g.1 = self.omega(&self.state.y, axis);
        }
        Ok(false)
    }

    fn any_enabled(&self) -> bool {
        self.watch.is_some()
    }

    fn plan(&mut self) {
        let Some((axis, noise)) = self.watch else {
            return;
        };
        self.driver.step_polynomial(self.eq, &mut self.finder.poly);
        // ω about the axis times |q|² over the step, and the noise level in its units (none
        // when |q|² is not proven positive over the step: ω is then enclosed from the state's
        // enclosures)
        let poly = &self.finder.poly;
        let (numerator, norm) = self.eq.omega_numerator(poly, axis);
        let norm = norm.enclose(poly, Interval::new(0.0, 1.0)).v;
        let numerator = norm
            .is_positive()
            .then(|| (numerator, noise * norm.lo().next_down()));
        let mut omega = Omega {
            eq: self.eq,
            driver: &mut self.driver,
            axis,
            noise,
            numerator: numerator.as_ref(),
        };
        let mut ran_out = false;
        self.finder
            .plan(&mut omega, self.state.t, 0, &mut |_| ran_out = true);
        self.unproven_steps += u64::from(ran_out);
    }

    fn begin_scan(&mut self) -> Real {
        self.g.2 = self.g.0;
        self.t0
    }

    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        let (axis, noise) = self.watch?;
        let mut omega = Omega {
            eq: self.eq,
            driver: &mut self.driver,
            axis,
            noise,
            numerator: None,
        };
        self.finder.first_firing(
            &mut omega,
            &mut self.side,
            (t_scan, &[self.g.2]),
            (self.state.t, &[self.g.1]),
        )
    }

    fn end_scan(&mut self) {}

    fn fire(&mut self, fired: Fired) -> Result<AfterFiring, Free3dError> {
        let t = fired.firing.t;
        // the side it left (the scan leaves the side of the sample before the crossing)
        let rising = self.side[0] == Side::Neg;
        self.record.crossings.push(Crossing { t, rising });
        self.side[0] = Side::Zero;
        if t == self.state.t {
            return Ok(AfterFiring::AtStepEnd);
        }
        self.g.2 = fired.values[0];
        Ok(AfterFiring::ScanFrom(t))
    }

    fn finish_step(&mut self, _event_at_end: bool) -> Result<(), Free3dError> {
        if self.renormalise {
            let n = self.state.y[..4].iter().map(|v| v * v).sum::<Real>().sqrt();
            if n != 1.0 {
                for v in &mut self.state.y[..4] {
                    *v /= n;
                }
                self.evaluations += self.driver.rescaled(self.eq, &self.state, 1.0 / n);
            }
        }
        // the next step starts from the value its scan ended with
        self.g.0 = self.g.1;
        Ok(())
    }
}
