//! The driver: the general solution by the first method that applies, the constants fixed by
//! the initial conditions, and the verification by substitution.

use thiserror::Error;

use super::conditions::Condition;
use super::parse::Ode;
use super::verify::verify;
use super::{constant, euler, first_order, invert};
use crate::ExprError;
use crate::sym::{Sym, solve_linear};

/// Why an equation has no closed-form answer here.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DsolveError {
    /// The equation does not parse (located in the user's text).
    #[error("{0}")]
    Formula(ExprError),
    /// The question is malformed (what, and how to fix it).
    #[error("{0}")]
    Invalid(String),
    /// An initial condition does not parse or does not fit the equation.
    #[error("{0}")]
    Condition(String),
    /// No method of the table applies, or its answer did not verify.
    #[error("no closed-form method applies to `{equation}`: {reason}")]
    NoMethod {
        /// The equation, `lhs - rhs = 0`, derivatives written with primes.
        equation: String,
        /// What was tried.
        reason: String,
    },
}

/// How a solution was checked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verification {
    /// The residual (and the conditions) simplified to exactly 0.
    Symbolic,
    /// The residual vanished (relative 1e-8) at this many points, random values for the other
    /// names and the free constants.
    Numeric {
        /// Points where it was evaluated.
        points: usize,
    },
}

/// A verified solution.
#[derive(Debug, Clone, PartialEq)]
pub struct OdeSolution {
    /// `x(t)`, explicit.
    pub solution: Sym,
    /// The method, in words (`constant coefficients, under-damped`).
    pub method: String,
    /// Constants still free in the solution (`C1`, `C2`).
    pub constants: Vec<String>,
    /// Constants fixed by the initial conditions, with their values.
    pub determined: Vec<(String, Sym)>,
    /// What was assumed about the other names (`k/m > 0`).
    pub assumptions: Vec<String>,
    /// How it was verified.
    pub verification: Verification,
}

/// A general solution (or a few candidates, the branches of a root), before the conditions.
pub(super) struct General {
    pub candidates: Vec<Sym>,
    pub method: String,
    pub assumptions: Vec<String>,
    /// Expressions assumed positive (for the numerical check).
    pub positive: Vec<Sym>,
}

impl Ode {
    /// The equation as written, `lhs - rhs = 0` with primes.
    pub fn display(&self) -> String {
        let mut s = format!("{} = 0", self.residual);
        for k in (1..=self.order).rev() {
            s = s.replace(
                &super::derivative_name(&self.func, k),
                &format!("{}{}", self.func, "'".repeat(k)),
            );
        }
        s
    }

