//! Symbolic expressions in a canonical form, for algebra: simplification, derivatives,
//! antiderivatives, equation solving.
//!
//! A [`Sym`] is always kept canonical by its constructors ([`Sym::sum`], [`Sym::product`],
//! [`Sym::pow`], [`Sym::call`]), after Cohen's "automatic simplification" (*Computer Algebra and
//! Symbolic Computation*, 2003): sums and products are flattened and sorted, numbers are
//! folded exactly (rationals stay rationals), like terms are collected (`x + x → 2*x`), equal
//! bases are merged (`x*x → x^2`, `x^a*x^b → x^(a+b)`), `0` and `1` vanish, a number
//! multiplying a sum is distributed, `sqrt(u)` is `u^(1/2)`, and `sin(u)^2 + cos(u)^2 → 1` inside
//! sums. Conversion to an [`Expr`] prints it readably: `-2*pi*F0*cos(2*pi*x/b)/b`.

pub(crate) mod build;
mod closed_form;
mod convert;
mod cubic;
mod diff;
pub mod dsolve;
mod eval;
mod expand;
mod identities;
mod integrate;
mod order;
pub mod poly;
mod quartic;
mod real_roots;
mod solve;
mod solve_higher;

pub use closed_form::quadratic_roots;
pub use integrate::Antiderivative;
pub use real_roots::{MAX_NUMERIC_DEGREE, RealRoots, real_roots};
pub use solve::{Solutions, Solved, solve_linear};

use crate::ast::{BinOp, Expr, Func};
use crate::number::Number;

/// A canonical symbolic expression.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Sym {
    /// A number.
    Num(Number),
    /// A name (`x`, `F0`, also `pi` and `e`, kept exact).
    Var(String),
    /// A sum of two or more terms.
    Add(Vec<Sym>),
    /// A product of two or more factors, the number first.
    Mul(Vec<Sym>),
    /// `base^exponent`.
    Pow(Box<Sym>, Box<Sym>),
    /// A function call (never `sqrt` or `log`: those are `u^(1/2)` and `ln`).
    Call(Func, Vec<Sym>),
    /// A comparison (1 or 0).
    Cmp(BinOp, Box<Sym>, Box<Sym>),
    /// `a and b`.
    And(Box<Sym>, Box<Sym>),
    /// `a or b`.
    Or(Box<Sym>, Box<Sym>),
    /// `not a`.
    Not(Box<Sym>),
}

impl Sym {
    /// The number `n`.
    pub fn int(n: i64) -> Sym {
        Sym::Num(Number::int(n))
    }

    /// The rational `n/d`.
    pub fn rational(n: i64, d: i64) -> Sym {
        Sym::Num(Number::rational(i128::from(n), i128::from(d)))
    }

    /// The name `name`.
    pub fn var(name: &str) -> Sym {
        Sym::Var(name.to_string())
    }

    /// Zero.
    pub fn zero() -> Sym {
        Sym::Num(Number::ZERO)
    }

    /// One.
    pub fn one() -> Sym {
        Sym::Num(Number::ONE)
    }

    /// The number, if this is one.
    pub fn as_num(&self) -> Option<Number> {
        match self {
            Sym::Num(n) => Some(*n),
            _ => None,
        }
    }

    /// Whether this is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.as_num().is_some_and(Number::is_zero)
    }

    /// Whether this is exactly one.
    pub fn is_one(&self) -> bool {
        self.as_num().is_some_and(Number::is_one)
    }

    /// Whether `name` does not occur.
    pub fn free_of(&self, name: &str) -> bool {
        match self {
            Sym::Num(_) => true,
            Sym::Var(v) => v != name,
            Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => xs.iter().all(|x| x.free_of(name)),
            Sym::Pow(a, b) | Sym::Cmp(_, a, b) | Sym::And(a, b) | Sym::Or(a, b) => {
                a.free_of(name) && b.free_of(name)
            }
            Sym::Not(a) => a.free_of(name),
        }
    }

    /// Every name that occurs, sorted, without `pi` and `e`.
    pub fn names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_names(&mut out);
        out.sort();
        out.dedup();
        out.retain(|n| n != "pi" && n != "e");
        out
    }

    fn collect_names(&self, out: &mut Vec<String>) {
        match self {
            Sym::Num(_) => {}
            Sym::Var(v) => out.push(v.clone()),
            Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => {
                for x in xs {
                    x.collect_names(out);
                }
            }
            Sym::Pow(a, b) | Sym::Cmp(_, a, b) | Sym::And(a, b) | Sym::Or(a, b) => {
                a.collect_names(out);
                b.collect_names(out);
            }
            Sym::Not(a) => a.collect_names(out),
        }
    }

    /// Replaces every occurrence of the sub-expression `from` by `to`, re-simplifying.
    #[must_use]
    pub fn replace(&self, from: &Sym, to: &Sym) -> Sym {
        if self == from {
            return to.clone();
        }
        self.map_children(|c| c.replace(from, to))
    }

    /// Replaces the name `name` by `with`.
    #[must_use]
    pub fn substitute(&self, name: &str, with: &Sym) -> Sym {
        self.replace(&Sym::var(name), with)
    }

    /// Rebuilds this node with `f` applied to each child, through the simplifying
    /// constructors.
    #[must_use]
    pub fn map_children(&self, f: impl Fn(&Sym) -> Sym) -> Sym {
        match self {
            Sym::Num(_) | Sym::Var(_) => self.clone(),
            Sym::Add(xs) => Sym::sum(xs.iter().map(&f).collect()),
            Sym::Mul(xs) => Sym::product(xs.iter().map(&f).collect()),
            Sym::Pow(a, b) => Sym::pow(f(a), f(b)),
            Sym::Call(func, xs) => Sym::call(*func, xs.iter().map(&f).collect()),
            Sym::Cmp(op, a, b) => Sym::cmp(*op, f(a), f(b)),
            Sym::And(a, b) => Sym::logic(BinOp::And, f(a), f(b)),
            Sym::Or(a, b) => Sym::logic(BinOp::Or, f(a), f(b)),
            Sym::Not(a) => Sym::negation(f(a)),
        }
    }

    /// Whether this node or any node below it satisfies `pred` (depth first, stopping at the
    /// first).
    pub fn any(&self, pred: &mut dyn FnMut(&Sym) -> bool) -> bool {
        if pred(self) {
            return true;
        }
        match self {
            Sym::Num(_) | Sym::Var(_) => false,
            Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => xs.iter().any(|c| c.any(pred)),
            Sym::Pow(a, b) | Sym::Cmp(_, a, b) | Sym::And(a, b) | Sym::Or(a, b) => {
                a.any(pred) || b.any(pred)
            }
            Sym::Not(a) => a.any(pred),
        }
    }

    /// Parses and canonicalises a formula.
    pub fn parse(text: &str) -> Result<Sym, crate::ExprError> {
        Ok(Sym::from_expr(&crate::parse(text)?.expr))
    }
}

impl std::fmt::Display for Sym {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.to_expr())
    }
}

/// Simplifies an expression to its canonical, readable form.
///
/// # Example
/// ```
/// use mechkit_expr::{parse, simplify};
/// let e = parse("x*x + 2*x - x + 0.5*y/y").unwrap().expr;
/// assert_eq!(simplify(&e).to_string(), "x^2 + x + 1/2");
/// ```
pub fn simplify(e: &Expr) -> Expr {
    Sym::from_expr(e).to_expr()
}
