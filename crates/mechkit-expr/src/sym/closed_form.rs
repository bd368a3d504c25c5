//! The real roots of a polynomial with numeric coefficients in closed form, when what is left
//! after its rational roots are divided out has degree four at most.
//!
//! In order: the square-free part `p / gcd(p, p')` (exact coefficients), so each root comes
//! once and the discriminants below are not zero by rounding; the rational roots (the
//! rational root theorem), divided out exactly, so `x^3 - 6x^2 + 11x - 6` gives `1, 2, 3`;
//! then the quadratic formula, [`cubic_roots`] or [`quartic_roots`] on the rest. Each root is
//! substituted back into the polynomial and its value checked against the rounding error of
//! that evaluation before it is returned.

use super::Sym;
use super::cubic::cubic_roots;
use super::poly::NumPoly;
use super::quartic::quartic_roots;
use crate::number::Number;

/// The value of an expression without names.
pub(super) fn numeric_value(s: &Sym) -> Option<f64> {
    s.eval(&|_| None).ok().filter(|v| v.is_finite())
}

/// The distinct real roots of `a x² + b x + c` (`a ≠ 0`) in floating point, increasing,
/// without the cancellation of the textbook formula: the coefficients are scaled by the
/// power of two nearest the largest of them first (so `b²` and `4ac` cannot overflow: `1e300 x² + 1e300 x − 1e300`),
/// then `q = −(b + sign(b) √Δ)/2` and the roots are `q/a` and `c/q` (so `1e-200 x² + x − 1`
/// has the roots `−1e200` and `1`, not `0`). A discriminant within `1e-12` of the terms it is
/// made of gives one root. A root beyond the range of doubles is infinite: the caller decides.
///
/// (Press et al., *Numerical Recipes*, 3rd ed., §5.6.)
///
/// ```
/// use mechkit_expr::sym::quadratic_roots;
/// assert_eq!(quadratic_roots(1e-200, 1.0, -1.0), vec![-1e200, 1.0]);
/// let r = quadratic_roots(1e300, 1e300, -1e300);
/// assert!((r[1] - (5f64.sqrt() - 1.0) / 2.0).abs() < 1e-15);
/// assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
/// ```
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let largest = a.abs().max(b.abs()).max(c.abs());
    if !(largest.is_finite() && a != 0.0) {
        return Vec::new();
    }
    // a power of two, so that scaling rounds nothing (x² − 5x + 6 keeps its roots 2 and 3)
    let scale = 2f64.powi(largest.log2().floor() as i32);
    let (a, b, c) = (a / scale, b / scale, c / scale);
    let (b2, four_ac) = (b * b, 4.0 * a * c);
    let d = b2 - four_ac;
    if d.abs() <= 1e-12 * (b2 + four_ac.abs()) {
        return vec![-b / (2.0 * a)];
    }
    if d < 0.0 {
        return Vec::new();
    }
    let q = -0.5 * (b + d.sqrt().copysign(b));
    let (r1, r2) = (q / a, c / q);
    if r1 <= r2 { vec![r1, r2] } else { vec![r2, r1] }
}

/// The distinct real roots of `a u² + b u + c`, whose coefficients are expressions without
/// names (`a ≠ 0`); a discriminant within rounding of zero gives one root. `None` when a value
/// is not finite (overflow), where no root can be decided.
pub(super) fn real_quadratic(a: &Sym, b: &Sym, c: &Sym) -> Option<Vec<Sym>> {
    if let Some((a, b, c)) = float_coefficients(a, b, c) {
        // float coefficients: float roots, without cancellation (`None` when one overflows)
        let roots = quadratic_roots(a, b, c);
        return roots.iter().all(|r| r.is_finite()).then(|| {
            roots
                .into_iter()
                .map(|r| Sym::Num(Number::Float(r)))
                .collect()
        });
    }
    let b2 = Sym::pow(b.clone(), Sym::int(2));
    let four_ac = Sym::product(vec![Sym::int(4), a.clone(), c.clone()]);
    let disc = Sym::difference(b2.clone(), four_ac.clone());
    let (Some(d), Some(scale)) = (
        numeric_value(&disc),
        numeric_value(&b2).zip(numeric_value(&four_ac)),
    ) else {
        return None;
    };
    let scale = scale.0.abs() + scale.1.abs();
    let two_a = Sym::product(vec![Sym::int(2), a.clone()]);
    let zero = match disc.as_num() {
        Some(n) if n.is_exact() => n.is_zero(),
        _ => d.abs() <= 1e-12 * scale,
    };
    if zero {
        return Some(vec![Sym::negate(Sym::quotient(b.clone(), two_a))]);
    }
    if d < 0.0 {
        return Some(Vec::new());
    }
    let roots = [-1, 1]
        .into_iter()
        .map(|sign| {
            Sym::quotient(
                Sym::sum(vec![
                    Sym::negate(b.clone()),
                    Sym::product(vec![Sym::int(sign), Sym::sqrt(disc.clone())]),
                ]),
                two_a.clone(),
            )
        })
        .collect();
    Some(roots)
}

