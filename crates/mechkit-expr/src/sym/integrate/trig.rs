//! Powers and products of `sin`/`cos` (and `tan = sin/cos`), `sinh`/`cosh` (and `tanh`) of
//! `x`: an odd power by the substitution `u = cos x` or `u = sin x` (`u = cosh x`,
//! `u = sinh x`), even powers by the reduction formulas, `sin^m cos^n` with both even by
//! `sin² = 1 - cos²` (or `1 = sin² + cos²` when both are negative). `1/cos` and `1/sin` are
//! odd powers: `∫ dx/cos = ∫ du/(1 - u²)` with `u = sin x`.

use super::{Ctx, Sym, factors, integrate, var};
use crate::ast::Func;
use crate::number::Number;

/// The largest power reduced (each step of a reduction is one rule search).
const MAX_POWER: i64 = 40;

/// Exponents of (sin, cos) or (sinh, cosh) in a product of their powers.
struct Monomial {
    hyperbolic: bool,
    m: i64,
    n: i64,
}

fn monomial(f: &Sym, x: &str) -> Option<Monomial> {
    let (mut circular, mut hyperbolic) = (false, false);
    let (mut m, mut n) = (0i64, 0i64);
    for fac in factors(f) {
        let (call, k) = match &fac {
            Sym::Pow(b, e) => (&**b, e.as_num()?.as_integer()?),
            other => (other, 1),
        };
        let k = i64::try_from(k).ok().filter(|k| k.abs() <= MAX_POWER)?;
        let Sym::Call(func, args) = call else {
            return None;
        };
        if args.len() != 1 || !matches!(&args[0], Sym::Var(v) if v == x) {
            return None;
        }
        match func {
            Func::Sin | Func::Sinh => m += k,
            Func::Cos | Func::Cosh => n += k,
            Func::Tan | Func::Tanh => {
                m += k;
                n -= k;
            }
            _ => return None,
        }
        match func {
            Func::Sin | Func::Cos | Func::Tan => circular = true,
            _ => hyperbolic = true,
        }
    }
    if circular == hyperbolic || (m == 0 && n == 0) {
        return None;
    }
    Some(Monomial { hyperbolic, m, n })
}

/// Powers and products of the circular or hyperbolic functions of `x`.
pub(super) fn powers(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let mono = monomial(f, &x)?;
    integrate_monomial(&mono, ctx)
}

fn call(f: Func, x: &str) -> Sym {
    Sym::call(f, vec![var(x)])
}

fn power(f: Func, x: &str, k: i64) -> Sym {
    Sym::pow(call(f, x), Sym::int(k))
}

