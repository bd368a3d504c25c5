//! Between [`Expr`] (what is typed and printed) and [`Sym`] (what algebra works on).

use super::Sym;
use super::build::split_coefficient;
use super::identities::is_negated;
use crate::ast::{BinOp, Expr, Func};
use crate::number::Number;

impl Sym {
    /// The canonical form of an expression.
    pub fn from_expr(e: &Expr) -> Sym {
        match e {
            Expr::Num(x) => Sym::Num(Number::from_f64(*x)),
            Expr::Var(v) => Sym::Var(v.clone()),
            Expr::Neg(a) => Sym::negate(Sym::from_expr(a)),
            Expr::Not(a) => Sym::negation(Sym::from_expr(a)),
            Expr::Binary(op, a, b) => {
                let (a, b) = (Sym::from_expr(a), Sym::from_expr(b));
                match op {
                    BinOp::Add => Sym::sum(vec![a, b]),
                    BinOp::Sub => Sym::difference(a, b),
                    BinOp::Mul => Sym::product(vec![a, b]),
                    BinOp::Div => Sym::quotient(a, b),
                    BinOp::Pow => Sym::pow(a, b),
                    BinOp::And | BinOp::Or => Sym::logic(*op, a, b),
                    cmp => Sym::cmp(*cmp, a, b),
                }
            }
            Expr::Call(f, args) => Sym::call(*f, args.iter().map(Sym::from_expr).collect()),
        }
    }

    /// A readable expression: subtraction for negative terms, a denominator for negative
    /// powers, `sqrt` for `^(1/2)`, exact fractions as `a/b`.
    pub fn to_expr(&self) -> Expr {
        match self {
            Sym::Num(n) => number(*n),
            Sym::Var(v) => Expr::Var(v.clone()),
            Sym::Add(terms) => sum(terms),
            Sym::Mul(_) | Sym::Pow(..) => product(self),
            Sym::Call(f, args) => Expr::Call(*f, args.iter().map(Sym::to_expr).collect()),
            Sym::Cmp(op, a, b) => Expr::binary(*op, a.to_expr(), b.to_expr()),
            Sym::And(a, b) => Expr::binary(BinOp::And, a.to_expr(), b.to_expr()),
            Sym::Or(a, b) => Expr::binary(BinOp::Or, a.to_expr(), b.to_expr()),
            Sym::Not(a) => Expr::Not(Box::new(a.to_expr())),
        }
    }
}

fn number(n: Number) -> Expr {
    match n {
        Number::Rational(p, 1) => Expr::Num(p as f64),
        Number::Rational(p, q) => {
            Expr::binary(BinOp::Div, Expr::Num(p as f64), Expr::Num(q as f64))
        }
        Number::Float(x) => Expr::Num(x),
    }
}

fn sum(terms: &[Sym]) -> Expr {
    // Start with a positive term when there is one: `1 - x` rather than `-x + 1`.
    let first = terms.iter().position(|t| !is_negated(t)).unwrap_or(0);
    let mut acc = terms[first].to_expr();
    for (i, t) in terms.iter().enumerate() {
        if i == first {
            continue;
        }
        acc = if is_negated(t) {
            Expr::binary(BinOp::Sub, acc, Sym::negate(t.clone()).to_expr())
        } else {
            Expr::binary(BinOp::Add, acc, t.to_expr())
        };
    }
    acc
}

/// A power as a numerator factor, and whether it belongs in the denominator instead (with
/// the exponent's sign flipped).
fn power_factor(s: &Sym) -> (Expr, bool) {
    match s {
        // a division by zero stays visible as such (`0*y` in a denominator would read as 0)
        Sym::Pow(b, e) if b.is_zero() => {
            (Expr::binary(BinOp::Pow, b.to_expr(), e.to_expr()), false)
        }
        Sym::Pow(b, e) => {
            let (e, den) = match e.as_num() {
                Some(n) if n.is_negative() => (Sym::Num(n.negated()), true),
                _ if is_negated(e) => (Sym::negate((**e).clone()), true),
                _ => ((**e).clone(), false),
            };
            (power(b, &e), den)
        }
        other => (other.to_expr(), false),
    }
}

fn power(base: &Sym, exp: &Sym) -> Expr {
    if exp.is_one() {
        return base.to_expr();
    }
    if exp.as_num() == Some(Number::rational(1, 2)) {
        return Expr::Call(Func::Sqrt, vec![base.to_expr()]);
    }
    Expr::binary(BinOp::Pow, base.to_expr(), exp.to_expr())
}

