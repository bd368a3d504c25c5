//! Dimensional analysis of formulas: the dimension of `-m*g*Dmg*v*abs(v)` given the dimensions
//! of its names, and an error when a formula adds metres to seconds.

use std::fmt;

use crate::ast::{BinOp, Expr, Func};
use crate::error::{ExprError, ExprErrorKind};
use crate::formula::Formula;
use crate::scope::builtin_constant;
use crate::units::{Dimension, MAX_WRITTEN_DENOMINATOR, Ratio, UnitSystem};

/// The dimension of a (sub)formula, as far as it is known.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dim {
    /// Known exactly.
    Known(Dimension),
    /// A number written in the formula. It takes the dimension of what it is added to or
    /// compared with (`x - 1`, `max(0, F)`); as a factor its unit is unknowable (`0.5*v` may be
    /// a drag force with b = 0.5 kg/s), so a product with a literal is [`Dim::Unknown`].
    Literal,
    /// Not known: a value given without units, whose dimension the user did not state.
    Unknown,
}

impl Dim {
    /// Dimensionless.
    pub const NONE: Dim = Dim::Known(Dimension::NONE);

    /// The known dimension, if any.
    pub fn known(self) -> Option<Dimension> {
        match self {
            Dim::Known(d) => Some(d),
            _ => None,
        }
    }

    /// Whether a value of this dimension may stand where `want` is required.
    pub fn fits(self, want: Dimension) -> bool {
        match self {
            Dim::Known(d) => d == want,
            Dim::Literal | Dim::Unknown => true,
        }
    }
}

impl fmt::Display for Dim {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Dim::Known(d) => write!(f, "{}", d.describe()),
            Dim::Literal => write!(f, "a plain number"),
            Dim::Unknown => write!(f, "unknown (given without units)"),
        }
    }
}

impl Formula {
    /// The dimension of the formula, given the dimension of each name (`pi` and `e` are
    /// dimensionless). Fails where the formula combines dimensions that do not fit.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{Dim, Formula, units::Dimension};
    /// let f = Formula::parse("-m*g*Dmg*v*abs(v)").unwrap();
    /// let dims = |n: &str| match n {
    ///     "m" => Dim::Known(Dimension::MASS),
    ///     "g" => Dim::Known(Dimension::ACCELERATION),
    ///     "Dmg" => Dim::Known(Dimension::VELOCITY.powi(-2)),
    ///     "v" => Dim::Known(Dimension::VELOCITY),
    ///     _ => Dim::Unknown,
    /// };
    /// assert_eq!(f.dimension(&dims).unwrap(), Dim::Known(Dimension::FORCE));
    /// assert!(Formula::parse("m + v").unwrap().dimension(&dims).is_err());
    /// ```
    pub fn dimension(&self, dims: &dyn Fn(&str) -> Dim) -> Result<Dim, ExprError> {
        self.dimension_with(dims, &|_| None)
    }

    /// As [`Formula::dimension`], with the values of the names that have fixed values, so
    /// that an exponent may be a named constant (`x^n` with `n = 3`).
    pub fn dimension_with(
        &self,
        dims: &dyn Fn(&str) -> Dim,
        values: &dyn Fn(&str) -> Option<f64>,
    ) -> Result<Dim, ExprError> {
        infer(self.expr(), &Env { dims, values }).map_err(|f| {
            self.error(
                ExprErrorKind::Dimension {
                    message: f.message,
                    hint: f.hint,
                },
                self.full_span(),
            )
        })
    }

    /// [`Formula::expect_dimension`] in a unit system: in SI the same; in reduced units, where
    /// every quantity is a pure number, only that the formula is consistent in itself (a force
    /// `sin(t)` is then as valid as `-x`).
    pub fn expect_dimension_in(
        &self,
        units: UnitSystem,
        want: Dimension,
        what: &str,
        dims: &dyn Fn(&str) -> Dim,
        values: &dyn Fn(&str) -> Option<f64>,
    ) -> Result<(), ExprError> {
        match units {
            UnitSystem::Si => self.expect_dimension(want, what, dims, values),
            UnitSystem::Reduced => self.dimension_with(dims, values).map(|_| ()),
        }
    }

