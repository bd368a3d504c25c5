//! The integral of a measured force: `W = ∫F dx` over positions (a work, and the running work
//! `W(x)` along the path) or `J = ∫F dt` over times (an impulse), with what follows from it by
//! the work-energy theorem (`v(x)` and a turning point) or the impulse-momentum theorem
//! (`Δv = J/m`).

use crate::Real;
use crate::quad::{SampleRule, SamplesError, cumulative};

/// A force sampled along a path or in time, integrated.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledIntegral {
    /// The rule used.
    pub rule: SampleRule,
    /// `∫F dx` over all samples.
    pub total: Real,
    /// The running integral at each sample (starts at 0).
    pub cumulative: Vec<Real>,
    /// The sample of largest `|F|`: `(x, F)`.
    pub peak: (Real, Real),
    /// `x_last - x_first`.
    pub span: Real,
}

impl SampledIntegral {
    /// Integrates samples `F(xᵢ)` with `rule` (`x` in path order: increasing, or decreasing
    /// for a path walked backwards).
    ///
    /// ```
    /// use mechkit::energy::SampledIntegral;
    /// use mechkit::quad::SampleRule;
    /// // a spring, F = -k x with k = 100, from x = 0.1 to 0.4
    /// let x: Vec<f64> = (0..=30).map(|i| 0.1 + 0.01 * f64::from(i)).collect();
    /// let f: Vec<f64> = x.iter().map(|x| -100.0 * x).collect();
    /// let w = SampledIntegral::new(&x, &f, SampleRule::Trapezoid).unwrap();
    /// assert!((w.total + 0.5 * 100.0 * (0.4f64.powi(2) - 0.1f64.powi(2))).abs() < 1e-12);
    /// ```
    pub fn new(x: &[Real], f: &[Real], rule: SampleRule) -> Result<Self, SamplesError> {
        let cumulative = cumulative(x, f, rule)?;
        let total = cumulative[cumulative.len() - 1];
        let k = (0..f.len())
            .max_by(|&i, &j| f[i].abs().total_cmp(&f[j].abs()))
            .unwrap_or(0);
        Ok(Self {
            rule,
            total,
            cumulative,
            peak: (x[k], f[k]),
            span: x[x.len() - 1] - x[0],
        })
    }

    /// The average force over the span, `total / span`.
    pub fn mean(&self) -> Real {
        self.total / self.span
    }

    /// With `x` a position: the speed `v(xᵢ) = sqrt(v0² + 2W(xᵢ)/m)` of a body of mass `mass`
    /// starting with speed `v0`, NaN past a turning point.
    pub fn speeds(&self, mass: Real, v0: Real) -> Vec<Real> {
        let mut stopped = false;
        self.cumulative
            .iter()
            .map(|w| {
                let v2 = v0 * v0 + 2.0 * w / mass;
                stopped |= v2 < 0.0;
                if stopped { Real::NAN } else { v2.sqrt() }
            })
            .collect()
    }

    /// With `x` a position: where the kinetic energy `½mv0² + W(x)` first reaches zero
    /// (linear between the samples), if it does.
    pub fn turning_point(&self, x: &[Real], mass: Real, v0: Real) -> Option<Real> {
        let k0 = 0.5 * mass * v0 * v0;
        let k = |i: usize| k0 + self.cumulative[i];
        (1..x.len()).find(|&i| k(i) < 0.0).map(|i| {
            let (a, b) = (k(i - 1), k(i));
            x[i - 1] + (x[i] - x[i - 1]) * a / (a - b)
        })
    }
}
