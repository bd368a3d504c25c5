//! Savitzky-Golay filters: smoothing and differentiating evenly spaced samples by fitting a
//! polynomial of order `p` to a moving window of `w = 2m + 1` points by least squares and
//! evaluating it (or its derivative) at the window's centre. Near the ends, where no centred
//! window fits, the polynomial fitted to the first (last) `w` samples is evaluated at the first
//! (last) `m` samples, as SciPy's `savgol_filter(..., mode="interp")` does.
//!
//! A. Savitzky and M. J. E. Golay, "Smoothing and differentiation of data by simplified least
//! squares procedures", *Analytical Chemistry* 36 (1964) 1627-1639.

use super::polyfit::PolyFit;
use super::{DerivError, check_samples};
use crate::Real;

/// Relative tolerance of [`uniform_step`], against the step.
const UNIFORM_RTOL: Real = 1e-9;

/// Tolerance of [`uniform_step`] against the times themselves: a column printed with 8
/// significant digits (`9.9900100e-03`, the course's `reentry.txt`) rounds each time by up to
/// 5e-9 of itself, so its steps differ by up to 1e-8 of the times.
const PRINTED_RTOL: Real = 1e-7;

/// The largest step error [`uniform_step`] accepts, relative to the step, however large the
/// times: a filter with a step off by a thousandth differentiates to a thousandth.
const MAX_STEP_RTOL: Real = 1e-3;

/// The step `h` of an evenly spaced grid: `Some(h)` when every `tᵢ₊₁ − tᵢ` is within a relative
/// 1e-9 of the average step `(tₙ₋₁ − t₀)/(n − 1)` (negative for a decreasing grid), or within
/// the rounding of times printed with 8 digits (1e-7 of the times, at most 1e-3 of the step);
/// `None` for fewer than 2 points, a zero or non-finite step, or uneven spacing.
///
/// Time columns written with 16 digits (`1.0000000000000020e-03`) are uniform to about 1e-12
/// relative; a hand-typed column like `0.1 0.2 0.3` is uniform to 1e-16; one written with 8
/// digits (`9.9900100e-03`) to about 1e-8 of the times.
///
/// # Example
/// ```
/// use mechkit::deriv::uniform_step;
///
/// assert_eq!(uniform_step(&[0.0, 0.5, 1.0, 1.5]), Some(0.5));
/// assert_eq!(uniform_step(&[0.0, 0.5, 1.1]), None);
/// ```
pub fn uniform_step(t: &[Real]) -> Option<Real> {
    let h = average_step(t)?;
    first_uneven(t, h).is_none().then_some(h)
}

fn average_step(t: &[Real]) -> Option<Real> {
    let n = t.len();
    if n < 2 {
        return None;
    }
    let h = (t[n - 1] - t[0]) / (n - 1) as Real;
    (h.is_finite() && h != 0.0).then_some(h)
}

/// The first `i` where `tᵢ₊₁ − tᵢ` differs from `h` by more than the tolerance.
fn first_uneven(t: &[Real], h: Real) -> Option<usize> {
    t.windows(2).position(|w| {
        let printed = (PRINTED_RTOL * w[0].abs().max(w[1].abs())).min(MAX_STEP_RTOL * h.abs());
        ((w[1] - w[0]) - h).abs() > (UNIFORM_RTOL * h.abs()).max(printed) || w[1].is_nan()
    })
}

/// A Savitzky-Golay filter: a window of `window` (odd) points and a polynomial of order
/// `order < window`.
///
/// Larger windows smooth more and bias more: the fit of order `p` follows curvature on the
/// scale of the window, so the window should be short compared with the time over which the
/// signal changes. The classic choice for a derivative is `order` 2 or 3 (`order` 2 and 3 give
/// the same smoothed values and first derivatives inside).
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::deriv::SavitzkyGolay;
///
/// // A falling ball, y = 1.6 − 4.9 t², sampled every ms with ±0.1 mm of alternating noise.
/// let h = 1e-3;
/// let y: Vec<f64> = (0..200)
///     .map(|i| {
///         let t = i as f64 * h;
///         1.6 - 4.9 * t * t + if i % 2 == 0 { 1e-4 } else { -1e-4 }
///     })
///     .collect();
/// let filter = SavitzkyGolay::new(51, 2).unwrap();
/// let a = filter.derivative(&y, h, 2);
/// assert_relative_eq!(a[100], -9.8, max_relative = 0.01);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SavitzkyGolay {
    window: usize,
    order: usize,
}

