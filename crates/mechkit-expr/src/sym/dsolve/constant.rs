//! Linear equations with constant coefficients, `a2 x'' + a1 x' + a0 x = g(t)`: the
//! homogeneous solution from the roots of the characteristic polynomial, a particular one by
//! undetermined coefficients or variation of parameters.

use super::characteristic::higher_basis;
use super::forcing::undetermined;
use super::parse::{Ode, derivative_name};
use super::solve::General;
use crate::ast::Func;
use crate::number::Number;
use crate::sym::Sym;
use crate::sym::identities::is_negated;

/// The homogeneous solutions and what they assumed.
pub(super) struct Basis {
    pub functions: Vec<Sym>,
    pub case: String,
    pub assumptions: Vec<String>,
    pub positive: Vec<Sym>,
}

/// The coefficients `a_k` of a linear equation `Σ a_k x^(k) = g` (any functions of `t`),
/// and `g`; `None` when it is not linear or has no highest derivative.
pub(super) fn linear_parts(ode: &Ode) -> Option<(Vec<Sym>, Sym)> {
    let names: Vec<String> = (0..=ode.order)
        .map(|k| derivative_name(&ode.func, k))
        .collect();
    let a: Vec<Sym> = names.iter().map(|n| ode.residual.diff(n)).collect();
    if a.iter().any(|ak| names.iter().any(|n| !ak.free_of(n))) || a[ode.order].is_zero() {
        return None;
    }
    let mut g = ode.residual.clone();
    for n in &names {
        g = g.substitute(n, &Sym::zero());
    }
    let g = Sym::negate(g);
    let mut check = vec![ode.residual.clone(), g.clone()];
    for (ak, n) in a.iter().zip(&names) {
        check.push(Sym::negate(Sym::product(vec![ak.clone(), Sym::var(n)])));
    }
    Sym::sum(check).expand().is_zero().then_some((a, g))
}

/// The general solution when the equation is linear with coefficients free of `t`; `None`
/// otherwise (or, at order 1, when the forcing is not of the undetermined-coefficients kind:
/// the integrating factor takes it then).
pub(super) fn solve(ode: &Ode, constants: &[&str]) -> Option<General> {
    let t = ode.var.as_str();
    let (a, g) = linear_parts(ode)?;
    if a.iter().any(|ak| !ak.free_of(t)) {
        return None;
    }
    let basis = if a.len() > 3 {
        Basis {
            functions: higher_basis(&a, t)?,
            case: ", characteristic roots".into(),
            assumptions: Vec::new(),
            positive: Vec::new(),
        }
    } else {
        basis(&a, t)
    };
    let mut method = format!("constant coefficients{}", basis.case);
    let particular = if g.is_zero() {
        Sym::zero()
    } else if let Some((p, resonant)) = undetermined(&a, &g, t) {
        method.push_str(if resonant {
            ", undetermined coefficients (resonance)"
        } else {
            ", undetermined coefficients"
        });
        p
    } else if ode.order == 2 {
        method.push_str(", variation of parameters");
        variation(&a[2], &basis.functions, &g, t)?
    } else {
        return None;
    };
    Some(General {
        candidates: vec![general(&basis.functions, constants, particular)],
        method,
        assumptions: basis.assumptions,
        positive: basis.positive,
    })
}

/// `c₁ y₁ + … + cₙ yₙ + particular`: the general solution of a linear equation from a basis
/// of its homogeneous solutions and one particular solution.
pub(super) fn general(functions: &[Sym], constants: &[&str], particular: Sym) -> Sym {
    let mut terms: Vec<Sym> = functions
        .iter()
        .zip(constants)
        .map(|(y, c)| Sym::product(vec![Sym::var(c), y.clone()]))
        .collect();
    terms.push(particular);
    Sym::sum(terms)
}

fn exp_rt(r: &Sym, t: &str) -> Sym {
    Sym::call(Func::Exp, vec![Sym::product(vec![r.clone(), Sym::var(t)])])
}

/// `e^{αt} cos βt`, `e^{αt} sin βt`.
fn oscillating(alpha: &Sym, beta: &Sym, t: &str) -> Vec<Sym> {
    let bt = Sym::product(vec![beta.clone(), Sym::var(t)]);
    [Func::Cos, Func::Sin]
        .into_iter()
        .map(|f| Sym::product(vec![exp_rt(alpha, t), Sym::call(f, vec![bt.clone()])]))
        .collect()
}

