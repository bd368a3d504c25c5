//! Issue 26: the deepest formulas the parser accepts (`MAX_DEPTH` = 256 levels) go through
//! every recursive pass over their tree (dimensions, compilation, native code, evaluation,
//! printing, simplification, the derivative and its program, dropping) on a small stack.
//!
//! Measured (one thread, a stack searched by halving until the pass overflowed): in a
//! release build the worst pass at 256 levels needs 330 KiB (the derivative of a tower of
//! powers), the parser 183 KiB (nested calls); a rayon worker has 2 MiB. A debug build
//! gives every temporary its own slot and needs up to 8 times more (the derivative of 256
//! nested calls passes 2 MiB there), so the test's thread has 1 MiB in release and 8 MiB in
//! debug.

use mechkit_expr::units::Dimension;
use mechkit_expr::{Dim, Formula, Interval, MAX_DEPTH, MapScope, Sym, simplify};

fn stack() -> usize {
    if cfg!(debug_assertions) {
        8 << 20
    } else {
        1 << 20
    }
}

/// Formulas exactly `MAX_DEPTH` levels deep, of every shape that nests.
fn deepest() -> Vec<String> {
    let n = MAX_DEPTH;
    let nested =
        |open: &str, close: &str, k: usize| format!("{}x{}", open.repeat(k), close.repeat(k));
    vec![
        vec!["x"; n + 1].join("+"),
        (0..=n)
            .map(|i| ["x", "y", "2"][i % 3])
            .collect::<Vec<_>>()
            .join("*"),
        vec!["x"; n + 1].join("-"),
        vec!["x"; n + 1].join("/"),
        vec!["x < 1"; n / 2].join(" and "),
        nested("(", ")", n),
        nested("floor(", ")", n),
        nested("-(", ")", n / 2),
        nested("y-(", ")", n / 2),
        nested("1/(1+", ")", n / 3),
        nested("if(x > 0,", ", 0)", n - 1),
        nested("max(y,", ")", n),
    ]
}

fn every_pass(text: &str) {
    let f = Formula::parse(text).expect("within the limit");
    let _ = f.dimension(&|_| Dim::Known(Dimension::NONE));
    let scope = MapScope::new().slot("x", 0).slot("y", 1);
    let p = f.compile(&scope).expect("names defined");
    let v = [0.5, 0.25];
    let native = p.clone().native();
    let (a, b) = (p.eval_interpreted(&v), native.eval(&v));
    assert!(
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
        "{a} {b}"
    );
    let _ = p.eval_interval(&[Interval::new(0.1, 0.2), Interval::new(0.3, 0.4)]);
    let _ = f.eval_with(&|n| (n == "x" || n == "y").then_some(0.5));
    assert!(!f.expr().to_string().is_empty());
    let _ = simplify(f.expr()).to_string();
    let d = Sym::from_expr(f.expr()).diff("x").to_expr();
    let _ = d.to_string();
    let _ = mechkit_expr::Program::compile(&d, &scope)
        .expect("names defined")
        .native()
        .eval(&v);
    drop(d);
    drop(f);
}

#[test]
fn issue_026_every_pass_over_the_deepest_formulas_fits_a_small_stack() {
    for text in deepest() {
        let head: String = text.chars().take(30).collect();
        std::thread::Builder::new()
            .stack_size(stack())
            .spawn(move || every_pass(&text))
            .expect("a thread starts")
            .join()
            .unwrap_or_else(|_| panic!("a pass failed on `{head}…`"));
    }
}
