//! Integrals of rational functions: with numeric coefficients by partial fractions
//! ([`super::partial_fractions`]), with symbols `c/(a + b x²)` (atan, or logarithms when the
//! signs say so: `1/(c^2 - x^2)`).

use super::partial_fractions::partial_fractions;
use super::{Ctx, Sym, ln_abs, var};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::identities::is_negated;
use crate::sym::poly::{NumPoly, coefficients};

/// Numerator and denominator polynomials of a product of polynomial factors and negative
/// integer powers of polynomials.
fn as_fraction(f: &Sym, x: &str) -> Option<(Sym, Sym)> {
    let factors = super::factors(f);
    let (mut num, mut den) = (Vec::new(), Vec::new());
    for fac in factors {
        match &fac {
            Sym::Pow(b, e)
                if e.as_num()
                    .and_then(Number::as_integer)
                    .is_some_and(|n| n < 0) =>
            {
                coefficients(b, x)?;
                den.push(Sym::pow((**b).clone(), Sym::negate((**e).clone())));
            }
            other => {
                coefficients(other, x)?;
                num.push(fac.clone());
            }
        }
    }
    if den.is_empty() {
        return None;
    }
    Some((Sym::product(num), Sym::product(den)))
}

/// Rational functions: `c/(a + b x^2)` with symbols, anything with numeric coefficients whose
/// denominator factors into rational linear factors and at most one irreducible quadratic.
pub(super) fn rational(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let (num, den) = as_fraction(f, x)?;
    let nc = coefficients(&num, x)?;
    let dc = coefficients(&den, x)?;
    if let (Some(n), Some(d)) = (NumPoly::from_syms(&nc), NumPoly::from_syms(&dc)) {
        return partial_fractions(&n, &d, x);
    }
    // c/(a + b x^2) with symbolic a, b
    if nc.len() == 1 && dc.len() == 3 && dc[1].is_zero() {
        return Some(Sym::product(vec![
            nc[0].clone(),
            inverse_quadratic(&dc[0], &dc[2], x, ctx)?,
        ]));
    }
    None
}

/// `∫ dx/(a + b x^2)`: `atan(x sqrt(b/a))/sqrt(a b)` for `a, b > 0` (assumed when not known),
/// a logarithm when they have opposite signs.
fn inverse_quadratic(a: &Sym, b: &Sym, x: &str, ctx: &mut Ctx) -> Option<Sym> {
    let xv = var(x);
    // Some(true) positive, Some(false) negative, None unknown (a symbol: assumed positive,
    // a negated symbol: assumed negative)
    let sign = |s: &Sym| match s.as_num() {
        Some(n) => Some(!n.is_negative()),
        None if is_negated(s) => Some(false),
        None => None,
    };
    match (sign(a), sign(b)) {
        (Some(false), Some(false)) => {
            let r = inverse_quadratic(&Sym::negate(a.clone()), &Sym::negate(b.clone()), x, ctx)?;
            return Some(Sym::negate(r));
        }
        (None, Some(false)) | (Some(false), None) => {
            return Some(inverse_quadratic_opposite(a, b, x, ctx));
        }
        (Some(pa), Some(pb)) if pa != pb && a.as_num().is_some() && b.as_num().is_some() => {
            // 1/(a - c² x²) with a > 0 > b: ln|(√a + √-b x)/(√a − √-b x)| / (2 √(−a b))
            let (a, b) = if pa {
                (a.clone(), b.clone())
            } else {
                (Sym::negate(a.clone()), Sym::negate(b.clone()))
            };
            let (sa, sb) = (Sym::sqrt(a.clone()), Sym::sqrt(Sym::negate(b.clone())));
            let r = Sym::quotient(
                ln_abs(Sym::quotient(
                    Sym::sum(vec![sa.clone(), Sym::product(vec![sb.clone(), xv.clone()])]),
                    Sym::difference(sa, Sym::product(vec![sb, xv])),
                )),
                Sym::product(vec![
                    Sym::int(2),
                    Sym::sqrt(Sym::negate(Sym::product(vec![a, b]))),
                ]),
            );
            return Some(if pa { r } else { Sym::negate(r) });
        }
        _ => {}
    }
    if matches!((sign(a), sign(b)), (Some(pa), Some(pb)) if pa != pb) {
        return Some(inverse_quadratic_opposite(a, b, x, ctx));
    }
    // assume the unknown coefficients positive, and say so
    let (sa, sb) = (ctx.sqrt_positive(a), ctx.sqrt_positive(b));
    Some(Sym::quotient(
        Sym::call(
            Func::Atan,
            vec![Sym::quotient(
                Sym::product(vec![sb.clone(), xv]),
                sa.clone(),
            )],
        ),
        Sym::product(vec![sa, sb]),
    ))
}

/// `∫ dx/(a + b x²)` with `a` and `b` of opposite signs (one of them symbolic, assumed of the
/// sign it reads with): `ln|(√a + √-b x)/(√a − √-b x)|/(2 √a √-b)` for `a > 0 > b`.
fn inverse_quadratic_opposite(a: &Sym, b: &Sym, x: &str, ctx: &mut Ctx) -> Sym {
    let a_positive = match a.as_num() {
        Some(n) => !n.is_negative(),
        None => !is_negated(a),
    };
    let (a, b, flip) = if a_positive {
        (a.clone(), b.clone(), false)
    } else {
        (Sym::negate(a.clone()), Sym::negate(b.clone()), true)
    };
    let sa = ctx.sqrt_positive(&a);
    let sb = ctx.sqrt_positive(&Sym::negate(b));
    let xv = var(x);
    let r = Sym::quotient(
        ln_abs(Sym::quotient(
            Sym::sum(vec![sa.clone(), Sym::product(vec![sb.clone(), xv.clone()])]),
            Sym::difference(sa.clone(), Sym::product(vec![sb.clone(), xv])),
        )),
        Sym::product(vec![Sym::int(2), sa, sb]),
    );
    if flip { Sym::negate(r) } else { r }
}
