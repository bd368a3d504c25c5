//! Equations: one equation for one unknown (symbolically when it is linear or quadratic in
//! it, else numerically on an interval), or several linear equations for several unknowns
//! (Cramer's rule), with values for the other names evaluated into numbers.

use mechkit_expr::Number;
use mechkit_expr::Sym;
use mechkit_expr::sym::poly::{NumPoly, coefficients};
use mechkit_expr::sym::{Solutions, quadratic_roots, real_roots, solve_linear};

use super::equation::{check_unknown, equation};
use super::{CalculusError, Params, lookup};
use crate::Real;
use crate::roots::find_all;

/// The answer to `lhs = rhs`.
///
/// Serialized as `{equation: "lhs - rhs = 0", unknown, symbolic: [roots] | null,
/// no_real_root, every_value, assumptions, numeric, interval: [a, b] | null,
/// root_bound: B | null, values_put_in}`.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// `lhs - rhs`, canonical.
    pub equation: Sym,
    /// The unknown.
    pub unknown: String,
    /// Symbolic solutions, when the equation is linear or quadratic in the unknown.
    pub symbolic: Option<Solutions>,
    /// What the symbolic solution assumed.
    pub assumptions: Vec<String>,
    /// Numeric values of the symbolic solutions (when every name has a value), or the roots
    /// found on the interval.
    pub numeric: Vec<Real>,
    /// The interval searched (or that the numeric values were kept to): the one given, or
    /// `[-B, B]` for Cauchy's bound `B` when every real root of a polynomial was searched for.
    pub interval: Option<(Real, Real)>,
    /// Cauchy's bound `B` on the roots when the interval searched was `[-B, B]` (a polynomial
    /// solved numerically without an interval given).
    pub root_bound: Option<Real>,
    /// The values given to the other names.
    pub parameters: Vec<(String, Real)>,
    /// Whether `symbolic` is the answer with the values put in, because they break what the
    /// symbolic solution assumed (`a*x = 1` with a = 0 has no solution, not `x = 1/a`).
    pub values_put_in: bool,
}

impl Solution {
    /// The symbolic roots, when the solution is a list of roots.
    pub fn roots(&self) -> Option<&[Sym]> {
        match &self.symbolic {
            Some(Solutions::Roots(r)) => Some(r),
            _ => None,
        }
    }

    /// Whether there is no answer: no root found and not every value solves it.
    pub fn is_empty(&self) -> bool {
        self.numeric.is_empty()
            && !matches!(self.symbolic, Some(Solutions::Roots(_) | Solutions::Every))
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Solution {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("Solution", 10)?;
        st.serialize_field("equation", &format!("{} = 0", self.equation))?;
        st.serialize_field("unknown", &self.unknown)?;
        st.serialize_field(
            "symbolic",
            &self
                .roots()
                .map(|r| r.iter().map(ToString::to_string).collect::<Vec<_>>()),
        )?;
        st.serialize_field(
            "no_real_root",
            &matches!(self.symbolic, Some(Solutions::NoRealRoot)),
        )?;
        st.serialize_field(
            "every_value",
            &matches!(self.symbolic, Some(Solutions::Every)),
        )?;
        st.serialize_field("assumptions", &self.assumptions)?;
        st.serialize_field("numeric", &self.numeric)?;
        st.serialize_field("interval", &self.interval.map(|(a, b)| [a, b]))?;
        st.serialize_field("root_bound", &self.root_bound)?;
        st.serialize_field("values_put_in", &self.values_put_in)?;
        st.end()
    }
}

/// Solves one equation for `x`: symbolically when it is linear or quadratic in `x` (or a
/// polynomial that [`Sym::solve`] solves in closed form); a polynomial of degree three or more
/// whose coefficients have values in `params` in closed form with those values, or else for
/// every real root numerically inside Cauchy's bound ([`real_roots`]); any other equation
/// numerically on `interval` with `params` for the other names. With `interval`, only the
/// roots in it are kept.
pub fn solve(
    text: &str,
    x: &str,
    interval: Option<(Real, Real)>,
    params: &Params,
) -> Result<Solution, CalculusError> {
    let (eq, names) = equation(text)?;
    check_unknown(x, text, &names)?;
    super::check_not_given(params, &[x])?;
    let env = lookup(params);
    let (mut symbolic, mut assumptions) = match eq.solve(x) {
        Some(s) => (Some(s.solutions), s.assumptions),
        None => (None, Vec::new()),
    };
    let mut numeric = Vec::new();
    let mut root_bound = None;
    let mut searched = false;
    let mut interval_used = interval;
    let within = |v: &Real| interval.is_none_or(|(a, b)| (a.min(b)..=a.max(b)).contains(v));
    if symbolic.is_none()
        && let Some(poly) = polynomial(&eq, x, &env, text, interval.is_some())?
    {
        // a polynomial of degree three or more with values for its coefficients
        if let Some(roots) = poly.closed_form_roots() {
            symbolic = Some(if roots.is_empty() {
                Solutions::NoRealRoot
            } else {
                Solutions::Roots(roots)
            });
        } else if let Some(found) =
            real_roots(&poly.0.iter().map(|c| c.to_f64()).collect::<Vec<_>>())
        {
            numeric = found.roots;
            searched = true;
            if interval.is_none() {
                interval_used = Some((-found.bound, found.bound));
                root_bound = Some(found.bound);
                if numeric.is_empty() {
                    symbolic = Some(Solutions::NoRealRoot);
                }
            }
            numeric.retain(within);
        }
    }
    let mut values_put_in = false;
    if let Some(Solutions::Roots(roots)) = &symbolic {
        numeric = match valued_low_degree(&eq, x, &env) {
            // linear: the formula's value, as it reads (`m*v/dt`, not `-(-m*v)/dt`)
            Some(Solutions::Roots(v)) if v.len() == 1 && roots.len() == 1 => {
                vec![roots[0].eval(&env).unwrap_or(Real::NAN)]
            }
            // quadratic with every coefficient valued: its roots with the values put in,
            // computed without cancellation
            Some(Solutions::Roots(v)) => v.iter().filter_map(|r| r.eval(&|_| None).ok()).collect(),
            // the values break an assumption: `a*x = 1` with a = 0 has no solution
            Some(other) => {
                symbolic = Some(other);
                assumptions.clear();
                values_put_in = true;
                Vec::new()
            }
            None => roots.iter().filter_map(|r| r.eval(&env).ok()).collect(),
        };
        if let Some(&bad) = numeric.iter().find(|v| !v.is_finite()) {
            let why = if assumptions.is_empty() {
                format!(
                    "the root of `{}` overflows double precision; rescale the equation (other units)",
                    text.trim()
                )
            } else {
                format!(
                    "the root of `{}` overflows double precision, or the values given break what \
                     it assumes ({}); rescale the equation, or check the values",
                    text.trim(),
                    assumptions.join(" and ")
                )
            };
            return Err(CalculusError::NotFinite {
                what: x.to_string(),
                value: bad,
                why,
            });
        }
        numeric.retain(within);
    } else if searched {
        // every real root of the polynomial, found above
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
        unknown: x.to_string(),
        symbolic,
        assumptions,
        numeric,
        interval: interval_used,
        root_bound,
        parameters: params.to_vec(),
        values_put_in,
    })
}

