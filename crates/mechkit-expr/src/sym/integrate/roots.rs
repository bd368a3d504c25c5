//! `x^k (a + b x²)^(n/2)`, and `x^k (a + b x²)^-n` with symbolic `a`, `b` (a force or field
//! `1/(x² + a²)^2`): what the trigonometric (`x = sqrt(a/-b) sin t`) and hyperbolic
//! (`x = sqrt(a/b) sinh t`) substitutions give, by reduction formulas down to
//! `∫ dx/sqrt(a + b x²)` (`asin` for `b < 0`, a logarithm, the inverse hyperbolic sine or
//! cosine, for `b > 0`). A quadratic with a linear term is first completed to a square
//! (`x = t - c1/(2 c2)`). Odd `k` goes by `w = x²` (see `substitution`).

use super::substitution::split_power_of_x;
use super::{Ctx, Sym, integrate, ln_abs, var};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::identities::is_negated;
use crate::sym::poly::coefficients;

/// Integrands `x^k (a + b x²)^p` with `p` a half-integer (or a negative integer with
/// symbolic coefficients), `k` an even integer; any integer `k` when the quadratic has a
/// linear term (completed to a square first).
pub(super) fn quadratic_roots(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let (k, rest) = split_power_of_x(f, x);
    let [Sym::Pow(base, e)] = rest.as_slice() else {
        return None;
    };
    let p = e.as_num()?;
    let (n, q) = p.as_rational()?;
    // integer powers: only the negative ones with symbolic coefficients (numeric ones are
    // partial fractions)
    let integer_power = q == 1 && n <= -2;
    if !(q == 2 || integer_power) || k.abs() > 12 || n.abs() > 24 {
        return None;
    }
    let c = coefficients(base, x)?;
    if c.len() != 3
        || c.iter().any(|s| !s.free_of(x))
        || (integer_power && c.iter().all(|s| s.as_num().is_some()))
    {
        return None;
    }
    if !c[1].is_zero() {
        if q == 2 && k < 0 && i128::from(-k) - n - 2 >= 0 && !c[0].is_zero() {
            return reciprocal(-k, p, &c, ctx);
        }
        // any power of x: the shift makes it a polynomial in t (`x*sqrt(2*a*x - x^2)`)
        return complete_square(f, &c, ctx);
    }
    if k % 2 != 0 {
        return None; // odd powers go by w = x² (`substitution::odd_power_of_x`)
    }
    let (a, b) = (c[0].clone(), c[2].clone());
    reduce(k, p, &a, &b, base, ctx)
}

/// `∫ q^p/x^k dx` for `q = c0 + c1 x + c2 x²` with `c0 ≠ 0`, a half-integer `p = n/2` and
/// `k ≥ n + 2` (`1/(x sqrt(-x² + 4x - 3))`), by `t = 1/x`: `q = Q(t)/t²` with
/// `Q = c0 t² + c1 t + c2`, and for `x > 0` the integrand becomes `-t^(k - n - 2) Q^p`, a
/// power of `t` times a root of a quadratic; for `x < 0`, `|t|^n = -t^n` flips the sign:
/// `F = sign(x) G(1/x)`.
fn reciprocal(k: i64, p: Number, c: &[Sym], ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let (n, _) = p.as_rational()?;
    let t = ctx.fresh();
    let tv = var(&t);
    let big_q = Sym::sum(vec![
        Sym::product(vec![c[0].clone(), Sym::pow(tv.clone(), Sym::int(2))]),
        Sym::product(vec![c[1].clone(), tv.clone()]),
        c[2].clone(),
    ]);
    let power = i64::try_from(n).ok()?;
    let g = Sym::negate(Sym::product(vec![
        Sym::pow(tv, Sym::int(k - power - 2)),
        Sym::pow(big_q, Sym::Num(p)),
    ]));
    let big_g = ctx.integrate_in(&g, &t)?;
    let xv = var(&x);
    Some(Sym::product(vec![
        Sym::call(Func::Sign, vec![xv.clone()]),
        big_g.substitute(&t, &Sym::pow(xv, Sym::int(-1))),
    ]))
}

/// `x = t - c1/(2 c2)` removes the linear term of the quadratic.
pub(super) fn complete_square(f: &Sym, c: &[Sym], ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let shift = Sym::quotient(c[1].clone(), Sym::product(vec![Sym::int(2), c[2].clone()]));
    let t = ctx.fresh();
    let g = substitute_expanding(f, &x, &Sym::difference(var(&t), shift.clone()));
    // The shift removes the linear term unless the expansion was too large to carry out
    // (`Sym::expand`'s bounds) or the coefficients do not cancel in the canonical form; a
    // second completion of the result would repeat the same expansions, so there is none.
    if ctx.completing || !ctx.spend(super::size(&g)) {
        return None;
    }
    ctx.completing = true;
    let big_g = ctx.integrate_in(&g, &t);
    ctx.completing = false;
    let big_g = big_g?;
    Some(big_g.substitute(&t, &Sym::sum(vec![var(&x), shift])))
}