fn integrate_monomial(mono: &Monomial, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let Monomial { hyperbolic, m, n } = *mono;
    let (fs, fc) = if hyperbolic {
        (Func::Sinh, Func::Cosh)
    } else {
        (Func::Sin, Func::Cos)
    };
    // sign of the square of the "other" function: sin² = 1 - cos², sinh² = cosh² - 1,
    // cos² = 1 - sin², cosh² = 1 + sinh²
    let odd_sin = m % 2 != 0;
    let odd_cos = n % 2 != 0;
    if odd_sin || odd_cos {
        // prefer a positive odd power (a polynomial in u)
        let use_sin_power = odd_sin && (m > 0 || !odd_cos || n < 0);
        let u = ctx.fresh();
        let uv = var(&u);
        let u2 = Sym::pow(uv.clone(), Sym::int(2));
        let g = if use_sin_power {
            // u = cos (cosh): sin^m cos^n dx = sin^(m-1) u^n sin dx, du = ∓ sin dx
            let s2 = if hyperbolic {
                Sym::difference(u2, Sym::one())
            } else {
                Sym::difference(Sym::one(), u2)
            };
            let sign = if hyperbolic { 1 } else { -1 };
            Sym::product(vec![
                Sym::int(sign),
                Sym::pow(s2, Sym::int((m - 1) / 2)),
                Sym::pow(uv, Sym::int(n)),
            ])
        } else {
            // u = sin (sinh): du = cos dx
            let c2 = if hyperbolic {
                Sym::sum(vec![Sym::one(), u2])
            } else {
                Sym::difference(Sym::one(), u2)
            };
            Sym::product(vec![
                Sym::pow(c2, Sym::int((n - 1) / 2)),
                Sym::pow(uv, Sym::int(m)),
            ])
        };
        let g = if (use_sin_power && m > 0) || (!use_sin_power && n > 0) {
            g.expand()
        } else {
            g
        };
        let big_g = ctx.integrate_in(&g, &u)?;
        let back = call(if use_sin_power { fc } else { fs }, x);
        return Some(big_g.substitute(&u, &back));
    }
    // both even
    if m != 0 && n != 0 {
        if m > 0 || n > 0 {
            // write the positive even power through the other function
            let u2 = if m > 0 {
                power(fc, x, 2)
            } else {
                power(fs, x, 2)
            };
            // sin² = 1 - cos², cos² = 1 - sin², sinh² = cosh² - 1, cosh² = 1 + sinh²
            let other_sq = match (m > 0, hyperbolic) {
                (_, false) => Sym::difference(Sym::one(), u2),
                (true, true) => Sym::difference(u2, Sym::one()),
                (false, true) => Sym::sum(vec![Sym::one(), u2]),
            };
            let (k, keep) = if m > 0 {
                (m, power(fc, x, n))
            } else {
                (n, power(fs, x, m))
            };
            let g = Sym::product(vec![Sym::pow(other_sq, Sym::int(k / 2)), keep]).expand();
            return integrate(&g, ctx);
        }
        // both negative: 1 = sin² + cos² (1 = cosh² - sinh²)
        let a = integrate_monomial(
            &Monomial {
                hyperbolic,
                m: m + 2,
                n,
            },
            ctx,
        )?;
        let b = integrate_monomial(
            &Monomial {
                hyperbolic,
                m,
                n: n + 2,
            },
            ctx,
        )?;
        return Some(if hyperbolic {
            Sym::difference(b, a)
        } else {
            Sym::sum(vec![a, b])
        });
    }
    if m == 0 {
        reduce(fc, n, ctx)
    } else {
        reduce(fs, m, ctx)
    }
}

/// `∫ f(x)^k dx` for an even `k` by the reduction formulas:
/// `∫ cos^k = cos^(k-1) sin/k + (k-1)/k ∫ cos^(k-2)`,
/// `∫ sin^k = -sin^(k-1) cos/k + (k-1)/k ∫ sin^(k-2)`,
/// `∫ cos^-j = sin cos^(1-j)/(j-1) + (j-2)/(j-1) ∫ cos^(2-j)`,
/// `∫ sin^-j = -cos sin^(1-j)/(j-1) + (j-2)/(j-1) ∫ sin^(2-j)`, and the hyperbolic ones.
fn reduce(f: Func, k: i64, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    if k == 0 {
        return Some(var(x));
    }
    if !ctx.spend(1) {
        return None;
    }
    let partner = match f {
        Func::Sin => Func::Cos,
        Func::Cos => Func::Sin,
        Func::Sinh => Func::Cosh,
        _ => Func::Sinh,
    };
    // d/dx f = s_d * partner
    let s_d = if f == Func::Sin || !matches!(f, Func::Cos) {
        1
    } else {
        -1
    };
    // d/dx partner = s_p * f
    let s_p = match f {
        Func::Sin => -1, // (cos)' = -sin
        _ => 1,          // (sin)' = cos, (sinh)' = cosh, (cosh)' = sinh
    };
    // (f²)' relation: partner² = c0 + c1 f²
    let (c0, c1) = match f {
        Func::Sin | Func::Cos => (1, -1),
        Func::Sinh => (1, 1),
        _ => (-1, 1),
    };
    let next = reduce(f, if k > 0 { k - 2 } else { k + 2 }, ctx)?;
    // d/dx[partner f^(j)] = s_p f^(j+1) + j s_d partner² f^(j-1)
    //                     = s_p f^(j+1) + j s_d (c0 f^(j-1) + c1 f^(j+1))
    //                     = (s_p + j s_d c1) f^(j+1) + j s_d c0 f^(j-1)
    // k > 0: j = k - 1 gives f^k and f^(k-2); k < 0: j = k + 1 gives f^(k+2) and f^k
    let j = if k > 0 { k - 1 } else { k + 1 };
    let (hi, lo) = (s_p + j * s_d * c1, j * s_d * c0);
    let boundary = Sym::product(vec![call(partner, x), power(f, x, j)]);
    let (target, other) = if k > 0 { (hi, lo) } else { (lo, hi) };
    // ∫ f^k = (boundary - other ∫ f^(other power)) / target
    if target == 0 {
        return None;
    }
    Some(Sym::product(vec![
        Sym::Num(Number::rational(1, i128::from(target))),
        Sym::difference(boundary, Sym::product(vec![Sym::int(other), next])),
    ]))
}

