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
    if dc.len() == 3 && dc[1].is_zero() && !dc[2].is_zero() && nc.len() <= 2 * MAX_LINEAR_FACTORS {
        return over_quadratic(&nc, &dc, &den, ctx);
    }
    if let r @ Some(_) = linear_factors(f, ctx) {
        return r;
    }
    // a x² + b x + c = a (x + b/(2a))² + c − b²/(4a): shifted, it has no linear term
    if dc.len() == 3 && !dc[2].is_zero() && nc.len() <= 2 * MAX_LINEAR_FACTORS {
        return super::roots::complete_square(f, &dc, ctx);
    }
    None
}

/// `∫ N(x)/(a + b x²) dx` with symbols: `N = Q (a + b x²)/b + r₀ + r₁ x` by long division, then
/// `∫ Q/b + r₁ ln|a + b x²|/(2 b) + r₀ ∫ dx/(a + b x²)` (`v^2/(v^2 - a)`, `x^3/(c^2 + x^2)`).
fn over_quadratic(nc: &[Sym], dc: &[Sym], den: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let b = &dc[2];
    let (q, r) = if nc.len() >= 3 {
        let monic: Vec<Sym> = dc
            .iter()
            .map(|c| smaller(Sym::quotient(c.clone(), b.clone())))
            .collect();
        divide_monic(nc, &monic)
    } else {
        (Vec::new(), nc.to_vec())
    };
    let mut out = Vec::new();
    if !q.is_empty() {
        out.push(ctx.integrate_in(&smaller(Sym::quotient(poly(&q, x), b.clone())), x)?);
    }
    if let Some(r1) = r.get(1).filter(|r1| !r1.is_zero()) {
        out.push(smaller(Sym::quotient(
            Sym::product(vec![r1.clone(), ln_abs(den.clone())]),
            Sym::product(vec![Sym::int(2), b.clone()]),
        )));
    }
    if !r[0].is_zero() {
        out.push(Sym::product(vec![
            r[0].clone(),
            inverse_quadratic(&dc[0], b, x, ctx)?,
        ]));
    }
    Some(Sym::sum(out))
}

/// The most linear factors (counted with their powers) taken apart with symbols.
const MAX_LINEAR_FACTORS: usize = 8;

