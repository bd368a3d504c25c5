//! The one-question calculus of the command line, as library calls: the derivative of a
//! formula, its antiderivative and definite integral (closed form next to adaptive quadrature,
//! and whether they agree), the solutions of an equation (symbolic, else numeric on an
//! interval), and unit conversion.

use mechkit_expr::sym::{Solutions, solve_linear};
use mechkit_expr::units::{Dimension, Quantity, Unit, UnitError};
use mechkit_expr::{ExprError, Sym, parse};
use thiserror::Error;

use crate::Real;
use crate::function::Function;
use crate::quad::{QuadResult, Rule, Tolerance, integrate as quadrature, integrate_rule};
use crate::roots::find_all;

mod equation;
use equation::{check_unknown, equation};

/// A formula, a unit or a value that could not be read.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum CalculusError {
    /// The formula does not parse.
    #[error("{0}")]
    Formula(#[from] ExprError),
    /// A unit or quantity does not parse.
    #[error("{0}")]
    Unit(#[from] UnitError),
    /// Something else is wrong with the question (what, and how to fix it).
    #[error("{0}")]
    Invalid(String),
}

/// Values given for the names of a formula (`--set a=1,b=2`), SI.
pub type Params = [(String, Real)];

fn lookup(params: &Params) -> impl Fn(&str) -> Option<Real> + '_ {
    move |n| params.iter().find(|(k, _)| k == n).map(|(_, v)| *v)
}

/// Reads `a=1,b=2 m,th=pi/6` into names and SI values ([`crate::values::params`]).
pub fn parse_params(text: &str) -> Result<Vec<(String, Real)>, CalculusError> {
    crate::values::params(text).map_err(|e| {
        CalculusError::Invalid(
            e.message
                .strip_prefix("--set ")
                .or_else(|| e.message.strip_prefix("--set: "))
                .unwrap_or(&e.message)
                .to_string(),
        )
    })
}

/// A derivative.
#[derive(Debug, Clone, PartialEq)]
pub struct Derivative {
    /// The formula, canonical.
    pub input: Sym,
    /// Its derivative, simplified.
    pub result: Sym,
}

/// `d/dx` of `text`.
pub fn derivative(text: &str, x: &str) -> Result<Derivative, CalculusError> {
    let input = Sym::from_expr(&parse(text)?.expr);
    let result = input.diff(x);
    Ok(Derivative { input, result })
}

/// The value of a derivative at a point by the symbolic derivative and by Ridders'
/// extrapolation of central differences, side by side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivativeCheck {
    /// Where.
    pub at: Real,
    /// The symbolic derivative's value.
    pub symbolic: Real,
    /// Ridders' estimate.
    pub numeric: Real,
    /// Its error estimate.
    pub numeric_error: Real,
    /// Whether they agree within the estimate (or 1e-9 relative).
    pub agree: bool,
}

/// `d/dx text` at `at`, symbolically and numerically (initial step `h`, e.g. 0.1 or a tenth
/// of the scale of `x`), with `params` for the other names.
///
/// ```
/// let c = mechkit::calculus::derivative_at("x^3*sin(x)", "x", 1.2, &[], 0.1).unwrap();
/// assert!(c.agree && (c.symbolic - c.numeric).abs() < 1e-10);
/// ```
pub fn derivative_at(
    text: &str,
    x: &str,
    at: Real,
    params: &Params,
    h: Real,
) -> Result<DerivativeCheck, CalculusError> {
    let f = Function::parse(text, &[x], params)?;
    let symbolic = f.diff(x).at1(at);
    let est = crate::deriv::derivative(|v| f.at1(v), at, h);
    let agree = (symbolic - est.value).abs() <= (10.0 * est.error).max(1e-9 * symbolic.abs());
    Ok(DerivativeCheck {
        at,
        symbolic,
        numeric: est.value,
        numeric_error: est.error,
        agree,
    })
}

