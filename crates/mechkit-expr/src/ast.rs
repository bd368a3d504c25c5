//! The expression tree: what a formula means, independent of how it was written.

use std::fmt;

/// A scalar expression.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A number.
    Num(f64),
    /// A name: a variable (`x`, `feather.v`) or a constant (`g`, `pi`).
    Var(String),
    /// `-a`
    Neg(Box<Expr>),
    /// `not a` (1 when `a` is 0, else 0)
    Not(Box<Expr>),
    /// `a op b`
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `f(a, b, …)`
    Call(Func, Vec<Expr>),
}

/// Binary operators, from loosest to tightest binding: `or`, `and`, comparisons, `+ -`, `* /`,
/// `^`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BinOp {
    /// `a or b`, `a || b`
    Or,
    /// `a and b`, `a && b`
    And,
    /// `a < b`
    Lt,
    /// `a <= b`
    Le,
    /// `a > b`
    Gt,
    /// `a >= b`
    Ge,
    /// `a == b`
    Eq,
    /// `a != b`
    Ne,
    /// `a + b`
    Add,
    /// `a - b`
    Sub,
    /// `a * b`
    Mul,
    /// `a / b`
    Div,
    /// `a ^ b`, `a ** b` (right-associative)
    Pow,
}

impl BinOp {
    /// Binding power: larger binds tighter.
    pub fn precedence(self) -> u8 {
        match self {
            BinOp::Or => 1,
            BinOp::And => 2,
            BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge | BinOp::Eq | BinOp::Ne => 4,
            BinOp::Add | BinOp::Sub => 5,
            BinOp::Mul | BinOp::Div => 6,
            BinOp::Pow => 8,
        }
    }

    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            BinOp::Or => "or",
            BinOp::And => "and",
            BinOp::Lt => "<",
            BinOp::Le => "<=",
            BinOp::Gt => ">",
            BinOp::Ge => ">=",
            BinOp::Eq => "==",
            BinOp::Ne => "!=",
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Pow => "^",
        }
    }

    /// True for `< <= > >= == !=`.
    pub fn is_comparison(self) -> bool {
        matches!(
            self,
            BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge | BinOp::Eq | BinOp::Ne
        )
    }

    /// Applies the operator to two numbers. Comparisons and logic give 1 or 0.
    pub fn apply(self, a: f64, b: f64) -> f64 {
        let truth = |c: bool| if c { 1.0 } else { 0.0 };
        match self {
            BinOp::Or => truth(a != 0.0 || b != 0.0),
            BinOp::And => truth(a != 0.0 && b != 0.0),
            BinOp::Lt => truth(a < b),
            BinOp::Le => truth(a <= b),
            BinOp::Gt => truth(a > b),
            BinOp::Ge => truth(a >= b),
            BinOp::Eq => truth(a == b),
            BinOp::Ne => truth(a != b),
            BinOp::Add => a + b,
            BinOp::Sub => a - b,
            BinOp::Mul => a * b,
            BinOp::Div => a / b,
            BinOp::Pow => pow(a, b),
        }
    }
}

/// `a^b`, using repeated multiplication for small integer exponents (exact for `x^2`).
pub fn pow(a: f64, b: f64) -> f64 {
    if b.fract() == 0.0 && b.abs() <= 64.0 {
        a.powi(b as i32)
    } else {
        a.powf(b)
    }
}

macro_rules! functions {
    ($( $variant:ident = $name:literal, $arity:expr, $doc:literal; )*) => {
        /// Built-in functions.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum Func {
            $( #[doc = $doc] $variant, )*
        }

        impl Func {
            /// Every built-in function.
            pub const ALL: &'static [Func] = &[$( Func::$variant, )*];

            /// The name as written in formulas.
            pub fn name(self) -> &'static str {
                match self { $( Func::$variant => $name, )* }
            }

            /// How many arguments it takes.
            pub fn arity(self) -> Arity {
                match self { $( Func::$variant => $arity, )* }
            }
        }
    };
}

/// How many arguments a function takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arity {
    /// Exactly this many.
    Exactly(usize),
    /// This many or more.
    AtLeast(usize),
}

impl Arity {
    /// Whether `n` arguments are accepted.
    pub fn accepts(self, n: usize) -> bool {
        match self {
            Arity::Exactly(k) => n == k,
            Arity::AtLeast(k) => n >= k,
        }
    }
}

impl fmt::Display for Arity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Arity::Exactly(1) => write!(f, "1 argument"),
            Arity::Exactly(k) => write!(f, "{k} arguments"),
            Arity::AtLeast(k) => write!(f, "{k} or more arguments"),
        }
    }
}

use Arity::{AtLeast, Exactly};

