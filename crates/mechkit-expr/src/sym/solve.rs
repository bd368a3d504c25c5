//! Solving equations symbolically: one polynomial equation for one unknown (all its real roots:
//! by formula up to degree two, in closed form up to degree four, see [`super::closed_form`]), and small linear systems (Cramer's rule, so the answers come out as one
//! fraction: statics problems such as the tensions holding a chandelier).

use super::Sym;
use super::poly::{NumPoly, coefficients};

/// The solutions of `f = 0` for one unknown.
#[derive(Debug, Clone, PartialEq)]
pub enum Solutions {
    /// The real roots (as expressions, numeric ones sorted).
    Roots(Vec<Sym>),
    /// No real root (a negative discriminant, or `c = 0` with `c ≠ 0`).
    NoRealRoot,
    /// Every value is a root (`0 = 0`).
    Every,
}

/// What a symbolic solution assumed.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// The solutions.
    pub solutions: Solutions,
    /// Conditions under which they hold (`a ≠ 0`, a non-negative discriminant).
    pub assumptions: Vec<String>,
}

impl Sym {
    /// Solves `self = 0` for `x` when it is a polynomial in `x`: of degree at most two by
    /// formula; of degree three or four, or one whose rational roots leave a factor of degree
    /// four at most, in closed form when its coefficients are numbers; with symbolic
    /// coefficients when the polynomial is a power `a x^n + d` (n = 3, 4) or has the factor
    /// `x^k`. `None` otherwise (solve numerically then).
    ///
    /// ```
    /// use mechkit_expr::Sym;
    /// use mechkit_expr::sym::Solutions;
    /// let s = Sym::parse("x^2 - 5*x + 6").unwrap().solve("x").unwrap();
    /// assert_eq!(s.solutions, Solutions::Roots(vec![Sym::int(2), Sym::int(3)]));
    /// ```
    pub fn solve(&self, x: &str) -> Option<Solved> {
        solve_coefficients(&coefficients(self, x)?)
    }
}

/// Solves the polynomial with coefficients `c` (lowest degree first): up to degree two by
/// formula, numeric ones of higher degree by [`NumPoly::closed_form_roots`], symbolic ones of
/// higher degree by [`super::solve_higher::solve_higher`].
pub(super) fn solve_coefficients(c: &[Sym]) -> Option<Solved> {
    if c.len() > 3 {
        if let Some(p) = NumPoly::from_syms(c) {
            let roots = p.closed_form_roots()?;
            return Some(Solved {
                solutions: if roots.is_empty() {
                    Solutions::NoRealRoot
                } else {
                    Solutions::Roots(roots)
                },
                assumptions: Vec::new(),
            });
        }
        return super::solve_higher::solve_higher(c);
    }
    {
        let mut assumptions = Vec::new();
        // `-g/2 ≠ 0` says no more than `g ≠ 0`
        let nonzero = |s: &Sym, assumptions: &mut Vec<String>| {
            if s.as_num().is_none() {
                let (_, rest) = super::build::split_coefficient(s);
                assumptions.push(format!("{} ≠ 0", rest.unwrap_or_else(|| s.clone())));
            }
        };
        let solutions = match c.len() {
            1 if c[0].is_zero() => Solutions::Every,
            1 => {
                if c[0].as_num().is_none() {
                    assumptions.push(format!("{} ≠ 0", c[0]));
                }
                Solutions::NoRealRoot
            }
            2 => {
                nonzero(&c[1], &mut assumptions);
                Solutions::Roots(vec![Sym::negate(Sym::quotient(c[0].clone(), c[1].clone()))])
            }
            3 if let Some((a, b, cc)) =
                super::closed_form::float_coefficients(&c[2], &c[1], &c[0]) =>
            {
                // float coefficients: the roots are floats, computed without cancellation
                // (a root that overflows is infinite, refused by whoever evaluates it)
                let roots = super::closed_form::quadratic_roots(a, b, cc);
                if roots.is_empty() {
                    Solutions::NoRealRoot
                } else {
                    Solutions::Roots(
                        roots
                            .into_iter()
                            .map(|r| Sym::Num(crate::number::Number::Float(r)))
                            .collect(),
                    )
                }
            }
            3 => {
                nonzero(&c[2], &mut assumptions);
                let (a, b, cc) = (c[2].clone(), c[1].clone(), c[0].clone());
                let disc = Sym::difference(
                    Sym::pow(b.clone(), Sym::int(2)),
                    Sym::product(vec![Sym::int(4), a.clone(), cc]),
                );
                match disc.as_num() {
                    Some(d) if d.is_negative() => Solutions::NoRealRoot,
                    Some(d) if d.is_zero() => Solutions::Roots(vec![Sym::negate(Sym::quotient(
                        b,
                        Sym::product(vec![Sym::int(2), a]),
                    ))]),
                    _ => {
                        if disc.as_num().is_none() {
                            // 4*v0^2 - 8*g*h ≥ 0 says no more than v0^2 - 2*g*h ≥ 0
                            let shown = match &disc {
                                Sym::Add(terms) => {
                                    let (c, _) = super::identities::content(terms);
                                    Sym::quotient(disc.clone(), Sym::Num(c.abs()))
                                }
                                other => other.clone(),
                            };
                            assumptions.push(format!("{shown} ≥ 0"));
                        }
                        let root = |sign: i64| {
                            Sym::quotient(
                                Sym::sum(vec![
                                    Sym::negate(b.clone()),
                                    Sym::product(vec![Sym::int(sign), Sym::sqrt(disc.clone())]),
                                ]),
                                Sym::product(vec![Sym::int(2), a.clone()]),
                            )
                        };
                        let mut roots = vec![root(-1), root(1)];
                        // exact coefficients whose radical folded into a float (too many
                        // digits): the float roots, computed without cancellation
                        if roots
                            .iter()
                            .any(|r| r.as_num().is_some_and(|n| !n.is_exact()))
                            && let (Some(a), Some(b), Some(c)) =
                                (a.as_num(), b.as_num(), c[0].as_num())
                        {
                            roots = super::closed_form::quadratic_roots(
                                a.to_f64(),
                                b.to_f64(),
                                c.to_f64(),
                            )
                            .into_iter()
                            .map(|r| Sym::Num(crate::number::Number::Float(r)))
                            .collect();
                        }
                        if let (Some(p), Some(q)) = (numeric(&roots[0]), numeric(&roots[1]))
                            && p > q
                        {
                            roots.swap(0, 1);
                        }
                        Solutions::Roots(roots)
                    }
                }
            }
            _ => return None,
        };
        Some(Solved {
            solutions,
            assumptions,
        })
    }
}