/// An integral: the antiderivative when the rule table has one, and the definite value by
/// both routes when limits are given.
#[derive(Debug, Clone, PartialEq)]
pub struct Integral {
    /// The integrand, canonical.
    pub input: Sym,
    /// An antiderivative (verified by differentiation), if found.
    pub antiderivative: Option<Sym>,
    /// What it assumed.
    pub assumptions: Vec<String>,
    /// The definite integral, if limits were given.
    pub definite: Option<Definite>,
}

/// A definite integral by the closed form and by quadrature.
#[derive(Debug, Clone, PartialEq)]
pub struct Definite {
    /// Lower limit.
    pub from: Real,
    /// Upper limit.
    pub to: Real,
    /// `F(to) - F(from)`, when there is an antiderivative continuous on the interval and all
    /// names have values.
    pub closed_form: Option<Real>,
    /// Adaptive Gauss-Kronrod.
    pub quadrature: Result<QuadResult, String>,
    /// Whether the two agree within the quadrature's error estimate (or 1e-9 relative).
    pub agree: Option<bool>,
}

/// The integral of `text` with respect to `x`, with `params` giving values to the other names
/// (needed for the definite value).
pub fn integral(
    text: &str,
    x: &str,
    limits: Option<(Real, Real)>,
    params: &Params,
) -> Result<Integral, CalculusError> {
    let input = Sym::from_expr(&parse(text)?.expr);
    let anti = input.integrate(x);
    let (antiderivative, assumptions) = match anti {
        Some(a) => (Some(a.result), a.assumptions),
        None => (None, Vec::new()),
    };
    let definite = limits.map(|(from, to)| {
        let env = lookup(params);
        let at = |f: &Sym, v: Real| f.eval(&|n| if n == x { Some(v) } else { env(n) });
        let quad = quadrature(
            |v| at(&input, v).unwrap_or(Real::NAN),
            from,
            to,
            Tolerance::default(),
        )
        .map_err(|e| e.to_string());
        // the closed form counts only if it is continuous on the interval: compare with the
        // quadrature's value (a jump in ln|x| across 0 would show as a disagreement)
        let closed_form = antiderivative.as_ref().and_then(|big_f| {
            let (a, b) = (at(big_f, from).ok()?, at(big_f, to).ok()?);
            let v = b - a;
            v.is_finite().then_some(v)
        });
        let agree = match (&closed_form, &quad) {
            (Some(c), Ok(q)) => {
                Some((c - q.value).abs() <= (10.0 * q.error).max(1e-9 * c.abs().max(1e-12)))
            }
            _ => None,
        };
        Definite {
            from,
            to,
            closed_form,
            quadrature: quad,
            agree,
        }
    });
    if definite
        .as_ref()
        .is_some_and(|d| d.quadrature.is_err() && d.closed_form.is_none())
        && input
            .names()
            .iter()
            .any(|n| n != x && lookup(params)(n).is_none())
    {
        let missing: Vec<String> = input
            .names()
            .into_iter()
            .filter(|n| n != x && lookup(params)(n).is_none())
            .collect();
        return Err(CalculusError::Invalid(format!(
            "a definite value needs values for {}: give them with --set, e.g. --set {}=1",
            missing.join(", "),
            missing[0]
        )));
    }
    Ok(Integral {
        input,
        antiderivative,
        assumptions,
        definite,
    })
}

/// One fixed rule's estimate of a definite integral, next to the exact value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RuleEstimate {
    /// The rule.
    pub rule: Rule,
    /// Number of intervals.
    pub n: usize,
    /// Its value.
    pub value: Real,
    /// `value - reference`.
    pub error: Real,
    /// The convergence order measured against the previous number of intervals of the same
    /// rule, `ln(e_prev/e)/ln(n/n_prev)` (none for the first, or when an error is down at
    /// rounding level).
    pub observed_order: Option<Real>,
}