/// `∫ N(x)/Π (pᵢ + qᵢ x)^mᵢ dx` with symbols in `N`, `pᵢ`, `qᵢ`, the denominator written as
/// a product of powers of distinct linear factors (`1/(x*(a + b*x))`, `1/((x - a)*(x - b))`,
/// `1/(x^2*(a + b*x))`): the polynomial part by long division, the partial fractions by the
/// cover-up rule, `Aᵢⱼ = g⁽ˢ⁾(rᵢ)/s!` with `g = N/Π_{k≠i}(x − r_k)^m_k` at each root `rᵢ`.
fn linear_factors(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let xv = var(x);
    // (p, q, m) for each factor (p + q x)^-m
    let mut linear: Vec<(Sym, Sym, usize)> = Vec::new();
    let mut numerator = Vec::new();
    for fac in super::factors(f) {
        let (base, power) = match &fac {
            Sym::Pow(b, e) => match e.as_num().and_then(Number::as_integer) {
                Some(n) if n < 0 => ((**b).clone(), usize::try_from(-n).ok()?),
                _ => (fac.clone(), 0),
            },
            _ => (fac.clone(), 0),
        };
        let c = coefficients(&base, x)?;
        if power == 0 || c.len() != 2 {
            if power != 0 {
                return None;
            }
            numerator.push(fac);
            continue;
        }
        if c.iter().any(|k| !k.free_of(x)) || c[1].is_zero() {
            return None;
        }
        linear.push((c[0].clone(), c[1].clone(), power));
    }
    let total: usize = linear.iter().map(|l| l.2).sum();
    if linear.len() < 2 || total > MAX_LINEAR_FACTORS {
        return None;
    }
    let roots: Vec<Sym> = linear
        .iter()
        .map(|(p, q, _)| Sym::negate(Sym::quotient(p.clone(), q.clone())))
        .collect();
    for (i, a) in roots.iter().enumerate() {
        if roots[..i]
            .iter()
            .any(|b| Sym::difference(a.clone(), b.clone()).expand().is_zero())
        {
            return None;
        }
    }
    let lead = Sym::product(
        linear
            .iter()
            .map(|(_, q, m)| Sym::pow(q.clone(), Sym::int(*m as i64)))
            .collect(),
    );
    let monic = |r: &Sym| Sym::difference(xv.clone(), r.clone());
    let num = Sym::product(numerator);
    let nc = coefficients(&num, x)?;
    if nc.iter().any(|k| !k.free_of(x)) || nc.len() > 2 * MAX_LINEAR_FACTORS {
        return None;
    }
    let mut out = Vec::new();
    // the polynomial part: N = Q D + R with D = Π (x − rᵢ)^mᵢ, monic
    let dc = coefficients(
        &Sym::product(
            roots
                .iter()
                .zip(&linear)
                .map(|(r, l)| Sym::pow(monic(r), Sym::int(l.2 as i64)))
                .collect(),
        ),
        x,
    )?;
    let mut rest = num.clone();
    if nc.len() > total {
        let (q, r) = divide_monic(&nc, &dc);
        let q = poly(&q, x);
        out.push(ctx.integrate_in(&smaller(Sym::quotient(q, lead.clone())), x)?);
        rest = poly(&r, x);
    }
    for (i, (r, (p, q, m))) in roots.iter().zip(&linear).enumerate() {
        let others = Sym::product(
            roots
                .iter()
                .zip(&linear)
                .enumerate()
                .filter(|(k, _)| *k != i)
                .map(|(_, (rk, l))| Sym::pow(monic(rk), Sym::int(-(l.2 as i64))))
                .collect(),
        );
        let mut g = Sym::product(vec![rest.clone(), others]);
        let mut factorial = Number::ONE;
        for s in 0..*m {
            if s > 0 {
                g = g.diff(x);
                factorial = factorial.times(Number::int(s as i64));
            }
            if !ctx.spend(super::size(&g)) {
                return None;
            }
            let coefficient = smaller(Sym::quotient(
                g.substitute(x, r),
                Sym::product(vec![Sym::Num(factorial), lead.clone()]),
            ));
            let j = m - s; // the term A/(x − r)^j
            let linear_form = Sym::sum(vec![p.clone(), Sym::product(vec![q.clone(), xv.clone()])]);
            out.push(if j == 1 {
                Sym::product(vec![coefficient, ln_abs(linear_form)])
            } else {
                // ∫ (x − r)^-j = −(x − r)^(1−j)/(j − 1), (x − r) = (p + q x)/q
                Sym::product(vec![
                    coefficient,
                    Sym::rational(-1, j as i64 - 1),
                    Sym::pow(q.clone(), Sym::int(j as i64 - 1)),
                    Sym::pow(linear_form, Sym::int(1 - j as i64)),
                ])
            });
        }
    }
    Some(Sym::sum(out))
}

/// `s` or its expansion, whichever has fewer nodes.
fn smaller(s: Sym) -> Sym {
    let e = s.expand();
    if super::size(&e) < super::size(&s) {
        e
    } else {
        s
    }
}

/// `n = q d + r` for a monic `d` (coefficients lowest degree first).
fn divide_monic(n: &[Sym], d: &[Sym]) -> (Vec<Sym>, Vec<Sym>) {
    let dd = d.len() - 1;
    let mut r = n.to_vec();
    let mut q = vec![Sym::zero(); n.len() - dd];
    for k in (0..q.len()).rev() {
        let top = r[k + dd].clone();
        for (i, di) in d.iter().enumerate() {
            r[k + i] = Sym::difference(
                r[k + i].clone(),
                Sym::product(vec![top.clone(), di.clone()]),
            )
            .expand();
        }
        q[k] = top;
    }
    r.truncate(dd);
    (q, r)
}

/// `Σ cₖ xᵏ`.
fn poly(c: &[Sym], x: &str) -> Sym {
    Sym::sum(
        c.iter()
            .enumerate()
            .map(|(k, ck)| Sym::product(vec![ck.clone(), Sym::pow(var(x), Sym::int(k as i64))]))
            .collect(),
    )
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