    /// Checks that the formula has dimension `want`; the error says what it has instead.
    pub fn expect_dimension(
        &self,
        want: Dimension,
        what: &str,
        dims: &dyn Fn(&str) -> Dim,
        values: &dyn Fn(&str) -> Option<f64>,
    ) -> Result<(), ExprError> {
        let got = self.dimension_with(dims, values)?;
        if got.fits(want) {
            Ok(())
        } else {
            Err(self.error(
                ExprErrorKind::Dimension {
                    message: format!(
                        "{what} must have dimension {}, but this formula has {got}",
                        want.describe()
                    ),
                    hint: Some(format!(
                        "check the units of the names the formula uses: {what} is in {}",
                        want.describe()
                    )),
                },
                self.full_span(),
            ))
        }
    }
}

/// Why a formula's dimensions do not fit, and what would fix it.
struct Failure {
    message: String,
    hint: Option<String>,
}

impl From<String> for Failure {
    fn from(message: String) -> Self {
        Self {
            message,
            hint: None,
        }
    }
}

fn same(op: &str, a: Dim, b: Dim, ea: &Expr, eb: &Expr) -> Result<Dim, Failure> {
    match (a, b) {
        (Dim::Known(x), Dim::Known(y)) if x != y => Err(Failure {
            message: format!(
                "cannot {op} `{ea}` ({}) and `{eb}` ({})",
                x.describe(),
                y.describe()
            ),
            hint: Some(format!(
                "both sides must have the same dimension: check `{eb}`, or multiply it by a \
                 constant with units (defined in [constants])"
            )),
        }),
        (Dim::Known(x), _) | (_, Dim::Known(x)) => Ok(Dim::Known(x)),
        (Dim::Unknown, _) | (_, Dim::Unknown) => Ok(Dim::Unknown),
        (Dim::Literal, Dim::Literal) => Ok(Dim::Literal),
    }
}

fn dimensionless(func: &str, a: Dim, e: &Expr) -> Result<(), Failure> {
    match a {
        Dim::Known(d) if !d.is_none() => Err(Failure {
            message: format!(
                "`{func}` needs a dimensionless argument, but `{e}` has dimension {}",
                d.describe()
            ),
            hint: Some(format!(
                "scale the argument by a constant with units, e.g. `{func}(omega*t)` with `omega = \"2 1/s\"` in [constants]"
            )),
        }),
        _ => Ok(()),
    }
}

/// What dimensional analysis knows about names.
struct Env<'a> {
    dims: &'a dyn Fn(&str) -> Dim,
    values: &'a dyn Fn(&str) -> Option<f64>,
}

fn constant_value(e: &Expr, env: &Env<'_>) -> Option<f64> {
    e.eval_with(&|n| (env.values)(n).or_else(|| builtin_constant(n)))
        .ok()
}

/// The dimension of `e`. The recursion only walks the tree; what each node makes of its
/// operands' dimensions is worked out in functions of their own, so that a frame of the
/// recursion stays small (a debug build gives every temporary of a function its own slot:
/// with the rules inline, a formula [`crate::MAX_DEPTH`] levels deep took 8 MB of stack).
fn infer(e: &Expr, env: &Env<'_>) -> Result<Dim, Failure> {
    match e {
        Expr::Num(_) => Ok(Dim::Literal),
        Expr::Var(name) => name_dimension(name, env),
        Expr::Neg(a) => infer(a, env),
        Expr::Not(a) => infer(a, env).map(|_| Dim::NONE),
        Expr::Binary(op, a, b) => {
            let da = infer(a, env)?;
            let db = infer(b, env)?;
            binary(e, *op, (da, db), (a, b), env)
        }
        Expr::Call(func, args) => {
            let mut ds = Vec::with_capacity(args.len());
            for a in args {
                ds.push(infer(a, env)?);
            }
            call(e, *func, &ds, args)
        }
    }
}

#[inline(never)]
fn name_dimension(name: &str, env: &Env<'_>) -> Result<Dim, Failure> {
    let dims = env.dims;
    Ok(match builtin_constant(name) {
        Some(_) if matches!(dims(name), Dim::Unknown) => Dim::NONE,
        _ => match dims(name) {
            Dim::Known(d) if d.is_too_large() => {
                return Err(format!("`{name}` has a dimension whose exponent is too large").into());
            }
            d => d,
        },
    })
}

