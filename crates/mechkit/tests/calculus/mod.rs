//! The one-question calculus: differential equations in closed form.

mod dsolve;