/// `sin A cos B = (sin(A + B) + sin(A − B))/2`, `sin A sin B = (cos(A − B) − cos(A + B))/2`,
/// `cos A cos B = (cos(A − B) + cos(A + B))/2` for two different arguments linear in `x`
/// (a driven oscillator's `sin(w*t)*cos(w0*t)`).
pub(super) fn product_to_sum(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let Sym::Mul(fs) = f else { return None };
    let [Sym::Call(f1, a1), Sym::Call(f2, a2)] = fs.as_slice() else {
        return None;
    };
    let linear = |s: &Sym| {
        crate::sym::poly::coefficients(s, &x)
            .is_some_and(|c| c.len() == 2 && c.iter().all(|k| k.free_of(&x)))
    };
    if a1 == a2 || !linear(&a1[0]) || !linear(&a2[0]) {
        return None;
    }
    let (a, b) = (a1[0].clone(), a2[0].clone());
    let plus = Sym::sum(vec![a.clone(), b.clone()]);
    let minus = Sym::difference(a.clone(), b.clone());
    let half = |s: Sym| Sym::product(vec![Sym::rational(1, 2), s]);
    let sin = |s: Sym| Sym::call(Func::Sin, vec![s]);
    let cos = |s: Sym| Sym::call(Func::Cos, vec![s]);
    let g = match (f1, f2) {
        (Func::Sin, Func::Cos) => half(Sym::sum(vec![sin(plus), sin(minus)])),
        (Func::Cos, Func::Sin) => half(Sym::difference(sin(plus), sin(minus))),
        (Func::Sin, Func::Sin) => half(Sym::difference(cos(minus), cos(plus))),
        (Func::Cos, Func::Cos) => half(Sym::sum(vec![cos(minus), cos(plus)])),
        _ => return None,
    };
    integrate(&g, ctx)
}

/// `sin 2u = 2 sin u cos u` and `cos 2u` in the functions of `u` beside it (`2 cos² u - 1`
/// beside cosines only, `1 - 2 sin² u` beside sines only, else `cos² u - sin² u`), when the
/// integrand holds a trigonometric function of `u` as well: `sin(2x)/(1 + cos(x)^2)` and
/// `exp(sin x) sin 2x` in one argument, for the substitutions. `None` when there is no such
/// pair.
pub(super) fn double_angles(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let mut calls: Vec<(Func, Sym)> = Vec::new();
    f.any(&mut |s| {
        if let Sym::Call(func @ (Func::Sin | Func::Cos | Func::Tan), args) = s
            && args.len() == 1
            && !args[0].free_of(&x)
            && !calls.contains(&(*func, args[0].clone()))
        {
            calls.push((*func, args[0].clone()));
        }
        false
    });
    let half = |w: &Sym| Sym::product(vec![Sym::rational(1, 2), w.clone()]);
    let (_, w) = calls
        .iter()
        .find(|(func, w)| {
            matches!(func, Func::Sin | Func::Cos) && calls.iter().any(|(_, u)| *u == half(w))
        })?
        .clone();
    let u = half(&w);
    let of_u: Vec<Func> = calls
        .iter()
        .filter(|(_, v)| *v == u)
        .map(|(func, _)| *func)
        .collect();
    let (sin, cos) = (
        Sym::call(Func::Sin, vec![u.clone()]),
        Sym::call(Func::Cos, vec![u]),
    );
    let square = |s: &Sym| Sym::pow(s.clone(), Sym::int(2));
    let double_cos = if of_u.iter().all(|g| *g == Func::Cos) {
        Sym::sum(vec![
            Sym::product(vec![Sym::int(2), square(&cos)]),
            Sym::int(-1),
        ])
    } else if of_u.iter().all(|g| *g == Func::Sin) {
        Sym::difference(Sym::one(), Sym::product(vec![Sym::int(2), square(&sin)]))
    } else {
        Sym::difference(square(&cos), square(&sin))
    };
    let g = f
        .replace(
            &Sym::call(Func::Sin, vec![w.clone()]),
            &Sym::product(vec![Sym::int(2), sin, cos]),
        )
        .replace(&Sym::call(Func::Cos, vec![w]), &double_cos);
    (g != *f).then(|| integrate(&g, ctx))?
}