functions! {
    Sin = "sin", Exactly(1), "sine (radians)";
    Cos = "cos", Exactly(1), "cosine (radians)";
    Tan = "tan", Exactly(1), "tangent (radians)";
    Asin = "asin", Exactly(1), "inverse sine";
    Acos = "acos", Exactly(1), "inverse cosine";
    Atan = "atan", Exactly(1), "inverse tangent";
    Atan2 = "atan2", Exactly(2), "`atan2(y, x)`: angle of the point (x, y)";
    Sinh = "sinh", Exactly(1), "hyperbolic sine";
    Cosh = "cosh", Exactly(1), "hyperbolic cosine";
    Tanh = "tanh", Exactly(1), "hyperbolic tangent";
    Exp = "exp", Exactly(1), "exponential";
    Log = "log", Exactly(1), "natural logarithm (as in MATLAB and NumPy)";
    Ln = "ln", Exactly(1), "natural logarithm";
    Log10 = "log10", Exactly(1), "base-10 logarithm";
    Sqrt = "sqrt", Exactly(1), "square root";
    Cbrt = "cbrt", Exactly(1), "cube root";
    Abs = "abs", Exactly(1), "absolute value";
    Sign = "sign", Exactly(1), "sign: -1, 0 or 1";
    Min = "min", AtLeast(2), "smallest argument";
    Max = "max", AtLeast(2), "largest argument";
    Floor = "floor", Exactly(1), "round down";
    Ceil = "ceil", Exactly(1), "round up";
    Heaviside = "heaviside", Exactly(1), "step: 0 for x < 0, 1/2 at 0, 1 for x > 0";
    If = "if", Exactly(3), "`if(cond, a, b)`: a where cond is non-zero, else b";
}

impl Func {
    /// Looks a function up by name.
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.iter().copied().find(|f| f.name() == name)
    }

    /// The reciprocal functions a formula may call, read as `1/f(u)`: `sec(x)` is
    /// `1/cos(x)`.
    pub const RECIPROCALS: &'static [(&'static str, Func)] = &[
        ("sec", Func::Cos),
        ("csc", Func::Sin),
        ("cot", Func::Tan),
        ("sech", Func::Cosh),
        ("csch", Func::Sinh),
        ("coth", Func::Tanh),
    ];

    /// The function whose reciprocal `name` is (`sec` → `cos`), if it is one of
    /// [`Func::RECIPROCALS`].
    pub fn reciprocal_of(name: &str) -> Option<Func> {
        Func::RECIPROCALS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, f)| f)
    }

    /// Applies a one-argument function.
    pub fn apply1(self, x: f64) -> f64 {
        match self {
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Asin => x.asin(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
            Func::Sinh => x.sinh(),
            Func::Cosh => x.cosh(),
            Func::Tanh => x.tanh(),
            Func::Exp => x.exp(),
            Func::Log | Func::Ln => x.ln(),
            Func::Log10 => x.log10(),
            Func::Sqrt => x.sqrt(),
            Func::Cbrt => x.cbrt(),
            Func::Abs => x.abs(),
            Func::Sign => sign(x),
            Func::Floor => x.floor(),
            Func::Ceil => x.ceil(),
            Func::Heaviside => heaviside(x),
            Func::Atan2 | Func::Min | Func::Max | Func::If => {
                panic!("{} does not take one argument", self.name())
            }
        }
    }

    /// Applies a two-argument function (`atan2`, and `min`/`max` of a pair).
    pub fn apply2(self, a: f64, b: f64) -> f64 {
        match self {
            Func::Atan2 => a.atan2(b),
            Func::Min => min(a, b),
            Func::Max => max(a, b),
            _ => panic!("{} does not take two arguments", self.name()),
        }
    }

    /// Applies the function to its arguments; the argument count must fit [`Func::arity`].
    pub fn apply(self, args: &[f64]) -> f64 {
        assert!(
            self.arity().accepts(args.len()),
            "{} takes {}, got {}",
            self.name(),
            self.arity(),
            args.len()
        );
        match self {
            Func::Min => args.iter().copied().reduce(min).unwrap_or(f64::NAN),
            Func::Max => args.iter().copied().reduce(max).unwrap_or(f64::NAN),
            Func::Atan2 => self.apply2(args[0], args[1]),
            Func::If => select(args[0], args[1], args[2]),
            _ => self.apply1(args[0]),
        }
    }
}

/// `if(c, a, b)`.
pub fn select(c: f64, a: f64, b: f64) -> f64 {
    if c == 0.0 { b } else { a }
}

/// -1, 0 or 1 (NaN stays NaN).
pub fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x // 0, -0 or NaN
    }
}

/// 0 for x < 0, 1/2 at 0, 1 for x > 0 (NaN stays NaN).
pub fn heaviside(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        0.0
    } else if x == 0.0 {
        0.5
    } else {
        x
    }
}

/// The smaller; NaN if either is NaN (a NaN must not be hidden in physics).
pub fn min(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}

/// The larger; NaN if either is NaN.
pub fn max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

