//! Partial fractions over the rationals: the denominator factors into rational linear terms
//! (rational roots with their multiplicities) and powers of irreducible quadratics (found by
//! square-free decomposition, `gcd(d, d')`, and by rational roots in `x²` of an even
//! polynomial: `x^4 + 5 x^2 + 4 = (x² + 1)(x² + 4)`).

use super::{Sym, ln_abs, var};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::NumPoly;

enum Term {
    Linear(Number, usize),
    /// `x/q^j` and `1/q^j` for the quadratic of that index.
    QuadraticX(usize, usize),
    QuadraticOne(usize, usize),
}

/// `∫ n/d dx` by partial fractions.
pub(super) fn partial_fractions(n: &NumPoly, d: &NumPoly, x: &str) -> Option<Sym> {
    let (q, r) = n.div_rem(d)?;
    let mut out = vec![integrate_poly(&q, x)];
    if r.is_zero() {
        return Some(Sym::sum(out));
    }
    if d.degree()? > 24 {
        return None;
    }
    // factor d = lead * Π (x - r_i)^m_i * Π q_k^n_k
    let mut rest = d.clone();
    let mut linear: Vec<(Number, usize)> = Vec::new();
    for root in d.rational_roots() {
        let factor = NumPoly::new(vec![root.negated(), Number::ONE]);
        let m = divide_out(&mut rest, &factor);
        linear.push((root, m));
    }
    let mut quadratics: Vec<(NumPoly, usize)> = Vec::new();
    for qd in quadratic_candidates(&rest) {
        let m = divide_out(&mut rest, &qd);
        if m > 0 {
            quadratics.push((qd, m));
        }
    }
    if rest.degree()? != 0 {
        return None;
    }
    // unknown coefficients: A_ij for (x - r_i)^-j, B_kj, C_kj for (B x + C)/q_k^j
    let mut basis: Vec<NumPoly> = Vec::new();
    let mut terms: Vec<Term> = Vec::new();
    let xpoly = NumPoly::new(vec![Number::ZERO, Number::ONE]);
    for (root, m) in &linear {
        let f = NumPoly::new(vec![root.negated(), Number::ONE]);
        let mut p = d.clone();
        for j in 1..=*m {
            p = p.div_rem(&f)?.0;
            basis.push(p.clone());
            terms.push(Term::Linear(*root, j));
        }
    }
    for (k, (qd, m)) in quadratics.iter().enumerate() {
        let mut p = d.clone();
        for j in 1..=*m {
            p = p.div_rem(qd)?.0;
            basis.push(p.times(&xpoly));
            terms.push(Term::QuadraticX(k, j));
            basis.push(p.clone());
            terms.push(Term::QuadraticOne(k, j));
        }
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
    let mut bq = vec![vec![Number::ZERO; 0]; quadratics.len()];
    for (k, (_, m)) in quadratics.iter().enumerate() {
        bq[k] = vec![Number::ZERO; 2 * m];
    }
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
            Term::QuadraticX(k, j) => bq[*k][2 * (j - 1)] = *c,
            Term::QuadraticOne(k, j) => bq[*k][2 * (j - 1) + 1] = *c,
        }
    }
    for ((qd, m), cs) in quadratics.iter().zip(&bq) {
        for j in 1..=*m {
            out.push(quadratic_term(
                qd,
                j,
                cs[2 * (j - 1)],
                cs[2 * (j - 1) + 1],
                x,
            )?);
        }
    }
    Some(Sym::sum(out))
}

/// Divides `factor` out of `p` as often as it goes; the multiplicity.
fn divide_out(p: &mut NumPoly, factor: &NumPoly) -> usize {
    let mut m = 0;
    while let Some((quot, rem)) = p.div_rem(factor) {
        if !rem.is_zero() || m > 64 {
            break;
        }
        *p = quot;
        m += 1;
    }
    m
}

/// Quadratic factors of a polynomial without rational roots: itself when of degree 2, the
/// quadratics of its square-free decomposition, the two factors of an even quartic that splits
/// over the rationals (`x⁴ + 4 = (x² + 2x + 2)(x² - 2x + 2)`), and `x² - y` for rational roots
/// `y` of an even polynomial in `y = x²`.
fn quadratic_candidates(p: &NumPoly) -> Vec<NumPoly> {
    let mut out: Vec<NumPoly> = Vec::new();
    let mut push = |q: NumPoly| {
        let q = monic(&q);
        let mut found = even_quartic_factors(&q);
        if q.degree() == Some(2) {
            found.push(q);
        }
        for q in found {
            if !out.contains(&q) {
                out.push(q);
            }
        }
    };
    push(p.clone());
    let mut cur = p.clone();
    for _ in 0..8 {
        let g = gcd(&cur, &derivative(&cur));
        if g.degree().unwrap_or(0) == 0 {
            break;
        }
        if let Some((q, _)) = cur.div_rem(&g) {
            push(q);
        }
        push(g.clone());
        cur = g;
    }
    // even polynomials: rational roots in x²
    if p.0.iter().skip(1).step_by(2).all(|c| c.is_zero()) {
        let y = NumPoly::new(p.0.iter().step_by(2).copied().collect());
        for root in y.rational_roots() {
            push(NumPoly::new(vec![
                root.negated(),
                Number::ZERO,
                Number::ONE,
            ]));
        }
    }
    out
}

