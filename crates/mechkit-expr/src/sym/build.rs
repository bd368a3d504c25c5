//! The simplifying constructors: every `Sym` is built through these, so it is always
//! canonical.

use super::Sym;
use super::identities::{content, content_number, fold_call, is_negated, pythagoras};
use super::order::{compare, compare_terms};
use crate::ast::{BinOp, Func};
use crate::number::Number;

#[path = "build_terms.rs"]
mod terms;
pub(crate) use terms::{hash_of, split_coefficient};
use terms::{may_equal, split_coefficient_owned};

/// Whether `a` and `b` can differ only by their numbers: the numeric coefficients of terms
/// and factors, and those a product pushed into its sums (`x*(2*y + 2)` and `x*(y + 1)`).
/// Two sums one number apart must pass; most that are not fail without anything built.
fn same_but_numbers(a: &Sym, b: &Sym) -> bool {
    fn factors(t: &Sym) -> &[Sym] {
        match t {
            Sym::Num(_) => &[],
            Sym::Mul(xs) if matches!(xs.first(), Some(Sym::Num(_))) => &xs[1..],
            Sym::Mul(xs) => xs,
            other => std::slice::from_ref(other),
        }
    }
    let all = |xs: &[Sym], ys: &[Sym]| {
        xs.len() == ys.len() && xs.iter().zip(ys).all(|(x, y)| same_but_numbers(x, y))
    };
    match (a, b) {
        (Sym::Num(_), Sym::Num(_)) => true,
        (Sym::Add(xs), Sym::Add(ys)) => all(xs, ys),
        (Sym::Pow(x, e), Sym::Pow(y, f)) => e == f && same_but_numbers(x, y),
        // `2*x` against `x`: the factors after the number (a product's are never products)
        (Sym::Mul(_), _) | (_, Sym::Mul(_)) => all(factors(a), factors(b)),
        _ => a == b,
    }
}

/// Divides the content `held` (already counted in `coefficient`) out of the sum `base`:
/// its primitive part, as [`content`] gives it.
fn make_primitive(base: &mut Sym, held: &mut Number, coefficient: &mut Number) {
    if held.is_one() {
        return;
    }
    let Sym::Add(terms) = base else {
        unreachable!("only sums hold a content")
    };
    let (c, primitive) = content(terms);
    // `content` may keep a number it was expected to take out (it stays total)
    if c != *held {
        *coefficient = coefficient
            .times(c)
            .times(held.recip().expect("a content is not zero"));
    }
    *base = primitive;
    *held = Number::ONE;
}

fn with_coefficient(c: Number, rest: Sym) -> Sym {
    if c.is_one() {
        rest
    } else {
        Sym::product(vec![Sym::Num(c), rest])
    }
}

impl Sym {
    /// The canonical sum of `terms`.
    pub fn sum(terms: Vec<Sym>) -> Sym {
        let mut flat = Vec::with_capacity(terms.len());
        for t in terms {
            match t {
                Sym::Add(xs) => flat.extend(xs),
                other => flat.push(other),
            }
        }
        let mut constant = Number::ZERO;
        let mut collected: Vec<(Sym, Number)> = Vec::new();
        // a hash of each collected term, which tells deep terms apart before they are compared
        let mut keys: Vec<Option<u64>> = Vec::new();
        for t in flat {
            match split_coefficient_owned(t) {
                (c, None) => constant = constant.plus(c),
                (c, Some(rest)) => {
                    let mut key = None;
                    let like = (0..collected.len()).find(|&i| {
                        may_equal(&rest, &mut key, &collected[i].0, &mut keys[i])
                            && collected[i].0 == rest
                    });
                    if let Some(i) = like {
                        collected[i].1 = collected[i].1.plus(c);
                    } else {
                        collected.push((rest, c));
                        keys.push(key);
                    }
                }
            }
        }
        collected.retain(|(_, c)| !c.is_zero());
        pythagoras(&mut collected, &mut constant);
        let mut out: Vec<Sym> = collected
            .into_iter()
            .map(|(rest, c)| with_coefficient(c, rest))
            .collect();
        out.sort_by(compare_terms);
        if !constant.is_zero() || out.is_empty() {
            out.push(Sym::Num(constant));
        }
        if out.len() == 1 {
            out.pop().expect("one term")
        } else {
            Sym::Add(out)
        }
    }