/// The values of `a`, `b`, `c` when they are numbers and one of them is a float (an exact
/// quadratic keeps the radical form of its roots), for [`quadratic_roots`].
pub(super) fn float_coefficients(a: &Sym, b: &Sym, c: &Sym) -> Option<(f64, f64, f64)> {
    let (a, b, c) = (a.as_num()?, b.as_num()?, c.as_num()?);
    (!(a.is_exact() && b.is_exact() && c.is_exact())).then(|| (a.to_f64(), b.to_f64(), c.to_f64()))
}

impl NumPoly {
    /// The distinct real roots in closed form, increasing, each checked by substitution;
    /// `None` when a factor of degree five or more is left after the rational roots, or a root
    /// fails the check (solve numerically then).
    ///
    /// ```
    /// use mechkit_expr::Sym;
    /// use mechkit_expr::sym::poly::NumPoly;
    /// let p = NumPoly::from_syms(&mechkit_expr::sym::poly::coefficients(
    ///     &Sym::parse("x^3 - 6*x^2 + 11*x - 6").unwrap(), "x").unwrap()).unwrap();
    /// assert_eq!(p.closed_form_roots().unwrap(), vec![Sym::int(1), Sym::int(2), Sym::int(3)]);
    /// ```
    pub fn closed_form_roots(&self) -> Option<Vec<Sym>> {
        match self.degree()? {
            0 => return Some(Vec::new()),
            // the rational root search and the gcd grow quickly with the degree
            d if d > super::real_roots::MAX_NUMERIC_DEGREE => return None,
            _ => {}
        }
        let mut rest = self.square_free().unwrap_or_else(|| self.clone());
        let mut roots = Vec::new();
        // x = 0, exactly, also for float coefficients
        while rest.0.first().is_some_and(|c| c.is_zero()) {
            rest.0.remove(0);
            if !roots.contains(&Sym::zero()) {
                roots.push(Sym::zero());
            }
        }
        for r in rest.rational_roots() {
            let (q, rem) = rest.div_rem(&NumPoly::new(vec![r.negated(), Number::ONE]))?;
            if !rem.is_zero() {
                return None;
            }
            rest = q;
            roots.push(Sym::Num(r));
        }
        let c = &rest.0;
        roots.extend(match c.len() {
            0 | 1 => Vec::new(),
            2 => vec![Sym::Num(c[0].checked_div(c[1])?.negated())],
            3 => real_quadratic(&Sym::Num(c[2]), &Sym::Num(c[1]), &Sym::Num(c[0]))?,
            4 => cubic_roots(c[3], c[2], c[1], c[0]),
            5 => quartic_roots(c[4], c[3], c[2], c[1], c[0])?,
            _ => return None,
        });
        let mut valued = roots
            .into_iter()
            .map(|r| {
                let v = numeric_value(&r)?;
                self.vanishes_at(v).then_some((r, v))
            })
            .collect::<Option<Vec<_>>>()?;
        valued.sort_by(|a, b| a.1.total_cmp(&b.1));
        valued.dedup_by(|a, b| a.0 == b.0);
        Some(valued.into_iter().map(|(r, _)| r).collect())
    }

    /// Whether the value at `x` is zero to within a multiple of the rounding error of
    /// evaluating it (the check a root passes before it is returned).
    pub fn vanishes_at(&self, x: f64) -> bool {
        let (value, scale) = self.0.iter().rev().fold((0.0, 0.0), |(v, s), c| {
            let c = c.to_f64();
            (v * x + c, s * x.abs() + c.abs())
        });
        value.is_finite() && value.abs() <= 1e-9 * scale
    }
}