impl SavitzkyGolay {
    /// A filter of `window` points (odd) and polynomial order `order` (less than `window`).
    pub fn new(window: usize, order: usize) -> Result<Self, DerivError> {
        if window.is_multiple_of(2) {
            return Err(DerivError::EvenWindow { window });
        }
        if window <= order {
            return Err(DerivError::WindowTooShort { window, order });
        }
        Ok(Self { window, order })
    }

    /// The window length, in points.
    pub fn window(&self) -> usize {
        self.window
    }

    /// The polynomial order.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The smoothed samples (the fitted polynomial's values).
    ///
    /// # Panics
    /// If `y` is shorter than the window.
    pub fn smooth(&self, y: &[Real]) -> Vec<Real> {
        self.derivative(y, 1.0, 0)
    }

    /// The `deriv`-th derivative of samples `y` spaced `h` apart (zero where `deriv > order`).
    ///
    /// # Panics
    /// If `y` is shorter than the window, or `h` is zero or not finite.
    pub fn derivative(&self, y: &[Real], h: Real, deriv: usize) -> Vec<Real> {
        let (n, w) = (y.len(), self.window);
        assert!(
            n >= w,
            "a Savitzky-Golay window of {w} points needs at least {w} samples, got {n}"
        );
        assert!(
            h.is_finite() && h != 0.0,
            "the step must be finite and not zero, got {h}"
        );
        let m = w / 2;
        let fit = PolyFit::new(w, self.order);
        let scale = h.powi(-(deriv as i32));
        let apply = |weights: &[Real], from: usize| -> Real {
            scale
                * weights
                    .iter()
                    .zip(&y[from..from + w])
                    .map(|(a, b)| a * b)
                    .sum::<Real>()
        };
        let mut out = vec![0.0; n];
        let centre = fit.weights(m as Real, deriv);
        for (i, o) in out.iter_mut().enumerate().take(n - m).skip(m) {
            *o = apply(&centre, i - m);
        }
        for i in 0..m {
            out[i] = apply(&fit.weights(i as Real, deriv), 0);
            let j = w - 1 - i;
            out[n - 1 - i] = apply(&fit.weights(j as Real, deriv), n - w);
        }
        out
    }

