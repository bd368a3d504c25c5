//! A formula with values for its parameters, evaluated as a function of one or more variables:
//! what the one-question tools (potentials, line integrals, quadrature rules) evaluate.

use mechkit_expr::{Sym, builtin_constant, parse};

use crate::Real;
use crate::calculus::{CalculusError, Params};

/// `f(vars…)`: a canonical symbolic formula with every other name given a value.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    sym: Sym,
    vars: Vec<String>,
    params: Vec<(String, Real)>,
}

impl Function {
    /// Parses `text` as a function of `vars`, with `params` for the other names. Every name
    /// must be a variable, a parameter or a built-in constant (`pi`, `e`); the error lists the
    /// missing ones and how to give them.
    pub fn parse(text: &str, vars: &[&str], params: &Params) -> Result<Self, CalculusError> {
        let sym = Sym::from_expr(&parse(text)?.expr);
        Self::new(sym, vars, params)
    }

    /// As [`Function::parse`], from a symbolic expression.
    pub fn new(sym: Sym, vars: &[&str], params: &Params) -> Result<Self, CalculusError> {
        let missing: Vec<String> = sym
            .names()
            .into_iter()
            .filter(|n| {
                !vars.contains(&n.as_str())
                    && !params.iter().any(|(k, _)| k == n)
                    && builtin_constant(n).is_none()
            })
            .collect();
        if let Some(first) = missing.first() {
            return Err(CalculusError::Invalid(format!(
                "`{sym}` needs values for {}: give them with --set, e.g. --set {first}=1 \
                 (the variable is {})",
                missing.join(", "),
                vars.join(", ")
            )));
        }
        Ok(Self {
            sym,
            vars: vars.iter().map(|v| (*v).to_string()).collect(),
            params: params.to_vec(),
        })
    }

    /// The formula.
    pub fn sym(&self) -> &Sym {
        &self.sym
    }

    /// The variables, in argument order.
    pub fn vars(&self) -> &[String] {
        &self.vars
    }

    /// The parameter values.
    pub fn params(&self) -> &[(String, Real)] {
        &self.params
    }

    /// Another formula of the same variables and parameters (a derivative, an antiderivative).
    #[must_use]
    pub fn with_sym(&self, sym: Sym) -> Self {
        Self {
            sym,
            vars: self.vars.clone(),
            params: self.params.clone(),
        }
    }

    /// `d/d(var)`, symbolically.
    #[must_use]
    pub fn diff(&self, var: &str) -> Self {
        self.with_sym(self.sym.diff(var))
    }

    /// The value at `args` (one per variable); NaN where the formula is undefined.
    pub fn at(&self, args: &[Real]) -> Real {
        debug_assert_eq!(args.len(), self.vars.len());
        let env = |n: &str| {
            self.vars
                .iter()
                .position(|v| v == n)
                .map(|i| args[i])
                .or_else(|| self.params.iter().find(|(k, _)| k == n).map(|(_, v)| *v))
        };
        self.sym.eval(&env).unwrap_or(Real::NAN)
    }

    /// The value at `x`, for a function of one variable.
    pub fn at1(&self, x: Real) -> Real {
        self.at(&[x])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_and_missing_names() {
        let f = Function::parse("a*x^2 + pi", &["x"], &[("a".into(), 2.0)]).unwrap();
        assert!((f.at1(3.0) - (18.0 + std::f64::consts::PI)).abs() < 1e-14);
        assert!((f.diff("x").at1(3.0) - 12.0).abs() < 1e-14);
        let e = Function::parse("a*x + b", &["x"], &[]).unwrap_err();
        assert!(e.to_string().contains("a, b"), "{e}");
        assert!(
            Function::parse("ln(x)", &["x"], &[])
                .unwrap()
                .at1(-1.0)
                .is_nan()
        );
    }
}