impl Expr {
    /// Shorthand for a binary node.
    pub fn binary(op: BinOp, lhs: Expr, rhs: Expr) -> Expr {
        Expr::Binary(op, Box::new(lhs), Box::new(rhs))
    }

    /// Visits every name in the expression, in reading order.
    pub fn for_each_var<'a>(&'a self, f: &mut impl FnMut(&'a str)) {
        match self {
            Expr::Num(_) => {}
            Expr::Var(name) => f(name),
            Expr::Neg(a) | Expr::Not(a) => a.for_each_var(f),
            Expr::Binary(_, a, b) => {
                a.for_each_var(f);
                b.for_each_var(f);
            }
            Expr::Call(_, args) => args.iter().for_each(|a| a.for_each_var(f)),
        }
    }

    /// Whether the expression mentions `name`.
    pub fn mentions(&self, name: &str) -> bool {
        let mut found = false;
        self.for_each_var(&mut |n| found |= n == name);
        found
    }

    /// Evaluates by walking the tree, looking names up with `env`. For one-off evaluations
    /// (constants, checks); compile to a [`crate::Program`] for hot loops.
    ///
    /// Returns the first name that `env` does not know as the error.
    pub fn eval_with(&self, env: &dyn Fn(&str) -> Option<f64>) -> Result<f64, String> {
        Ok(match self {
            Expr::Num(x) => *x,
            Expr::Var(name) => env(name).ok_or_else(|| name.clone())?,
            Expr::Neg(a) => -a.eval_with(env)?,
            Expr::Not(a) => {
                if a.eval_with(env)? == 0.0 {
                    1.0
                } else {
                    0.0
                }
            }
            Expr::Binary(op, a, b) => op.apply(a.eval_with(env)?, b.eval_with(env)?),
            Expr::Call(func, args) => {
                let values = args
                    .iter()
                    .map(|a| a.eval_with(env))
                    .collect::<Result<Vec<_>, _>>()?;
                func.apply(&values)
            }
        })
    }
}

/// Printing binding powers: unary minus sits between `* /` and `^` (so `-x^2` is `-(x^2)`).
const PREC_NEG: u8 = 7;
const PREC_NOT: u8 = 3;
const PREC_ATOM: u8 = 10;

impl Expr {
    fn precedence(&self) -> u8 {
        match self {
            Expr::Num(x) if *x < 0.0 => PREC_NEG,
            Expr::Num(_) | Expr::Var(_) | Expr::Call(..) => PREC_ATOM,
            Expr::Neg(_) => PREC_NEG,
            Expr::Not(_) => PREC_NOT,
            Expr::Binary(op, ..) => op.precedence(),
        }
    }

    fn fmt_child(&self, f: &mut fmt::Formatter<'_>, needs_parens: bool) -> fmt::Result {
        if needs_parens {
            write!(f, "({self})")
        } else {
            write!(f, "{self}")
        }
    }
}

impl fmt::Display for Expr {
    /// Prints with the fewest parentheses that re-parse to the same tree.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Expr::Num(x) => write!(f, "{}", format_number(*x)),
            Expr::Var(name) => write!(f, "{name}"),
            Expr::Neg(a) => {
                write!(f, "-")?;
                // `--x` would lex fine but reads badly; `-(-x)` is clearer.
                let parens = a.precedence() <= PREC_NEG;
                a.fmt_child(f, parens)
            }
            Expr::Not(a) => {
                write!(f, "not ")?;
                a.fmt_child(f, a.precedence() < PREC_NOT)
            }
            Expr::Binary(op, a, b) => {
                let p = op.precedence();
                let (left_parens, right_parens) = if *op == BinOp::Pow {
                    // right-associative: a^b^c = a^(b^c); a negative base needs parentheses.
                    (
                        a.precedence() <= p,
                        b.precedence() < p && !matches!(**b, Expr::Neg(_)),
                    )
                } else if op.is_comparison() {
                    // comparisons do not chain
                    (a.precedence() <= p, b.precedence() <= p)
                } else {
                    (a.precedence() < p, b.precedence() <= p)
                };
                a.fmt_child(f, left_parens)?;
                match op {
                    BinOp::Pow => write!(f, "^")?,
                    BinOp::Mul | BinOp::Div => write!(f, "{}", op.symbol())?,
                    _ => write!(f, " {} ", op.symbol())?,
                }
                b.fmt_child(f, right_parens)
            }
            Expr::Call(func, args) => {
                write!(f, "{}(", func.name())?;
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{a}")?;
                }
                write!(f, ")")
            }
        }
    }
}

/// Shortest text that reads back as the same `f64`; non-finite values as `inf`/`nan` names.
pub fn format_number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        let plain = format!("{x}");
        let sci = format!("{x:e}");
        if sci.len() < plain.len() { sci } else { plain }
    }
}
