//! Derivatives: the chain rule over every operator and function of the language, piecewise
//! functions included (`abs`, `sign`, `heaviside`, `floor`, `min`, `max`, `if`: their
//! derivatives where they are differentiable).

use super::Sym;
use crate::ast::{BinOp, Func};

impl Sym {
    /// The derivative with respect to `x`, simplified.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Sym;
    /// let f = Sym::parse("-F0*sin(2*pi*x/b)").unwrap();
    /// assert_eq!(f.diff("x").to_string(), "-2*pi*F0*cos(2*pi*x/b)/b");
    /// ```
    #[must_use]
    pub fn diff(&self, x: &str) -> Sym {
        if self.free_of(x) {
            return Sym::zero();
        }
        match self {
            // free of x (handled above), or x itself
            Sym::Num(_) | Sym::Var(_) => Sym::int(i64::from(*self == Sym::var(x))),
            Sym::Add(terms) => Sym::sum(terms.iter().map(|t| t.diff(x)).collect()),
            Sym::Mul(factors) => Sym::sum(
                (0..factors.len())
                    .map(|i| {
                        let mut f = factors.clone();
                        f[i] = f[i].diff(x);
                        Sym::product(f)
                    })
                    .collect(),
            ),
            Sym::Pow(b, e) => {
                let (b, e) = ((**b).clone(), (**e).clone());
                if e.free_of(x) {
                    // d(u^n) = n u^(n-1) u'
                    Sym::product(vec![
                        e.clone(),
                        Sym::pow(b.clone(), Sym::difference(e, Sym::one())),
                        b.diff(x),
                    ])
                } else {
                    // d(u^v) = u^v (v' ln u + v u'/u)
                    Sym::product(vec![
                        self.clone(),
                        Sym::sum(vec![
                            Sym::product(vec![e.diff(x), Sym::call(Func::Ln, vec![b.clone()])]),
                            Sym::product(vec![e, b.diff(x), Sym::pow(b, Sym::int(-1))]),
                        ]),
                    ])
                }
            }
            Sym::Call(f, args) => call_derivative(*f, args, x),
            // comparisons and logic are piecewise constant
            Sym::Cmp(..) | Sym::And(..) | Sym::Or(..) | Sym::Not(_) => Sym::int(0),
        }
    }

    /// The gradient with respect to `vars`.
    pub fn gradient(&self, vars: &[&str]) -> Vec<Sym> {
        vars.iter().map(|v| self.diff(v)).collect()
    }
}

