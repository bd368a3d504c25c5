//! Polynomials in one variable: with symbolic coefficients (to recognise `a + b*x^2`), and with
//! exact numeric coefficients (division, rational roots, partial fractions).

use super::Sym;
use crate::number::Number;

/// The highest degree treated as a polynomial. `x^(10^10)` is a monomial, but a list of its
/// coefficients would take 240 GB (a fuzz finding: `exp(-x^10^10*…)` aborted the integrator).
pub const MAX_DEGREE: usize = 1000;

/// The coefficients of `s` as a polynomial in `x`, lowest degree first; `None` if it is not one
/// (after expansion) or its degree passes [`MAX_DEGREE`].
pub fn coefficients(s: &Sym, x: &str) -> Option<Vec<Sym>> {
    let e = s.expand();
    let terms = match &e {
        Sym::Add(ts) => ts.clone(),
        other => vec![other.clone()],
    };
    let mut coeffs: Vec<Vec<Sym>> = Vec::new();
    for t in terms {
        let factors = match t {
            Sym::Mul(fs) => fs,
            other => vec![other],
        };
        let mut degree = 0usize;
        let mut rest = Vec::new();
        for f in factors {
            match &f {
                Sym::Var(v) if v == x => degree += 1,
                Sym::Pow(b, p) if matches!(&**b, Sym::Var(v) if v == x) => {
                    let k = p.as_num()?.as_integer()?;
                    degree = degree.checked_add(usize::try_from(k).ok()?)?;
                }
                other if other.free_of(x) => rest.push(f),
                _ => return None,
            }
        }
        if degree > MAX_DEGREE {
            return None;
        }
        if coeffs.len() <= degree {
            coeffs.resize(degree + 1, Vec::new());
        }
        coeffs[degree].push(Sym::product(rest));
    }
    let out: Vec<Sym> = coeffs.into_iter().map(Sym::sum).collect();
    Some(if out.is_empty() {
        vec![Sym::zero()]
    } else {
        out
    })
}

/// A polynomial with exact numeric coefficients, lowest degree first, no trailing zeros.
#[derive(Debug, Clone, PartialEq)]
pub struct NumPoly(pub Vec<Number>);

impl NumPoly {
    /// From coefficients (trailing zeros removed).
    pub fn new(mut c: Vec<Number>) -> Self {
        while c.last().is_some_and(|x| x.is_zero()) {
            c.pop();
        }
        NumPoly(c)
    }

    /// From symbolic coefficients that are all numbers.
    pub fn from_syms(c: &[Sym]) -> Option<Self> {
        c.iter()
            .map(Sym::as_num)
            .collect::<Option<Vec<_>>>()
            .map(NumPoly::new)
    }

    /// Degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// Whether it is zero.
    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// Quotient and remainder of the division by `d` (not zero).
    pub fn div_rem(&self, d: &NumPoly) -> Option<(NumPoly, NumPoly)> {
        let dd = d.degree()?;
        let lead = *d.0.last()?;
        let mut r = self.0.clone();
        let n = self.degree().unwrap_or(0);
        if self.is_zero() || n < dd {
            return Some((NumPoly::new(vec![]), self.clone()));
        }
        let mut q = vec![Number::ZERO; n - dd + 1];
        for k in (0..=n - dd).rev() {
            let c = r[k + dd].checked_div(lead)?;
            q[k] = c;
            for (i, di) in d.0.iter().enumerate() {
                r[k + i] = r[k + i].plus(c.times(*di).negated());
            }
        }
        r.truncate(dd);
        Some((NumPoly::new(q), NumPoly::new(r)))
    }

    /// Product.
    #[must_use]
    pub fn times(&self, o: &NumPoly) -> NumPoly {
        if self.is_zero() || o.is_zero() {
            return NumPoly::new(vec![]);
        }
        let mut c = vec![Number::ZERO; self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in o.0.iter().enumerate() {
                c[i + j] = c[i + j].plus(a.times(*b));
            }
        }
        NumPoly::new(c)
    }

    /// Value at `x`.
    pub fn eval(&self, x: Number) -> Number {
        self.0
            .iter()
            .rev()
            .fold(Number::ZERO, |acc, c| acc.times(x).plus(*c))
    }

    /// Rational roots (rational root theorem), each once. Needs exact coefficients.
    pub fn rational_roots(&self) -> Vec<Number> {
        let Some(deg) = self.degree() else {
            return vec![];
        };
        if deg == 0 || self.0.iter().any(|c| !c.is_exact()) {
            return vec![];
        }
        // scale to integers
        let lcm = self.0.iter().fold(1i128, |l, c| {
            let (_, d) = c.as_rational().expect("exact");
            let g = gcd(l, d);
            (l / g).saturating_mul(d)
        });
        let mut ints: Vec<i128> = self
            .0
            .iter()
            .map(|c| {
                let (n, d) = c.as_rational().expect("exact");
                n.saturating_mul(lcm / d)
            })
            .collect();
        // the primitive part: 735134400*x^7 + 735134400 has the candidates of x^7 + 1
        let content = ints.iter().fold(0i128, |g, c| gcd(g, *c));
        for c in &mut ints {
            *c /= content;
        }
        let mut roots = Vec::new();
        // a zero root first
        let low = ints.iter().position(|c| *c != 0).unwrap_or(0);
        if low > 0 {
            roots.push(Number::ZERO);
        }
        let (a0, an) = (ints[low], ints[deg]);
        if a0.unsigned_abs() > 1_000_000_000 || an.unsigned_abs() > 1_000_000_000 {
            return roots;
        }
        let (ps, qs) = (divisors(a0), divisors(an));
        // each candidate costs an exact evaluation: past this many, leave the rest to the
        // callers' other methods (as for the coefficients too large above)
        if ps.len() * qs.len() > 20_000 {
            return roots;
        }
        for p in ps {
            for q in &qs {
                let q = *q;
                for sign in [1, -1] {
                    let r = Number::rational(sign * p, q);
                    if !roots.contains(&r) && self.eval(r).is_zero() {
                        roots.push(r);
                    }
                }
            }
        }
        roots
    }

