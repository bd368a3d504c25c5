//! Products of powers of `sin` and `cos` of linear arguments, alone with different arguments
//! (`sin(x)^2*cos(2*x)`) or times `exp(a x + b)` (the energy of a damped oscillation,
//! `exp(-2 b t) cos(w t)^2`): the trigonometric product is written as a sum of single sines
//! and cosines by the product-to-sum formulas, and each term goes by a linear substitution
//! or, times the exponential, by the cyclic rule of [`super::by_parts`].

use super::{Ctx, Sym, factors, integrate};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::coefficients;

/// The largest number of sine and cosine factors linearised (`2^(n-1)` terms).
const MAX_FACTORS: usize = 8;

/// `∫ exp(a x + b) Π sin/cos(c_i x + d_i)^(k_i) dx` with at least two trigonometric factors,
/// and without the exponential when the arguments differ.
pub(super) fn trig_products(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let linear = |s: &Sym| {
        coefficients(s, x).is_some_and(|c| c.len() == 2 && c.iter().all(|k| k.free_of(x)))
    };
    let mut exp = None;
    let mut trig: Vec<(Func, Sym)> = Vec::new();
    for g in factors(f) {
        let (call, k) = match &g {
            Sym::Pow(b, e) => (&**b, e.as_num().and_then(Number::as_integer)?),
            other => (other, 1),
        };
        let Sym::Call(func, args) = call else {
            return None;
        };
        if !linear(&args[0]) {
            return None;
        }
        match func {
            Func::Exp if exp.is_none() => exp = Some(g.clone()),
            Func::Sin | Func::Cos if k > 0 => {
                for _ in 0..k {
                    trig.push((*func, args[0].clone()));
                    if trig.len() > MAX_FACTORS {
                        return None;
                    }
                }
            }
            _ => return None,
        }
    }
    if exp.is_none() && trig.iter().all(|(_, a)| *a == trig[0].1) {
        return None; // one argument: powers and reduction formulas (`trig`)
    }
    if trig.len() < 2 || !ctx.spend(1 << (trig.len() - 1)) {
        return None;
    }
    let sum = Sym::product(vec![exp.unwrap_or_else(Sym::one), linearise(&trig)]).expand();
    if sum == *f {
        return None;
    }
    integrate(&sum, ctx)
}

/// `Π f_i(u_i)` as a sum of single sines and cosines: `sin A cos B = (sin(A+B) + sin(A−B))/2`,
/// `sin A sin B = (cos(A−B) − cos(A+B))/2`, `cos A cos B = (cos(A−B) + cos(A+B))/2`.
fn linearise(trig: &[(Func, Sym)]) -> Sym {
    match trig {
        [] => Sym::one(),
        [(f, a)] => Sym::call(*f, vec![a.clone()]),
        [(f1, a), (f2, b), rest @ ..] => {
            let plus = Sym::sum(vec![a.clone(), b.clone()]).expand();
            let minus = Sym::difference(a.clone(), b.clone()).expand();
            // (sign, function, argument) of the two halves
            let halves = match (f1, f2) {
                (Func::Sin, Func::Cos) => [(1, Func::Sin, plus), (1, Func::Sin, minus)],
                (Func::Cos, Func::Sin) => [(1, Func::Sin, plus), (-1, Func::Sin, minus)],
                (Func::Sin, Func::Sin) => [(1, Func::Cos, minus), (-1, Func::Cos, plus)],
                _ => [(1, Func::Cos, minus), (1, Func::Cos, plus)],
            };
            Sym::sum(
                halves
                    .into_iter()
                    .map(|(sign, f, arg)| {
                        let mut next = vec![(f, arg)];
                        next.extend_from_slice(rest);
                        Sym::product(vec![Sym::rational(sign, 2), linearise(&next)])
                    })
                    .collect(),
            )
        }
    }
}
