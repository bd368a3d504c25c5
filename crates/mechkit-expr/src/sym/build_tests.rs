//! Tests of the canonical product and sum constructors (`build.rs`).
use std::cell::Cell;

use super::*;

thread_local! {
    /// Calls of [`Sym::product`] on this thread.
    pub static PRODUCTS: Cell<u64> = const { Cell::new(0) };
}

/// `x0/(a + x^2)^0 + 3*(x1/(a + x^2)^1 + 3*(…)/(2*a))/(2*a)`, `n` deep: the shape the
/// reduction formula for `∫ dx/(a + x²)ⁿ` builds.
fn nested(n: usize, a: &str) -> String {
    let mut s = String::from("y");
    for i in 0..n {
        s = format!("x{i}/({a} + x^2)^{i} + 3*({s})/(2*{a})");
    }
    s
}

/// Found by the `calculus` target (2026-12-05): `1/(2*z^44 + x^2)^22` took 11 s, and a
/// formula of 700 characters nested 20 deep 5 s to parse: a product made its sum factor
/// primitive and then scaled it again, each a pass over the terms, so a sum nested `n`
/// deep was rebuilt `2ⁿ` times. Now the products built grow with the square of the depth
/// (the old code: 7,167 at depth 10, 1.8 million at depth 18), and the value is unchanged.
#[test]
fn fuzz_a_deeply_nested_sum_is_rebuilt_once_per_level() {
    // `a` a symbol, and a sum (a second sum in each product: the fuzz input
    // `1/(2*z^666…6 - 6666644 + x^2)^22` took 13 s that way, comparing the two sums)
    for (n, sum) in [
        (20, true),
        (40, true),
        (10, false),
        (20, false),
        (40, false),
    ] {
        let src = nested(n, if sum { "(a - 1)" } else { "a" });
        PRODUCTS.with(|c| c.set(0));
        let _ = Sym::parse(&src).unwrap();
        let calls = PRODUCTS.with(Cell::get);
        assert!(calls < 40 * (n * n) as u64, "depth {n}: {calls} products");
        if sum {
            continue;
        }
        let f = Sym::parse(&src).unwrap();
        // the value against the same nesting in floating point
        let (a, x): (f64, f64) = (1.7, 0.3);
        let mut want = 2.0;
        for i in 0..n {
            let xi = 0.1 * i as f64 + 0.05;
            want = xi / (a + x * x).powi(i as i32) + 3.0 * want / (2.0 * a);
        }
        let mut vars: Vec<(String, f64)> =
            vec![("a".into(), a), ("x".into(), x), ("y".into(), 2.0)];
        vars.extend((0..n).map(|i| (format!("x{i}"), 0.1 * i as f64 + 0.05)));
        let got = f
            .eval(&|name: &str| vars.iter().find(|(v, _)| v == name).map(|(_, x)| *x))
            .unwrap();
        assert!(
            (got - want).abs() <= 1e-12 * want.abs(),
            "depth {n}: {got} vs {want}"
        );
    }
    // the canonical forms the constructors promise are kept
    for (a, b) in [
        ("2*(x + 1)", "2*x + 2"),
        ("(x + 1)*(2*y + 2)", "(2*x + 2)*(y + 1)"),
        ("-(x + y)/pi", "(-x - y)/pi"),
        ("(x + 1)*(2*x + 2)", "2*(x + 1)^2"),
        ("3*(x/2 + 3*(y + 1)/4)", "3*x/2 + 9*y/4 + 9/4"),
        // one base though the numbers hide in a term's own sum
        (
            "(x/2 + z*(y + 1))*(x + z*(2*y + 2))",
            "(x + z*(2*y + 2))^2/2",
        ),
        (
            "(x/2 + z*(y + 1))*(x + z*(2*y + 2))^3",
            "(x + z*(2*y + 2))^4/2",
        ),
    ] {
        assert_eq!(Sym::parse(a).unwrap(), Sym::parse(b).unwrap(), "{a} vs {b}");
    }
}
