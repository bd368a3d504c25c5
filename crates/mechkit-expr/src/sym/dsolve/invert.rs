//! Solving `lhs(x) = rhs` for `x` when `x` occurs once in `lhs`, by peeling off one operation
//! at a time: sums, products, powers (both roots of an even power), `ln`, `exp` and the
//! trigonometric functions (principal branches); logarithms of the same size combined into
//! one; and a quotient of two linear functions,
//! `(a + b x)/(c + d x) = R`, as `x = (R c - a)/(b - R d)`.

use crate::ast::Func;
use crate::sym::Sym;
use crate::sym::build::split_coefficient;
use crate::sym::poly::coefficients;

/// Peeling depth limit.
const MAX_DEPTH: usize = 32;

/// The values of `x` with `lhs = rhs`, every branch (an even power gives two). With
/// `constant`, `ln|u| = R + C` gives `u = C*exp(R)` (the sign and the size of `e^C` are one
/// arbitrary constant).
pub(super) fn solve_for(lhs: &Sym, x: &str, rhs: &Sym, constant: Option<&str>) -> Vec<Sym> {
    peel(lhs, x, rhs.clone(), constant, 0)
}

fn peel(lhs: &Sym, x: &str, rhs: Sym, constant: Option<&str>, depth: usize) -> Vec<Sym> {
    if depth > MAX_DEPTH || lhs.free_of(x) {
        return Vec::new();
    }
    let next = |l: &Sym, r: Sym| peel(l, x, r, constant, depth + 1);
    match lhs {
        Sym::Var(v) if v == x => vec![rhs],
        Sym::Add(terms) => {
            let (with, without): (Vec<Sym>, Vec<Sym>) =
                terms.iter().cloned().partition(|t| !t.free_of(x));
            let rhs = Sym::difference(rhs, Sym::sum(without));
            match with.as_slice() {
                [one] => next(one, rhs),
                _ => match one_logarithm(&with) {
                    // c ln|P| = R + C: P = C e^{R/c}
                    Some((c, p)) => ln_abs(&p, divided(&rhs, c, constant), x, constant, depth),
                    None => Vec::new(),
                },
            }
        }
        Sym::Mul(factors) => {
            let (with, without): (Vec<Sym>, Vec<Sym>) =
                factors.iter().cloned().partition(|t| !t.free_of(x));
            match with.as_slice() {
                [one] => next(one, divided(&rhs, Sym::product(without), constant)),
                _ => linear_fraction(&with, x, &Sym::quotient(rhs, Sym::product(without)))
                    .map(|(g, v)| next(&g, v))
                    .unwrap_or_default(),
            }
        }
        Sym::Pow(b, e) if e.free_of(x) => {
            let root = Sym::pow(rhs, Sym::quotient(Sym::one(), (**e).clone()));
            let even = e
                .as_num()
                .and_then(crate::number::Number::as_rational)
                .is_some_and(|(p, _)| p % 2 == 0);
            let mut out = next(b, root.clone());
            if even {
                out.extend(next(b, Sym::negate(root)));
            }
            out
        }
        Sym::Pow(b, e) if b.free_of(x) => next(
            e,
            Sym::quotient(
                Sym::call(Func::Ln, vec![rhs]),
                Sym::call(Func::Ln, vec![(**b).clone()]),
            ),
        ),
        Sym::Call(f, args) if args.len() == 1 => {
            let u = &args[0];
            let call = |g: Func| Sym::call(g, vec![rhs.clone()]);
            match f {
                Func::Ln => {
                    if let Sym::Call(Func::Abs, inner) = u {
                        return ln_abs(&inner[0], rhs, x, constant, depth);
                    }
                    next(u, call(Func::Exp))
                }
                Func::Exp => next(u, call(Func::Ln)),
                Func::Atan => next(u, call(Func::Tan)),
                Func::Tan => next(u, call(Func::Atan)),
                Func::Sin => next(u, call(Func::Asin)),
                Func::Asin => next(u, call(Func::Sin)),
                Func::Cos => next(u, call(Func::Acos)),
                Func::Acos => next(u, call(Func::Cos)),
                Func::Cbrt => next(u, Sym::pow(rhs.clone(), Sym::int(3))),
                Func::Abs => {
                    let mut out = next(u, rhs.clone());
                    out.extend(next(u, Sym::negate(rhs)));
                    out
                }
                _ => Vec::new(),
            }
        }
        _ => Vec::new(),
    }
}