fn call_derivative(f: Func, args: &[Sym], x: &str) -> Sym {
    // ln|v|' = v'/v (sign(v)/|v| = 1/v wherever v ≠ 0)
    if let (Func::Ln | Func::Log, Sym::Call(Func::Abs, inner)) = (f, &args[0]) {
        return Sym::quotient(inner[0].diff(x), inner[0].clone());
    }
    let u = args[0].clone();
    let du = u.diff(x);
    let inv = |s: Sym| Sym::pow(s, Sym::int(-1));
    let sq = |s: Sym| Sym::pow(s, Sym::int(2));
    let one_minus_u2 = || Sym::difference(Sym::one(), sq(u.clone()));
    let outer = match f {
        Func::Sin => Sym::call(Func::Cos, vec![u.clone()]),
        Func::Cos => Sym::negate(Sym::call(Func::Sin, vec![u.clone()])),
        Func::Tan => inv(sq(Sym::call(Func::Cos, vec![u.clone()]))),
        Func::Asin => Sym::pow(one_minus_u2(), Sym::rational(-1, 2)),
        Func::Acos => Sym::negate(Sym::pow(one_minus_u2(), Sym::rational(-1, 2))),
        Func::Atan => inv(Sym::sum(vec![Sym::one(), sq(u.clone())])),
        Func::Sinh => Sym::call(Func::Cosh, vec![u.clone()]),
        Func::Cosh => Sym::call(Func::Sinh, vec![u.clone()]),
        Func::Tanh => inv(sq(Sym::call(Func::Cosh, vec![u.clone()]))),
        Func::Exp => Sym::call(Func::Exp, vec![u.clone()]),
        Func::Ln | Func::Log => inv(u.clone()),
        Func::Log10 => inv(Sym::product(vec![
            u.clone(),
            Sym::call(Func::Ln, vec![Sym::int(10)]),
        ])),
        Func::Sqrt => Sym::product(vec![
            Sym::rational(1, 2),
            Sym::pow(u.clone(), Sym::rational(-1, 2)),
        ]),
        Func::Cbrt => Sym::product(vec![
            Sym::rational(1, 3),
            Sym::pow(Sym::call(Func::Cbrt, vec![u.clone()]), Sym::int(-2)),
        ]),
        // |u|' = sign(u) u' (undefined at 0, where sign gives 0)
        Func::Abs => Sym::call(Func::Sign, vec![u.clone()]),
        // piecewise constant: zero wherever they are differentiable
        Func::Sign | Func::Heaviside | Func::Floor | Func::Ceil => return Sym::zero(),
        Func::Atan2 => {
            // atan2(y, x)' = (x y' - y x') / (x² + y²)
            let (y, xx) = (u.clone(), args[1].clone());
            return Sym::product(vec![
                Sym::difference(
                    Sym::product(vec![xx.clone(), y.diff(x)]),
                    Sym::product(vec![y.clone(), xx.diff(x)]),
                ),
                inv(Sym::sum(vec![sq(xx), sq(y)])),
            ]);
        }
        Func::Min | Func::Max => {
            // the derivative of the argument that is the extremum; pairwise for more
            let op = if f == Func::Min { BinOp::Le } else { BinOp::Ge };
            let first = args[0].clone();
            let rest = if args.len() == 2 {
                args[1].clone()
            } else {
                Sym::call(f, args[1..].to_vec())
            };
            return Sym::call(
                Func::If,
                vec![
                    Sym::cmp(op, first.clone(), rest.clone()),
                    first.diff(x),
                    rest.diff(x),
                ],
            );
        }
        Func::If => {
            return Sym::call(
                Func::If,
                vec![args[0].clone(), args[1].diff(x), args[2].diff(x)],
            );
        }
    };
    Sym::product(vec![outer, du])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(src: &str) -> String {
        Sym::parse(src).unwrap().diff("x").to_string()
    }

    #[test]
    fn rules() {
        assert_eq!(d("x^3"), "3*x^2");
        assert_eq!(d("k*x^2/2"), "k*x");
        assert_eq!(d("C/x"), "-C/x^2");
        assert_eq!(d("sin(3*x)"), "3*cos(3*x)");
        assert_eq!(d("exp(-a*x)"), "-a*exp(-a*x)");
        assert_eq!(d("ln(x)"), "1/x");
        assert_eq!(d("sqrt(x)"), "1/(2*sqrt(x))");
        assert_eq!(d("abs(x)"), "sign(x)");
        assert_eq!(d("x*sin(x)"), "x*cos(x) + sin(x)");
        assert_eq!(d("atan(x/sqrt(a))/sqrt(a)"), "1/(a*(x^2/a + 1))");
        assert_eq!(d("if(x < 0, -x, x^2)"), "if(x < 0, -1, 2*x)");
        assert_eq!(d("heaviside(x)"), "0");
        assert_eq!(d("2^x"), "2^x*ln(2)");
    }

    #[test]
    fn gradient_of_a_potential() {
        let u = Sym::parse("k*(x^2 + y^2)/2").unwrap();
        let g: Vec<String> = u
            .gradient(&["x", "y"])
            .iter()
            .map(ToString::to_string)
            .collect();
        assert_eq!(g, vec!["k*x", "k*y"]);
    }
}
