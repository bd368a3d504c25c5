//! Finite differences of samples on any strictly increasing grid: forward, backward, central
//! (three-point) and the three-point second derivative. The formulas and their orders are in
//! the [module docs](crate::deriv).

use super::DerivError;
use crate::Real;

/// A finite-difference scheme for [`differentiate`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Difference {
    /// `(xᵢ₊₁ − xᵢ)/(tᵢ₊₁ − tᵢ)`, first order: the course's `v[i] = (x[i+1] - x[i])/dt`. The
    /// last point uses the backward difference.
    Forward,
    /// `(xᵢ − xᵢ₋₁)/(tᵢ − tᵢ₋₁)`, first order. The first point uses the forward difference.
    Backward,
    /// The three-point parabola, second order on any grid, one-sided at the ends.
    Central,
}

impl Difference {
    /// Every scheme.
    pub const ALL: [Self; 3] = [Self::Forward, Self::Backward, Self::Central];

    /// `forward`, `backward` or `central`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Forward => "forward",
            Self::Backward => "backward",
            Self::Central => "central",
        }
    }

    /// The scheme with this name, ignoring case; `None` for any other text.
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|d| d.name().eq_ignore_ascii_case(name.trim()))
    }

    /// The order of accuracy: 1 for forward and backward, 2 for central.
    pub fn order(self) -> usize {
        match self {
            Self::Forward | Self::Backward => 1,
            Self::Central => 2,
        }
    }

    /// The fewest samples the scheme needs: 2, or 3 for central.
    pub fn min_points(self) -> usize {
        match self {
            Self::Forward | Self::Backward => 2,
            Self::Central => 3,
        }
    }
}

/// Checks that `t` and `x` have the same length, at least `needed` samples, and strictly
/// increasing times.
pub(crate) fn check_samples(
    t: &[Real],
    x: &[Real],
    needed: usize,
    method: &str,
) -> Result<(), DerivError> {
    if t.len() != x.len() {
        return Err(DerivError::LengthMismatch {
            t: t.len(),
            x: x.len(),
        });
    }
    if t.len() < needed {
        return Err(DerivError::TooFewPoints {
            method: method.to_string(),
            needed,
            got: t.len(),
        });
    }
    match (1..t.len()).find(|&i| t[i].partial_cmp(&t[i - 1]) != Some(std::cmp::Ordering::Greater)) {
        Some(i) => Err(DerivError::NotIncreasing {
            index: i,
            value: t[i],
            previous_index: i - 1,
            previous: t[i - 1],
        }),
        None => Ok(()),
    }
}

/// `dx/dt` at every sample `(tᵢ, xᵢ)` by the given scheme (see the [module docs](crate::deriv)).
///
/// Errors: `t` and `x` differ in length, fewer than 2 samples (3 for central), or `t` is not
/// strictly increasing.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::deriv::{Difference, differentiate};
///
/// // x = t² on an uneven grid: the central scheme is exact for parabolas, ends included.
/// let t = [0.0, 0.1, 0.3, 0.4, 0.7];
/// let x: Vec<f64> = t.iter().map(|t| t * t).collect();
/// let v = differentiate(&t, &x, Difference::Central).unwrap();
/// for (v, t) in v.iter().zip(t) {
///     assert_relative_eq!(*v, 2.0 * t, epsilon = 1e-12);
/// }
/// let v = differentiate(&t, &x, Difference::Forward).unwrap();
/// assert_relative_eq!(v[0], 0.1, epsilon = 1e-12); // (0.01 − 0)/0.1
/// ```
pub fn differentiate(t: &[Real], x: &[Real], scheme: Difference) -> Result<Vec<Real>, DerivError> {
    let mut out = vec![0.0; t.len()];
    differentiate_into(t, x, scheme, &mut out)?;
    Ok(out)
}

/// As [`differentiate`], writing into `out`.
///
/// # Panics
/// If `out` has not the length of `t`.
pub fn differentiate_into(
    t: &[Real],
    x: &[Real],
    scheme: Difference,
    out: &mut [Real],
) -> Result<(), DerivError> {
    let method = format!("the {} difference", scheme.name());
    check_samples(t, x, scheme.min_points(), &method)?;
    assert_eq!(out.len(), t.len(), "one output value per sample");
    let n = t.len();
    let slope = |i: usize| (x[i] - x[i - 1]) / (t[i] - t[i - 1]);
    match scheme {
        Difference::Forward => {
            for (i, v) in out.iter_mut().enumerate().take(n - 1) {
                *v = slope(i + 1);
            }
            out[n - 1] = slope(n - 1);
        }
        Difference::Backward => {
            out[0] = slope(1);
            for (i, v) in out.iter_mut().enumerate().skip(1) {
                *v = slope(i);
            }
        }
        Difference::Central => {
            for i in 1..n - 1 {
                let (h1, h2) = (t[i] - t[i - 1], t[i + 1] - t[i]);
                out[i] = (h2 * slope(i) + h1 * slope(i + 1)) / (h1 + h2);
            }
            let (h1, h2) = (t[1] - t[0], t[2] - t[1]);
            out[0] = slope(1) - h1 * (slope(2) - slope(1)) / (h1 + h2);
            let (h1, h2) = (t[n - 2] - t[n - 3], t[n - 1] - t[n - 2]);
            out[n - 1] = slope(n - 1) + h2 * (slope(n - 1) - slope(n - 2)) / (h1 + h2);
        }
    }
    Ok(())
}

