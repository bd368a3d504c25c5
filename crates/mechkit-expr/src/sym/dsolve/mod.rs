//! Ordinary differential equations in closed form: `x' = f(t, x)` of first order, linear
//! equations with constant coefficients up to order 4, and Euler–Cauchy equations.
//!
//! An equation is written with primes, `m*x'' + c*x' + k*x = F0*cos(w*t)`; [`Ode::parse`]
//! reads it (the derivatives become the placeholder names `__x_d1`, `__x_d2` inside). The
//! methods, tried in this order:
//!
//! - **constant coefficients**: `a2 x'' + a1 x' + a0 x = g(t)`. The roots of
//!   `a2 r² + a1 r + a0` give the homogeneous solution: two real roots (over-damped),
//!   a double root (critically damped), or `α ± iβ` (under-damped,
//!   `e^{αt}(C1 cos βt + C2 sin βt)`). With symbolic coefficients the case is assumed and the
//!   assumption recorded (`k/m > 0`). At order 3 and 4 (numeric coefficients) the rational
//!   roots are divided out and the rest solved in closed form (`characteristic`). A forcing
//!   that is a sum of `t^k e^{at} cos(bt)`, `… sin(bt)` terms gets a particular solution by
//!   undetermined coefficients, multiplied by `t^s` when `a + ib` is a root of multiplicity
//!   `s` (resonance); any other forcing by variation of parameters (order 2) or an
//!   integrating factor (order 1).
//! - **Euler–Cauchy**: `c2 t² x'' + c1 t x' + c0 x = g(t)`, constant coefficients in `s = ln t`.
//! - **linear first order**: `x' + P(t) x = Q(t)`, `x = (∫ Q μ dt + C)/μ`, `μ = e^{∫P}`.
//! - **separable**: `x' = g(t) h(x)` (a product, or a sum that factors), `∫ dx/h = ∫ g dt + C`,
//!   solved for `x` when the left side can be inverted (powers, `ln`, `exp`, trigonometric
//!   functions, a quotient of linear functions).
//! - **Bernoulli**: `x' + P x = Q x^n`, linear in `v = x^{1-n}`.
//!
//! Values for the other names are put in first; when no method then applies, after a
//! solution in the letters ([`Ode::solve_with_values`]).
//!
//! Every solution is substituted back into the equation: the residual must simplify to 0,
//! or else vanish numerically at many points (relative 1e-8), or, for a solution that holds
//! only on an interval, on the stretch around the conditions' point; the conditions are
//! checked the same way. A solution that fails is never returned.

mod characteristic;
mod conditions;
mod constant;
mod euler;
mod first_order;
mod forcing;
mod invert;
mod parse;
mod solve;
mod values;
mod verify;

pub use conditions::Condition;
pub use parse::{Ode, derivative_name};
pub use solve::{DsolveError, OdeSolution, Verification};

#[cfg(test)]
mod tests;