    /// Solves the equation, with the constants fixed by `conditions` (fewer conditions than
    /// the order leave constants `C1`, `C2` free).
    ///
    /// ```
    /// use mechkit_expr::sym::dsolve::{Condition, Ode};
    /// let ode = Ode::parse("x'' + 4*x = 0", "x", "t").unwrap();
    /// let ic = Condition::parse_list("x(0)=1, x'(0)=0", "x").unwrap();
    /// assert_eq!(ode.solve(&ic).unwrap().solution.to_string(), "cos(2*t)");
    /// ```
    pub fn solve(&self, conditions: &[Condition]) -> Result<OdeSolution, DsolveError> {
        if conditions.len() > self.order {
            return Err(DsolveError::Condition(format!(
                "{} conditions for an equation of order {}: give at most one per constant",
                conditions.len(),
                self.order
            )));
        }
        for c in conditions {
            if c.order >= self.order {
                return Err(DsolveError::Condition(format!(
                    "the condition {}{c} is on a derivative of order {} but the equation is of \
                     order {}: conditions go on {} up to its derivative of order {}",
                    self.func,
                    c.order,
                    self.order,
                    self.func,
                    self.order - 1
                )));
            }
            if !c.at.free_of(&self.var) || !c.value.free_of(&self.var) {
                return Err(DsolveError::Condition(format!(
                    "the condition {}{c} depends on {}: give the point and the value as numbers \
                     or names",
                    self.func, self.var
                )));
            }
        }
        self.check_regular(conditions)?;
        let constants = self.fresh_constants(conditions);
        let names: Vec<&str> = constants.iter().map(String::as_str).collect();
        let no_method = |reason: String| DsolveError::NoMethod {
            equation: self.display(),
            reason,
        };
        let general = constant::solve(self, &names)
            .or_else(|| euler::solve(self, &names))
            .or_else(|| {
                (self.order == 1)
                    .then(|| first_order::solve(self, &names))
                    .flatten()
            });
        let Some(general) = general else {
            return self
                .equilibrium(conditions)
                .ok_or_else(|| self.no_method_applies(&no_method));
        };
        for candidate in &general.candidates {
            for (solution, determined) in apply(self, candidate, &names, conditions) {
                if let Some((verification, note)) =
                    verify(self, &solution, conditions, &general.positive)
                {
                    let constants = names
                        .iter()
                        .filter(|c| !solution.free_of(c))
                        .map(|c| (*c).to_string())
                        .collect();
                    return Ok(OdeSolution {
                        solution,
                        method: general.method.clone(),
                        constants,
                        determined,
                        assumptions: general.assumptions.iter().cloned().chain(note).collect(),
                        verification,
                    });
                }
            }
        }
        self.equilibrium(conditions).ok_or_else(|| {
            no_method(format!(
                "the {} solution did not verify by substitution{}",
                general.method,
                if conditions.is_empty() {
                    ""
                } else {
                    " (or the conditions could not be met)"
                }
            ))
        })
    }

    /// The constant solution `x(t) = x₀` when the conditions start at rest at `x₀`
    /// (`x(t₀) = x₀` and every derivative given 0) and the equation holds there: a
    /// separable equation at a root of its right-hand side (`m v' = -c v^2`, `v(0) = 0`),
    /// which the general solution reaches only with an infinite constant.
    fn equilibrium(&self, conditions: &[Condition]) -> Option<OdeSolution> {
        if conditions.len() != self.order {
            return None;
        }
        let x0 = conditions.iter().find(|c| c.order == 0)?.value.clone();
        if conditions
            .iter()
            .any(|c| c.order > 0 && !c.value.expand().is_zero())
        {
            return None;
        }
        let (verification, note) = verify(self, &x0, conditions, &[])?;
        Some(OdeSolution {
            solution: x0,
            method: "equilibrium: the equation holds at rest at the initial value".into(),
            constants: Vec::new(),
            determined: Vec::new(),
            assumptions: note.into_iter().collect(),
            verification,
        })
    }

    /// Why no method of the table applies, by order.
    fn no_method_applies(&self, no_method: &dyn Fn(String) -> DsolveError) -> DsolveError {
        no_method(if self.order == 1 {
            "it is neither linear, separable (with an invertible integral) nor Bernoulli".into()
        } else if self.order == 2 {
            "only linear equations with constant coefficients (or of Euler–Cauchy form, \
             t^2 x'' + a t x' + b x) are solved at order 2"
                .into()
        } else {
            format!(
                "at order {} only linear equations with constant numeric coefficients \
                 are solved, when the characteristic polynomial's roots have a closed \
                 form here",
                self.order
            )
        })
    }

    /// `C1`, `C2`, … not used in the equation or the conditions.
    fn fresh_constants(&self, conditions: &[Condition]) -> Vec<String> {
        let mut used = self.residual.names();
        for c in conditions {
            used.extend(c.at.names());
            used.extend(c.value.names());
        }
        (1..)
            .map(|i| format!("C{i}"))
            .filter(|c| !used.contains(c))
            .take(self.order)
            .collect()
    }
}