/// The dimension of `e = a op b` from those of `a` and `b`.
#[inline(never)]
fn binary(
    e: &Expr,
    op: BinOp,
    (da, db): (Dim, Dim),
    (a, b): (&Expr, &Expr),
    env: &Env<'_>,
) -> Result<Dim, Failure> {
    Ok(match op {
        BinOp::Add => same("add", da, db, a, b)?,
        BinOp::Sub => same("subtract", da, db, a, b)?,
        op if op.is_comparison() => {
            same("compare", da, db, a, b)?;
            Dim::NONE
        }
        BinOp::And | BinOp::Or => Dim::NONE,
        BinOp::Mul | BinOp::Div => match (da, db) {
            (Dim::Literal, Dim::Literal) => Dim::Literal,
            (Dim::Known(x), Dim::Known(y)) => Dim::Known(
                if op == BinOp::Mul {
                    x.checked_mul(y)
                } else {
                    x.checked_div(y)
                }
                .map_err(|err| too_large(err, e))?,
            ),
            // A known dimensionless factor (pi, a ratio) keeps the other side as it is.
            (Dim::Known(x), other) if x.is_none() && op == BinOp::Mul => other,
            (other, Dim::Known(y)) if y.is_none() => other,
            _ => Dim::Unknown,
        },
        BinOp::Pow => power(da, db, a, b, env)?,
        _ => unreachable!("all operators covered"),
    })
}

/// The dimension of `e = func(args)` from those of its arguments, `ds`.
#[inline(never)]
fn call(e: &Expr, func: Func, ds: &[Dim], args: &[Expr]) -> Result<Dim, Failure> {
    Ok(match func {
        Func::Abs | Func::Floor | Func::Ceil => ds[0],
        Func::Sign | Func::Heaviside => Dim::NONE,
        Func::Sqrt => root(ds[0], 2, e)?,
        Func::Cbrt => root(ds[0], 3, e)?,
        Func::Min | Func::Max => {
            let mut acc = ds[0];
            for (d, a) in ds.iter().zip(args).skip(1) {
                acc = same("compare", acc, *d, &args[0], a)?;
            }
            acc
        }
        Func::Atan2 => {
            same("compare", ds[0], ds[1], &args[0], &args[1])?;
            Dim::NONE
        }
        Func::If => same("choose between", ds[1], ds[2], &args[1], &args[2])?,
        _ => {
            dimensionless(func.name(), ds[0], &args[0])?;
            Dim::NONE
        }
    })
}

/// The failure of a checked dimension operation in `e`.
fn too_large(err: crate::units::DimensionError, e: &Expr) -> Failure {
    Failure {
        message: format!("the dimension of `{e}`: {err}"),
        hint: Some(
            "make the quantity dimensionless before raising it to a large power (divide it by \
             a constant with its units)"
                .into(),
        ),
    }
}

fn root(d: Dim, n: i32, e: &Expr) -> Result<Dim, Failure> {
    match d {
        Dim::Known(x) => x
            .pow_rational(Ratio::new(1, i64::from(n)).unwrap_or(Ratio::ONE))
            .map(Dim::Known)
            .map_err(|err| too_large(err, e)),
        other => Ok(other),
    }
}

/// The dimension of `a^b`: exact for a fixed exponent that is a fraction p/q with
/// q ≤ [`MAX_WRITTEN_DENOMINATOR`] (`x^1.5` is `x^(3/2)`, `x^(1/3)`, `x^n` with `n = 3`).
fn power(base: Dim, exponent: Dim, a: &Expr, b: &Expr, env: &Env<'_>) -> Result<Dim, Failure> {
    dimensionless("^", exponent, b)
        .map_err(|_| Failure::from(format!("the exponent `{b}` must be dimensionless")))?;
    let Dim::Known(d) = base else {
        return Ok(base);
    };
    if d.is_none() {
        return Ok(base);
    }
    let Some(p) = constant_value(b, env) else {
        return Err(format!(
            "`{a}` has dimension {} and can only be raised to a fixed number, not to `{b}`",
            d.describe()
        )
        .into());
    };
    let whole = || Expr::Binary(BinOp::Pow, Box::new(a.clone()), Box::new(b.clone()));
    match Ratio::from_f64(p, MAX_WRITTEN_DENOMINATOR) {
        Some(r) => d
            .pow_rational(r)
            .map(Dim::Known)
            .map_err(|err| too_large(err, &whole())),
        None if p.is_finite() && p.abs() <= f64::from(i32::MAX) => Err(Failure {
            message: format!(
                "`{a}` ({}) raised to {p} has no exact dimension: a power of a quantity with \
                 units must be a fraction p/q with q at most {MAX_WRITTEN_DENOMINATOR}",
                d.describe()
            ),
            hint: Some(format!(
                "write the power as a fraction, e.g. `{a}^(3/2)`, or make `{a}` dimensionless \
                 (divide it by a constant with its units)"
            )),
        }),
        None => Err(too_large(
            crate::units::DimensionError::ExponentTooLarge,
            &whole(),
        )),
    }
}

#[cfg(test)]
#[path = "dims_tests.rs"]
mod tests;
