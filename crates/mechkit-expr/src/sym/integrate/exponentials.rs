//! Exponentials in disguise: a power with a constant base, `b^x = exp(x ln b)`, and functions
//! of `ln x`, which `x = exp(u)` makes functions of `u` times `exp(u)`.

use super::{Ctx, Sym, var};
use crate::ast::Func;

/// `f` with every power `b^g(x)` of a base `b` free of `x` written `exp(g(x) ln b)` (`b`
/// assumed positive when it is not a number); `None` when there is none.
pub(super) fn powers_as_exponentials(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let mut bases = Vec::new();
    constant_bases(f, &x, &mut bases);
    if bases.is_empty() {
        return None;
    }
    for b in bases
        .iter()
        .filter(|b| !matches!(b, Sym::Var(v) if v == "e"))
    {
        ctx.assume_positive(b);
    }
    Some(rewrite(f, &x))
}

/// Whether `b^e` is a power of a constant base to rewrite: `e` depends on `x`, `b` does not
/// and is not a negative number or zero.
fn constant_base<'a>(s: &'a Sym, x: &str) -> Option<&'a Sym> {
    match s {
        Sym::Pow(b, e)
            if b.free_of(x)
                && !e.free_of(x)
                && b.as_num().is_none_or(|n| !n.is_negative() && !n.is_zero()) =>
        {
            Some(b)
        }
        _ => None,
    }
}

fn constant_bases(s: &Sym, x: &str, out: &mut Vec<Sym>) {
    s.any(&mut |node| {
        if let Some(b) = constant_base(node, x)
            && !out.contains(b)
        {
            out.push(b.clone());
        }
        false
    });
}

fn rewrite(s: &Sym, x: &str) -> Sym {
    let s = s.map_children(|c| rewrite(c, x));
    match constant_base(&s, x) {
        Some(b) => {
            let Sym::Pow(_, e) = &s else { return s };
            Sym::call(
                Func::Exp,
                vec![Sym::product(vec![
                    (**e).clone(),
                    Sym::call(Func::Ln, vec![b.clone()]),
                ])],
            )
        }
        None => s,
    }
}

/// `exp(c ln b)` written `b^c` again, and `exp(ln y)` as `y`.
pub(super) fn exp_of_logs_as_powers(s: &Sym) -> Sym {
    let s = s.map_children(exp_of_logs_as_powers);
    if let Sym::Call(Func::Exp, args) = &s {
        let mut rest = super::factors(&args[0]);
        let logs: Vec<usize> = (0..rest.len())
            .filter(|&i| matches!(&rest[i], Sym::Call(Func::Ln, _)))
            .collect();
        if let [i] = logs[..]
            && let Sym::Call(Func::Ln, inner) = rest.remove(i)
        {
            return Sym::pow(inner[0].clone(), Sym::product(rest));
        }
    }
    s
}

/// `∫ f(x) dx = ∫ f(exp u) exp(u) du` with `u = ln x`, for an integrand holding `ln x`
/// (`sin(ln x)`, `cos(ln x)/x^2`): what is left must be free of `x`.
pub(super) fn log_substitution(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    if !holds_log_of(f, &x) {
        return None;
    }
    let u = ctx.fresh();
    let exp_u = Sym::call(Func::Exp, vec![var(&u)]);
    let g = Sym::product(vec![f.substitute(&x, &exp_u), exp_u]);
    if !g.free_of(&x) || holds_log_of(&g, &u) {
        return None;
    }
    let big_g = ctx.integrate_in(&g, &u)?;
    let back = big_g.substitute(&u, &Sym::call(Func::Ln, vec![var(&x)]));
    Some(exp_of_logs_as_powers(&back))
}

/// Whether `s` holds `ln(x)` itself.
fn holds_log_of(s: &Sym, x: &str) -> bool {
    s.any(&mut |node| {
        matches!(node, Sym::Call(Func::Ln, args) if matches!(&args[0], Sym::Var(v) if v == x))
    })
}
