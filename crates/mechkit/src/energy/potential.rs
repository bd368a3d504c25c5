//! A one-dimensional potential and its force, `F = -dU/dx`, from whichever the user knows.
//!
//! Given `U(x)`, the force is its symbolic derivative. Given `F(x)`, the potential is
//! `U = -∫F dx` from the rule table when it has an antiderivative (verified by differentiation),
//! otherwise by adaptive quadrature from a reference point where `U = 0`. Either way `F'(x)` is
//! symbolic, so the stability of an equilibrium (`U'' = -F'`) never rests on a finite difference.

use mechkit_expr::Sym;

use crate::Real;
use crate::calculus::{CalculusError, Params};
use crate::function::Function;
use crate::quad::{Tolerance, integrate};

/// How the potential was obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Origin {
    /// Given as `U(x)`.
    Given,
    /// `U = -∫F dx` in closed form.
    Symbolic,
    /// `U(x) = -∫_{x_ref}^x F dx'` by quadrature (no closed form found).
    Numeric {
        /// Where `U = 0`.
        reference: Real,
    },
}

/// `U(x)` and `F(x) = -U'(x)` of a conservative force in one dimension.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::struct_field_names)] // `potential` is U, `force` is F: the physics' names
pub struct Potential {
    var: String,
    potential: Option<Function>,
    force: Function,
    force_slope: Function,
    origin: Origin,
}

impl Potential {
    /// From a potential `U(x)` typed as a formula of `var`, with `params` for the other names.
    ///
    /// ```
    /// use mechkit::energy::Potential;
    /// let p = Potential::from_potential("U0*((a/r)^12 - (b/r)^6)", "r",
    ///     &[("U0".into(), 1.0), ("a".into(), 1.0), ("b".into(), 1.0)]).unwrap();
    /// assert_eq!(p.force_formula().to_string(), "U0*(12*a^12/r^13 - 6*b^6/r^7)");
    /// assert!(p.force(2f64.powf(1.0 / 6.0)).abs() < 1e-14);
    /// ```
    pub fn from_potential(text: &str, var: &str, params: &Params) -> Result<Self, CalculusError> {
        let u = Function::parse(text, &[var], params)?;
        let force = u.with_sym(Sym::negate(u.sym().diff(var)));
        let force_slope = force.diff(var);
        Ok(Self {
            var: var.to_string(),
            potential: Some(u),
            force,
            force_slope,
            origin: Origin::Given,
        })
    }

    /// From a force `F(x)`: `U = -∫F dx` in closed form when the rule table has it, else by
    /// quadrature with `U(reference) = 0`.
    pub fn from_force(
        text: &str,
        var: &str,
        params: &Params,
        reference: Real,
    ) -> Result<Self, CalculusError> {
        let force = Function::parse(text, &[var], params)?;
        let force_slope = force.diff(var);
        let (potential, origin) = match force.sym().integrate(var) {
            Some(anti) => (
                Some(force.with_sym(Sym::negate(anti.result))),
                Origin::Symbolic,
            ),
            None => (None, Origin::Numeric { reference }),
        };
        Ok(Self {
            var: var.to_string(),
            potential,
            force,
            force_slope,
            origin,
        })
    }

    /// The variable's name.
    pub fn var(&self) -> &str {
        &self.var
    }

    /// How `U` was obtained.
    pub fn origin(&self) -> Origin {
        self.origin
    }

    /// `U(x)` as a formula, when there is a closed form.
    pub fn potential_formula(&self) -> Option<&Sym> {
        self.potential.as_ref().map(Function::sym)
    }

    /// `F(x) = -dU/dx` as a formula.
    pub fn force_formula(&self) -> &Sym {
        self.force.sym()
    }

    /// `U''(x) = -F'(x)` as a formula.
    pub fn curvature_formula(&self) -> Sym {
        Sym::negate(self.force_slope.sym().clone())
    }

    /// `F(x)`; NaN where undefined.
    pub fn force(&self, x: Real) -> Real {
        self.force.at1(x)
    }

    /// `U''(x)`.
    pub fn curvature(&self, x: Real) -> Real {
        -self.force_slope.at1(x)
    }

    /// `U(x)`; NaN where undefined (or where the quadrature of `F` fails).
    pub fn potential(&self, x: Real) -> Real {
        match (&self.potential, self.origin) {
            (Some(u), _) => u.at1(x),
            (None, Origin::Numeric { reference }) => self.potential_between(reference, x, 0.0),
            (None, _) => Real::NAN,
        }
    }