    /// The canonical product of `factors`.
    ///
    /// A sum factor is kept as given, with its numeric content counted in the product's
    /// number, and made primitive only where it is compared with another sum or raised to a
    /// power: a lone sum then takes the product's number in one pass over its terms. (Making
    /// it primitive first and scaling it after rebuilt its terms twice, and a sum nested `n`
    /// deep, `x + 3*(x + 3*(…)/2)/2`, `2ⁿ` times.)
    pub fn product(factors: Vec<Sym>) -> Sym {
        #[cfg(test)]
        tests::PRODUCTS.with(|n| n.set(n.get() + 1));
        let mut coefficient = Number::ONE;
        // (base, exponent, the numeric content a sum base still holds, a hash of a base that
        // is not a sum: deep bases are told apart by it before they are compared node by node)
        let mut bases: Vec<(Sym, Sym, Number, Option<u64>)> = Vec::new();
        let mut pending = factors;
        while let Some(f) = pending.pop() {
            match f {
                Sym::Num(n) => coefficient = coefficient.times(n),
                Sym::Mul(xs) => pending.extend(xs),
                other => {
                    let (mut base, exp, mut held) = match other {
                        Sym::Pow(b, e) => (*b, *e, Number::ONE),
                        // a sum is compared by its primitive part: x - pi and pi - x are one
                        // base up to the number -1
                        Sym::Add(terms) => {
                            let c = content_number(&terms);
                            coefficient = coefficient.times(c);
                            (Sym::Add(terms), Sym::one(), c)
                        }
                        x => (x, Sym::one(), Number::ONE),
                    };
                    let is_sum = matches!(base, Sym::Add(_));
                    let mut key = None;
                    let mut found = None;
                    for (i, (b, _, h, k)) in bases.iter_mut().enumerate() {
                        if !is_sum && !may_equal(&base, &mut key, b, k) {
                            continue;
                        }
                        if is_sum && matches!(b, Sym::Add(_)) {
                            // only sums that may be one number apart are made primitive
                            if !same_but_numbers(b, &base) {
                                continue;
                            }
                            make_primitive(b, h, &mut coefficient);
                            make_primitive(&mut base, &mut held, &mut coefficient);
                        }
                        if *b == base {
                            found = Some(i);
                            break;
                        }
                    }
                    match found {
                        Some(i) => bases[i].1 = Sym::sum(vec![bases[i].1.clone(), exp]),
                        None => bases.push((base, exp, held, key)),
                    }
                }
            }
        }
        if coefficient.is_zero() {
            return Sym::zero();
        }
        let mut out: Vec<(Sym, Number)> = Vec::new();
        for (mut base, exp, mut held, _) in bases {
            if exp.is_one() && matches!(base, Sym::Add(_)) {
                out.push((base, held));
                continue;
            }
            make_primitive(&mut base, &mut held, &mut coefficient);
            match Sym::pow(base, exp) {
                Sym::Num(n) => coefficient = coefficient.times(n),
                Sym::Mul(xs) => {
                    // (a*b)^n came apart, or a numeric root: fold it in again
                    for x in xs {
                        match x {
                            Sym::Num(n) => coefficient = coefficient.times(n),
                            other => out.push((other, Number::ONE)),
                        }
                    }
                }
                other => out.push((other, Number::ONE)),
            }
        }
        if coefficient.is_zero() {
            return Sym::zero();
        }
        // Sums take the numbers: each sum factor gives up its numeric content (so that
        // 2*(x + 1) and (2*x + 2) are one thing), and the product's number goes into the first
        // sum. 2*(x + 1) = 2*x + 2, -(x + y)/pi = (-x - y)/pi, (x + 1)*(2*y + 2) =
        // (2*x + 2)*(y + 1), whatever the order they were built in.
        if out.iter().any(|(f, _)| matches!(f, Sym::Add(_))) {
            let mut sums = Vec::new();
            let mut others = Vec::new();
            for (f, held) in out {
                match f {
                    Sym::Add(terms) if held.is_one() => {
                        let (c, primitive) = content(&terms);
                        coefficient = coefficient.times(c);
                        sums.push((primitive, Number::ONE));
                    }
                    sum @ Sym::Add(_) => sums.push((sum, held)),
                    other => others.push(other),
                }
            }
            // a lone sum as given: its terms times the product's number over its content
            // (unless it may be the base of a power beside it, one number apart)
            if let [(sum @ Sym::Add(terms), held)] = sums.as_slice()
                && !held.is_one()
                && !others
                    .iter()
                    .any(|f| matches!(f, Sym::Pow(b, _) if same_but_numbers(b, sum)))
                && coefficient.is_exact()
                && let Some(inv) = held.recip()
            {
                let net = coefficient.times(inv);
                others.push(if net.is_one() {
                    Sym::Add(terms.clone())
                } else {
                    Sym::sum(
                        terms
                            .iter()
                            .map(|t| Sym::product(vec![Sym::Num(net), t.clone()]))
                            .collect(),
                    )
                });
                others.sort_by(compare);
                return match others.len() {
                    1 => others.pop().expect("one factor"),
                    _ => Sym::Mul(others),
                };
            }
            let mut sums: Vec<Sym> = sums
                .into_iter()
                .map(|(mut sum, mut held)| {
                    make_primitive(&mut sum, &mut held, &mut coefficient);
                    sum
                })
                .collect();
            sums.sort_by(compare);
            // Sums whose numbers hid inside their terms' own sums (`x/2 + z*(y + 1)` is
            // `x + z*(2*y + 2)` over 2) were not recognised as one base above; now primitive,
            // they are, and the product is formed again from them.
            let repeated = sums.windows(2).any(|w| w[0] == w[1])
                || others.iter().any(|f| {
                    matches!(f, Sym::Pow(b, _) if matches!(**b, Sym::Add(_)) && sums.contains(b))
                });
            if repeated {
                others.extend(sums);
                others.push(Sym::Num(coefficient));
                return Sym::product(others);
            }
            if !coefficient.is_one() {
                let Sym::Add(terms) = sums.remove(0) else {
                    unreachable!("sums are sums")
                };
                let scaled = Sym::sum(
                    terms
                        .into_iter()
                        .map(|t| Sym::product(vec![Sym::Num(coefficient), t]))
                        .collect(),
                );
                sums.insert(0, scaled);
            }
            others.extend(sums);
            others.sort_by(compare);
            return match others.len() {
                1 => others.pop().expect("one factor"),
                _ => Sym::Mul(others),
            };
        }
        let mut out: Vec<Sym> = out.into_iter().map(|(f, _)| f).collect();
        out.sort_by(compare);
        if !coefficient.is_one() {
            out.insert(0, Sym::Num(coefficient));
        }
        match out.len() {
            0 => Sym::Num(coefficient),
            1 => out.pop().expect("one factor"),
            _ => Sym::Mul(out),
        }
    }

