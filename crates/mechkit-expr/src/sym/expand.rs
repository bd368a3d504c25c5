//! Expansion: products of sums multiplied out, small integer powers of sums expanded.

use super::Sym;

/// Expansions that would produce more terms than this are left alone.
const MAX_TERMS: usize = 2000;

/// Nor more nodes than this in all (a few terms can each be huge: products of towers of
/// symbolic coefficients took seconds to multiply out).
const MAX_NODES: usize = 20_000;

/// Whether multiplying out `acc` by `terms` stays within the bounds: `|acc| |terms|` terms
/// of `Σ size(acc) |terms| + Σ size(terms) |acc|` nodes.
fn within_bounds(acc: &[Sym], terms: &[Sym]) -> bool {
    let total = |xs: &[Sym]| xs.iter().map(super::integrate::size).sum::<usize>();
    acc.len() * terms.len() <= MAX_TERMS
        && total(acc) * terms.len() + total(terms) * acc.len() <= MAX_NODES
}

impl Sym {
    /// Multiplies out products and positive integer powers (up to 12) of sums; function
    /// arguments are left as they are.
    ///
    /// ```
    /// use mechkit_expr::Sym;
    /// assert_eq!(Sym::parse("(x + 1)^2").unwrap().expand().to_string(), "x^2 + 2*x + 1");
    /// ```
    #[must_use]
    pub fn expand(&self) -> Sym {
        match self {
            Sym::Add(xs) => Sym::sum(xs.iter().map(Sym::expand).collect()),
            Sym::Mul(xs) => {
                let mut acc = vec![Sym::one()];
                for f in xs {
                    let terms = match f.expand() {
                        Sym::Add(ts) => ts,
                        other => vec![other],
                    };
                    if !within_bounds(&acc, &terms) {
                        return self.clone();
                    }
                    acc = acc
                        .iter()
                        .flat_map(|a| {
                            terms
                                .iter()
                                .map(move |t| Sym::product(vec![a.clone(), t.clone()]))
                        })
                        .collect();
                }
                Sym::sum(acc)
            }
            Sym::Pow(b, e) => {
                let base = b.expand();
                match (e.as_num().and_then(crate::Number::as_integer), &base) {
                    (Some(n @ 2..=12), Sym::Add(_)) => {
                        let product = Sym::Mul(vec![base.clone(); n as usize]);
                        // Sym::Mul would merge equal factors back into a power; expand the
                        // raw product instead.
                        expand_product(&product).unwrap_or_else(|| Sym::pow(base, (**e).clone()))
                    }
                    _ => Sym::pow(base, (**e).clone()),
                }
            }
            other => other.clone(),
        }
    }
}

fn expand_product(p: &Sym) -> Option<Sym> {
    let Sym::Mul(xs) = p else {
        return Some(p.clone());
    };
    let mut acc = vec![Sym::one()];
    for f in xs {
        let terms = match f {
            Sym::Add(ts) => ts.clone(),
            other => vec![other.clone()],
        };
        if !within_bounds(&acc, &terms) {
            return None;
        }
        acc = acc
            .iter()
            .flat_map(|a| {
                terms
                    .iter()
                    .map(move |t| Sym::product(vec![a.clone(), t.clone()]))
            })
            .collect();
        acc = match Sym::sum(acc) {
            Sym::Add(ts) => ts,
            other => vec![other],
        };
    }
    Some(Sym::sum(acc))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A few terms can each be huge: the product of two sums of towers is left alone when
    /// multiplying it out would build more than `MAX_NODES` nodes, however few the terms.
    #[test]
    fn large_terms_are_not_multiplied_out() {
        let tower = |v: &str| (0..40).map(|_| v).collect::<Vec<_>>().join("^");
        let big = format!("({} + {})", tower("a"), tower("b"));
        let product = Sym::parse(&format!("{big}*{big}*{big}*(x + 1)")).unwrap();
        let expanded = product.expand();
        assert!(
            super::super::integrate::size(&expanded) < MAX_NODES,
            "{}",
            super::super::integrate::size(&expanded)
        );
        let small = Sym::parse("(a + b)*(x + 1)").unwrap().expand();
        assert_eq!(small.to_string(), "a*x + a + b*x + b");
    }
}
