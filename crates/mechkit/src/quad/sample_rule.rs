//! The rules a course applies to sampled data, chosen by name, with their running integrals.
//!
//! With spacings `h_i = x_{i+1} − x_i`:
//!
//! | rule | integral | running integral at `x_k` |
//! |------|----------|---------------------------|
//! | left | `Σ y_i h_i` | the partial sums |
//! | right | `Σ y_{i+1} h_i` | the partial sums |
//! | midpoint (even number of intervals) | `Σ_j y_{2j+1} (x_{2j+2} − x_{2j})` | partial sums at even `k`; at odd `k = 2j+1`, `y_k (x_k − x_{k−1})` more |
//! | trapezoid | [`trapz`] | [`cumtrapz`] |
//! | Simpson | [`simpson`] | SciPy's `cumulative_simpson` |
//!
//! The midpoint rule on samples takes every other sample as the midpoint of a pair of intervals,
//! so its running integral is that of the piecewise-constant function it integrates: at the
//! middle sample of a pair, the rectangle has covered the first half of the pair.

use std::fmt;

use thiserror::Error;

use super::samples::{cumtrapz_into, cumulative_simpson_into, simpson, trapz};
use super::summation::{prefix_into, sum_columns};
use crate::Real;

/// A quadrature rule for samples `(x_i, y_i)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum SampleRule {
    /// Rectangles of height `y_i` on `[x_i, x_{i+1}]`.
    Left,
    /// Rectangles of height `y_{i+1}` on `[x_i, x_{i+1}]`.
    Right,
    /// Rectangles of height `y_{2j+1}` on `[x_{2j}, x_{2j+2}]` (even number of intervals).
    Midpoint,
    /// Trapezoids.
    Trapezoid,
    /// Parabolas through pairs of intervals.
    Simpson,
}

impl SampleRule {
    /// Every rule, in the order of the course.
    pub const ALL: [SampleRule; 5] = [
        SampleRule::Left,
        SampleRule::Right,
        SampleRule::Midpoint,
        SampleRule::Trapezoid,
        SampleRule::Simpson,
    ];

    /// `"left"`, `"right"`, `"midpoint"`, `"trapezoid"` or `"simpson"`.
    pub fn name(&self) -> &'static str {
        match self {
            SampleRule::Left => "left",
            SampleRule::Right => "right",
            SampleRule::Midpoint => "midpoint",
            SampleRule::Trapezoid => "trapezoid",
            SampleRule::Simpson => "simpson",
        }
    }

    /// Reads a rule's [name](SampleRule::name).
    ///
    /// # Example
    /// ```
    /// use mechkit::quad::SampleRule;
    /// assert_eq!(SampleRule::parse("trapezoid"), Some(SampleRule::Trapezoid));
    /// assert_eq!(SampleRule::parse("gauss-legendre"), None);
    /// ```
    pub fn parse(text: &str) -> Option<SampleRule> {
        let text = text.trim();
        Self::ALL.into_iter().find(|r| r.name() == text)
    }
}

impl fmt::Display for SampleRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why samples could not be integrated.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum SamplesError {
    /// `x` and `y` have different lengths.
    #[error("x has {x} samples but y has {y}")]
    LengthMismatch {
        /// Samples of `x`.
        x: usize,
        /// Samples of `y`.
        y: usize,
    },
    /// Fewer than two samples.
    #[error("at least 2 samples are needed, not {n}")]
    TooFewSamples {
        /// The samples given.
        n: usize,
    },
    /// The midpoint rule with an odd number of intervals.
    #[error(
        "the midpoint rule on samples needs an even number of intervals (an odd number of \
         samples), not {intervals}: use the trapezoid rule, or drop or add a sample"
    )]
    MidpointOddIntervals {
        /// The intervals given.
        intervals: usize,
    },
}

fn check(x: &[Real], y: &[Real], rule: SampleRule) -> Result<usize, SamplesError> {
    if x.len() != y.len() {
        return Err(SamplesError::LengthMismatch {
            x: x.len(),
            y: y.len(),
        });
    }
    let n = x.len();
    if n < 2 {
        return Err(SamplesError::TooFewSamples { n });
    }
    if rule == SampleRule::Midpoint && (n - 1) % 2 == 1 {
        return Err(SamplesError::MidpointOddIntervals { intervals: n - 1 });
    }
    Ok(n)
}

/// `∫ y dx` over all the samples by `rule`. `x` may decrease (the integral is then negated);
/// it is not checked for order or finiteness.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::{SampleRule, integrate_samples};
/// let x = [0.0, 0.5, 1.0];
/// let y = [0.0, 0.25, 1.0]; // x²
/// assert_relative_eq!(integrate_samples(&x, &y, SampleRule::Left).unwrap(), 0.125);
/// assert_relative_eq!(integrate_samples(&x, &y, SampleRule::Midpoint).unwrap(), 0.25);
/// assert_relative_eq!(integrate_samples(&x, &y, SampleRule::Simpson).unwrap(), 1.0 / 3.0);
/// ```
pub fn integrate_samples(x: &[Real], y: &[Real], rule: SampleRule) -> Result<Real, SamplesError> {
    let n = check(x, y, rule)?;
    let h = [&x[..n - 1], &x[1..]];
    let value = match rule {
        SampleRule::Left => sum_columns([h[0], h[1], &y[..n - 1]], |[x0, x1, y]| (x1 - x0) * y),
        SampleRule::Right => sum_columns([h[0], h[1], &y[1..]], |[x0, x1, y]| (x1 - x0) * y),
        SampleRule::Midpoint => midpoint(x, y),
        SampleRule::Trapezoid => trapz(x, y),
        SampleRule::Simpson => simpson(x, y),
    };
    Ok(value)
}

