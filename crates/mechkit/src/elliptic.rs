//! Complete elliptic integral of the first kind, Jacobi's elliptic functions and the
//! incomplete integral: what the exact torque-free motion is written in.
//!
//! With the parameter `m = k²` and its complement `m₁ = 1 − m` (passed separately where `m` is
//! close to 1, as near the separatrix of a tennis racket, so that no digits are lost):
//!
//! - `K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ) = π / (2 AGM(1, √m₁))` (Gauss; Abramowitz & Stegun
//!   17.6);
//! - `sn`, `cn`, `dn` by the descending Landen transformation driven by the same AGM
//!   (Abramowitz & Stegun 16.4), after reducing `u` modulo the period `4K`;
//! - `F(φ | m) = sin φ R_F(cos²φ, 1 − m sin²φ, 1)` with Carlson's symmetric integral `R_F` by
//!   the duplication theorem (Carlson, Numer. Algorithms 10, 1995), extended beyond `|φ| ≤ π/2`
//!   by `F(φ + nπ) = F(φ) + 2nK`.

use std::f64::consts::PI;

use crate::Real;

/// The arithmetic-geometric mean of `a` and `b` (both ≥ 0).
///
/// ```
/// use mechkit::elliptic::agm;
/// // Gauss's constant: 1/AGM(1, √2) = 0.8346268416740731…
/// assert!((1.0 / agm(1.0, 2f64.sqrt()) - 0.834_626_841_674_073_2).abs() < 1e-15);
/// ```
pub fn agm(mut a: Real, mut b: Real) -> Real {
    for _ in 0..64 {
        if (a - b).abs() <= 2.0 * Real::EPSILON * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    0.5 * (a + b)
}

/// `K(m)`, the complete elliptic integral of the first kind, for `0 ≤ m < 1` (infinite at 1).
///
/// ```
/// use mechkit::elliptic::complete_k;
/// assert_eq!(complete_k(0.0), std::f64::consts::FRAC_PI_2);
/// assert!((complete_k(0.5) - 1.854_074_677_301_372).abs() < 1e-15);
/// ```
pub fn complete_k(m: Real) -> Real {
    complete_k_complement(1.0 - m)
}

/// `K` as a function of the complementary parameter `m₁ = 1 − m` (accurate near `m = 1`).
pub fn complete_k_complement(m1: Real) -> Real {
    if m1 <= 0.0 {
        return Real::INFINITY;
    }
    PI / (2.0 * agm(1.0, m1.sqrt()))
}

/// Jacobi's `(sn, cn, dn)(u | m)` for `0 ≤ m ≤ 1`.
///
/// ```
/// use mechkit::elliptic::jacobi;
/// let (sn, cn, dn) = jacobi(0.7, 0.8);
/// assert!((sn - 0.612_365_484_117_245_3).abs() < 1e-15);
/// assert!((sn * sn + cn * cn - 1.0).abs() < 1e-15);
/// assert!((dn * dn + 0.8 * sn * sn - 1.0).abs() < 1e-15);
/// ```
pub fn jacobi(u: Real, m: Real) -> (Real, Real, Real) {
    jacobi_complement(u, m, 1.0 - m)
}

/// As [`jacobi`], with the complement `m₁ = 1 − m` given (accurate near `m = 1`).
pub fn jacobi_complement(u: Real, m: Real, m1: Real) -> (Real, Real, Real) {
    if m1 <= 0.0 {
        let s = 1.0 / u.cosh();
        return (u.tanh(), s, s);
    }
    if m <= 0.0 {
        return (u.sin(), u.cos(), 1.0);
    }
    // u modulo the period 4K of sn and cn
    let period = 4.0 * complete_k_complement(m1);
    let u = u - period * (u / period).round();
    let mut a = [0.0; 32];
    let mut c = [0.0; 32];
    a[0] = 1.0;
    c[0] = m.sqrt();
    let mut b = m1.sqrt();
    let mut n = 0;
    while c[n].abs() > Real::EPSILON * a[n] && n < 31 {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = (a[n] * b).sqrt();
        n += 1;
    }
    let mut phi = Real::from(1u32 << n) * a[n] * u;
    for j in (1..=n).rev() {
        phi = 0.5 * (phi + (c[j] / a[j] * phi.sin()).asin());
    }
    let (sn, cn) = phi.sin_cos();
    (sn, cn, (m1 + m * cn * cn).sqrt())
}

/// Carlson's symmetric elliptic integral `R_F(x, y, z)` (at most one argument zero).
pub fn carlson_rf(mut x: Real, mut y: Real, mut z: Real) -> Real {
    for _ in 0..100 {
        let mean = (x + y + z) / 3.0;
        let dev = [1.0 - x / mean, 1.0 - y / mean, 1.0 - z / mean];
        if dev.iter().all(|d| d.abs() < 1e-3) {
            let (dx, dy) = (dev[0], dev[1]);
            let dz = -(dx + dy);
            let e2 = dx * dy - dz * dz;
            let e3 = dx * dy * dz;
            return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0)
                / mean.sqrt();
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
    }
    Real::NAN
}

/// The incomplete elliptic integral of the first kind `F(φ | m)`, any real `φ`, `0 ≤ m < 1`,
/// given by its complement `m₁ = 1 − m` (accurate near `m = 1`). `F(am(u)) = u`: the inverse of the amplitude.
pub fn incomplete_f_complement(phi: Real, m1: Real) -> Real {
    let turns = (phi / PI).round();
    let p = phi - turns * PI;
    let (s, c) = p.sin_cos();
    let f = s * carlson_rf(c * c, c * c + m1 * s * s, 1.0);
    if turns == 0.0 {
        f
    } else {
        f + 2.0 * turns * complete_k_complement(m1)
    }
}

/// `F(φ | m)` ([`incomplete_f_complement`] with `m₁ = 1 − m`).
///
/// ```
/// use mechkit::elliptic::incomplete_f;
/// assert!((incomplete_f(1.2, 0.6) - 1.381_322_687_881_858).abs() < 1e-14);
/// ```
pub fn incomplete_f(phi: Real, m: Real) -> Real {
    incomplete_f_complement(phi, 1.0 - m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sn_of_f_is_sin() {
        for &(phi, m) in &[
            (0.3, 0.2),
            (1.4, 0.9),
            (2.9, 0.5),
            (-4.0, 0.7),
            (7.0, 0.999),
        ] {
            let u = incomplete_f(phi, m);
            let (sn, cn, _) = jacobi(u, m);
            assert!((sn - Real::sin(phi)).abs() < 1e-13, "{phi} {m}");
            assert!((cn - Real::cos(phi)).abs() < 1e-13, "{phi} {m}");
        }
    }
}
