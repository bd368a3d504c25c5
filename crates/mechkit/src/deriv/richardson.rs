//! Derivatives of functions: the central difference `(f(x + h) − f(x − h))/2h` (error
//! `h² f'''/6`), and Ridders' method, which extrapolates a tableau of central differences with
//! steps `h, h/1.4, h/1.4², …` to step zero (Richardson extrapolation, removing one even power
//! of `h` per column) and stops when the error estimate starts to grow (round-off taking over).
//!
//! C. J. F. Ridders, "Accurate computation of F'(x) and F'(x)F''(x)", *Advances in Engineering
//! Software* 4 (1982) 75-76; Press et al., *Numerical Recipes*, 3rd ed., §5.7 (`dfridr`).

use crate::Real;

/// Step reduction between rows of the tableau.
const SHRINK: Real = 1.4;
/// Rows of the tableau at most.
const ROWS: usize = 10;
/// Stop when the diagonal moves by more than this times the best error estimate.
const SAFE: Real = 2.0;

/// A value with an estimate of its absolute error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The value.
    pub value: Real,
    /// Estimated absolute error.
    pub error: Real,
}

/// The central difference `(f(x + h) − f(x − h))/2h`, second order in `h`.
///
/// # Example
/// ```
/// let d = mechkit::deriv::central(f64::sin, 0.0, 1e-3);
/// assert!((d - 1.0).abs() < 2e-7); // error h²/6
/// ```
pub fn central(mut f: impl FnMut(Real) -> Real, x: Real, h: Real) -> Real {
    (f(x + h) - f(x - h)) / (2.0 * h)
}

/// `f'(x)` by Ridders' method, starting from step `h` (which should be large enough that
/// `f` changes noticeably over it: 0.1 of the scale on which `f` varies is typical), with an
/// error estimate. Uses at most 20 evaluations of `f`.
///
/// The error estimate is the larger of the tableau's (how much the best entry differs from
/// its neighbours) and a bound on the round-off in that entry (`ε(|f(x+s)| + |f(x−s)|)/2s` for
/// each difference with step `s`, carried through the extrapolation), so it does not claim
/// more accuracy than floating point gives. Typical accuracy is 1e-13 relative for smooth
/// functions; a non-finite value of `f` near `x` makes the result NaN.
///
/// # Panics
/// If `h` is not positive and finite.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
///
/// let d = mechkit::deriv::derivative(f64::exp, 1.0, 0.1);
/// assert_relative_eq!(d.value, 1f64.exp(), max_relative = 1e-12);
/// assert!(d.error < 1e-10);
/// ```
pub fn derivative(mut f: impl FnMut(Real) -> Real, x: Real, h: Real) -> Estimate {
    assert!(
        h > 0.0 && h.is_finite(),
        "the step must be positive and finite, got {h}"
    );
    // A central difference and a bound on its round-off. The step actually taken is the
    // difference of the two representable abscissae, so that no error hides in `x ± s`.
    let mut difference = |s: Real| -> Entry {
        let (xp, xm) = (x + s, x - s);
        let (fp, fm) = (f(xp), f(xm));
        Entry {
            value: (fp - fm) / (xp - xm),
            roundoff: Real::EPSILON * (fp.abs() + fm.abs()) / (xp - xm),
        }
    };
    // The tableau, row by row: row i holds the central difference with step h/1.4^i and its
    // extrapolations. Only the previous row is needed.
    let mut step = h;
    let mut previous = vec![difference(step)];
    let mut best = Estimate {
        value: previous[0].value,
        error: Real::INFINITY,
    };
    let mut best_tableau_error = Real::INFINITY;
    for _ in 1..ROWS {
        step /= SHRINK;
        let mut row = Vec::with_capacity(previous.len() + 1);
        row.push(difference(step));
        let mut factor = SHRINK * SHRINK;
        for j in 1..=previous.len() {
            let (a, b) = (row[j - 1], previous[j - 1]);
            let value = (a.value * factor - b.value) / (factor - 1.0);
            let roundoff = (a.roundoff * factor + b.roundoff) / (factor - 1.0);
            factor *= SHRINK * SHRINK;
            let error = (value - a.value).abs().max((value - b.value).abs());
            if error <= best_tableau_error {
                best_tableau_error = error;
                best = Estimate {
                    value,
                    error: error.max(roundoff),
                };
            }
            row.push(Entry { value, roundoff });
        }
        let last = row.len() - 1;
        let moved = (row[last].value - previous[last - 1].value).abs();
        previous = row;
        if moved >= SAFE * best_tableau_error {
            break;
        }
    }
    best
}

/// An entry of Ridders' tableau.
#[derive(Debug, Clone, Copy)]
struct Entry {
    value: Real,
    /// Bound on its round-off error.
    roundoff: Real,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_quadratics_at_once() {
        let d = derivative(|x| 3.0 * x * x - x, 2.0, 0.1);
        assert!((d.value - 11.0).abs() < 1e-12, "{d:?}");
    }

    #[test]
    fn counts_evaluations() {
        let mut calls = 0;
        let _ = derivative(
            |x| {
                calls += 1;
                x.sin()
            },
            0.3,
            0.1,
        );
        assert!(calls <= 2 * ROWS, "{calls}");
    }

    #[test]
    fn central_difference_error_is_second_order() {
        let e1 = (central(f64::exp, 0.0, 1e-2) - 1.0).abs();
        let e2 = (central(f64::exp, 0.0, 5e-3) - 1.0).abs();
        assert!((e1 / e2 - 4.0).abs() < 0.01, "{}", e1 / e2);
    }
}
