//! # mechkit-expr: formulas and units for mechkit
//!
//! The analytical half of mechkit: users type forces, potentials and conditions as formulas,
//! with values that carry units. This crate parses them, checks their names and dimensions
//! with errors that point at the offending column, and compiles them to flat programs that
//! evaluate without allocating, for the hot loop of a simulation.
//!
//! It knows nothing of physics: names are bound by the caller through a [`Scope`].
//!
//! ```
//! use mechkit_expr::{Formula, MapScope};
//! use mechkit_expr::units::{Dimension, Quantity};
//!
//! let g = Quantity::parse("9.8 m/s^2").unwrap();
//! assert_eq!(g.dim, Dimension::ACCELERATION);
//!
//! let force = Formula::parse("-m*g - b*v").unwrap();
//! let scope = MapScope::new()
//!     .constant("m", 2.0).constant("g", g.value).constant("b", 0.5)
//!     .slot("v", 0);
//! let program = force.compile(&scope).unwrap();
//! assert_eq!(program.eval(&[-4.0]), -2.0 * 9.8 + 2.0);
//! ```
//!
//! ## Modules
//! - [`Formula`]: parsed text with name locations; [`Formula::compile`] to a [`Program`].
//! - [`ast`]: the expression tree, operators and built-in functions.
//! - [`units`]: dimensions, the unit table, [`units::Quantity`] parsing.
//! - [`Dim`]: dimensional analysis of formulas.
//! - [`interval`]: [`Interval`] and [`Jet`], guaranteed bounds of a [`Program`] and of its
//!   derivative over a box ([`Program::eval_interval`], [`Program::eval_jet`]).
//!
//! The language: numbers (`1e-9`), names (dotted: `feather.vx`), `+ - * / ^` (also `**`),
//! unary minus, parentheses, comparisons `< <= > >= == !=`, `and or not` (also `&& || !`),
//! `if(c, a, b)`, and the functions listed in [`ast::Func`]. Constants `pi` and `e` are built
//! in (a scope may redefine them).

pub mod ast;
mod compile;
mod dims;
mod error;
mod formula;
pub mod interval;
mod lexer;
mod number;
mod parser;
mod scope;
mod short;
pub mod span;
mod suggest;
pub mod sym;
pub mod units;

pub use ast::{BinOp, Expr, Func};
pub use compile::{Kernel, KernelBuilder, Program, Val, native_code};
pub use dims::Dim;
pub use error::{ExprError, ExprErrorKind};
pub use formula::Formula;
pub use interval::{Interval, Jet};
pub use number::Number;
pub use parser::{MAX_DEPTH, Parsed, parse};
pub use scope::{BUILTIN_CONSTANTS, Binding, MapScope, Scope, builtin_constant};
pub use short::{short_fixed, short_number};
pub use span::Span;
pub use suggest::{did_you_mean, edit_distance, nearest};
pub use sym::{Sym, simplify};
