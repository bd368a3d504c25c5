//! Root finding: Brent's method (Brent, *Algorithms for Minimization without Derivatives*,
//! 1973, ch. 4), which combines bisection's guarantee with the speed of inverse quadratic
//! interpolation.

use crate::Real;

/// A root of `f` in `[a, b]`, where `f(a)` and `f(b)` have opposite signs (or one is zero),
/// to within `tol` in `x`. `None` if the signs do not bracket a root.
///
/// # Example
/// ```
/// let root = mechkit::roots::brent(|x| x * x - 2.0, 0.0, 2.0, 1e-14).unwrap();
/// assert!((root - 2f64.sqrt()).abs() < 1e-14);
/// ```
pub fn brent(f: impl FnMut(Real) -> Real, a: Real, b: Real, tol: Real) -> Option<Real> {
    brent_with_values(f, a, b, None, tol)
}

/// As [`brent`], with `f(a)` and `f(b)` already known.
pub fn brent_with_values(
    mut f: impl FnMut(Real) -> Real,
    a: Real,
    b: Real,
    values: Option<(Real, Real)>,
    tol: Real,
) -> Option<Real> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = values.unwrap_or_else(|| (f(a), f(b)));
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() || fa.is_nan() || fb.is_nan() {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, b, c) = (b, c, b);
            (fa, fb, fc) = (fb, fc, fb);
        }
        let tol1 = 2.0 * Real::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = f(b);
        if fb.is_nan() {
            return None;
        }
    }
    Some(b)
}

/// Every root of `f` in `[a, b]` that shows as a sign change (or an exact zero) between
/// `samples` equally spaced points, each refined by Brent's method to `tol`, sorted. Roots where
/// `f` touches zero without changing sign, and pairs of roots closer than the sampling step,
/// can be missed: raise `samples` to look closer.
///
/// ```
/// let roots = mechkit::roots::find_all(f64::sin, -1.0, 10.0, 1000, 1e-14);
/// assert_eq!(roots.len(), 4); // 0, π, 2π, 3π
/// ```
pub fn find_all(
    mut f: impl FnMut(Real) -> Real,
    a: Real,
    b: Real,
    samples: usize,
    tol: Real,
) -> Vec<Real> {
    let n = samples.max(1);
    let h = (b - a) / n as Real;
    let mut roots: Vec<Real> = Vec::new();
    let mut x0 = a;
    let mut f0 = f(x0);
    for i in 1..=n {
        let x1 = if i == n { b } else { a + i as Real * h };
        let f1 = f(x1);
        if f0 == 0.0 {
            roots.push(x0);
        } else if f0.is_finite() && f1.is_finite() && f0.signum() != f1.signum() && f1 != 0.0 {
            // a sign change; a pole (huge values of both signs) and a jump (a step across
            // zero) are refused below
            if let Some(r) = brent_with_values(&mut f, x0, x1, Some((f0, f1)), tol) {
                let fr = f(r);
                if fr.abs() <= f0.abs().max(f1.abs()) && vanishes_at(&mut f, r, x1 - x0) {
                    roots.push(r);
                }
            }
        }
        x0 = x1;
        f0 = f1;
    }
    if f0 == 0.0 {
        roots.push(x0);
    }
    roots.dedup_by(|p, q| (*p - *q).abs() <= 2.0 * tol);
    roots
}

/// Whether `f` goes to zero at `r`, found between two samples `width` apart: `|f|` on both
/// sides must shrink with the distance to `r` (by at least half from `1e-3` to `1e-6` of the
/// width; a root of any order `|x − r|^p` with `p` above 0.1 shrinks by more), else the sign
/// change is a jump across zero (`floor(x) = 1.5` at 2, a step function), no root. A value
/// already zero there counts as a root.
fn vanishes_at(f: &mut impl FnMut(Real) -> Real, r: Real, width: Real) -> bool {
    let mut size = |d: Real| f(r - d).abs().max(f(r + d).abs());
    let far = size(1e-3 * width);
    // no closer than a few units in the last place of `r`, where `r ± d` is still not `r`
    let near = size((1e-6 * width).max(4.0 * Real::EPSILON * r.abs()));
    far == 0.0 || near <= 0.5 * far
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_roots() {
        let r = brent(f64::cos, 0.0, 3.0, 1e-15).unwrap();
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
        let r = brent(|x| x.powi(3) - x - 1.0, 1.0, 2.0, 1e-15).unwrap();
        assert!((r - 1.324_717_957_244_746).abs() < 1e-14);
    }

    #[test]
    fn step_functions_converge_like_bisection() {
        let r = brent(|x| if x < 0.3 { -1.0 } else { 1.0 }, 0.0, 1.0, 1e-12).unwrap();
        assert!((r - 0.3).abs() < 1e-11);
    }

    #[test]
    fn all_roots_on_an_interval() {
        let r = find_all(|x| (x - 1.0) * (x - 2.0) * (x + 0.5), -3.0, 3.0, 100, 1e-14);
        assert_eq!(r.len(), 3);
        assert!(
            (r[0] + 0.5).abs() < 1e-13 && (r[1] - 1.0).abs() < 1e-13 && (r[2] - 2.0).abs() < 1e-13
        );
        // a pole is not a root
        assert!(find_all(|x| 1.0 / x, -1.0, 1.0, 7, 1e-14).is_empty());
        // roots of higher order are kept
        let r = find_all(|x| (x - 1.0f64).powi(3), 0.0, 3.0, 100, 1e-14);
        assert_eq!(r.len(), 1);
        let r = find_all(|x| (x - 1.0f64).cbrt(), 0.0, 3.0, 100, 1e-14);
        assert_eq!(r.len(), 1);
    }

    /// Review C-07: a sign change across a jump is no root: `floor(x) = 1.5` has none, nor
    /// has a step from −1 to 1.
    #[test]
    fn a_sign_change_across_a_jump_is_not_a_root() {
        assert!(find_all(|x| x.floor() - 1.5, 0.0, 3.0, 2000, 1e-14).is_empty());
        let step = |x: Real| if x > 1.0 { 1.0 } else { -1.0 };
        assert!(find_all(step, 0.0, 2.0, 2000, 1e-14).is_empty());
        assert!(find_all(Real::signum, -1.0, 2.0, 7, 1e-14).is_empty());
    }

    #[test]
    fn rejects_non_brackets() {
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12).is_none());
        assert_eq!(brent(|x| x, 0.0, 1.0, 1e-12), Some(0.0));
    }
}