/// `Σ_j y_{2j+1} (x_{2j+2} − x_{2j})` for an odd number of samples.
fn midpoint(x: &[Real], y: &[Real]) -> Real {
    let pairs = x
        .chunks_exact(2)
        .zip(x[2..].iter().step_by(2))
        .zip(y[1..].iter().step_by(2));
    pairs.map(|((a, &c), &m)| m * (c - a[0])).sum()
}

/// The running integral `∫_{x_0}^{x_k} y dx` at every sample by `rule` (starts at 0, has the
/// length of `x`); its last element is [`integrate_samples`]'s value.
///
/// # Example
/// ```
/// use mechkit::quad::{SampleRule, cumulative};
/// let x = [0.0, 1.0, 2.0];
/// let y = [1.0, 2.0, 3.0];
/// assert_eq!(cumulative(&x, &y, SampleRule::Left).unwrap(), [0.0, 1.0, 3.0]);
/// assert_eq!(cumulative(&x, &y, SampleRule::Midpoint).unwrap(), [0.0, 2.0, 4.0]);
/// ```
pub fn cumulative(x: &[Real], y: &[Real], rule: SampleRule) -> Result<Vec<Real>, SamplesError> {
    let n = check(x, y, rule)?;
    let mut out = vec![0.0; n];
    match rule {
        SampleRule::Left => {
            prefix_into(
                [&x[..n - 1], &x[1..], &y[..n - 1]],
                |[x0, x1, y]| (x1 - x0) * y,
                &mut out,
            );
        }
        SampleRule::Right => {
            prefix_into(
                [&x[..n - 1], &x[1..], &y[1..]],
                |[x0, x1, y]| (x1 - x0) * y,
                &mut out,
            );
        }
        SampleRule::Midpoint => {
            let mut total = 0.0;
            for j in (0..n - 1).step_by(2) {
                out[j + 1] = total + y[j + 1] * (x[j + 1] - x[j]);
                total += y[j + 1] * (x[j + 2] - x[j]);
                out[j + 2] = total;
            }
        }
        SampleRule::Trapezoid => cumtrapz_into(x, y, &mut out),
        SampleRule::Simpson => cumulative_simpson_into(x, y, &mut out),
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for rule in SampleRule::ALL {
            assert_eq!(SampleRule::parse(rule.name()), Some(rule));
            assert_eq!(rule.to_string(), rule.name());
        }
        assert_eq!(SampleRule::parse("Simpson"), None);
    }

    #[test]
    fn errors() {
        let e = integrate_samples(&[0.0, 1.0], &[1.0], SampleRule::Left).unwrap_err();
        assert_eq!(e, SamplesError::LengthMismatch { x: 2, y: 1 });
        let e = cumulative(&[0.0], &[1.0], SampleRule::Trapezoid).unwrap_err();
        assert_eq!(e, SamplesError::TooFewSamples { n: 1 });
        let x = [0.0, 1.0, 2.0, 3.0];
        let e = integrate_samples(&x, &x, SampleRule::Midpoint).unwrap_err();
        assert_eq!(e, SamplesError::MidpointOddIntervals { intervals: 3 });
        assert!(e.to_string().contains("trapezoid"), "{e}");
        assert!(cumulative(&x, &x, SampleRule::Midpoint).is_err());
    }

    #[test]
    fn running_integrals_end_at_the_integral() {
        let x: Vec<Real> = (0..=12)
            .map(|i| (Real::from(i) / 12.0).powf(1.5) * 2.0)
            .collect();
        let y: Vec<Real> = x.iter().map(|x| x.cos() + x).collect();
        for rule in SampleRule::ALL {
            let total = integrate_samples(&x, &y, rule).unwrap();
            let c = cumulative(&x, &y, rule).unwrap();
            assert_eq!(c.len(), x.len());
            assert_eq!(c[0], 0.0);
            assert!(
                (c[12] - total).abs() < 1e-14,
                "{rule}: {} vs {total}",
                c[12]
            );
            // a prefix of the samples gives the same running integral (at even indices for the
            // pair rules)
            for k in (2..=12).step_by(2) {
                let part = integrate_samples(&x[..=k], &y[..=k], rule).unwrap();
                assert!((c[k] - part).abs() < 1e-14, "{rule} at {k}");
            }
        }
    }

    #[test]
    fn left_and_right_on_two_samples() {
        let (x, y) = ([1.0, 3.0], [2.0, 5.0]);
        assert_eq!(integrate_samples(&x, &y, SampleRule::Left), Ok(4.0));
        assert_eq!(integrate_samples(&x, &y, SampleRule::Right), Ok(10.0));
        assert_eq!(cumulative(&x, &y, SampleRule::Right), Ok(vec![0.0, 10.0]));
        // walked backwards
        assert_eq!(
            integrate_samples(&[3.0, 1.0], &[5.0, 2.0], SampleRule::Left),
            Ok(-10.0)
        );
    }
}
