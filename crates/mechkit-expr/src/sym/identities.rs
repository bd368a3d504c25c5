//! The identities the simplifying constructors apply: the numeric content of a sum,
//! constant folding of function calls, and `sin² + cos² = 1`.

use super::Sym;
use super::build::split_coefficient;
use crate::ast::Func;
use crate::number::Number;

/// The numeric content of a sum alone (what [`content`] divides out; one when there is none),
/// without building the primitive part.
pub(crate) fn content_number(terms: &[Sym]) -> Number {
    let coeffs: Vec<Number> = terms.iter().map(|t| split_coefficient(t).0).collect();
    let mut num_gcd: i128 = 0;
    let mut den_lcm: i128 = 1;
    for c in &coeffs {
        let Some((n, d)) = c.as_rational() else {
            return Number::ONE;
        };
        num_gcd = gcd(num_gcd, n);
        let g = gcd(den_lcm, d).max(1);
        den_lcm = match (den_lcm / g).checked_mul(d) {
            Some(l) if l < 1 << 40 => l,
            _ => return Number::ONE,
        };
    }
    if num_gcd == 0 {
        return Number::ONE;
    }
    let sign = if coeffs[0].is_negative() { -1 } else { 1 };
    Number::rational(sign * num_gcd, den_lcm)
}

/// The numeric content of a sum and its primitive part: `2*x + 4 = 2*(x + 2)`,
/// `-x/2 - y/2 = -1/2*(x + y)` (the first term of the primitive part has a positive
/// coefficient). Sums with float coefficients keep their numbers.
pub(crate) fn content(terms: &[Sym]) -> (Number, Sym) {
    let c = content_number(terms);
    if c.is_one() {
        return (c, Sym::Add(terms.to_vec()));
    }
    let inv = c.recip().expect("content is not zero");
    let primitive = terms
        .iter()
        .map(|t| {
            let (k, rest) = split_coefficient(t);
            let k = k.times(inv);
            match rest {
                None => Sym::Num(k),
                Some(r) => Sym::product(vec![Sym::Num(k), r]),
            }
        })
        .collect();
    match Sym::sum(primitive) {
        s @ Sym::Add(_) => (c, s),
        // cannot happen for a canonical sum (its terms stay distinct), but stay total
        other => (Number::ONE, Sym::Add(vec![other])),
    }
}

pub(super) fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Whether a term reads with a minus sign: a negative number or a negative coefficient.
pub(crate) fn is_negated(s: &Sym) -> bool {
    match s {
        Sym::Num(n) => n.is_negative(),
        Sym::Mul(xs) => matches!(xs.first(), Some(Sym::Num(n)) if n.is_negative()),
        Sym::Add(xs) => xs.iter().all(is_negated),
        _ => false,
    }
}

/// Exact values of functions at numbers (`sin(0) = 0`, `ln(1) = 0`, `abs(-3) = 3`), floats
/// for float arguments, `None` where the exact value is not a number (`sin(1)`).
pub(super) fn fold_call(f: Func, args: &[Sym]) -> Option<Sym> {
    if f == Func::If {
        return args[0].as_num().map(|c| {
            if c.is_zero() {
                args[2].clone()
            } else {
                args[1].clone()
            }
        });
    }
    let nums: Vec<Number> = args.iter().map(Sym::as_num).collect::<Option<_>>()?;
    let x = nums[0];
    let exact = |v: Number| Some(Sym::Num(v));
    let int = |n: i64| Some(Sym::int(n));
    if nums.iter().any(|n| !n.is_exact()) {
        let values: Vec<f64> = nums.iter().map(|n| n.to_f64()).collect();
        return Some(Sym::Num(Number::Float(f.apply(&values))));
    }
    match f {
        Func::Abs => exact(x.abs()),
        Func::Sign => int(if x.is_zero() {
            0
        } else if x.is_negative() {
            -1
        } else {
            1
        }),
        Func::Heaviside => {
            if x.is_zero() {
                exact(Number::rational(1, 2))
            } else {
                int(i64::from(!x.is_negative()))
            }
        }
        Func::Floor | Func::Ceil => {
            let v = if f == Func::Floor {
                x.to_f64().floor()
            } else {
                x.to_f64().ceil()
            };
            exact(Number::from_f64(v))
        }
        Func::Min | Func::Max => {
            let pick = nums.iter().copied().reduce(|a, b| {
                let less = a.total_cmp(&b) == std::cmp::Ordering::Less;
                if less == (f == Func::Min) { a } else { b }
            })?;
            exact(pick)
        }
        Func::Cbrt => x.exact_root(3).map(Sym::Num),
        Func::Sin | Func::Tan | Func::Asin | Func::Atan | Func::Sinh | Func::Tanh
            if x.is_zero() =>
        {
            int(0)
        }
        Func::Cos | Func::Cosh | Func::Exp if x.is_zero() => int(1),
        Func::Acos | Func::Ln if x.is_one() => int(0),
        Func::Log10 => {
            let n = x.as_integer()?;
            let mut p = 1i128;
            for k in 0..38 {
                if p == n {
                    return int(k);
                }
                p = p.checked_mul(10)?;
            }
            None
        }
        _ => None,
    }
}

/// `c*r*sin(u)^2 + c*r*cos(u)^2 → c*r`: finds such pairs among collected terms (rest,
/// coefficient) and merges them.
pub(super) fn pythagoras(terms: &mut Vec<(Sym, Number)>, constant: &mut Number) {
    // (u, other factors as a product) of a term holding the factor f(u)^2; nothing is
    // cloned unless the term has one
    let squared = |s: &Sym, f: Func| -> Option<(Sym, Sym)> {
        let factors = match s {
            Sym::Mul(xs) => xs.as_slice(),
            other => std::slice::from_ref(other),
        };
        let (i, u) = factors.iter().enumerate().find_map(|(i, x)| match x {
            Sym::Pow(b, e) if e.as_num() == Some(Number::int(2)) => match &**b {
                Sym::Call(g, args) if *g == f => Some((i, &args[0])),
                _ => None,
            },
            _ => None,
        })?;
        let rest = factors
            .iter()
            .enumerate()
            .filter(|&(k, _)| k != i)
            .map(|(_, x)| x.clone())
            .collect();
        Some((u.clone(), Sym::product(rest)))
    };
    let mut i = 0;
    while i < terms.len() {
        let Some((u, rest)) = squared(&terms[i].0, Func::Sin) else {
            i += 1;
            continue;
        };
        let c = terms[i].1;
        let partner = terms.iter().position(|(t, k)| {
            *k == c && squared(t, Func::Cos).is_some_and(|(v, r)| v == u && r == rest)
        });
        if let Some(j) = partner {
            let (hi, lo) = if i > j { (i, j) } else { (j, i) };
            terms.remove(hi);
            terms.remove(lo);
            match rest {
                Sym::Num(n) => *constant = constant.plus(n.times(c)),
                r => match terms.iter_mut().find(|(t, _)| *t == r) {
                    Some((_, k)) => *k = k.plus(c),
                    None => terms.push((r, c)),
                },
            }
            i = 0;
        } else {
            i += 1;
        }
    }
    terms.retain(|(_, c)| !c.is_zero());
}
