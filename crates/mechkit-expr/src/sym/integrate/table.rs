//! Antiderivatives of the elementary functions of `x` itself, and the squares of the circular
//! and hyperbolic functions by the double angle.

use super::{Sym, ln_abs, var};
use crate::ast::Func;
use crate::number::Number;

/// Antiderivatives of the functions of `x` itself.
pub(super) fn table(f: &Sym, x: &str) -> Option<Sym> {
    let xv = var(x);
    let is_x = |s: &Sym| *s == xv;
    Some(match f {
        Sym::Var(_) => Sym::product(vec![Sym::rational(1, 2), Sym::pow(xv, Sym::int(2))]),
        Sym::Pow(b, n) if is_x(b) && n.free_of(x) => {
            if n.as_num() == Some(Number::MINUS_ONE) {
                ln_abs(xv)
            } else {
                let n1 = Sym::sum(vec![(**n).clone(), Sym::one()]);
                Sym::quotient(Sym::pow(xv, n1.clone()), n1)
            }
        }
        // squares by the double angle: sin^2 x = (1 - cos 2x)/2, sinh^2 x = (cosh 2x - 1)/2
        Sym::Pow(b, n) if n.as_num() == Some(Number::int(2)) => {
            let Sym::Call(func, a) = &**b else {
                return None;
            };
            if !is_x(&a[0]) {
                return None;
            }
            let quarter = |g: Func| {
                Sym::product(vec![
                    Sym::rational(1, 4),
                    Sym::call(g, vec![Sym::product(vec![Sym::int(2), xv.clone()])]),
                ])
            };
            let half_x = Sym::product(vec![Sym::rational(1, 2), xv.clone()]);
            match func {
                Func::Sin => Sym::difference(half_x, quarter(Func::Sin)),
                Func::Cos => Sym::sum(vec![half_x, quarter(Func::Sin)]),
                Func::Sinh => Sym::difference(quarter(Func::Sinh), half_x),
                Func::Cosh => Sym::sum(vec![quarter(Func::Sinh), half_x]),
                Func::Tan => Sym::difference(Sym::call(Func::Tan, vec![xv.clone()]), xv),
                Func::Tanh => Sym::difference(xv.clone(), Sym::call(Func::Tanh, vec![xv])),
                _ => return None,
            }
        }
        // sec^2 and sech^2
        Sym::Pow(b, n) if n.as_num() == Some(Number::int(-2)) => match &**b {
            Sym::Call(Func::Cos, a) if is_x(&a[0]) => Sym::call(Func::Tan, vec![xv]),
            Sym::Call(Func::Cosh, a) if is_x(&a[0]) => Sym::call(Func::Tanh, vec![xv]),
            _ => return None,
        },
        Sym::Call(func, args) if is_x(&args[0]) && args.len() == 1 => {
            let call = |g: Func| Sym::call(g, vec![xv.clone()]);
            match func {
                Func::Sin => Sym::negate(call(Func::Cos)),
                Func::Cos => call(Func::Sin),
                Func::Tan => Sym::negate(ln_abs(call(Func::Cos))),
                Func::Exp => call(Func::Exp),
                Func::Sinh => call(Func::Cosh),
                Func::Cosh => call(Func::Sinh),
                Func::Tanh => Sym::call(Func::Ln, vec![call(Func::Cosh)]),
                Func::Ln => Sym::difference(Sym::product(vec![xv.clone(), call(Func::Ln)]), xv),
                Func::Atan => Sym::difference(
                    Sym::product(vec![xv.clone(), call(Func::Atan)]),
                    Sym::product(vec![
                        Sym::rational(1, 2),
                        Sym::call(
                            Func::Ln,
                            vec![Sym::sum(vec![Sym::one(), Sym::pow(xv, Sym::int(2))])],
                        ),
                    ]),
                ),
                Func::Asin => Sym::sum(vec![
                    Sym::product(vec![xv.clone(), call(Func::Asin)]),
                    Sym::sqrt(Sym::difference(Sym::one(), Sym::pow(xv, Sym::int(2)))),
                ]),
                Func::Acos => Sym::difference(
                    Sym::product(vec![xv.clone(), call(Func::Acos)]),
                    Sym::sqrt(Sym::difference(Sym::one(), Sym::pow(xv, Sym::int(2)))),
                ),
                Func::Abs => Sym::product(vec![Sym::rational(1, 2), xv.clone(), call(Func::Abs)]),
                Func::Sign => call(Func::Abs),
                Func::Heaviside => Sym::product(vec![xv.clone(), call(Func::Heaviside)]),
                _ => return None,
            }
        }
        _ => return None,
    })
}
