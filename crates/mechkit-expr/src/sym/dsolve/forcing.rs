//! Undetermined coefficients: a forcing that is a sum of `c t^k e^{at} cos(bt)` and
//! `c t^k e^{at} sin(bt)` terms (products of sines and cosines are first turned into sums,
//! `sinh`/`cosh` into exponentials, `sin(bt + φ)` split) gets the trial
//! `t^s e^{at} (P(t) cos bt + Q(t) sin bt)`, `s` the multiplicity of `a + ib` as a root of the
//! characteristic polynomial (resonance when `s > 0`); the coefficients of `P` and `Q` solve
//! the linear system from matching terms.

use crate::ast::Func;
use crate::sym::poly::coefficients;
use crate::sym::{Sym, solve_linear};

/// Product-to-sum steps allowed per term.
const MAX_STEPS: usize = 64;

/// One group of forcing terms with the same `e^{at}` and frequency `b` (zero: no sine).
struct Group {
    a: Sym,
    b: Sym,
    degree: usize,
    terms: Vec<Sym>,
}

/// A particular solution of `Σ a_k x^(k) = g`, and whether it is resonant.
pub(super) fn undetermined(a: &[Sym], g: &Sym, t: &str) -> Option<(Sym, bool)> {
    let mut groups: Vec<Group> = Vec::new();
    for term in linear_terms(g, t)? {
        let (coef, k, ra, b, trig) = parts(&term, t)?;
        let rebuilt = Sym::product(vec![
            coef,
            Sym::pow(Sym::var(t), Sym::int(k as i64)),
            exp_at(&ra, t),
            trig.map_or_else(Sym::one, |f| Sym::call(f, vec![times_t(&b, t)])),
        ]);
        match groups.iter_mut().find(|gr| gr.a == ra && gr.b == b) {
            Some(gr) => {
                gr.degree = gr.degree.max(k);
                gr.terms.push(rebuilt);
            }
            None => groups.push(Group {
                a: ra,
                b,
                degree: k,
                terms: vec![rebuilt],
            }),
        }
    }
    let mut total = Vec::new();
    let mut resonant = false;
    for (i, gr) in groups.iter().enumerate() {
        let s = multiplicity(a, &gr.a, &gr.b);
        resonant |= s > 0;
        total.push(group_particular(a, gr, s, i, t)?);
    }
    Some((Sym::sum(total), resonant))
}

fn times_t(b: &Sym, t: &str) -> Sym {
    Sym::product(vec![b.clone(), Sym::var(t)])
}

fn exp_at(a: &Sym, t: &str) -> Sym {
    Sym::call(Func::Exp, vec![times_t(a, t)])
}

/// `u = r t + φ` with `r`, `φ` free of `t`.
fn linear_in(u: &Sym, t: &str) -> Option<(Sym, Sym)> {
    let r = u.diff(t);
    if !r.free_of(t) {
        return None;
    }
    let phi = Sym::difference(u.clone(), times_t(&r, t)).expand();
    phi.free_of(t).then_some((r, phi))
}

/// `sinh`, `cosh` as exponentials, `sin(bt + φ)` and `cos(bt + φ)` split by the addition
/// theorems.
fn rewrite(s: &Sym, t: &str) -> Sym {
    let s = s.map_children(|c| rewrite(c, t));
    let Sym::Call(f, args) = &s else { return s };
    let u = &args[0];
    if u.free_of(t) {
        return s;
    }
    let half = |sign: i64| {
        Sym::product(vec![
            Sym::rational(1, 2),
            Sym::sum(vec![
                Sym::call(Func::Exp, vec![u.clone()]),
                Sym::product(vec![
                    Sym::int(sign),
                    Sym::call(Func::Exp, vec![Sym::negate(u.clone())]),
                ]),
            ]),
        ])
    };
    match f {
        Func::Sinh => half(-1),
        Func::Cosh => half(1),
        Func::Sin | Func::Cos => match linear_in(u, t) {
            Some((r, phi)) if !phi.is_zero() => {
                let bt = times_t(&r, t);
                let (sb, cb) = (
                    Sym::call(Func::Sin, vec![bt.clone()]),
                    Sym::call(Func::Cos, vec![bt]),
                );
                let (sp, cp) = (
                    Sym::call(Func::Sin, vec![phi.clone()]),
                    Sym::call(Func::Cos, vec![phi]),
                );
                if *f == Func::Sin {
                    Sym::sum(vec![Sym::product(vec![sb, cp]), Sym::product(vec![cb, sp])])
                } else {
                    Sym::difference(Sym::product(vec![cb, cp]), Sym::product(vec![sb, sp]))
                }
            }
            _ => s.clone(),
        },
        _ => s.clone(),
    }
}

