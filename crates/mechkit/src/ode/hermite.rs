//! Cubic Hermite interpolation between two step endpoints, from values and derivatives: the
//! interpolant fixed-step methods use to place events between steps. Its error is O(h⁴) in
//! the interpolated function, below the error of the methods it serves.

use crate::Real;

/// Value at `s ∈ [0, 1]` (fraction of the step `h`) of the cubic with values `y0`, `y1` and
/// derivatives `d0`, `d1` at the ends.
pub fn hermite(y0: Real, d0: Real, y1: Real, d1: Real, h: Real, s: Real) -> Real {
    let s2 = s * s;
    let s3 = s2 * s;
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1
}

/// Derivative with respect to time of [`hermite`] at `s`.
pub fn hermite_derivative(y0: Real, d0: Real, y1: Real, d1: Real, h: Real, s: Real) -> Real {
    let s2 = s * s;
    let dh00 = 6.0 * s2 - 6.0 * s;
    let dh10 = 3.0 * s2 - 4.0 * s + 1.0;
    let dh01 = -6.0 * s2 + 6.0 * s;
    let dh11 = 3.0 * s2 - 2.0 * s;
    (dh00 * y0 + dh01 * y1) / h + dh10 * d0 + dh11 * d1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_cubics_exactly() {
        // y = t^3 - 2t on [1, 1.5]
        let f = |t: Real| t * t * t - 2.0 * t;
        let df = |t: Real| 3.0 * t * t - 2.0;
        let (t0, h) = (1.0, 0.5);
        for s in [0.0, 0.25, 0.6, 1.0] {
            let t = t0 + s * h;
            let y = hermite(f(t0), df(t0), f(t0 + h), df(t0 + h), h, s);
            let d = hermite_derivative(f(t0), df(t0), f(t0 + h), df(t0 + h), h, s);
            assert!((y - f(t)).abs() < 1e-14);
            assert!((d - df(t)).abs() < 1e-13);
        }
    }
}