fn numeric(s: &Sym) -> Option<f64> {
    s.eval(&|_| None).ok()
}

/// Solves the linear system `eqs = 0` for `unknowns`; `Err` says why it cannot (not linear,
/// singular).
///
/// ```
/// use mechkit_expr::Sym;
/// use mechkit_expr::sym::solve_linear;
/// // a chandelier of weight m*g hangs from two cables at angles a and b
/// let eqs = [
///     Sym::parse("T1*cos(a) - T2*cos(b)").unwrap(),
///     Sym::parse("T1*sin(a) + T2*sin(b) - m*g").unwrap(),
/// ];
/// let t = solve_linear(&eqs, &["T1", "T2"]).unwrap();
/// assert_eq!(t[0].to_string(), "g*m*cos(b)/(cos(a)*sin(b) + cos(b)*sin(a))");
/// ```
pub fn solve_linear(eqs: &[Sym], unknowns: &[&str]) -> Result<Vec<Sym>, String> {
    let n = unknowns.len();
    if eqs.len() != n {
        let plural = |k: usize, noun: &str| {
            if k == 1 {
                format!("1 {noun}")
            } else {
                format!("{k} {noun}s")
            }
        };
        return Err(format!(
            "{} for {}: give one equation per unknown",
            plural(eqs.len(), "equation"),
            plural(n, "unknown")
        ));
    }
    let mut a = vec![vec![Sym::zero(); n]; n];
    let mut rhs = Vec::with_capacity(n);
    for (i, e) in eqs.iter().enumerate() {
        for (j, u) in unknowns.iter().enumerate() {
            let c = e.diff(u);
            if unknowns.iter().any(|v| !c.free_of(v)) {
                return Err(format!("equation {} is not linear in {u}", i + 1));
            }
            a[i][j] = c;
        }
        let mut at_zero = e.clone();
        for u in unknowns {
            at_zero = at_zero.substitute(u, &Sym::zero());
        }
        rhs.push(Sym::negate(at_zero));
    }
    let d = det(&a);
    if d.is_zero() {
        return Err("the system is singular (no unique solution)".into());
    }
    Ok((0..n)
        .map(|j| {
            let mut aj = a.clone();
            for (row, b) in aj.iter_mut().zip(&rhs) {
                row[j] = b.clone();
            }
            Sym::quotient(det(&aj).expand(), d.expand())
        })
        .collect())
}

/// Determinant by cofactor expansion (the systems here are small).
fn det(m: &[Vec<Sym>]) -> Sym {
    match m.len() {
        0 => Sym::one(),
        1 => m[0][0].clone(),
        n => Sym::sum(
            (0..n)
                .filter(|&j| !m[0][j].is_zero())
                .map(|j| {
                    let minor: Vec<Vec<Sym>> = m[1..]
                        .iter()
                        .map(|row| {
                            row.iter()
                                .enumerate()
                                .filter(|(k, _)| *k != j)
                                .map(|(_, v)| v.clone())
                                .collect()
                        })
                        .collect();
                    let sign = if j % 2 == 0 { 1 } else { -1 };
                    Sym::product(vec![Sym::int(sign), m[0][j].clone(), det(&minor)])
                })
                .collect(),
        ),
    }
}

#[cfg(test)]
#[path = "solve_tests.rs"]
mod tests;