fn product(s: &Sym) -> Expr {
    let (c, rest) = split_coefficient(s);
    let factors: Vec<Sym> = match rest {
        Some(Sym::Mul(xs)) => xs,
        Some(other) => vec![other],
        None => Vec::new(),
    };
    let mut num = Vec::new();
    let mut den = Vec::new();
    for f in &factors {
        let (e, in_den) = power_factor(f);
        if in_den { den.push(e) } else { num.push(e) }
    }
    let (p, q) = match c {
        Number::Rational(p, q) => (p, q),
        Number::Float(x) => {
            // a float coefficient stays in front
            let mut all = vec![Expr::Num(x)];
            all.extend(num);
            return divide(chain(all), den);
        }
    };
    if q != 1 {
        den.insert(0, Expr::Num(q as f64));
    }
    let negative = p < 0;
    if p.abs() != 1 || num.is_empty() {
        num.insert(0, Expr::Num(p as f64));
    } else if negative {
        let first = num.remove(0);
        num.insert(0, Expr::Neg(Box::new(first)));
    }
    divide(chain(num), den)
}

fn chain(factors: Vec<Expr>) -> Expr {
    factors
        .into_iter()
        .reduce(|a, b| Expr::binary(BinOp::Mul, a, b))
        .unwrap_or(Expr::Num(1.0))
}

fn divide(num: Expr, den: Vec<Expr>) -> Expr {
    if den.is_empty() {
        num
    } else {
        Expr::binary(BinOp::Div, num, chain(den))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn show(src: &str) -> String {
        Sym::parse(src).unwrap().to_string()
    }

    #[test]
    fn canonical_forms_read_well() {
        assert_eq!(show("x*x"), "x^2");
        assert_eq!(show("x + x + y - y"), "2*x");
        assert_eq!(show("0.5*x"), "x/2");
        assert_eq!(show("-0.5*x"), "-x/2");
        assert_eq!(show("3/2*x"), "3*x/2");
        assert_eq!(show("2*(x + 1)"), "2*x + 2");
        assert_eq!(show("1 - x"), "1 - x");
        assert_eq!(show("-x + 1"), "1 - x");
        assert_eq!(show("x^2*x^3"), "x^5");
        assert_eq!(show("x^a*x^b"), "x^(a + b)");
        assert_eq!(show("sqrt(x)*sqrt(x)"), "x");
        assert_eq!(show("1/sqrt(a)"), "1/sqrt(a)");
        assert_eq!(show("x/(a*b)"), "x/(a*b)");
        assert_eq!(show("(a/r)^12"), "a^12/r^12");
        assert_eq!(show("-F0*2*pi/b*cos(2*pi*x/b)"), "-2*pi*F0*cos(2*pi*x/b)/b");
        assert_eq!(show("sin(x)^2 + cos(x)^2"), "1");
        assert_eq!(show("3*sin(u)^2*m + 3*m*cos(u)^2 + y"), "3*m + y");
        assert_eq!(show("sin(-x)"), "-sin(x)");
        assert_eq!(show("cos(-2*x)"), "cos(2*x)");
        assert_eq!(show("log(e^x)"), "x");
        assert_eq!(show("exp(0) + sin(0) + ln(1)"), "1");
        assert_eq!(show("x^2 + 2*x + 1"), "x^2 + 2*x + 1");
        assert_eq!(show("1 + 2*x + x^2"), "x^2 + 2*x + 1");
        assert_eq!(show("4^(1/2)"), "2");
        assert_eq!(show("x*0 + 1*y"), "y");
        assert_eq!(show("(x^2)^3"), "x^6");
    }

    #[test]
    fn printing_round_trips() {
        for src in [
            "-2*pi*F0*cos(2*pi*x/b)/b",
            "x^2 + 2*x + 1",
            "atan(x/sqrt(a))/sqrt(a)",
            "-x/2 + y^(1/3) - 3/(4*z)",
            "if(x < 0, -x, x^2)",
            "U0*(a^12/r^12 - b^6/r^6)",
            "exp(-x)*sin(3*x)",
            "1.5e-9*x + 0.1",
        ] {
            let s = Sym::parse(src).unwrap();
            let printed = s.to_string();
            assert_eq!(
                Sym::parse(&printed).unwrap(),
                s,
                "{src} printed as {printed}"
            );
        }
    }
}