    /// Whether every coefficient is an exact rational.
    pub fn is_exact(&self) -> bool {
        self.0.iter().all(|c| c.is_exact())
    }

    /// The derivative.
    #[must_use]
    pub fn derivative(&self) -> NumPoly {
        NumPoly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.times(Number::int(k as i64)))
                .collect(),
        )
    }

    /// The same polynomial divided by its leading coefficient (zero stays zero).
    #[must_use]
    pub fn monic(&self) -> NumPoly {
        match self.0.last().and_then(|l| l.recip()) {
            Some(r) => NumPoly::new(self.0.iter().map(|c| c.times(r)).collect()),
            None => self.clone(),
        }
    }

    /// The monic greatest common divisor (Euclid's algorithm); `None` when the arithmetic left
    /// the exact rationals (a coefficient overflowed into a float), where a remainder that
    /// should be zero may not be.
    pub fn gcd(&self, o: &NumPoly) -> Option<NumPoly> {
        let (mut a, mut b) = (self.monic(), o.monic());
        while !b.is_zero() {
            let (_, r) = a.div_rem(&b)?;
            (a, b) = (b, r.monic());
            if !b.is_exact() {
                return None;
            }
        }
        a.is_exact().then(|| a.monic())
    }

    /// The square-free part: the product of the distinct irreducible factors, so each root
    /// once (`p / gcd(p, p')`, Yun). `None` as for [`NumPoly::gcd`].
    pub fn square_free(&self) -> Option<NumPoly> {
        if !self.is_exact() {
            return None;
        }
        let g = self.gcd(&self.derivative())?;
        let (q, r) = self.div_rem(&g)?;
        (r.is_zero() && q.is_exact()).then_some(q)
    }

    /// As a symbolic polynomial in `x`.
    pub fn to_sym(&self, x: &str) -> Sym {
        Sym::sum(
            self.0
                .iter()
                .enumerate()
                .map(|(k, c)| {
                    Sym::product(vec![
                        Sym::Num(*c),
                        Sym::pow(Sym::var(x), Sym::int(k as i64)),
                    ])
                })
                .collect(),
        )
    }
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

fn divisors(n: i128) -> Vec<i128> {
    let n = n.abs();
    let mut out = Vec::new();
    let mut d = 1;
    while d * d <= n {
        if n % d == 0 {
            out.push(d);
            if d != n / d {
                out.push(n / d);
            }
        }
        d += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz finding `calculus/integrate-x-to-the-1e10` (found by the `expression` target
    /// before `calculus` was split from it): `exp(-x^10^10*pi^p*smx-0-x^10*pi)` asked the
    /// integrator for the coefficients of a degree-10^10 polynomial, a 240 GB list, and the
    /// process aborted.
    #[test]
    fn fuzz_a_huge_degree_is_not_a_coefficient_list() {
        let big = Sym::parse("x^10^10").unwrap();
        assert!(coefficients(&big, "x").is_none());
        let at_limit = Sym::parse("x^1000 + 1").unwrap();
        assert_eq!(coefficients(&at_limit, "x").map(|c| c.len()), Some(1001));
        let found = Sym::parse("exp(-x^10^10*pi^p*smx-0-x^10*pi)").unwrap();
        assert!(found.integrate("x").is_none());
    }

    #[test]
    fn coefficients_of_a_symbolic_polynomial() {
        let c = coefficients(&Sym::parse("a + b*x^2 + 3*x*(x + 1)").unwrap(), "x").unwrap();
        let shown: Vec<String> = c.iter().map(ToString::to_string).collect();
        assert_eq!(shown, vec!["a", "3", "b + 3"]);
        assert!(coefficients(&Sym::parse("sin(x)").unwrap(), "x").is_none());
        assert!(coefficients(&Sym::parse("1/x").unwrap(), "x").is_none());
    }

    #[test]
    fn division_and_roots() {
        let n = |v: i64| Number::int(v);
        // (x - 1)(x + 2)(2x - 3) = 2x^3 - x^2 - 7x + 6
        let p = NumPoly::new(vec![n(6), n(-7), n(-1), n(2)]);
        let mut roots = p.rational_roots();
        roots.sort_by(Number::total_cmp);
        assert_eq!(roots, vec![n(-2), n(1), Number::rational(3, 2)]);
        let (q, r) = p.div_rem(&NumPoly::new(vec![n(-1), n(1)])).unwrap();
        assert!(r.is_zero());
        assert_eq!(q, NumPoly::new(vec![n(-6), n(1), n(2)]));
    }
}
