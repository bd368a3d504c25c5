//! Integrals of rational functions: `1/(a + b x²)` (atan, or logarithms when the signs say so)
//! and partial fractions when the denominator factors into rational linear terms (with at most
//! one irreducible quadratic).

use super::Sym;
use super::integrate::{Ctx, ln_abs, var};
use super::poly::{NumPoly, coefficients};
use crate::ast::Func;
use crate::number::Number;

/// Numerator and denominator polynomials of a product of polynomial factors and negative
/// integer powers of polynomials.
fn as_fraction(f: &Sym, x: &str) -> Option<(Sym, Sym)> {
    let factors = match f {
        Sym::Mul(xs) => xs.clone(),
        other => vec![other.clone()],
    };
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
    let sign = |s: &Sym| s.as_num().map(|n| !n.is_negative());
    match (sign(a), sign(b)) {
        (Some(false), Some(false)) => {
            let r = inverse_quadratic(&Sym::negate(a.clone()), &Sym::negate(b.clone()), x, ctx)?;
            return Some(Sym::negate(r));
        }
        (Some(pa), Some(pb)) if pa != pb => {
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
    // assume the unknown coefficients positive, and say so
    let mut unknown = Vec::new();
    for c in [a, b] {
        if c.as_num().is_none() {
            unknown.push(c.clone());
        }
    }
    for c in unknown {
        let statement = format!("{c} > 0");
        if !ctx.assumptions.contains(&statement) {
            ctx.assumptions.push(statement);
            ctx.positive.push(c);
        }
    }
    let (sa, sb) = (Sym::sqrt(a.clone()), Sym::sqrt(b.clone()));
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

/// Partial fractions over the rationals.
fn partial_fractions(n: &NumPoly, d: &NumPoly, x: &str) -> Option<Sym> {
    let (q, r) = n.div_rem(d)?;
    let mut out = vec![integrate_poly(&q, x)];
    if r.is_zero() {
        return Some(Sym::sum(out));
    }
    // factor d = lead * Π (x - r_i)^m_i * rest
    let mut rest = d.clone();
    let mut linear: Vec<(Number, usize)> = Vec::new();
    for root in d.rational_roots() {
        let factor = NumPoly::new(vec![root.negated(), Number::ONE]);
        let mut m = 0;
        while let Some((quot, rem)) = rest.div_rem(&factor) {
            if !rem.is_zero() {
                break;
            }
            rest = quot;
            m += 1;
        }
        linear.push((root, m));
    }
    let quadratic = match rest.degree()? {
        0 => None,
        2 => Some(rest.clone()),
        _ => return None,
    };
    // unknown coefficients: A_ij for (x - r_i)^-j, then B, C for (B x + C)/quadratic
    let mut basis: Vec<NumPoly> = Vec::new();
    let mut terms: Vec<Term> = Vec::new();
    for (root, m) in &linear {
        for j in 1..=*m {
            let mut p = d.clone();
            let f = NumPoly::new(vec![root.negated(), Number::ONE]);
            for _ in 0..j {
                p = p.div_rem(&f)?.0;
            }
            basis.push(p);
            terms.push(Term::Linear(*root, j));
        }
    }
    if let Some(qd) = &quadratic {
        let cofactor = d.div_rem(qd)?.0;
        basis.push(cofactor.times(&NumPoly::new(vec![Number::ZERO, Number::ONE])));
        terms.push(Term::QuadraticX);
        basis.push(cofactor);
        terms.push(Term::QuadraticOne);
    }
    let size = d.degree()?;
    if basis.len() != size {
        return None;
    }
    let coeff = |p: &NumPoly, k: usize| p.0.get(k).copied().unwrap_or(Number::ZERO);
    let matrix: Vec<Vec<Number>> = (0..size)
        .map(|k| basis.iter().map(|b| coeff(b, k)).collect())
        .collect();
    let rhs: Vec<Number> = (0..size).map(|k| coeff(&r, k)).collect();
    let sol = solve_exact(matrix, rhs)?;
    let xv = var(x);
    let (mut bq, mut cq) = (Number::ZERO, Number::ZERO);
    for (t, c) in terms.iter().zip(&sol) {
        match t {
            Term::Linear(root, j) => {
                let lin = Sym::difference(xv.clone(), Sym::Num(*root));
                out.push(if *j == 1 {
                    Sym::product(vec![Sym::Num(*c), ln_abs(lin)])
                } else {
                    let k = Number::int(1 - *j as i64);
                    Sym::product(vec![
                        Sym::Num(c.checked_div(k)?),
                        Sym::pow(lin, Sym::Num(k)),
                    ])
                });
            }
            Term::QuadraticX => bq = *c,
            Term::QuadraticOne => cq = *c,
        }
    }
    if let Some(qd) = quadratic {
        // (B x + C)/(a x² + b x + c): complete the square
        let (c0, c1, c2) = (qd.0[0], qd.0[1], qd.0[2]);
        let qsym = qd.to_sym(x);
        let half = Number::rational(1, 2);
        // B/(2a) ln(q) + (C - B b/(2a)) ∫ 1/q
        let log_coeff = bq.times(half).checked_div(c2)?;
        out.push(Sym::product(vec![
            Sym::Num(log_coeff),
            Sym::call(Func::Ln, vec![qsym]),
        ]));
        let rest_coeff = cq.plus(bq.times(c1).times(half).checked_div(c2)?.negated());
        // ∫ dx/(a x² + b x + c) = 2/√(4ac − b²) atan((2 a x + b)/√(4ac − b²))
        let disc = Number::int(4)
            .times(c2)
            .times(c0)
            .plus(c1.times(c1).negated());
        if !disc.is_negative() && !disc.is_zero() {
            let s = Sym::sqrt(Sym::Num(disc));
            out.push(Sym::product(vec![
                Sym::Num(rest_coeff.times(Number::int(2))),
                Sym::pow(s.clone(), Sym::int(-1)),
                Sym::call(
                    Func::Atan,
                    vec![Sym::quotient(
                        Sym::sum(vec![
                            Sym::product(vec![Sym::Num(c2.times(Number::int(2))), xv]),
                            Sym::Num(c1),
                        ]),
                        s,
                    )],
                ),
            ]));
        } else {
            return None;
        }
    }
    Some(Sym::sum(out))
}

enum Term {
    Linear(Number, usize),
    QuadraticX,
    QuadraticOne,
}

fn integrate_poly(p: &NumPoly, x: &str) -> Sym {
    Sym::sum(
        p.0.iter()
            .enumerate()
            .map(|(k, c)| {
                let k1 = Number::int(k as i64 + 1);
                Sym::product(vec![
                    Sym::Num(c.checked_div(k1).expect("k + 1 > 0")),
                    Sym::pow(var(x), Sym::Num(k1)),
                ])
            })
            .collect(),
    )
}

/// Gaussian elimination with exact numbers.
fn solve_exact(mut a: Vec<Vec<Number>>, mut b: Vec<Number>) -> Option<Vec<Number>> {
    let n = b.len();
    for col in 0..n {
        let piv = (col..n).find(|&r| !a[r][col].is_zero())?;
        a.swap(col, piv);
        b.swap(col, piv);
        let inv = a[col][col].recip()?;
        for r in 0..n {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col].times(inv);
                let pivot_row = a[col].clone();
                for (dst, src) in a[r].iter_mut().zip(&pivot_row).skip(col) {
                    *dst = dst.plus(f.times(*src).negated());
                }
                b[r] = b[r].plus(f.times(b[col]).negated());
            }
        }
    }
    (0..n).map(|i| b[i].checked_div(a[i][i])).collect()
}