    /// `U(b)` given `U(a) = u_a`: by the closed form, or by quadrature of `F` from `a`.
    pub fn potential_between(&self, a: Real, b: Real, u_a: Real) -> Real {
        if let Some(u) = &self.potential {
            return u.at1(b);
        }
        let tol = Tolerance {
            abs: 1e-13,
            rel: 1e-12,
        };
        if let Ok(r) = integrate(|x| self.force(x), a, b, tol) {
            u_a - r.value
        } else {
            #[cfg(test)]
            tests::FAILED.with(|n| n.set(n.get() + 1));
            Real::NAN
        }
    }

    /// `U` at every point of the ascending grid `xs`: by the closed form, or by quadrature of
    /// `F` between neighbours (accumulated from the first point, where `U` is taken from the
    /// reference).
    pub fn potential_on(&self, xs: &[Real]) -> Vec<Real> {
        if let Some(u) = &self.potential {
            return xs.iter().map(|&x| u.at1(x)).collect();
        }
        let mut out = Vec::with_capacity(xs.len());
        let Some(&first) = xs.first() else {
            return out;
        };
        let reference = match self.origin {
            Origin::Numeric { reference } => reference,
            _ => Real::NAN,
        };
        // the last point the quadrature from the reference could not reach: a point not
        // integrable lies between the two, and between the reference and every point beyond
        let mut unreachable_from: Option<Real> = None;
        let mut u = self.potential(first);
        if !u.is_finite() {
            unreachable_from = Some(first);
        }
        out.push(u);
        for w in xs.windows(2) {
            if u.is_finite() {
                u = self.potential_between(w[0], w[1], u);
            } else if unreachable_from.is_some_and(|x| reference <= x) {
                // past a point the reference cannot reach, on its far side: so is this one
                // (a failing quadrature costs its whole subdivision budget)
                u = Real::NAN;
            } else {
                // restart past a singular point: the reference is lost, so the curve is
                // continued from the integral of F from the reference where possible
                u = self.potential(w[1]);
                if !u.is_finite() {
                    unreachable_from = Some(w[1]);
                }
            }
            out.push(u);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use super::*;

    thread_local! {
        /// Quadratures of `F` that failed on this thread (each spends its whole budget).
        pub static FAILED: Cell<u32> = const { Cell::new(0) };
    }

    /// Found by the `command_line` target (2026-12-05): `mechkit potential --force
    /// "-sin(2*pi/x)" --range=-1:2 …` took 25 s. Past x = 0, where the quadrature of `F`
    /// cannot converge, every grid point and every equilibrium (hundreds, where `F` oscillates)
    /// retried the quadrature from the reference across 0, each to its subdivision limit. A
    /// point the reference cannot reach now marks the far side unreachable (0.08 s).
    #[test]
    fn fuzz_a_point_the_reference_cannot_reach_is_tried_once() {
        let p = Potential::from_force("-sin(2*pi/x)", "x", &[], -1.0).unwrap();
        FAILED.with(|n| n.set(0));
        let d = p.diagram(-1.0, 2.0, None, 2000);
        let failed = FAILED.with(Cell::get);
        assert!(failed <= 3, "{failed} failed quadratures");
        // left of 0 the potential is known, right of it not
        assert!(d.potential[..600].iter().all(|u| u.is_finite()));
        assert!(
            d.potential[d.potential.len() - 100..]
                .iter()
                .all(|u| u.is_nan())
        );
    }

    #[test]
    fn force_from_potential_and_back() {
        let p = Potential::from_force(
            "-F0*sin(2*pi*x/b)",
            "x",
            &crate::calculus::parse_params("F0=1,b=1").unwrap(),
            0.0,
        )
        .unwrap();
        assert_eq!(p.origin(), Origin::Symbolic);
        let u = |x: Real| {
            -(1.0 / (2.0 * std::f64::consts::PI)) * (2.0 * std::f64::consts::PI * x).cos()
        };
        for x in [0.0, 0.1, 0.37, 0.5] {
            assert!((p.potential(x) - u(x)).abs() < 1e-14);
        }
        assert!((p.curvature(0.0) - 2.0 * std::f64::consts::PI).abs() < 1e-12);
    }

    #[test]
    fn numeric_potential_when_there_is_no_closed_form() {
        // F = -x*exp(-x^4): no rule of the table integrates it
        let p = Potential::from_force("-x*exp(-x^4)", "x", &[], 0.0).unwrap();
        assert!(matches!(p.origin(), Origin::Numeric { .. }));
        let xs: Vec<Real> = (0..=20).map(|i| f64::from(i) * 0.1).collect();
        let grid = p.potential_on(&xs);
        for (&x, &u) in xs.iter().zip(&grid) {
            let direct = p.potential(x);
            assert!((u - direct).abs() < 1e-12, "{x}: {u} vs {direct}");
        }
        // U(x) = ∫0^x s e^{-s^4} ds, increasing
        assert!(grid.windows(2).all(|w| w[1] > w[0]));
    }
}
