//! The one-question calculus: differential equations in closed form, and integrals from a table
//! written without the rules.

mod dsolve;
mod review_integrals;