/// `d²x/dt²` at every sample: three points inside, the cubic through the four outermost points
/// at each end (see the [module docs](crate::deriv) for the orders). With exactly 3 samples all three
/// get the parabola's second derivative (first order at the ends).
///
/// Errors as [`differentiate`]; at least 3 samples are needed.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::deriv::second_derivative;
///
/// // y = 1.6 − 4.9 t²: a = −9.8 everywhere, on any grid.
/// let t = [0.0, 0.01, 0.03, 0.04, 0.06];
/// let y: Vec<f64> = t.iter().map(|t| 1.6 - 4.9 * t * t).collect();
/// for a in second_derivative(&t, &y).unwrap() {
///     assert_relative_eq!(a, -9.8, epsilon = 1e-9);
/// }
/// ```
pub fn second_derivative(t: &[Real], x: &[Real]) -> Result<Vec<Real>, DerivError> {
    check_samples(t, x, 3, "the second derivative")?;
    let n = t.len();
    let slope = |i: usize| (x[i] - x[i - 1]) / (t[i] - t[i - 1]);
    let mut out = vec![0.0; n];
    for i in 1..n - 1 {
        out[i] = 2.0 * (slope(i + 1) - slope(i)) / (t[i + 1] - t[i - 1]);
    }
    if n == 3 {
        (out[0], out[2]) = (out[1], out[1]);
    } else {
        out[0] = cubic_second_derivative([0, 1, 2, 3].map(|i| (t[i], x[i])));
        out[n - 1] = cubic_second_derivative([n - 1, n - 2, n - 3, n - 4].map(|i| (t[i], x[i])));
    }
    Ok(out)
}

/// The second derivative at the first node of the cubic through four points, by divided
/// differences: `p''(t₀) = 2 f[t₀,t₁,t₂] + 2 f[t₀,t₁,t₂,t₃] ((t₀ − t₁) + (t₀ − t₂))`.
fn cubic_second_derivative(p: [(Real, Real); 4]) -> Real {
    let dd = |a: (Real, Real), b: (Real, Real)| (b.1 - a.1) / (b.0 - a.0);
    let (f01, f12, f23) = (dd(p[0], p[1]), dd(p[1], p[2]), dd(p[2], p[3]));
    let f012 = (f12 - f01) / (p[2].0 - p[0].0);
    let f123 = (f23 - f12) / (p[3].0 - p[1].0);
    let f0123 = (f123 - f012) / (p[3].0 - p[0].0);
    2.0 * f012 + 2.0 * f0123 * ((p[0].0 - p[1].0) + (p[0].0 - p[2].0))
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    #[test]
    fn names_round_trip() {
        for d in Difference::ALL {
            assert_eq!(Difference::parse(d.name()), Some(d));
        }
        assert_eq!(Difference::parse(" Central"), Some(Difference::Central));
        assert_eq!(Difference::parse("centered"), None);
    }

    #[test]
    fn forward_is_the_course_loop() {
        let dt = 0.5;
        let x = [0.0, 1.0, 4.0, 9.0];
        let t = [0.0, 0.5, 1.0, 1.5];
        let v = differentiate(&t, &x, Difference::Forward).unwrap();
        assert_eq!(v, [2.0, 6.0, 10.0, 10.0]);
        for i in 0..3 {
            assert_eq!(v[i], (x[i + 1] - x[i]) / dt);
        }
        let v = differentiate(&t, &x, Difference::Backward).unwrap();
        assert_eq!(v, [2.0, 2.0, 6.0, 10.0]);
    }

    #[test]
    fn central_on_a_uniform_grid_is_the_textbook_formula() {
        let t = [0.0, 0.1, 0.2, 0.3];
        let x = [1.0, 1.3, 1.1, 0.4];
        let v = differentiate(&t, &x, Difference::Central).unwrap();
        assert_relative_eq!(v[1], (x[2] - x[0]) / 0.2, epsilon = 1e-12);
        assert_relative_eq!(
            v[0],
            (-3.0 * x[0] + 4.0 * x[1] - x[2]) / 0.2,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            v[3],
            (3.0 * x[3] - 4.0 * x[2] + x[1]) / 0.2,
            epsilon = 1e-12
        );
    }

    #[test]
    fn second_derivative_ends_are_exact_for_cubics() {
        let t = [0.0, 0.2, 0.3, 0.7, 0.8, 1.1];
        let x: Vec<Real> = t.iter().map(|t| t * t * t - t).collect();
        let a = second_derivative(&t, &x).unwrap();
        assert_relative_eq!(a[0], 0.0, epsilon = 1e-12);
        assert_relative_eq!(a[5], 6.6, epsilon = 1e-12);
        let a = second_derivative(&[0.0, 1.0, 3.0], &[0.0, 1.0, 9.0]).unwrap();
        assert_eq!(a, [2.0, 2.0, 2.0]);
    }

    #[test]
    fn errors_say_what_is_wrong() {
        let e = differentiate(&[0.0, 1.0], &[0.0], Difference::Forward).unwrap_err();
        assert_eq!(
            e.to_string(),
            "t has 2 values but x has 1; each time needs exactly one value"
        );
        let e = differentiate(&[0.0, 1.0], &[0.0, 1.0], Difference::Central).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the central difference needs at least 3 points, got 2"
        );
        let e = differentiate(&[0.0, 1.0, 1.0], &[0.0; 3], Difference::Backward).unwrap_err();
        assert_eq!(
            e.to_string(),
            "t must increase strictly, but t[2] = 1 follows t[1] = 1; sort the samples by time \
             and remove or average repeated times"
        );
        let e = second_derivative(&[0.0, Real::NAN, 1.0], &[0.0; 3]).unwrap_err();
        assert!(matches!(e, DerivError::NotIncreasing { index: 1, .. }));
    }
}