/// Substitutes and expands the bases of powers (so that the quadratic shows its new
/// coefficients).
fn substitute_expanding(f: &Sym, x: &str, with: &Sym) -> Sym {
    match f {
        Sym::Pow(b, e) => Sym::pow(b.substitute(x, with).expand(), (**e).clone()),
        Sym::Mul(xs) => Sym::product(
            xs.iter()
                .map(|s| substitute_expanding(s, x, with))
                .collect(),
        ),
        other => other.substitute(x, with).expand(),
    }
}

fn term(x: &str, k: i64, base: &Sym, p: Number) -> Sym {
    Sym::product(vec![
        Sym::pow(var(x), Sym::int(k)),
        Sym::pow(base.clone(), Sym::Num(p)),
    ])
}

fn reduce(k: i64, p: Number, a: &Sym, b: &Sym, base: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    if !ctx.spend(1) {
        return None;
    }
    let one = Number::ONE;
    if k >= 2 {
        // x^k R^p = x^(k-2) (R^(p+1) - a R^p)/b
        let hi = reduce(k - 2, p.plus(one), a, b, base, ctx)?;
        let lo = reduce(k - 2, p, a, b, base, ctx)?;
        return Some(Sym::quotient(
            Sym::difference(hi, Sym::product(vec![a.clone(), lo])),
            b.clone(),
        ));
    }
    if k <= -2 {
        // ∫ x^-m R^q = [x^(1-m) R^q - 2 b q ∫ x^(2-m) R^(q-1)]/(1 - m)
        let m = -k;
        let inner = reduce(k + 2, p.plus(one.negated()), a, b, base, ctx)?;
        return Some(Sym::quotient(
            Sym::difference(
                term(x, 1 - m, base, p),
                Sym::product(vec![Sym::int(2), b.clone(), Sym::Num(p), inner]),
            ),
            Sym::int(1 - m),
        ));
    }
    if p == Number::MINUS_ONE {
        // ∫ dx/(a + b x²): atan or logarithms (integer powers)
        return integrate(&Sym::pow(base.clone(), Sym::int(-1)), ctx);
    }
    let half = Number::rational(1, 2);
    if p == half.negated() {
        return inverse_root(a, b, base, ctx);
    }
    let two = Number::int(2);
    if !p.is_negative() {
        // ∫ R^(2p) = x R^(2p)/(2p+1) + 2 p a/(2p+1) ∫ R^(2p-2)
        let lower = reduce(0, p.plus(one.negated()), a, b, base, ctx)?;
        let d = two.times(p).plus(one);
        return Some(Sym::sum(vec![
            Sym::quotient(term(x, 1, base, p), Sym::Num(d)),
            Sym::product(vec![
                Sym::Num(two.times(p).checked_div(d)?),
                a.clone(),
                lower,
            ]),
        ]));
    }
    // p ≤ -3/2: ∫ R^(2p) = [(2p+3) ∫ R^(2p+2) - x R^(2p+2)]/(2 a (p+1))
    let p1 = p.plus(one);
    let higher = reduce(0, p1, a, b, base, ctx)?;
    let c3 = two.times(p).plus(Number::int(3));
    Some(Sym::quotient(
        Sym::difference(
            Sym::product(vec![Sym::Num(c3), higher]),
            term(x, 1, base, p1),
        ),
        Sym::product(vec![Sym::Num(two.times(p1)), a.clone()]),
    ))
}

/// `∫ dx/sqrt(a + b x²)`: `asin(x sqrt(-b)/sqrt(a))/sqrt(-b)` for `b < 0` (assuming `a > 0`),
/// `ln|sqrt(b) x + sqrt(a + b x²)|/sqrt(b)` for `b > 0` (assuming `b > 0` when symbolic).
fn inverse_root(a: &Sym, b: &Sym, base: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let xv = var(&x);
    let negative = |s: &Sym| match s.as_num() {
        Some(n) => n.is_negative(),
        None => is_negated(s),
    };
    if negative(b) {
        if negative(a) {
            return None; // no real values
        }
        let sa = ctx.sqrt_positive(a);
        let sn = ctx.sqrt_positive(&Sym::negate(b.clone()));
        return Some(Sym::quotient(
            Sym::call(
                Func::Asin,
                vec![Sym::quotient(Sym::product(vec![xv, sn.clone()]), sa)],
            ),
            sn,
        ));
    }
    let sb = ctx.sqrt_positive(b);
    let inside = Sym::sum(vec![
        Sym::product(vec![sb.clone(), xv]),
        Sym::sqrt(base.clone()),
    ]);
    let a_positive = a.as_num().is_some_and(|n| !n.is_negative());
    let log = if a_positive {
        Sym::call(Func::Ln, vec![inside])
    } else {
        ln_abs(inside)
    };
    Some(Sym::quotient(log, sb))
}