/// The solutions of `eq = 0` for `x` with the values of the other names put in, when it is a
/// polynomial of degree two at most in `x` whose coefficients all have values: the roots as
/// numbers (infinite where one overflows), by [`quadratic_roots`] for a quadratic;
/// no root or every value when the values make the leading coefficients vanish.
fn valued_low_degree(eq: &Sym, x: &str, env: &dyn Fn(&str) -> Option<Real>) -> Option<Solutions> {
    let c = coefficients(eq, x)?;
    if c.len() > 3 {
        return None;
    }
    let mut v = c
        .iter()
        .map(|ci| ci.eval(env).ok())
        .collect::<Option<Vec<Real>>>()?;
    if v.iter().any(|c| !c.is_finite()) {
        return None;
    }
    while v.last() == Some(&0.0) {
        v.pop();
    }
    let float = |r: Real| Sym::Num(Number::Float(r));
    Some(match v.len() {
        0 => Solutions::Every,
        1 => Solutions::NoRealRoot,
        2 => Solutions::Roots(vec![float(-v[0] / v[1])]),
        _ => {
            let r = quadratic_roots(v[2], v[1], v[0]);
            if r.is_empty() {
                Solutions::NoRealRoot
            } else {
                Solutions::Roots(r.into_iter().map(float).collect())
            }
        }
    })
}

/// `eq` as a polynomial in `x` with numeric coefficients, the values given to the names
/// substituted (exact where they are short decimals); `None` when it is not a polynomial
/// (or too large a degree). An error when it is one of degree three or more whose
/// coefficients still need values and no interval was given: the message names them.
fn polynomial(
    eq: &Sym,
    x: &str,
    env: &dyn Fn(&str) -> Option<Real>,
    text: &str,
    has_interval: bool,
) -> Result<Option<NumPoly>, CalculusError> {
    let Some(c) = coefficients(eq, x) else {
        return Ok(None);
    };
    let mut missing: Vec<String> = c
        .iter()
        .flat_map(Sym::names)
        .filter(|n| env(n).is_none())
        .collect();
    missing.dedup();
    if !missing.is_empty() {
        if has_interval {
            return Ok(None);
        }
        missing.sort();
        missing.dedup();
        let degree = c.len() - 1;
        return Err(CalculusError::Invalid(format!(
            "`{text}` is a polynomial of degree {degree} in `{x}` with no closed form for \
             symbolic coefficients: give values for {} with --set (e.g. --set {}=1)",
            missing
                .iter()
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(", "),
            missing[0]
        )));
    }
    let numbers = c
        .iter()
        .map(|ci| {
            let mut v = ci.clone();
            for n in ci.names() {
                let value = env(&n).expect("checked above");
                v = v.substitute(&n, &Sym::Num(Number::from_f64(value)));
            }
            match v.as_num() {
                Some(n) => Some(n),
                None => v
                    .eval(&|_| None)
                    .ok()
                    .filter(|f| f.is_finite())
                    .map(Number::Float),
            }
        })
        .collect::<Option<Vec<_>>>();
    Ok(numbers.map(NumPoly::new).filter(|p| p.degree().is_some()))
}