/// The estimates of `∫ text dx` over `limits` by each rule with each number of intervals, and
/// the reference they are measured against: the closed form when the rule table has one
/// (checked against adaptive quadrature), else adaptive Gauss-Kronrod quadrature.
///
/// ```
/// use mechkit::calculus::rule_estimates;
/// use mechkit::quad::Rule;
/// let (reference, rows) = rule_estimates("1/(1 + x^2)", "x", (0.0, 1.0), &[],
///     &[Rule::Trapezoid], &[10]).unwrap();
/// assert!((reference - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
/// assert!((rows[0].value - 0.784_981).abs() < 1e-6);
/// let (_, rows) = rule_estimates("exp(x)", "x", (0.0, 1.0), &[], &[Rule::Simpson], &[8, 16]).unwrap();
/// assert!((rows[1].observed_order.unwrap() - 4.0).abs() < 0.05);
/// ```
pub fn rule_estimates(
    text: &str,
    x: &str,
    limits: (Real, Real),
    params: &Params,
    rules: &[Rule],
    ns: &[usize],
) -> Result<(Real, Vec<RuleEstimate>), CalculusError> {
    let f = Function::parse(text, &[x], params)?;
    let exact = integral(text, x, Some(limits), params)?
        .definite
        .and_then(|d| match (d.closed_form, d.agree, d.quadrature) {
            (Some(c), Some(true), _) => Some(c),
            (_, _, Ok(q)) => Some(q.value),
            _ => None,
        })
        .ok_or_else(|| {
            CalculusError::Invalid(format!(
                "`{text}` could not be integrated from {} to {} to compare the rules with",
                limits.0, limits.1
            ))
        })?;
    let mut rows = Vec::new();
    for &rule in rules {
        let mut previous: Option<(usize, Real)> = None;
        for &n in ns {
            let value = integrate_rule(|v| f.at1(v), limits.0, limits.1, rule, n)
                .map_err(|e| CalculusError::Invalid(format!("{}: {e}", rule.name())))?;
            let error = value - exact;
            // errors at the level of rounding carry no order
            let noise = 1e3 * Real::EPSILON * exact.abs().max(Real::MIN_POSITIVE);
            let observed_order = previous.and_then(|(n0, e0)| {
                let o = (e0.abs() / error.abs()).ln() / (n as Real / n0 as Real).ln();
                (o.is_finite() && n != n0 && e0.abs() > noise && error.abs() > noise).then_some(o)
            });
            previous = Some((n, error));
            rows.push(RuleEstimate {
                rule,
                n,
                value,
                error,
                observed_order,
            });
        }
    }
    Ok((exact, rows))
}

/// The answer to `lhs = rhs`.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// `lhs - rhs`, canonical.
    pub equation: Sym,
    /// Symbolic solutions, when the equation is linear or quadratic in the unknown.
    pub symbolic: Option<Solutions>,
    /// What the symbolic solution assumed.
    pub assumptions: Vec<String>,
    /// Numeric values of the symbolic solutions (when every name has a value), or the roots
    /// found on the interval.
    pub numeric: Vec<Real>,
}

/// Solves one equation for `x`: symbolically when it is linear or quadratic in `x`, otherwise
/// (or additionally, with an interval) numerically on `interval` with `params` for the other
/// names.
pub fn solve(
    text: &str,
    x: &str,
    interval: Option<(Real, Real)>,
    params: &Params,
) -> Result<Solution, CalculusError> {
    let (eq, names) = equation(text)?;
    check_unknown(x, text, &names)?;
    let env = lookup(params);
    let solved = eq.solve(x);
    let (symbolic, assumptions) = match solved {
        Some(s) => (Some(s.solutions), s.assumptions),
        None => (None, Vec::new()),
    };
    let mut numeric = Vec::new();
    if let Some(Solutions::Roots(roots)) = &symbolic {
        numeric = roots
            .iter()
            .filter_map(|r| r.eval(&env).ok())
            .filter(|v| v.is_finite())
            .collect();
        if let Some((a, b)) = interval {
            numeric.retain(|v| (a.min(b)..=a.max(b)).contains(v));
        }
    } else if let Some((a, b)) = interval {
        let f = |v: Real| {
            eq.eval(&|n| if n == x { Some(v) } else { env(n) })
                .unwrap_or(Real::NAN)
        };
        if let Some(missing) = eq.names().into_iter().find(|n| n != x && env(n).is_none()) {
            return Err(CalculusError::Invalid(format!(
                "solving numerically needs a value for `{missing}`: give it with --set {missing}=…"
            )));
        }
        numeric = find_all(
            f,
            a.min(b),
            a.max(b),
            2000,
            1e-14 * (a.abs().max(b.abs())).max(1.0),
        );
    } else if symbolic.is_none() {
        return Err(CalculusError::Invalid(format!(
            "`{text}` is not linear or quadratic in `{x}`: give an interval to search, e.g. --in 0:10"
        )));
    }
    Ok(Solution {
        equation: eq,
        symbolic,
        assumptions,
        numeric,
    })
}

