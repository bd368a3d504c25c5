//! Formulas compiled for the hot loop: names resolved to slots of a variable slice, constants
//! folded, common sub-expressions computed once. Two evaluators agree bit for bit: a portable
//! interpreter, and native code generated with Cranelift (feature `jit`, the default fast
//! path; [`Program::native`] attaches it, shared with every program of the same
//! instructions, so a sweep that rebuilds its scenario per run compiles each formula once). Over intervals, [`Program::eval_interval`] and
//! [`Program::eval_jet`] bound a formula and its derivative over a box (see
//! [`crate::interval`]), by the same instructions.

#[cfg(feature = "jit")]
mod cache;
mod derivative;
mod domain;
mod ir;
#[cfg(feature = "jit")]
mod jit;
#[cfg(feature = "jit")]
mod jit_kernel;
mod kernel;

pub use kernel::{Kernel, KernelBuilder, Val};

/// Whether compiled formulas get native code ([`Program::native`]): the `jit` feature is on
/// and `MECHKIT_JIT` is not `0`. (A host Cranelift cannot target still falls back to the
/// interpreter, with the same results.)
pub fn native_code() -> bool {
    #[cfg(feature = "jit")]
    {
        jit::enabled()
    }
    #[cfg(not(feature = "jit"))]
    {
        false
    }
}

#[cfg(any(test, not(feature = "jit")))]
use std::sync::Arc;

use ir::Ir;

use crate::ast::Expr;
use crate::interval::{Interval, Jet};
use crate::scope::Scope;

/// A compiled formula. Evaluate it with [`Program::eval`] on a slice of variable values laid
/// out as the [`Scope`] it was compiled against said.
///
/// # Example
/// ```
/// use mechkit_expr::{Formula, MapScope};
/// let f = Formula::parse("-k*(x - L)").unwrap();
/// let scope = MapScope::new().constant("k", 10.0).constant("L", 0.5).slot("x", 0);
/// let program = f.compile(&scope).unwrap().native();
/// assert!((program.eval(&[0.7]) + 2.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone)]
pub struct Program {
    ir: Ir,
    #[cfg(feature = "jit")]
    native: Option<jit::Attached>,
    #[cfg(not(feature = "jit"))]
    native: Option<Arc<()>>,
}

impl PartialEq for Program {
    fn eq(&self, other: &Program) -> bool {
        self.ir == other.ir
    }
}

impl Program {
    /// Compiles an expression, resolving names with `scope` (then the built-in `pi` and `e`).
    /// Fails on the first name that is not defined; without a span for it (see
    /// [`crate::Formula::compile`] for located errors).
    pub fn compile(expr: &Expr, scope: &dyn Scope) -> Result<Program, String> {
        Ok(Program {
            ir: Ir::build(expr, scope)?,
            native: None,
        })
    }

    /// The same program with native code attached, when the `jit` feature is on, the host is
    /// supported and `MECHKIT_JIT` is not `0`; otherwise unchanged (the interpreter serves).
    #[must_use]
    pub fn native(mut self) -> Program {
        #[cfg(feature = "jit")]
        if self.native.is_none() && self.ir.as_constant().is_none() && jit::enabled() {
            self.native = jit::Native::shared(&self.ir).ok();
        }
        self
    }

    /// The native code attached, for tests of its sharing.
    #[cfg(all(test, feature = "jit"))]
    fn native_code(&self) -> Option<&Arc<jit::Native>> {
        self.native.as_ref().map(|a| &a.code)
    }

    /// Whether evaluation runs native code.
    pub fn is_native(&self) -> bool {
        self.native.is_some()
    }

    /// Evaluates the program. `vars` must hold at least [`Program::slots`] values.
    #[inline]
    pub fn eval(&self, vars: &[f64]) -> f64 {
        self.check_slots(vars.len());
        #[cfg(feature = "jit")]
        if let Some(n) = &self.native {
            return n.call(vars);
        }
        self.ir.run(vars)
    }

    /// Evaluates with the interpreter, whatever is attached.
    pub fn eval_interpreted(&self, vars: &[f64]) -> f64 {
        self.check_slots(vars.len());
        self.ir.run(vars)
    }

    /// Bounds the program over a box: an enclosure of its value for every choice of
    /// `vars[s]` in its interval (both the exact value and the one [`Program::eval`]
    /// computes). [`Interval::ENTIRE`] where it may be NaN, so `is_positive()` on the result
    /// proves the formula positive on the whole box. `vars` must hold at least
    /// [`Program::slots`] intervals. Allocates nothing for programs of up to 32 instructions.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{Formula, Interval, MapScope};
    /// let scope = MapScope::new().slot("x", 0).slot("y", 1);
    /// let p = Formula::parse("sqrt(x^2 + y^2) - 0.5").unwrap().compile(&scope).unwrap();
    /// let g = p.eval_interval(&[Interval::new(0.6, 0.7), Interval::new(-0.1, 0.1)]);
    /// assert!(g.is_positive()); // the box lies outside the circle of radius 0.5
    /// assert!(g.contains(p.eval(&[0.65, 0.0])));
    /// ```
    pub fn eval_interval(&self, vars: &[Interval]) -> Interval {
        self.check_slots(vars.len());
        self.ir.run(vars)
    }