    /// The canonical `base^exp`.
    pub fn pow(base: Sym, exp: Sym) -> Sym {
        if exp.is_zero() {
            return Sym::one();
        }
        if exp.is_one() {
            return base;
        }
        if base.is_one() {
            return Sym::one();
        }
        match (&base, &exp) {
            (Sym::Num(b), Sym::Num(e)) => {
                if let Some(n) = e.as_integer() {
                    if let Some(v) = b.powi(n) {
                        return Sym::Num(v);
                    }
                } else if let (Some((p, q)), true) = (e.as_rational(), b.is_exact())
                    && let Ok(q) = u32::try_from(q)
                    && let Some(root) = b.exact_root(q)
                    && let Some(v) = root.powi(p)
                {
                    return Sym::Num(v);
                } else if let Some((p, q)) = e.as_rational()
                    && let Ok(q) = u32::try_from(q)
                    && let Some((outside, inside)) = b.split_power(q)
                    && let Some(factor) = outside.powi(p)
                {
                    // sqrt(396/25) = 6*sqrt(11)/5: the perfect powers come out of a root
                    return Sym::product(vec![Sym::Num(factor), Sym::pow(Sym::Num(inside), exp)]);
                } else if !b.is_exact() || !e.is_exact() {
                    return Sym::Num(Number::Float(crate::ast::pow(b.to_f64(), e.to_f64())));
                }
                Sym::Pow(Box::new(base), Box::new(exp))
            }
            (Sym::Num(b), _) if b.is_zero() && exp.as_num().is_some_and(|e| !e.is_negative()) => {
                Sym::zero()
            }
            (Sym::Pow(b, e1), Sym::Num(e2)) if e2.as_integer().is_some() => Sym::pow(
                (**b).clone(),
                Sym::product(vec![(**e1).clone(), exp.clone()]),
            ),
            // sqrt(4*x + 8*y) = 2*sqrt(x + 2*y): a positive content that is a perfect power
            // comes out of a fractional power
            (Sym::Add(terms), Sym::Num(e)) if e.as_integer().is_none() && e.is_exact() => {
                let (c, primitive) = content(terms);
                // the magnitude of the content, the sign stays inside
                let (c, primitive) = if c.is_negative() {
                    (c.negated(), Sym::negate(primitive))
                } else {
                    (c, primitive)
                };
                let (p, q) = e.as_rational().expect("exact");
                let taken = u32::try_from(q)
                    .ok()
                    .and_then(|q| c.exact_root(q))
                    .and_then(|r| r.powi(p));
                match (taken, &primitive) {
                    (Some(k), Sym::Add(_)) if !c.is_one() => Sym::product(vec![
                        Sym::Num(k),
                        Sym::Pow(Box::new(primitive), Box::new(exp)),
                    ]),
                    _ => Sym::Pow(Box::new(base), Box::new(exp)),
                }
            }
            (Sym::Add(terms), Sym::Num(e)) if e.as_integer().is_some() => {
                let (c, primitive) = content(terms);
                if c.is_one() {
                    Sym::Pow(Box::new(base), Box::new(exp))
                } else {
                    let k = c
                        .powi(e.as_integer().expect("integer"))
                        .unwrap_or(Number::Float(f64::NAN));
                    Sym::product(vec![
                        Sym::Num(k),
                        Sym::Pow(Box::new(primitive), Box::new(exp)),
                    ])
                }
            }
            (Sym::Mul(xs), Sym::Num(e)) if e.as_integer().is_some() => Sym::product(
                xs.iter()
                    .map(|x| Sym::pow(x.clone(), exp.clone()))
                    .collect(),
            ),
            (Sym::Call(Func::Exp, args), _) => {
                Sym::call(Func::Exp, vec![Sym::product(vec![args[0].clone(), exp])])
            }
            _ => Sym::Pow(Box::new(base), Box::new(exp)),
        }
    }