/// Solves several linear equations (`;`-separated) for several unknowns.
pub fn solve_system(text: &str, unknowns: &[&str]) -> Result<Vec<(String, Sym)>, CalculusError> {
    let (eqs, names): (Vec<Sym>, Vec<Vec<String>>) = text
        .split(';')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(equation)
        .collect::<Result<Vec<_>, _>>()?
        .into_iter()
        .unzip();
    let mut names = names.concat();
    names.sort();
    names.dedup();
    for u in unknowns {
        check_unknown(u, text, &names)?;
    }
    let sol = solve_linear(&eqs, unknowns).map_err(CalculusError::Invalid)?;
    Ok(unknowns.iter().map(|u| (*u).to_string()).zip(sol).collect())
}

/// A quantity in SI and, when asked, in another unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Conversion {
    /// The value in SI units.
    pub si: Real,
    /// Its dimension.
    pub dimension: Dimension,
    /// The value in the requested unit.
    pub converted: Option<(Real, String)>,
}

/// Converts `quantity` (`"60 km/h"`) to SI, and to `to` if given.
pub fn convert(quantity: &str, to: Option<&str>) -> Result<Conversion, CalculusError> {
    let q = Quantity::parse(quantity)?;
    let converted = match to {
        None => None,
        Some(u) => {
            let unit = Unit::parse(u)?;
            let v = q.value_in(&unit).ok_or_else(|| {
                CalculusError::Invalid(format!(
                    "cannot convert {} to {u}: the dimensions differ ({} vs {}); give --to a unit \
                     of {}, or leave it out to see the value in SI units",
                    quantity,
                    q.dim.describe(),
                    unit.dim.describe(),
                    q.dim.describe()
                ))
            })?;
            Some((v, u.to_string()))
        }
    };
    Ok(Conversion {
        si: q.value,
        dimension: q.dim,
        converted,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_acceptance_integral() {
        let i = integral("1/(a+x^2)", "x", Some((0.0, 1.0)), &[("a".into(), 1.0)]).unwrap();
        assert_eq!(
            i.antiderivative.unwrap().to_string(),
            "atan(x/sqrt(a))/sqrt(a)"
        );
        assert_eq!(i.assumptions, vec!["a > 0"]);
        let d = i.definite.unwrap();
        assert!((d.closed_form.unwrap() - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert_eq!(d.agree, Some(true));
    }

    #[test]
    fn equations() {
        let s = solve("x^2 - 5*x + 6 = 0", "x", None, &[]).unwrap();
        assert_eq!(s.numeric, vec![2.0, 3.0]);
        let s = solve("cos(x) = x", "x", Some((0.0, 1.0)), &[]).unwrap();
        assert!((s.numeric[0] - 0.739_085_133_215_160_6).abs() < 1e-12);
        assert!(solve("cos(x) = x", "x", None, &[]).is_err());
        let sys = solve_system("N - m*g*cos(t) = 0; f = m*g*sin(t)", &["N", "f"]).unwrap();
        assert_eq!(sys[1].1.to_string(), "g*m*sin(t)");
    }

    #[test]
    fn units() {
        let c = convert("60 km/h", Some("m/s")).unwrap();
        assert!((c.si - 16.666_666_666_666_668).abs() < 1e-12);
        assert!((c.converted.unwrap().0 - c.si).abs() < 1e-12);
        assert!(convert("60 km/h", Some("kg")).is_err());
    }
}