/// Solves several linear equations (`;`-separated) for several unknowns, symbolically.
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

/// The solution of a linear system: each unknown symbolically, and its value when every other
/// name has one.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SystemSolution {
    /// Each unknown and its value, a formula of the other names (a JSON object of texts).
    #[cfg_attr(feature = "serde", serde(serialize_with = "solution_map"))]
    pub solution: Vec<(String, Sym)>,
    /// The values given to the other names (a JSON object).
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::params"))]
    pub parameters: Vec<(String, Real)>,
    /// Each unknown's value with the names' values, when they were given for every name
    /// (non-finite where the system is singular for these values; null in JSON).
    #[cfg_attr(feature = "serde", serde(serialize_with = "numeric_map"))]
    pub numeric: Option<Vec<(String, Real)>>,
}

impl SystemSolution {
    /// Whether the values given make the system singular (a value is not finite).
    pub fn singular_with_values(&self) -> bool {
        self.numeric
            .as_ref()
            .is_some_and(|n| n.iter().any(|(_, v)| !v.is_finite()))
    }

    /// The names without a value that the solution still depends on.
    pub fn missing(&self) -> Vec<String> {
        let env = lookup(&self.parameters);
        let mut names: Vec<String> = self
            .solution
            .iter()
            .flat_map(|(_, s)| s.names())
            .filter(|n| env(n).is_none())
            .collect();
        names.sort();
        names.dedup();
        names
    }
}

#[cfg(feature = "serde")]
fn solution_map<S: serde::Serializer>(v: &[(String, Sym)], s: S) -> Result<S::Ok, S::Error> {
    s.collect_map(v.iter().map(|(k, x)| (k, x.to_string())))
}

#[cfg(feature = "serde")]
#[allow(clippy::ref_option)] // serde's `serialize_with` passes `&Option<T>`
fn numeric_map<S: serde::Serializer>(
    v: &Option<Vec<(String, Real)>>,
    s: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    match v {
        // a value that is not finite (the system is singular for these values) is null, as
        // documented on the field: not an answer, so the finiteness rule passes it
        Some(v) => {
            let mut map = s.serialize_map(Some(v.len()))?;
            for (k, x) in v {
                map.serialize_entry(k, &x.is_finite().then_some(*x))?;
            }
            map.end()
        }
        None => s.serialize_none(),
    }
}

/// The answer of `mechkit solve`: one equation, or a linear system.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(untagged))]
#[non_exhaustive]
pub enum Solved {
    /// One equation for one unknown.
    Equation(Solution),
    /// Linear equations for several unknowns.
    System(SystemSolution),
}

impl Solved {
    /// Whether there is no answer (no root; a system singular with the values given).
    pub fn failed(&self) -> bool {
        match self {
            Solved::Equation(s) => s.is_empty(),
            Solved::System(s) => s.singular_with_values(),
        }
    }
}

/// Solves `text` for `unknowns`: several unknowns or `;`-separated equations are a linear
/// system ([`solve_system`], then evaluated with `params` when every name has a value); one
/// equation for one unknown is [`solve`] (on `interval` if given).
pub fn solve_equations(
    text: &str,
    unknowns: &[&str],
    interval: Option<(Real, Real)>,
    params: &Params,
) -> Result<Solved, CalculusError> {
    if unknowns.len() > 1 || text.contains(';') {
        super::check_not_given(params, unknowns)?;
        let solution = solve_system(text, unknowns)?;
        let env = lookup(params);
        let numeric = solution
            .iter()
            .map(|(k, s)| s.eval(&env).ok().map(|v| (k.clone(), v)))
            .collect::<Option<Vec<_>>>()
            .filter(|_| !params.is_empty());
        return Ok(Solved::System(SystemSolution {
            solution,
            parameters: params.to_vec(),
            numeric,
        }));
    }
    let x = unknowns.first().copied().unwrap_or("x");
    solve(text, x, interval, params).map(Solved::Equation)
}

#[cfg(test)]
#[path = "solve_tests.rs"]
mod tests;
