//! Values for the other names: put in first (so that they decide the damping case), and,
//! when no method then applies, put in after a solution with the names kept symbolic (an
//! integral such as `∫ dv/(g - k v²)` may have a closed form in the letters and not in the
//! numbers); that solution is verified again with the values.

use super::conditions::Condition;
use super::parse::Ode;
use super::solve::{DsolveError, OdeSolution};
use super::verify::verify;
use crate::sym::Sym;

fn put_in(s: &Sym, values: &[(String, Sym)]) -> Sym {
    values
        .iter()
        .fold(s.clone(), |s, (k, v)| s.substitute(k, v))
}

impl Ode {
    /// Solves the equation with `values` for some of its names (and in the conditions).
    ///
    /// ```
    /// use mechkit_expr::Sym;
    /// use mechkit_expr::sym::dsolve::{Condition, Ode};
    /// let ode = Ode::parse("v' = g - k*v^2", "v", "t").unwrap();
    /// let ic = Condition::parse_list("v(0)=0", "v").unwrap();
    /// let values = [("g".to_string(), Sym::int(4)), ("k".to_string(), Sym::int(1))];
    /// let s = ode.solve_with_values(&values, &ic).unwrap();
    /// let v = s.solution.eval(&|n| (n == "t").then_some(1.0)).unwrap();
    /// assert!((v - 2.0 * (2.0_f64).tanh()).abs() < 1e-12);
    /// ```
    pub fn solve_with_values(
        &self,
        values: &[(String, Sym)],
        conditions: &[Condition],
    ) -> Result<OdeSolution, DsolveError> {
        let valued = self.with_values(values);
        let valued_conditions: Vec<Condition> = conditions
            .iter()
            .map(|c| Condition {
                order: c.order,
                at: put_in(&c.at, values),
                value: put_in(&c.value, values),
            })
            .collect();
        let first = valued.solve(&valued_conditions);
        let Err(DsolveError::NoMethod { .. }) = &first else {
            return first;
        };
        if values.is_empty() {
            return first;
        }
        let Ok(symbolic) = self.solve(conditions) else {
            return first;
        };
        let solution = put_in(&symbolic.solution, values);
        let Some((verification, note)) = verify(&valued, &solution, &valued_conditions, &[]) else {
            return first;
        };
        let given: Vec<&str> = values.iter().map(|(k, _)| k.as_str()).collect();
        Ok(OdeSolution {
            solution,
            method: format!(
                "{} (solved with {} symbolic, then the values put in)",
                symbolic.method,
                given.join(", ")
            ),
            constants: symbolic.constants,
            determined: symbolic
                .determined
                .into_iter()
                .map(|(c, v)| (c, put_in(&v, values)))
                .collect(),
            assumptions: symbolic.assumptions.into_iter().chain(note).collect(),
            verification,
        })
    }
}