/// `ln|u| = rhs`: `u = C e^R` when `rhs = R + C` (the sign and the size of `e^C` are one
/// arbitrary constant), else `u = ±e^rhs`.
fn ln_abs(u: &Sym, rhs: Sym, x: &str, constant: Option<&str>, depth: usize) -> Vec<Sym> {
    let next = |r: Sym| peel(u, x, r, constant, depth + 1);
    let with_constant = constant
        .filter(|c| rhs.diff(c).is_one() && !rhs.free_of(c))
        .map(|c| {
            Sym::product(vec![
                Sym::var(c),
                Sym::call(Func::Exp, vec![rhs.substitute(c, &Sym::zero())]),
            ])
        });
    if let Some(v) = with_constant {
        return next(v);
    }
    let e = Sym::call(Func::Exp, vec![rhs]);
    let mut out = next(e.clone());
    out.extend(next(Sym::negate(e)));
    out
}

/// `c ln|u1| - c ln|u2| + …` as `(c, u1/u2 …)`, one logarithm `c ln|u1/u2 …|` (what partial
/// fractions leave: `∫ dx/(x² - 1) = ln|x - 1|/2 - ln|x + 1|/2`); `None` unless every term
/// is a logarithm with a coefficient of the same size.
fn one_logarithm(terms: &[Sym]) -> Option<(Sym, Sym)> {
    let mut size = None;
    let mut factors = Vec::new();
    for term in terms {
        let (n, Some(Sym::Call(Func::Ln, u))) = split_coefficient(term) else {
            return None;
        };
        let inner = match &u[0] {
            Sym::Call(Func::Abs, v) => v[0].clone(),
            other => other.clone(),
        };
        let c = if n.is_negative() { n.negated() } else { n };
        if size.is_some_and(|s| s != c) {
            return None;
        }
        size = Some(c);
        factors.push(Sym::pow(
            inner,
            Sym::int(if n.is_negative() { -1 } else { 1 }),
        ));
    }
    Some((Sym::Num(size?), Sym::product(factors)))
}

/// `(R + C)/p`, written `R/p + C` when `C` is the arbitrary constant (`C/p` is one as well),
/// so that a logarithm peeled next still sees `+ C`.
fn divided(rhs: &Sym, p: Sym, constant: Option<&str>) -> Sym {
    match constant {
        Some(c) if rhs.diff(c).is_one() && p.free_of(c) => Sym::sum(vec![
            Sym::quotient(rhs.substitute(c, &Sym::zero()), p),
            Sym::var(c),
        ]),
        _ => Sym::quotient(rhs.clone(), p),
    }
}

/// `g` and its value with `Π factors = rhs` when the factors are `(a + b g)` and
/// `(c + d g)^-1` for `g` = `x` or one function of `x` (a Möbius transformation, what
/// `ln|(a + b x)/(c + d x)|` leaves once the logarithm is peeled, or
/// `ln|(cos x - 1)/(cos x + 1)|` from `x' = sin x`): `g = (R c - a)/(b - R d)`.
fn linear_fraction(factors: &[Sym], x: &str, rhs: &Sym) -> Option<(Sym, Sym)> {
    let mut inner = Sym::var(x);
    factors[0].any(&mut |n| {
        let found = matches!(n, Sym::Call(_, a) if !a[0].free_of(x));
        if found {
            inner = n.clone();
        }
        found
    });
    let g = "__g";
    let (mut num, mut den) = (Vec::new(), Vec::new());
    for f in factors {
        let (list, f) = match f {
            Sym::Pow(b, e)
                if e.as_num()
                    .is_some_and(|n| n == crate::number::Number::int(-1)) =>
            {
                (&mut den, &**b)
            }
            other => (&mut num, other),
        };
        let f = f.replace(&inner, &Sym::var(g));
        if !f.free_of(x) {
            return None;
        }
        list.push(f);
    }
    let linear = |s: Vec<Sym>| {
        let c = coefficients(&Sym::product(s), g)?;
        (c.len() <= 2 && c.iter().all(|k| k.free_of(g)))
            .then(|| (c[0].clone(), c.get(1).cloned().unwrap_or_else(Sym::zero)))
    };
    let ((a, b), (c, d)) = (linear(num)?, linear(den)?);
    let top = Sym::difference(Sym::product(vec![rhs.clone(), c]), a);
    let bottom = Sym::difference(b, Sym::product(vec![rhs.clone(), d]));
    (!bottom.is_zero()).then(|| (inner, Sym::quotient(top, bottom)))
}
