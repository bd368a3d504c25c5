//! Equations: one equation for one unknown (symbolically when it is linear or quadratic in
//! it, else numerically on an interval), or several linear equations for several unknowns
//! (Cramer's rule), with values for the other names evaluated into numbers.

use mechkit_expr::Sym;
use mechkit_expr::sym::{Solutions, solve_linear};

use super::equation::{check_unknown, equation};
use super::{CalculusError, Params, lookup};
use crate::Real;
use crate::roots::find_all;

/// The answer to `lhs = rhs`.
///
/// Serialized as `{equation: "lhs - rhs = 0", unknown, symbolic: [roots] | null,
/// no_real_root, every_value, assumptions, numeric}`.
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
    /// The interval searched (or that the numeric values were kept to), if one was given.
    pub interval: Option<(Real, Real)>,
    /// The values given to the other names.
    pub parameters: Vec<(String, Real)>,
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
        let mut st = s.serialize_struct("Solution", 7)?;
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
        st.end()
    }
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
        unknown: x.to_string(),
        symbolic,
        assumptions,
        numeric,
        interval,
        parameters: params.to_vec(),
    })
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
mod tests {
    use super::*;

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

    /// Issue 22: `--set` gives values to a linear system's other names.
    #[test]
    fn a_system_uses_the_values_given() {
        let p = [("a".to_string(), 2.0)];
        let Solved::System(s) =
            solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &p).unwrap()
        else {
            panic!("a system")
        };
        let n = s.numeric.as_ref().unwrap();
        assert!((n[0].1 - 4.0 / 3.0).abs() < 1e-15 && (n[1].1 - 1.0 / 3.0).abs() < 1e-15);
        assert!(!s.singular_with_values() && s.missing().is_empty());
        // singular for a = -1
        let p = [("a".to_string(), -1.0)];
        let s = solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &p).unwrap();
        assert!(s.failed());
        // no values: the symbolic solution alone
        let Solved::System(s) =
            solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &[]).unwrap()
        else {
            panic!("a system")
        };
        assert!(s.numeric.is_none() && s.missing() == ["a"]);
    }
}
