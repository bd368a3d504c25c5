//! Numerical value of a symbolic expression.

use super::Sym;
use crate::ast::{BinOp, pow};
use crate::number::Number;
use crate::scope::builtin_constant;

impl Sym {
    /// The value, looking names up with `env` (then `pi` and `e`). `Err` names the first
    /// undefined name.
    pub fn eval(&self, env: &dyn Fn(&str) -> Option<f64>) -> Result<f64, String> {
        Ok(match self {
            Sym::Num(n) => n.to_f64(),
            Sym::Var(v) => env(v)
                .or_else(|| builtin_constant(v))
                .ok_or_else(|| v.clone())?,
            Sym::Add(xs) => {
                let mut s = 0.0;
                for x in xs {
                    s += x.eval(env)?;
                }
                s
            }
            Sym::Mul(xs) => {
                let mut p = 1.0;
                for x in xs {
                    p *= x.eval(env)?;
                }
                p
            }
            Sym::Pow(b, e) => {
                let base = b.eval(env)?;
                match e.as_num() {
                    Some(n) if n == Number::rational(1, 2) => base.sqrt(),
                    Some(n) if n == Number::rational(-1, 2) => 1.0 / base.sqrt(),
                    _ => pow(base, e.eval(env)?),
                }
            }
            Sym::Call(f, xs) => {
                let values = xs
                    .iter()
                    .map(|x| x.eval(env))
                    .collect::<Result<Vec<_>, _>>()?;
                f.apply(&values)
            }
            Sym::Cmp(op, a, b) => op.apply(a.eval(env)?, b.eval(env)?),
            Sym::And(a, b) => BinOp::And.apply(a.eval(env)?, b.eval(env)?),
            Sym::Or(a, b) => BinOp::Or.apply(a.eval(env)?, b.eval(env)?),
            Sym::Not(a) => {
                if a.eval(env)? == 0.0 {
                    1.0
                } else {
                    0.0
                }
            }
        })
    }
}
