//! Derivatives of functions by Ridders' extrapolation from a first step h = 0.1: sin, exp and
//! x³ at several points, each within 1e-10 of the exact derivative, and the error estimate
//! an upper bound on the true error. The plain central difference with the same step is off
//! by its leading error term h² f'''/6.

use mechkit::Real;
use mechkit::deriv::{central, derivative};

/// Name, f, f' and f'''.
type Case = (
    &'static str,
    fn(Real) -> Real,
    fn(Real) -> Real,
    fn(Real) -> Real,
);

const CASES: [Case; 3] = [
    ("sin", Real::sin, Real::cos, |x| -x.cos()),
    ("exp", Real::exp, Real::exp, Real::exp),
    ("x^3", |x| x * x * x, |x| 3.0 * x * x, |_| 6.0),
];

const POINTS: [Real; 6] = [-2.0, -0.5, 0.0, 0.3, 1.0, 2.5];

#[test]
fn ridders_is_accurate_and_knows_it() {
    for (name, f, df, _) in CASES {
        for x in POINTS {
            let d = derivative(f, x, 0.1);
            let error = (d.value - df(x)).abs();
            println!("{name} at {x}: error {error:.1e}, estimate {:.1e}", d.error);
            assert!(error <= 1e-10, "{name} at {x}: {d:?}, true error {error:e}");
            assert!(
                error <= d.error,
                "{name} at {x}: {d:?}, true error {error:e}"
            );
        }
    }
}

#[test]
fn plain_central_difference_error_is_the_leading_term() {
    let h = 0.1;
    for (name, f, df, d3f) in CASES {
        for x in POINTS {
            let error = central(f, x, h) - df(x);
            let leading = h * h * d3f(x) / 6.0;
            assert!(
                (error - leading).abs() <= 0.01 * leading.abs(),
                "{name} at {x}: {error:e} against h² f'''/6 = {leading:e}"
            );
        }
    }
}