    /// The `deriv`-th derivative of samples `(tᵢ, yᵢ)`, checking what [`derivative`] assumes:
    /// equal lengths, at least `window` samples, strictly increasing and evenly spaced times
    /// (see [`uniform_step`]).
    ///
    /// [`derivative`]: SavitzkyGolay::derivative
    pub fn differentiate(
        &self,
        t: &[Real],
        y: &[Real],
        deriv: usize,
    ) -> Result<Vec<Real>, DerivError> {
        let method = format!("a Savitzky-Golay window of {} points", self.window);
        check_samples(t, y, self.window.max(2), &method)?;
        let h = average_step(t).expect("increasing times have a positive step");
        if let Some(index) = first_uneven(t, h) {
            return Err(DerivError::NotUniform {
                index,
                step: t[index + 1] - t[index],
                expected: h,
            });
        }
        Ok(self.derivative(y, h, deriv))
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    const Y: [Real; 12] = [1.0, 1.8, 2.9, 3.1, 4.6, 5.2, 5.9, 7.4, 7.6, 9.1, 9.4, 11.2];

    fn assert_close(got: &[Real], want: &[Real]) {
        for (g, w) in got.iter().zip(want) {
            assert_relative_eq!(*g, *w, epsilon = 1e-10, max_relative = 1e-10);
        }
    }

    // The reference numbers are pasted as Python prints them.
    #[allow(clippy::unreadable_literal)]
    #[test]
    fn agrees_with_scipy() {
        // python3 -c "from scipy.signal import savgol_filter as sg; y=[1.0, 1.8, 2.9, 3.1, 4.6,
        //   5.2, 5.9, 7.4, 7.6, 9.1, 9.4, 11.2]; print(sg(y,5,2)); print(sg(y,7,3,deriv=1,
        //   delta=0.1)); print(sg(y,7,2,deriv=2,delta=0.1))"          (SciPy 1.17.1)
        let smooth = [
            1.051428571428571,
            1.7942857142857138,
            2.6085714285714268,
            3.477142857142855,
            4.325714285714284,
            5.225714285714282,
            6.139999999999998,
            6.997142857142853,
            8.037142857142854,
            8.65428571428571,
            9.73714285714285,
            11.10571428571428,
        ];
        assert_close(&SavitzkyGolay::new(5, 2).unwrap().smooth(&Y), &smooth);
        let d1 = [
            7.460317460317489,
            8.19841269841271,
            8.603174603174605,
            8.674603174603178,
            7.9206349206349245,
            10.321428571428573,
            7.801587301587308,
            10.091269841269842,
            7.980158730158728,
            9.146825396825436,
            11.646825396825461,
            15.480158730158822,
        ];
        assert_close(
            &SavitzkyGolay::new(7, 3).unwrap().derivative(&Y, 0.1, 1),
            &d1,
        );
        let d2 = [
            -0.9523809523809195,
            -0.9523809523809195,
            -0.9523809523809195,
            -0.9523809523810595,
            6.428571428571288,
            0.4761904761903077,
            -0.952380952381181,
            -0.2380952380954821,
            4.999999999999728,
            5.000000000000019,
            5.000000000000019,
            5.000000000000019,
        ];
        assert_close(
            &SavitzkyGolay::new(7, 2).unwrap().derivative(&Y, 0.1, 2),
            &d2,
        );
    }

    #[test]
    fn derivative_above_the_order_is_zero() {
        let d = SavitzkyGolay::new(5, 1).unwrap().derivative(&Y, 0.1, 2);
        assert!(d.iter().all(|&x| x == 0.0));
    }

    #[test]
    fn construction_errors_say_what_to_use() {
        assert_eq!(
            SavitzkyGolay::new(10, 2).unwrap_err().to_string(),
            "a Savitzky-Golay window must be an odd number of points (a centre and as many \
             points on each side), not 10: use 9 or 11"
        );
        assert_eq!(
            SavitzkyGolay::new(3, 3).unwrap_err().to_string(),
            "a Savitzky-Golay window of 3 points cannot fit a polynomial of order 3: it has 4 \
             coefficients, more than the window has points; use a window of at least 5 points, \
             or a lower order"
        );
        assert!(SavitzkyGolay::new(1, 0).is_ok());
        assert!(SavitzkyGolay::new(3, 2).is_ok());
    }

    #[test]
    fn sampled_derivative_checks_the_grid() {
        let filter = SavitzkyGolay::new(5, 2).unwrap();
        let t: Vec<Real> = (0..12).map(|i| Real::from(i) * 0.1).collect();
        let d = filter.differentiate(&t, &Y, 1).unwrap();
        assert_close(&d, &filter.derivative(&Y, 0.1, 1));
        let mut uneven = t.clone();
        uneven[7] += 0.01;
        assert_eq!(
            filter.differentiate(&uneven, &Y, 1).unwrap_err(),
            DerivError::NotUniform {
                index: 6,
                step: uneven[7] - uneven[6],
                expected: 0.1
            }
        );
        assert!(matches!(
            filter.differentiate(&t[..4], &Y[..4], 1).unwrap_err(),
            DerivError::TooFewPoints {
                needed: 5,
                got: 4,
                ..
            }
        ));
    }

    #[test]
    fn uniform_steps() {
        assert_eq!(uniform_step(&[1.0]), None);
        assert_eq!(uniform_step(&[1.0, 1.0]), None);
        assert_eq!(uniform_step(&[3.0, 2.0, 1.0]), Some(-1.0));
        let t: Vec<Real> = (0..1000)
            .map(|i| Real::from(i) * 1e-3 * (1.0 + 1e-12))
            .collect();
        assert!(uniform_step(&t).is_some());
        // a column printed with 8 digits (the course's `reentry.txt`: 9.9900100e-03, …) is
        // uniform to the rounding of its times; once refused by `derive --smooth`
        let printed: Vec<Real> = (0..1001)
            .map(|i| {
                format!("{:.7e}", Real::from(i) * 9.990_009_99e-3)
                    .parse()
                    .unwrap()
            })
            .collect();
        assert!(uniform_step(&printed).is_some());
        // a step a hundredth off is not rounding
        let mut off = printed.clone();
        off[500] += 1e-4;
        assert_eq!(uniform_step(&off), None);
    }
}
