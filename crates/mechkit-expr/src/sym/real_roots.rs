//! Every real root of a polynomial with floating-point coefficients, without an interval from
//! the caller.
//!
//! All roots lie within Cauchy's bound `|x| ≤ B = 1 + max_k |a_k / a_n|`. Between two
//! neighbouring real roots of the derivative the polynomial is monotonic, so it has at most one
//! root there; the roots of the derivative are found the same way, recursively (the method of
//! isolating roots by the derivative's roots, e.g. Collins and Loos, "Real zeros of
//! polynomials", in *Computer Algebra*, 1983). Each bracketed root is then bisected down to
//! adjacent floating-point numbers. A root of even multiplicity, where the polynomial touches
//! zero without changing sign, is a root of the derivative where the polynomial's value is
//! within its rounding error of zero, and is found there.

/// The real roots of a polynomial and the interval they were searched in.
#[derive(Debug, Clone, PartialEq)]
pub struct RealRoots {
    /// The distinct real roots, increasing.
    pub roots: Vec<f64>,
    /// Cauchy's bound `B`: every root lies in `[-B, B]`.
    pub bound: f64,
}

/// The highest degree [`real_roots`] takes (its cost grows as the cube of the degree).
pub const MAX_NUMERIC_DEGREE: usize = 100;

/// The real roots of `a_0 + a_1 x + … + a_n x^n` (coefficients lowest degree first); `None` for
/// the zero polynomial, a coefficient that is not finite, a degree above
/// [`MAX_NUMERIC_DEGREE`], or values that overflow inside the bound.
///
/// ```
/// use mechkit_expr::sym::real_roots;
/// // x^5 - x - 1 has one real root
/// let r = real_roots(&[-1.0, -1.0, 0.0, 0.0, 0.0, 1.0]).unwrap();
/// assert_eq!(r.roots.len(), 1);
/// assert!((r.roots[0] - 1.167_303_978_261_418_7).abs() < 1e-15);
/// assert_eq!(r.bound, 2.0);
/// ```
pub fn real_roots(coefficients: &[f64]) -> Option<RealRoots> {
    if coefficients.iter().any(|c| !c.is_finite()) {
        return None;
    }
    let mut c = coefficients.to_vec();
    while c.last() == Some(&0.0) {
        c.pop();
    }
    if c.is_empty() || c.len() - 1 > MAX_NUMERIC_DEGREE {
        return None;
    }
    // x = 0 as a root is exact: divide it out
    let zeros = c.iter().take_while(|v| **v == 0.0).count();
    c.drain(..zeros);
    let n = c.len() - 1;
    let lead = c[n];
    let c: Vec<f64> = c.iter().map(|v| v / lead).collect();
    let bound = 1.0 + c[..n].iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if !bound.is_finite() || !eval(&c, bound).is_finite() || !eval(&c, -bound).is_finite() {
        return None;
    }
    let mut roots = if n == 0 {
        Vec::new()
    } else {
        roots_between(&c, -bound, bound)
    };
    if zeros > 0 {
        roots.push(0.0);
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    Some(RealRoots { roots, bound })
}

/// Horner's value at `x`.
fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, v| acc * x + v)
}

/// A bound on the rounding error of [`eval`] at `x`: `2n ε Σ |a_k| |x|^k` (Higham, *Accuracy
/// and Stability of Numerical Algorithms*, 2002, §5.1), doubled.
fn eval_error(c: &[f64], x: f64) -> f64 {
    let scale = c.iter().rev().fold(0.0, |acc, v| acc * x.abs() + v.abs());
    4.0 * c.len() as f64 * f64::EPSILON * scale
}

/// The distinct real roots in `[lo, hi]` of the polynomial `c` (degree at least one).
fn roots_between(c: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let n = c.len() - 1;
    if n == 1 {
        let r = -c[0] / c[1];
        return if (lo..=hi).contains(&r) {
            vec![r]
        } else {
            Vec::new()
        };
    }
    let d: Vec<f64> = c
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, v)| v * k as f64)
        .collect();
    let mut points = vec![lo];
    points.extend(
        roots_between(&d, lo, hi)
            .into_iter()
            .filter(|p| *p > lo && *p < hi),
    );
    points.push(hi);
    // the value at each point, or zero where it is within rounding of zero
    let values: Vec<f64> = points
        .iter()
        .map(|&x| {
            let v = eval(c, x);
            if v.abs() <= eval_error(c, x) { 0.0 } else { v }
        })
        .collect();
    let mut roots = Vec::new();
    for (i, (&x, &v)) in points.iter().zip(&values).enumerate() {
        if v == 0.0 {
            roots.push(x);
        } else if let Some(&w) = values.get(i + 1)
            && w != 0.0
            && v.signum() != w.signum()
        {
            roots.push(bisect(c, x, points[i + 1], v));
        }
    }
    roots
}

/// The root of `c` in `[a, b]`, where the signs at the ends differ (`fa` at `a`), bisected
/// until the ends are adjacent numbers or the value is zero.
fn bisect(c: &[f64], mut a: f64, mut b: f64, fa: f64) -> f64 {
    let sa = fa.signum();
    loop {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = eval(c, m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == sa {
            a = m;
        } else {
            b = m;
        }
    }
    // the end with the smaller value
    if eval(c, a).abs() <= eval(c, b).abs() {
        a
    } else {
        b
    }
}
