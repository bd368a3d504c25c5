//! What the instructions compute, over each kind of number they run on: `f64` (the values
//! [`super::Program::eval`] gives), [`Interval`] (enclosures over a box) and [`Jet`]
//! (enclosures with a derivative). [`super::ir::execute`] maps each instruction to one method
//! of [`Domain`]; the `f64` implementation here is the definition the native code agrees with
//! bit for bit, and the two others enclose it.

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::ast::{self, BinOp, Func};
use crate::interval::{Interval, Jet};

/// The operations of the instruction set over a kind of number.
pub(crate) trait Domain:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The number `c`.
    fn constant(c: f64) -> Self;
    /// `a*a`.
    fn square(self) -> Self;
    /// `a^b` by [`ast::pow`].
    fn pow(self, b: Self) -> Self;
    /// A one-argument built-in.
    fn call1(self, f: Func) -> Self;
    /// `atan2`, `min`, `max`.
    fn call2(self, f: Func, b: Self) -> Self;
    /// `< <= > >= == !=`: 1 or 0.
    fn compare(self, op: BinOp, b: Self) -> Self;
    /// `not a`: 1 where `a` is 0, else 0.
    fn not(self) -> Self;
    /// `a and b`.
    fn and(self, b: Self) -> Self;
    /// `a or b`.
    fn or(self, b: Self) -> Self;
    /// `if(self, a, b)`.
    fn select(self, a: Self, b: Self) -> Self;
    /// The operand whose bits, read as a signed integer, are smaller (for non-negative
    /// numbers, the smaller).
    fn min_bits(self, b: Self) -> Self;
    /// The operand whose bits are larger.
    fn max_bits(self, b: Self) -> Self;
}