fn terms_of(s: Sym) -> Vec<Sym> {
    match s {
        Sym::Add(ts) => ts,
        other => vec![other],
    }
}

/// The forcing as a sum of terms with at most one sine or cosine each.
fn linear_terms(g: &Sym, t: &str) -> Option<Vec<Sym>> {
    let mut pending = terms_of(rewrite(g, t).expand());
    let mut out = Vec::new();
    let mut steps = 0;
    while let Some(term) = pending.pop() {
        match product_to_sum(&term, t) {
            None => out.push(term),
            Some(sum) => {
                steps += 1;
                if steps > MAX_STEPS * 16 {
                    return None;
                }
                pending.extend(terms_of(sum.expand()));
            }
        }
    }
    Some(out)
}

/// One product-to-sum step when the term holds two sines/cosines (or a power of one).
fn product_to_sum(term: &Sym, t: &str) -> Option<Sym> {
    let factors = crate::sym::integrate::factors(term);
    let is_trig = |f: &Sym| matches!(f, Sym::Call(Func::Sin | Func::Cos, a) if !a[0].free_of(t));
    let mut trig = Vec::new();
    let mut rest = Vec::new();
    for f in factors {
        match &f {
            Sym::Pow(b, e) if is_trig(b) => {
                let n = e.as_num()?.as_integer()?;
                if n < 1 {
                    return None;
                }
                for _ in 0..n {
                    trig.push((**b).clone());
                }
            }
            _ if is_trig(&f) => trig.push(f),
            _ => rest.push(f),
        }
    }
    if trig.len() < 2 {
        return None;
    }
    let (Sym::Call(f1, x), Sym::Call(f2, y)) = (trig.pop()?, trig.pop()?) else {
        return None;
    };
    let (x, y) = (x[0].clone(), y[0].clone());
    let minus = Sym::difference(x.clone(), y.clone());
    let plus = Sym::sum(vec![x, y]);
    let c = |u: Sym| Sym::call(Func::Cos, vec![u]);
    let s = |u: Sym| Sym::call(Func::Sin, vec![u]);
    let pair = match (f1, f2) {
        (Func::Cos, Func::Cos) => Sym::sum(vec![c(minus), c(plus)]),
        (Func::Sin, Func::Sin) => Sym::difference(c(minus), c(plus)),
        // sin x cos y = (sin(x + y) + sin(x − y))/2
        (Func::Sin, Func::Cos) => Sym::sum(vec![s(plus), s(minus)]),
        (Func::Cos, Func::Sin) => Sym::difference(s(plus), s(minus)),
        _ => return None,
    };
    rest.extend(trig);
    rest.push(Sym::rational(1, 2));
    rest.push(pair);
    Some(Sym::product(rest))
}

type Parts = (Sym, usize, Sym, Sym, Option<Func>);

/// `coef t^k e^{a t} trig(b t)` of one term.
fn parts(term: &Sym, t: &str) -> Option<Parts> {
    let factors = crate::sym::integrate::factors(term);
    let (mut coef, mut k, mut a) = (Vec::new(), 0usize, Vec::new());
    let (mut b, mut trig) = (Sym::zero(), None);
    for f in factors {
        match &f {
            _ if f.free_of(t) => coef.push(f),
            Sym::Var(_) => k += 1,
            Sym::Pow(base, e) if matches!(&**base, Sym::Var(v) if v == t) => {
                let n = e.as_num()?.as_integer()?;
                k += usize::try_from(n).ok()?;
            }
            Sym::Call(Func::Exp, u) => {
                let (r, phi) = linear_in(&u[0], t)?;
                a.push(r);
                coef.push(Sym::call(Func::Exp, vec![phi]));
            }
            Sym::Pow(base, u) if matches!(&**base, Sym::Var(v) if v == "e") => {
                let (r, phi) = linear_in(u, t)?;
                a.push(r);
                coef.push(Sym::call(Func::Exp, vec![phi]));
            }
            Sym::Call(func @ (Func::Sin | Func::Cos), u) if trig.is_none() => {
                let (r, phi) = linear_in(&u[0], t)?;
                if !phi.is_zero() {
                    return None;
                }
                b = r;
                trig = Some(*func);
            }
            _ => return None,
        }
    }
    if k > 12 {
        return None;
    }
    Some((Sym::product(coef), k, Sym::sum(a), b, trig))
}

