use crate::{Formula, Func, KernelBuilder, MapScope};

/// `∂f/∂x` and `∂f/∂v` of a formula in `x, v` at a point, by the kernel's derivatives
/// (interpreted and native).
fn gradient(formula: &str, x: f64, v: f64) -> [[f64; 2]; 2] {
    let scope = MapScope::new().constant("k", 3.0).slot("x", 0).slot("v", 1);
    let f = Formula::parse(formula).unwrap().compile(&scope).unwrap();
    let mut b = KernelBuilder::new(4);
    let (xs, vs) = (b.get(0), b.get(1));
    let y = b.inline(&f, &[xs, vs]);
    for (slot, wrt) in [(2, xs), (3, vs)] {
        let d = b.derivatives(&[y], wrt).unwrap()[0].unwrap_or_else(|| b.constant(0.0));
        b.set(slot, d);
    }
    let kernel = b.finish();
    let native = kernel.clone().native();
    let (mut a, mut n) = ([x, v, 0.0, 0.0], [x, v, 0.0, 0.0]);
    kernel.run_interpreted(&mut a, 1);
    native.run(&mut n, 1);
    [[a[2], a[3]], [n[2], n[3]]]
}

fn central(formula: &str, x: f64, v: f64) -> [f64; 2] {
    let scope = MapScope::new().constant("k", 3.0).slot("x", 0).slot("v", 1);
    let f = Formula::parse(formula).unwrap().compile(&scope).unwrap();
    let e = |x: f64, v: f64| f.eval(&[x, v]);
    let h = 1e-6;
    [
        (e(x + h, v) - e(x - h, v)) / (2.0 * h),
        (e(x, v + h) - e(x, v - h)) / (2.0 * h),
    ]
}

#[test]
fn derivatives_match_central_differences_for_every_operator_and_function() {
    let formulas = [
        "-k*x - 0.3*v*abs(v)",
        "1000*(1 - x^2)*v - x",
        "x/(1 + v^2) - v/x",
        "x^2.5 + v^3 + x^v",
        "sin(x*v) + cos(x) + tan(0.3*v)",
        "asin(x/4) + acos(v/5) + atan(x - v)",
        "sinh(x) + cosh(v) + tanh(x*v)",
        "exp(-x^2)*ln(2 + v) + log10(x + 3) + log(4 + v)",
        "sqrt(1 + x^2) + cbrt(x + v + 5)",
        "min(x, v) + max(x^2, v) + atan2(v, x)",
        "if(x > v, x^3, v^2) + heaviside(x)*x + sign(v)*v + floor(x)",
        "-k*x/(x^2 + v^2)^(3/2)",
    ];
    for f in formulas {
        for (x, v) in [(0.7, 1.3), (1.9, -0.4), (-0.8, 0.6)] {
            let [interp, native] = gradient(f, x, v);
            assert_eq!(
                interp.map(f64::to_bits),
                native.map(f64::to_bits),
                "{f} at ({x}, {v})"
            );
            let fd = central(f, x, v);
            for (a, b) in interp.iter().zip(&fd) {
                if b.is_nan() {
                    // outside the formula's domain: the derivative is not finite either
                    assert!(
                        !a.is_finite(),
                        "{f} at ({x}, {v}): {a} where the formula is NaN"
                    );
                    continue;
                }
                let scale = 1.0 + a.abs().max(b.abs());
                assert!(
                    (a - b).abs() < 1e-6 * scale,
                    "{f} at ({x}, {v}): {interp:?} vs {fd:?}"
                );
            }
        }
    }
}

#[test]
fn values_that_do_not_depend_on_the_variable_have_a_structural_zero() {
    let mut b = KernelBuilder::new(3);
    let (x, y, z) = (b.get(0), b.get(1), b.get(2));
    let s = b.call(Func::Sin, y);
    let p = b.mul(x, y);
    let c = b.constant(2.0);
    let d = b.derivatives(&[s, p, c, z], x).unwrap();
    assert!(d[0].is_none() && d[2].is_none() && d[3].is_none());
    assert_eq!(d[1], Some(y));
}