    /// `-a`.
    pub fn negate(a: Sym) -> Sym {
        Sym::product(vec![Sym::int(-1), a])
    }

    /// `a - b`.
    pub fn difference(a: Sym, b: Sym) -> Sym {
        Sym::sum(vec![a, Sym::negate(b)])
    }

    /// `a / b`.
    pub fn quotient(a: Sym, b: Sym) -> Sym {
        Sym::product(vec![a, Sym::pow(b, Sym::int(-1))])
    }

    /// `sqrt(a)`.
    pub fn sqrt(a: Sym) -> Sym {
        Sym::pow(a, Sym::rational(1, 2))
    }

    /// A comparison.
    pub fn cmp(op: BinOp, a: Sym, b: Sym) -> Sym {
        if let (Some(x), Some(y)) = (a.as_num(), b.as_num()) {
            return Sym::int(i64::from(op.apply(x.to_f64(), y.to_f64()) != 0.0));
        }
        Sym::Cmp(op, Box::new(a), Box::new(b))
    }

    /// `a and b`, `a or b`.
    pub fn logic(op: BinOp, a: Sym, b: Sym) -> Sym {
        if let (Some(x), Some(y)) = (a.as_num(), b.as_num()) {
            return Sym::int(i64::from(op.apply(x.to_f64(), y.to_f64()) != 0.0));
        }
        match op {
            BinOp::And => Sym::And(Box::new(a), Box::new(b)),
            BinOp::Or => Sym::Or(Box::new(a), Box::new(b)),
            other => panic!("{} is not a logical operator", other.symbol()),
        }
    }

    /// `not a`.
    pub fn negation(a: Sym) -> Sym {
        match a.as_num() {
            Some(x) => Sym::int(i64::from(x.is_zero())),
            None => Sym::Not(Box::new(a)),
        }
    }

    /// The canonical call `f(args)`.
    pub fn call(f: Func, args: Vec<Sym>) -> Sym {
        match f {
            Func::Sqrt => return Sym::sqrt(args.into_iter().next().expect("one argument")),
            Func::Log => return Sym::call(Func::Ln, args),
            _ => {}
        }
        if let Some(v) = fold_call(f, &args) {
            return v;
        }
        let a0 = &args[0];
        match f {
            // odd functions take the sign out, even ones drop it
            Func::Sin
            | Func::Tan
            | Func::Asin
            | Func::Atan
            | Func::Sinh
            | Func::Tanh
            | Func::Cbrt
            | Func::Sign
                if is_negated(a0) =>
            {
                Sym::negate(Sym::call(f, vec![Sym::negate(a0.clone())]))
            }
            Func::Cos | Func::Cosh | Func::Abs if is_negated(a0) => {
                Sym::call(f, vec![Sym::negate(a0.clone())])
            }
            // |abs(u)| = abs(u), |exp(u)| = exp(u), |cosh(u)| = cosh(u) (positive)
            Func::Abs if matches!(a0, Sym::Call(Func::Abs | Func::Exp | Func::Cosh, _)) => {
                a0.clone()
            }
            Func::Ln => match a0 {
                Sym::Var(v) if v == "e" => Sym::one(),
                Sym::Call(Func::Exp, inner) => inner[0].clone(),
                Sym::Pow(b, e) if matches!(&**b, Sym::Var(v) if v == "e") => (**e).clone(),
                _ => Sym::Call(f, args),
            },
            Func::If if args[1] == args[2] => args[1].clone(),
            _ => Sym::Call(f, args),
        }
    }
}

#[cfg(test)]
#[path = "build_tests.rs"]
mod tests;
