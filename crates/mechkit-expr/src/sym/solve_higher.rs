//! Polynomial equations of degree three or more with symbolic coefficients, in the cases that
//! have a short answer: a factor `x^k` (`x = 0`, then the rest), and a power `a x^n + d`
//! (`x = cbrt(-d/a)` for n = 3, `x = ±(-d/a)^(1/4)` for n = 4). Each root is checked by
//! substituting it into the polynomial with sample values for the names.

use super::Sym;
use super::solve::{Solutions, Solved, solve_coefficients};
use crate::ast::Func;

/// The roots of the polynomial with symbolic coefficients `c` (lowest degree first, degree
/// three or more), or `None` when it is none of the cases above or a root fails its check.
pub(super) fn solve_higher(c: &[Sym]) -> Option<Solved> {
    let k = c.iter().take_while(|s| s.is_zero()).count();
    let solved = if k > 0 {
        let rest = solve_coefficients(&c[k..])?;
        let mut roots = vec![Sym::zero()];
        match rest.solutions {
            Solutions::Roots(r) => roots.extend(r.into_iter().filter(|r| !r.is_zero())),
            Solutions::NoRealRoot => {}
            Solutions::Every => return None,
        }
        Solved {
            solutions: Solutions::Roots(roots),
            assumptions: rest.assumptions,
        }
    } else {
        power(c)?
    };
    let Solutions::Roots(roots) = &solved.solutions else {
        return Some(solved);
    };
    roots.iter().all(|r| checks(c, r)).then_some(solved)
}

/// `a x^n + d = 0` for n = 3 or 4.
fn power(c: &[Sym]) -> Option<Solved> {
    let n = c.len() - 1;
    if !c[1..n].iter().all(Sym::is_zero) {
        return None;
    }
    let (a, d) = (&c[n], &c[0]);
    let ratio = Sym::negate(Sym::quotient(d.clone(), a.clone()));
    let mut assumptions = Vec::new();
    if a.as_num().is_none() {
        let (_, rest) = super::build::split_coefficient(a);
        assumptions.push(format!("{} ≠ 0", rest.unwrap_or_else(|| a.clone())));
    }
    let roots = match n {
        3 => vec![Sym::call(Func::Cbrt, vec![ratio])],
        4 => {
            if ratio.as_num().is_none() {
                assumptions.push(format!("{ratio} ≥ 0"));
            }
            let root = Sym::pow(ratio, Sym::rational(1, 4));
            vec![Sym::negate(root.clone()), root]
        }
        _ => return None,
    };
    Some(Solved {
        solutions: Solutions::Roots(roots),
        assumptions,
    })
}

/// Whether `root` makes the polynomial `c` vanish for sample values of its names (each set
/// where the root has a real value; at least one must).
fn checks(c: &[Sym], root: &Sym) -> bool {
    let mut names: Vec<String> = c.iter().flat_map(Sym::names).collect();
    names.sort();
    names.dedup();
    // values of both signs and sizes from 1/4 to 4, from a fixed pseudo-random sequence
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut checked = false;
    for _ in 0..16 {
        let values: Vec<f64> = names
            .iter()
            .map(|_| {
                seed = seed
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                let u = (seed >> 11) as f64 / (1u64 << 53) as f64;
                let size = 4f64.powf(2.0 * u - 1.0);
                if (seed >> 7) & 1 == 0 { size } else { -size }
            })
            .collect();
        let env = |n: &str| names.iter().position(|m| m == n).map(|i| values[i]);
        let Some(x) = root.eval(&env).ok().filter(|v| v.is_finite()) else {
            continue;
        };
        let mut value = 0.0;
        let mut scale = 0.0;
        for ci in c.iter().rev() {
            let Ok(v) = ci.eval(&env) else {
                return false;
            };
            value = value * x + v;
            scale = scale * x.abs() + v.abs();
        }
        if value.is_nan() || value.abs() > 1e-9 * scale {
            return false;
        }
        checked = true;
    }
    checked
}