/// The homogeneous solutions: the case is decided by the discriminant when it is a number,
/// else assumed (and recorded).
pub(super) fn basis(a: &[Sym], t: &str) -> Basis {
    let plain = |functions: Vec<Sym>, case: &str| Basis {
        functions,
        case: case.into(),
        assumptions: Vec::new(),
        positive: Vec::new(),
    };
    if a.len() == 2 {
        let r = Sym::negate(Sym::quotient(a[0].clone(), a[1].clone()));
        return plain(vec![exp_rt(&r, t)], "");
    }
    let (a0, a1, a2) = (&a[0], &a[1], &a[2]);
    let two_a2 = Sym::product(vec![Sym::int(2), a2.clone()]);
    let alpha = Sym::negate(Sym::quotient(a1.clone(), two_a2.clone()));
    let disc = Sym::sum(vec![
        Sym::pow(a1.clone(), Sym::int(2)),
        Sym::product(vec![Sym::int(-4), a0.clone(), a2.clone()]),
    ])
    .expand();
    if let Some(d) = disc.as_num() {
        let d_f = d.to_f64();
        let root = |sign: i64| {
            Sym::quotient(
                Sym::sum(vec![
                    Sym::negate(a1.clone()),
                    Sym::product(vec![Sym::int(sign), Sym::sqrt(disc.clone())]),
                ]),
                two_a2.clone(),
            )
        };
        return if d_f > 0.0 {
            plain(
                vec![exp_rt(&root(1), t), exp_rt(&root(-1), t)],
                ", over-damped (two real roots)",
            )
        } else if d_f == 0.0 {
            let e = exp_rt(&alpha, t);
            plain(
                vec![e.clone(), Sym::product(vec![Sym::var(t), e])],
                ", critically damped (double root)",
            )
        } else {
            let beta = Sym::quotient(Sym::sqrt(Sym::Num(d.negated())), two_a2.clone());
            let beta = if beta.as_num().is_some_and(Number::is_negative)
                || a2.as_num().is_some_and(Number::is_negative)
            {
                Sym::negate(beta)
            } else {
                beta
            };
            plain(
                oscillating(&alpha, &beta, t),
                ", under-damped (complex roots)",
            )
        };
    }
    if a0.is_zero() {
        let r = Sym::negate(Sym::quotient(a1.clone(), a2.clone()));
        return Basis {
            functions: vec![Sym::one(), exp_rt(&r, t)],
            case: ", over-damped (roots 0 and a real one)".into(),
            assumptions: vec![format!("{a1} ≠ 0")],
            positive: Vec::new(),
        };
    }
    let assumed = |functions, case: &str, positive: Sym| Basis {
        functions,
        case: case.into(),
        assumptions: vec![format!("{positive} > 0")],
        positive: vec![positive],
    };
    if a1.is_zero() {
        let q = Sym::quotient(a0.clone(), a2.clone());
        if is_negated(&q) {
            let w2 = Sym::negate(q);
            let w = Sym::sqrt(w2.clone());
            return assumed(
                vec![exp_rt(&w, t), exp_rt(&Sym::negate(w.clone()), t)],
                ", over-damped (two real roots)",
                w2,
            );
        }
        // sqrt(w^2) is w up to a sign, which the constant of the sine takes; w^2 > 0 says
        // no more than w ≠ 0
        if let Sym::Pow(b, n) = &q
            && n.as_num()
                .and_then(Number::as_integer)
                .is_some_and(|k| k % 2 == 0)
        {
            let w = Sym::pow((**b).clone(), Sym::quotient((**n).clone(), Sym::int(2)));
            return Basis {
                functions: oscillating(&Sym::zero(), &w, t),
                case: ", under-damped (oscillating)".into(),
                assumptions: vec![format!("{w} ≠ 0")],
                positive: Vec::new(),
            };
        }
        let w = match &q {
            Sym::Pow(b, n)
                if n.as_num()
                    .and_then(Number::as_integer)
                    .is_some_and(|k| k % 2 == 0) =>
            {
                Sym::pow((**b).clone(), Sym::quotient((**n).clone(), Sym::int(2)))
            }
            _ => Sym::sqrt(q.clone()),
        };
        return assumed(
            oscillating(&Sym::zero(), &w, t),
            ", under-damped (oscillating)",
            q,
        );
    }
    let beta2 = Sym::difference(
        Sym::quotient(a0.clone(), a2.clone()),
        Sym::pow(alpha.clone(), Sym::int(2)),
    );
    let beta = Sym::sqrt(beta2.clone());
    assumed(
        oscillating(&alpha, &beta, t),
        ", under-damped (complex roots)",
        beta2,
    )
}

/// `y_p = -y1 ∫ y2 g/(a2 W) + y2 ∫ y1 g/(a2 W)`, `W = y1 y2' - y2 y1'`.
pub(super) fn variation(a2: &Sym, y: &[Sym], g: &Sym, t: &str) -> Option<Sym> {
    let (y1, y2) = (&y[0], &y[1]);
    let w = Sym::difference(
        Sym::product(vec![y1.clone(), y2.diff(t)]),
        Sym::product(vec![y2.clone(), y1.diff(t)]),
    );
    let scale = Sym::quotient(g.clone(), Sym::product(vec![a2.clone(), w]));
    let u1 = Sym::negate(Sym::product(vec![y2.clone(), scale.clone()])).integrate(t)?;
    let u2 = Sym::product(vec![y1.clone(), scale]).integrate(t)?;
    Some(Sym::sum(vec![
        Sym::product(vec![u1.result, y1.clone()]),
        Sym::product(vec![u2.result, y2.clone()]),
    ]))
}