/// How often `a + ib` is a root of `Σ c_k r^k`: how many of the polynomial and its
/// derivatives vanish there, real and imaginary parts (`(a + ib)^j` expanded by repeated
/// multiplication), each simplified to 0.
fn multiplicity(c: &[Sym], a: &Sym, b: &Sym) -> usize {
    let zero = |s: Vec<Sym>| Sym::sum(s).expand().is_zero();
    // powers[j] = (Re, Im) of (a + ib)^j
    let mut powers = vec![(Sym::one(), Sym::zero())];
    for _ in 1..c.len() {
        let (re, im) = powers.last().expect("one power").clone();
        powers.push((
            Sym::difference(
                Sym::product(vec![re.clone(), a.clone()]),
                Sym::product(vec![im.clone(), b.clone()]),
            ),
            Sym::sum(vec![
                Sym::product(vec![re, b.clone()]),
                Sym::product(vec![im, a.clone()]),
            ]),
        ));
    }
    let mut s = 0;
    while s + 1 < c.len() {
        // the s-th derivative: Σ_k c_k k!/(k-s)! r^(k-s)
        let (mut re, mut im) = (Vec::new(), Vec::new());
        for (k, ck) in c.iter().enumerate().skip(s) {
            let falling: i64 = ((k - s + 1)..=k).map(|i| i as i64).product();
            let coef = Sym::product(vec![Sym::int(falling), ck.clone()]);
            re.push(Sym::product(vec![coef.clone(), powers[k - s].0.clone()]));
            im.push(Sym::product(vec![coef, powers[k - s].1.clone()]));
        }
        if !(zero(re) && zero(im)) {
            break;
        }
        s += 1;
    }
    s
}

/// The particular solution for one group: the trial, its coefficients matched.
fn group_particular(a: &[Sym], gr: &Group, s: usize, index: usize, t: &str) -> Option<Sym> {
    let tv = Sym::var(t);
    let trig = !gr.b.is_zero();
    let mut unknowns = Vec::new();
    let mut poly = |tag: &str| {
        let mut terms = Vec::new();
        for j in 0..=gr.degree {
            let name = format!("__{tag}{index}_{j}");
            terms.push(Sym::product(vec![
                Sym::var(&name),
                Sym::pow(tv.clone(), Sym::int(j as i64)),
            ]));
            unknowns.push(name);
        }
        Sym::sum(terms)
    };
    let bt = times_t(&gr.b, t);
    let (cos, sin) = (
        Sym::call(Func::Cos, vec![bt.clone()]),
        Sym::call(Func::Sin, vec![bt]),
    );
    let shape = if trig {
        let p = poly("A");
        let q = poly("B");
        Sym::sum(vec![
            Sym::product(vec![p, cos.clone()]),
            Sym::product(vec![q, sin.clone()]),
        ])
    } else {
        poly("A")
    };
    let e = exp_at(&gr.a, t);
    let trial = Sym::product(vec![
        Sym::pow(tv.clone(), Sym::int(s as i64)),
        e.clone(),
        shape,
    ]);
    let mut lhs = Vec::new();
    let mut d = trial.clone();
    for ak in a {
        lhs.push(Sym::product(vec![ak.clone(), d.clone()]));
        d = d.diff(t);
    }
    lhs.push(Sym::negate(Sym::sum(gr.terms.clone())));
    let mut r = Sym::sum(lhs).expand().replace(&e, &Sym::one());
    if trig {
        r = r
            .replace(&cos, &Sym::var("__cos"))
            .replace(&sin, &Sym::var("__sin"));
    }
    let mut eqs = Vec::new();
    for cj in coefficients(&r, t)? {
        if !cj.free_of(t) {
            return None;
        }
        let mut parts = vec![cj.clone()];
        if trig {
            parts = vec![cj.diff("__cos"), cj.diff("__sin")];
            let rest = cj
                .substitute("__cos", &Sym::zero())
                .substitute("__sin", &Sym::zero());
            if !rest.expand().is_zero() {
                return None;
            }
        }
        for p in parts {
            let p = p.expand();
            if !p.is_zero() && !eqs.contains(&p) {
                eqs.push(p);
            }
        }
    }
    let names: Vec<&str> = unknowns.iter().map(String::as_str).collect();
    let values = solve_linear(&eqs, &names).ok()?;
    let mut out = trial;
    for (n, v) in names.iter().zip(values) {
        out = out.substitute(n, &v);
    }
    Some(out)
}