/// The solution with constants fixed by the conditions: linear constants by Cramer's rule,
/// one constant inside a function by inverting it (every branch, the check picks).
fn apply(
    ode: &Ode,
    solution: &Sym,
    constants: &[&str],
    conditions: &[Condition],
) -> Vec<(Sym, Vec<(String, Sym)>)> {
    if conditions.is_empty() {
        return vec![(solution.clone(), Vec::new())];
    }
    let at = |c: &Condition| {
        let mut d = solution.clone();
        for _ in 0..c.order {
            d = d.diff(&ode.var);
        }
        d.substitute(&ode.var, &c.at)
    };
    let eqs: Vec<Sym> = conditions
        .iter()
        .map(|c| Sym::difference(at(c), c.value.clone()))
        .collect();
    let subsets: Vec<Vec<&str>> = match (conditions.len(), constants) {
        (1, [a, b]) => vec![vec![*a], vec![*b]],
        _ => vec![constants[..conditions.len()].to_vec()],
    };
    // a constant that is infinite (`0^(-1)`: the condition is met only in a limit), or a
    // number that is undefined, fixes nothing (one with names may be undefined only at the
    // values tried)
    let finite = |v: &Sym| {
        let named = !v.names().is_empty();
        match at_sample_values(v) {
            Ok(x) => x.is_finite() || (x.is_nan() && named),
            Err(_) => named,
        }
    };
    let fix = |vals: &[(String, Sym)]| {
        let mut s = solution.clone();
        for (c, v) in vals {
            s = s.substitute(c, v);
        }
        (s, vals.to_vec())
    };
    for subset in &subsets {
        if nearly_singular(&eqs, subset) {
            continue;
        }
        if let Ok(values) = solve_linear(&eqs, subset)
            && values.iter().all(finite)
        {
            let vals: Vec<(String, Sym)> = subset
                .iter()
                .map(|c| (*c).to_string())
                .zip(values)
                .collect();
            return vec![fix(&vals)];
        }
    }
    let mut out = Vec::new();
    if let [c] = conditions {
        for k in constants {
            let value_at = at(c);
            for v in invert::solve_for(&value_at, k, &c.value, None) {
                if !finite(&v) {
                    continue;
                }
                out.push(fix(&[((*k).to_string(), v)]));
            }
        }
    }
    out
}

/// `s` with its names at fixed values (0.7, 1.07, 1.44, … in the order of their first use).
fn at_sample_values(s: &Sym) -> Result<f64, String> {
    let names = s.names();
    s.eval(&|name: &str| {
        names
            .iter()
            .position(|m| m == name)
            .map(|i| 0.7 + 0.37 * i as f64)
    })
}

/// Whether the conditions, linear in `constants`, leave them undetermined in floating point:
/// the matrix `∂eq_i/∂C_j`, evaluated with the other names at fixed values, has a determinant
/// within 1e-10 of the product of its rows' sizes (`x(0)=0, x(pi)=1` for `x'' + x = 0`:
/// `sin(pi)` is not simplified to 0, and Cramer's rule would divide by it).
fn nearly_singular(eqs: &[Sym], constants: &[&str]) -> bool {
    let n = constants.len();
    if eqs.len() != n {
        return false;
    }
    let value = |s: &Sym| at_sample_values(s).ok().filter(|v| v.is_finite());
    let mut m = Vec::with_capacity(n);
    for e in eqs {
        let row: Option<Vec<f64>> = constants.iter().map(|c| value(&e.diff(c))).collect();
        let Some(row) = row else { return false };
        m.push(row);
    }
    let scale: f64 = m
        .iter()
        .map(|r| r.iter().map(|v| v * v).sum::<f64>().sqrt())
        .product();
    if scale == 0.0 {
        return true;
    }
    // Gaussian elimination with partial pivoting
    let mut det = 1.0;
    for k in 0..n {
        let p = (k..n)
            .max_by(|&i, &j| m[i][k].abs().total_cmp(&m[j][k].abs()))
            .expect("rows left");
        if p != k {
            m.swap(p, k);
            det = -det;
        }
        let pivot = m[k][k];
        det *= pivot;
        if pivot == 0.0 {
            return true;
        }
        let (top, bottom) = m.split_at_mut(k + 1);
        for row in bottom {
            let f = row[k] / pivot;
            for (v, p) in row[k..].iter_mut().zip(&top[k][k..]) {
                *v -= f * p;
            }
        }
    }
    det.abs() <= 1e-10 * scale
}