/// `x⁴ + b x² + d = (x² + r x + q)(x² - r x + q)` with `q = ±√d` and `r = √(2q - b)`, when
/// both are rational and `r > 0` (a monic `p`; nothing for any other).
fn even_quartic_factors(p: &NumPoly) -> Vec<NumPoly> {
    let c = &p.0;
    if p.degree() != Some(4) || !c[1].is_zero() || !c[3].is_zero() || !c[4].is_one() {
        return Vec::new();
    }
    let (b, d) = (c[2], c[0]);
    let Some(root_d) = d.exact_root(2) else {
        return Vec::new();
    };
    for q in [root_d, root_d.negated()] {
        let r2 = q.times(Number::int(2)).plus(b.negated());
        if r2.is_negative() || r2.is_zero() {
            continue;
        }
        if let Some(r) = r2.exact_root(2) {
            return vec![
                NumPoly::new(vec![q, r, Number::ONE]),
                NumPoly::new(vec![q, r.negated(), Number::ONE]),
            ];
        }
    }
    Vec::new()
}

fn monic(p: &NumPoly) -> NumPoly {
    let lead = *p.0.last().expect("not zero");
    NumPoly::new(
        p.0.iter()
            .map(|c| c.checked_div(lead).unwrap_or(*c))
            .collect(),
    )
}

fn derivative(p: &NumPoly) -> NumPoly {
    NumPoly::new(
        p.0.iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c.times(Number::int(k as i64)))
            .collect(),
    )
}

/// Greatest common divisor (monic), by Euclid's algorithm.
fn gcd(a: &NumPoly, b: &NumPoly) -> NumPoly {
    let (mut a, mut b) = (a.clone(), b.clone());
    for _ in 0..64 {
        if b.is_zero() {
            break;
        }
        let Some((_, r)) = a.div_rem(&b) else { break };
        a = b;
        b = r;
    }
    if a.is_zero() { a } else { monic(&a) }
}

/// `∫ (B x + C)/q^j dx` for a quadratic `q = c2 x² + c1 x + c0` without rational roots:
/// `B/(2 c2) ∫ q'/q^j + (C - B c1/(2 c2)) I_j`, with `Δ = 4 c2 c0 - c1²`,
/// `I_1 = 2/√Δ atan((2 c2 x + c1)/√Δ)` when `Δ > 0` (no real roots) and
/// `I_1 = 1/√-Δ ln|(2 c2 x + c1 - √-Δ)/(2 c2 x + c1 + √-Δ)|` when `Δ < 0` (two irrational
/// roots: `1/(x² - 2)`), and
/// `I_j = (2 c2 x + c1)/((j-1) Δ q^(j-1)) + 2 (2j - 3) c2/((j-1) Δ) I_(j-1)` for either.
fn quadratic_term(qd: &NumPoly, j: usize, b: Number, c: Number, x: &str) -> Option<Sym> {
    let (c0, c1, c2) = (qd.0[0], qd.0[1], qd.0[2]);
    let disc = Number::int(4)
        .times(c2)
        .times(c0)
        .plus(c1.times(c1).negated());
    if disc.is_zero() {
        return None;
    }
    let real_roots = disc.is_negative();
    let qsym = qd.to_sym(x);
    let xv = var(x);
    let half = Number::rational(1, 2);
    let log_coeff = b.times(half).checked_div(c2)?;
    let first = if j == 1 {
        Sym::product(vec![
            Sym::Num(log_coeff),
            if real_roots {
                ln_abs(qsym.clone())
            } else {
                Sym::call(Func::Ln, vec![qsym.clone()])
            },
        ])
    } else {
        let k = Number::int(1 - j as i64);
        Sym::product(vec![
            Sym::Num(log_coeff.checked_div(k)?),
            Sym::pow(qsym.clone(), Sym::Num(k)),
        ])
    };
    let rest_coeff = c.plus(b.times(c1).times(half).checked_div(c2)?.negated());
    let lin = Sym::sum(vec![
        Sym::product(vec![Sym::Num(c2.times(Number::int(2))), xv]),
        Sym::Num(c1),
    ]);
    let mut integral = if real_roots {
        let s = Sym::sqrt(Sym::Num(disc.negated()));
        Sym::product(vec![
            Sym::pow(s.clone(), Sym::int(-1)),
            ln_abs(Sym::quotient(
                Sym::difference(lin.clone(), s.clone()),
                Sym::sum(vec![lin.clone(), s]),
            )),
        ])
    } else {
        let s = Sym::sqrt(Sym::Num(disc));
        Sym::product(vec![
            Sym::int(2),
            Sym::pow(s.clone(), Sym::int(-1)),
            Sym::call(Func::Atan, vec![Sym::quotient(lin.clone(), s)]),
        ])
    };
    for i in 2..=j {
        let i1 = Number::int(i as i64 - 1);
        let d = i1.times(disc);
        integral = Sym::sum(vec![
            Sym::product(vec![
                Sym::Num(d.recip()?),
                lin.clone(),
                Sym::pow(qsym.clone(), Sym::Num(i1.negated())),
            ]),
            Sym::product(vec![
                Sym::Num(
                    Number::int(2 * (2 * i as i64 - 3))
                        .times(c2)
                        .checked_div(d)?,
                ),
                integral,
            ]),
        ]);
    }
    Some(Sym::sum(vec![
        first,
        Sym::product(vec![Sym::Num(rest_coeff), integral]),
    ]))
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