fn truth(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

impl Domain for f64 {
    #[inline]
    fn constant(c: f64) -> f64 {
        c
    }
    #[inline]
    fn square(self) -> f64 {
        self * self
    }
    #[inline]
    fn pow(self, b: f64) -> f64 {
        ast::pow(self, b)
    }
    #[inline]
    fn call1(self, f: Func) -> f64 {
        f.apply1(self)
    }
    #[inline]
    fn call2(self, f: Func, b: f64) -> f64 {
        f.apply2(self, b)
    }
    #[inline]
    fn compare(self, op: BinOp, b: f64) -> f64 {
        op.apply(self, b)
    }
    #[inline]
    fn not(self) -> f64 {
        truth(self == 0.0)
    }
    #[inline]
    fn and(self, b: f64) -> f64 {
        truth(self != 0.0 && b != 0.0)
    }
    #[inline]
    fn or(self, b: f64) -> f64 {
        truth(self != 0.0 || b != 0.0)
    }
    #[inline]
    fn select(self, a: f64, b: f64) -> f64 {
        ast::select(self, a, b)
    }
    #[inline]
    fn min_bits(self, b: f64) -> f64 {
        if (self.to_bits() as i64) < (b.to_bits() as i64) {
            self
        } else {
            b
        }
    }
    #[inline]
    fn max_bits(self, b: f64) -> f64 {
        if (self.to_bits() as i64) > (b.to_bits() as i64) {
            self
        } else {
            b
        }
    }
}

/// Whether `min_bits`/`max_bits` of values in `a` and `b` are their `min`/`max`: no sign bit
/// set, that is every value `>= 0` (`−0` has its sign bit set, but it is then the smaller
/// both ways, and equal to `+0`).
fn bits_are_order(a: Interval, b: Interval) -> bool {
    a.is_nonnegative() && b.is_nonnegative()
}

impl Domain for Interval {
    fn constant(c: f64) -> Interval {
        Interval::point(c)
    }
    fn square(self) -> Interval {
        self.sqr()
    }
    fn pow(self, b: Interval) -> Interval {
        Interval::pow(self, b)
    }
    fn call1(self, f: Func) -> Interval {
        self.apply1(f)
    }
    fn call2(self, f: Func, b: Interval) -> Interval {
        self.apply2(f, b)
    }
    fn compare(self, op: BinOp, b: Interval) -> Interval {
        Interval::compare(self, op, b)
    }
    fn not(self) -> Interval {
        self.logical_not()
    }
    fn and(self, b: Interval) -> Interval {
        self.logical_and(b)
    }
    fn or(self, b: Interval) -> Interval {
        self.logical_or(b)
    }
    fn select(self, a: Interval, b: Interval) -> Interval {
        Interval::select(self, a, b)
    }
    /// `min` where both are non-negative, else one of the two: their hull.
    fn min_bits(self, b: Interval) -> Interval {
        if bits_are_order(self, b) {
            self.min(b)
        } else {
            self.hull(b)
        }
    }
    fn max_bits(self, b: Interval) -> Interval {
        if bits_are_order(self, b) {
            self.max(b)
        } else {
            self.hull(b)
        }
    }
}

impl Domain for Jet {
    fn constant(c: f64) -> Jet {
        Jet::constant(c)
    }
    fn square(self) -> Jet {
        self.sqr()
    }
    fn pow(self, b: Jet) -> Jet {
        Jet::pow(self, b)
    }
    fn call1(self, f: Func) -> Jet {
        self.apply1(f)
    }
    fn call2(self, f: Func, b: Jet) -> Jet {
        self.apply2(f, b)
    }
    fn compare(self, op: BinOp, b: Jet) -> Jet {
        Jet::compare(self, op, b)
    }
    fn not(self) -> Jet {
        self.logical_not()
    }
    fn and(self, b: Jet) -> Jet {
        self.logical_and(b)
    }
    fn or(self, b: Jet) -> Jet {
        self.logical_or(b)
    }
    fn select(self, a: Jet, b: Jet) -> Jet {
        Jet::select(self, a, b)
    }
    /// `min` where both are non-negative; else one of the two, which may switch: the hull of
    /// the values with an ENTIRE derivative.
    fn min_bits(self, b: Jet) -> Jet {
        if bits_are_order(self.v, b.v) {
            self.min(b)
        } else {
            Jet::new(self.v.hull(b.v), Interval::ENTIRE)
        }
    }
    fn max_bits(self, b: Jet) -> Jet {
        if bits_are_order(self.v, b.v) {
            self.max(b)
        } else {
            Jet::new(self.v.hull(b.v), Interval::ENTIRE)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compile::Program;
    use crate::compile::ir::{Inst, Ir};
    use crate::{Formula, MapScope, Sym};
    use proptest::prelude::*;

    /// Formulas of x and y that, together, use every instruction a formula compiles to and
    /// every built-in function.
    const TEMPLATES: &[&str] = &[
        "sin(3*x) + x^2 - exp(-x)*y",
        "sqrt(x^2 + y^2) - 0.5",
        "abs(x - 0.3)",
        "if(x > 0.2, x, -x)",
        "atan2(y, x)",
        "(x - 0.5)^2 - 1e-12",
        "x^-3",
        "x^1.5",
        "min(x, y)",
        "tanh(x)/cosh(y)",
        "max(x, y, 0.1) - cos(x*y)",
        "tan(x) + atan(y)",
        "asin(x) - acos(y/2)",
        "log(x) + ln(y) - log10(x*y)",
        "cbrt(x - y) + sinh(y)",
        "sign(x) + heaviside(y) - floor(3*x) + ceil(2*y)",
        "x^y",
        "(x < y) + (x <= 0.5) - (y > x)*(x >= -0.5)",
        "(x == y) + (x != 0.25)",
        "if(x > 0 and y < 1 or not (x < y), x*y, y/x)",
        "exp(x)^2/(1 + y^2)",
        "x^7 - 3*x^4 + y^-2",
        "sqrt(x)*ln(x) + 0*y",
    ];

    fn scope() -> MapScope {
        MapScope::new().slot("x", 0).slot("y", 1)
    }

    fn compile(src: &str) -> Program {
        Formula::parse(src).unwrap().compile(&scope()).unwrap()
    }

    /// The exact partial derivatives, by the symbolic engine.
    fn gradient(src: &str) -> [Program; 2] {
        let g = Sym::parse(src).unwrap().gradient(&["x", "y"]);
        let p = |s: &Sym| Program::compile(&s.to_expr(), &scope()).unwrap();
        [p(&g[0]), p(&g[1])]
    }

    #[test]
    fn every_instruction_is_exercised() {
        let insts: Vec<Inst> = TEMPLATES.iter().flat_map(|s| compile(s).ir.insts).collect();
        let has = |f: &dyn Fn(&Inst) -> bool| insts.iter().any(f);
        assert!(has(&|i| matches!(i, Inst::Const(_))) && has(&|i| matches!(i, Inst::Load(_))));
        assert!(has(&|i| matches!(i, Inst::Neg(_))) && has(&|i| matches!(i, Inst::Not(_))));
        assert!(has(&|i| matches!(i, Inst::Add(..))) && has(&|i| matches!(i, Inst::Sub(..))));
        assert!(has(&|i| matches!(i, Inst::Mul(..))) && has(&|i| matches!(i, Inst::Div(..))));
        assert!(has(&|i| matches!(i, Inst::And(..))) && has(&|i| matches!(i, Inst::Or(..))));
        assert!(has(&|i| matches!(i, Inst::Pow(..))) && has(&|i| matches!(i, Inst::Square(_))));
        assert!(has(&|i| matches!(i, Inst::Select(..))));
        for op in [
            BinOp::Lt,
            BinOp::Le,
            BinOp::Gt,
            BinOp::Ge,
            BinOp::Eq,
            BinOp::Ne,
        ] {
            assert!(has(&|i| matches!(i, Inst::Cmp(o, ..) if *o == op)));
        }
        for f in Func::ALL.iter().filter(|f| **f != Func::If) {
            let called = |i: &Inst| matches!(i, Inst::Call1(g, _) | Inst::Call2(g, ..) if g == f);
            assert!(has(&called), "{} is not exercised", f.name());
        }
    }

    #[test]
    fn bit_minimum_and_maximum() {
        let ir = Ir {
            insts: vec![
                Inst::Load(0),
                Inst::Load(1),
                Inst::MinBits(0, 1),
                Inst::MaxBits(0, 1),
                Inst::Mul(2, 3),
            ],
            result: 4,
            slots: 2,
        };
        let p = Program { ir, native: None };
        let i = Interval::new;
        for (x, y) in [(i(0.0, 1.0), i(2.0, 3.0)), (i(-1.0, 1.0), i(-3.0, 2.0))] {
            let r = p.eval_interval(&[x, y]);
            let j = p.eval_jet(&[Jet::variable(x), Jet::new(y, Interval::ZERO)]);
            for (a, b) in [
                (x.lo(), y.lo()),
                (x.hi(), y.hi()),
                (x.lo(), y.hi()),
                (-0.0, 0.0),
            ] {
                if x.contains(a) && y.contains(b) {
                    assert!(r.contains(p.eval(&[a, b])) && j.v.contains(p.eval(&[a, b])));
                }
            }
        }
        // decided: min(x, y) = x, max = y, so the product x·y has derivative y
        let j = p.eval_jet(&[Jet::variable(i(0.0, 1.0)), Jet::constant(2.0)]);
        assert!(j.d.contains(2.0) && j.d.width() < 1e-12);
        // signs mixed: min_bits may switch operands
        let j = p.eval_jet(&[Jet::variable(i(-1.0, 1.0)), Jet::constant(0.5)]);
        assert!(j.d.is_entire());
    }

    #[test]
    fn nan_never_proves_a_sign() {
        let x = [Interval::new(-1.0, 1.0), Interval::point(1.0)];
        for src in [
            "(1/x)*0 + 1",
            "sqrt(x) + 1",
            "0*ln(x) + 2",
            "-(asin(2*x)^2) - 1",
        ] {
            let g = compile(src).eval_interval(&x);
            assert!(g.is_entire(), "{src}: {g}");
            let j = compile(src).eval_jet(&[Jet::variable(x[0]), Jet::constant(1.0)]);
            assert!(!j.is_increasing() && !j.is_decreasing() && !j.v.is_positive());
        }
        let nan = [Interval::point(f64::NAN), Interval::point(0.0)];
        for src in TEMPLATES
            .iter()
            .chain(&["x + 1", "abs(x) + 1", "exp(x)", "0/0 + y"])
        {
            let g = compile(src).eval_interval(&nan);
            assert!(!g.is_positive() && !g.is_negative(), "{src}: {g}");
        }
    }

    #[test]
    fn long_programs_run_on_the_heap() {
        use std::fmt::Write as _;
        let mut src = String::from("x");
        for k in 1..40 {
            let _ = write!(src, " + sin({k}*x)*y");
        }
        let p = compile(&src);
        assert!(p.len() > 32);
        let (x, y) = (Interval::new(0.1, 0.2), Interval::new(-1.0, 1.0));
        let r = p.eval_interval(&[x, y]);
        let j = p.eval_jet(&[Jet::variable(x), Jet::constant(0.5)]);
        for t in [0.1, 0.15, 0.2] {
            assert!(r.contains(p.eval(&[t, 0.5])) && j.v.contains(p.eval(&[t, 0.5])));
        }
    }

    #[test]
    fn proving_an_event_free_step() {
        // a ball at height y = 1 − t²/2 over t ∈ [0, 1]: the gap to the floor y − 0.4 stays
        // positive, and it is decreasing over [0.5, 1]
        let p = Formula::parse("y - 0.4")
            .unwrap()
            .compile(&MapScope::new().slot("y", 0))
            .unwrap();
        let t = Jet::variable(Interval::new(0.5, 1.0));
        let y = Jet::constant(1.0) - t.sqr() / Jet::constant(2.0);
        let g = p.eval_jet(&[y]);
        assert!(g.v.is_positive() && g.is_decreasing());
    }

    fn box_and_point(c: f64, a: f64, s: Interval, at: f64) -> (Interval, f64) {
        (Interval::point(c) + Interval::point(a) * s, c + a * at)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

        /// Along the line (x, y) = (cx + a·s, cy + b·s), s ∈ S: the point values lie in the
        /// interval and the jet enclosures, the exact derivative `a ∂f/∂x + b ∂f/∂y` in the
        /// jet's derivative, and differences in the jet's derivative times the step (the
        /// mean-value form, which kinks must keep too).
        #[test]
        fn programs_enclose_their_values_and_derivatives(
            k in 0..TEMPLATES.len(),
            cx in -2.0f64..2.0, cy in -2.0f64..2.0, a in -2.0f64..2.0, b in -2.0f64..2.0,
            e in -12i32..=0, u in 0.0f64..=1.0, point in prop::bool::weighted(0.1),
            r1 in 0.0f64..=1.0, r2 in 0.0f64..=1.0,
        ) {
            let src = TEMPLATES[k];
            let p = compile(src);
            let native = p.clone().native();
            let ws = if point { 0.0 } else { u * 10f64.powi(e) };
            let s = Interval::new(0.0, ws);
            let (s1, s2) = ((ws * r1).min(ws), (ws * r2).min(ws));
            let (xs, x1) = box_and_point(cx, a, s, s1);
            let (ys, y1) = box_and_point(cy, b, s, s1);
            let (x2, y2) = (cx + a * s2, cy + b * s2);
            let r = p.eval_interval(&[xs, ys]);
            let jx = Jet::new(xs, Interval::point(a));
            let jy = Jet::new(ys, Interval::point(b));
            let j = p.eval_jet(&[jx, jy]);
            let f1 = p.eval(&[x1, y1]);
            let f2 = p.eval(&[x2, y2]);
            for f in [f1, f2, native.eval(&[x1, y1]), p.eval_interpreted(&[x2, y2])] {
                prop_assert!(r.contains(f), "{src}: {f} not in {r}");
                prop_assert!(j.v.contains(f), "{src}: {f} not in jet {}", j.v);
            }
            let near = |d: Interval, x: f64, slack: f64| d.lo() - slack <= x && x <= d.hi() + slack;
            let [gx, gy] = gradient(src);
            let (dx, dy) = (gx.eval(&[x1, y1]) * a, gy.eval(&[x1, y1]) * b);
            let exact = dx + dy;
            if exact.is_finite() && f1.is_finite() {
                let slack = 1e-9 * (1.0 + dx.abs() + dy.abs());
                prop_assert!(near(j.d, exact, slack), "{src}: f' = {exact} not in {}", j.d);
            }
            if f1.is_finite() && f2.is_finite() && s1 != s2 {
                let slope = (f2 - f1) / (s2 - s1);
                let slack = 1e-10 * (1.0 + f1.abs() + f2.abs()) / (s2 - s1).abs();
                prop_assert!(near(j.d, slope, slack), "{src}: slope {slope} not in {}", j.d);
            }
        }
    }
}