    /// Bounds the program and its derivative with respect to one parameter over an interval
    /// of it: each `vars[s]` is the enclosure of that variable's value and rate (a constant
    /// has rate `[0, 0]`, the parameter itself [`Jet::variable`]). See [`Jet`] for what the
    /// derivative bound guarantees. Allocates nothing for programs of up to 32 instructions.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{Formula, Interval, Jet, MapScope};
    /// let scope = MapScope::new().slot("t", 0).slot("x", 1);
    /// let p = Formula::parse("x - 0.1*t").unwrap().compile(&scope).unwrap();
    /// // over t ∈ [0, 1], x ∈ [0.2, 0.4] moving at a rate in [0.5, 1]:
    /// let t = Jet::variable(Interval::new(0.0, 1.0));
    /// let x = Jet::new(Interval::new(0.2, 0.4), Interval::new(0.5, 1.0));
    /// let g = p.eval_jet(&[t, x]);
    /// assert!(g.v.is_positive() && g.is_increasing());
    /// ```
    pub fn eval_jet(&self, vars: &[Jet]) -> Jet {
        self.check_slots(vars.len());
        self.ir.run(vars)
    }

    /// Panics, as a caller bug, when fewer than [`Program::slots`] values are given.
    #[inline]
    fn check_slots(&self, given: usize) {
        assert!(
            given >= self.ir.slots,
            "program reads {} variables, {given} given",
            self.ir.slots
        );
    }

    /// How many variable slots the program reads (one more than the largest slot index).
    pub fn slots(&self) -> usize {
        self.ir.slots
    }

    /// The value, when the program reads no variables.
    pub fn as_constant(&self) -> Option<f64> {
        self.ir.as_constant()
    }

    /// Number of instructions after folding and sharing (a measure of evaluation cost).
    pub fn len(&self) -> usize {
        self.ir.insts.len()
    }

    /// Whether the program has no instructions (never true for a compiled formula).
    pub fn is_empty(&self) -> bool {
        self.ir.insts.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parser::parse;
    use crate::scope::MapScope;

    fn compile(src: &str, scope: &MapScope) -> Program {
        Program::compile(&parse(src).unwrap().expr, scope).unwrap()
    }

    #[test]
    fn constants_fold_away() {
        let scope = MapScope::new()
            .constant("g", 9.8)
            .constant("D", 4.0)
            .slot("v", 0);
        let p = compile("-g*D*v*abs(v)", &scope);
        assert_eq!(p.eval(&[-2.0]), -9.8 * 4.0 * -2.0 * 2.0);
        let c = compile("2*pi*g", &scope);
        assert_eq!(c.as_constant(), Some(2.0 * std::f64::consts::PI * 9.8));
    }

    #[test]
    fn common_subexpressions_are_computed_once() {
        let scope = MapScope::new().slot("x", 0).slot("y", 1);
        let p = compile("sin(x*y) + sin(x*y)^2 + x*y", &scope);
        // x, y, x*y, sin, sin^2, +, +
        assert_eq!(p.len(), 7);
        let (x, y) = (0.3_f64, 1.7_f64);
        let s = (x * y).sin();
        assert_eq!(p.eval(&[x, y]), s + s * s + x * y);
    }

    #[test]
    fn agrees_with_the_tree_walker() {
        let scope = MapScope::new().slot("x", 0).slot("y", 1);
        for src in [
            "x^2 + y^3 - x^-2 + x^0.5",
            "if(x > y, min(x, y, 3), max(x, y))",
            "atan2(y, x) + sign(x - y) + heaviside(y)",
            "not (x < 1 or y > 2) and x != y",
            "-(x - y)/(x + y)",
            "x",
            "3",
        ] {
            let p = compile(src, &scope);
            let native = p.clone().native();
            if cfg!(feature = "jit")
                && p.as_constant().is_none()
                && std::env::var("MECHKIT_JIT").as_deref() != Ok("0")
            {
                assert!(native.is_native(), "{src} has no native code");
            }
            let e = parse(src).unwrap().expr;
            for (x, y) in [(1.5, 0.5), (0.25, 3.0), (2.0, 2.0)] {
                let tree = e
                    .eval_with(&|n| match n {
                        "x" => Some(x),
                        "y" => Some(y),
                        _ => None,
                    })
                    .unwrap();
                let fast = p.eval(&[x, y]);
                assert!(
                    (tree - fast).abs() <= 1e-15 * tree.abs().max(1.0),
                    "{src} at ({x}, {y}): {tree} vs {fast}"
                );
                assert_eq!(
                    native.eval(&[x, y]).to_bits(),
                    fast.to_bits(),
                    "{src} native"
                );
            }
        }
    }

    #[test]
    fn long_programs_fall_back_to_the_heap() {
        use std::fmt::Write as _;
        let scope = MapScope::new().slot("x", 0);
        let mut src = String::new();
        for i in 0..100 {
            let _ = write!(src, "x^{}+", i + 4);
        }
        src.push('x');
        let p = compile(&src, &scope);
        assert!(p.len() > 64);
        let x: f64 = 0.9;
        let expect: f64 = (0..100).map(|i| x.powi(i + 4)).fold(0.0, |a, b| a + b) + x;
        assert!((p.eval(&[x]) - expect).abs() < 1e-12);
    }

    #[test]
    fn undefined_names_are_reported() {
        let e = Program::compile(&parse("x + q").unwrap().expr, &MapScope::new().slot("x", 0));
        assert_eq!(e.unwrap_err(), "q");
    }
}
