//! The built-in functions, comparisons, logic and `if` over [`Jet`]s: the chain rule
//! `f(u)′ = f′(u)·u′` in interval arithmetic,
//!
//! | f | f′(u) |
//! |---|---|
//! | `exp`, `ln`, `log10` | `eᵘ`, `1/u`, `1/(u ln 10)` |
//! | `sqrt`, `cbrt` | `1/(2√u)`, `1/(3∛u²)` (ENTIRE where `u` reaches 0) |
//! | `sin`, `cos`, `tan` | `cos u`, `−sin u`, `1 + tan² u` |
//! | `asin`, `acos`, `atan` | `±1/√(1 − u²)`, `1/(1 + u²)` |
//! | `sinh`, `cosh`, `tanh` | `cosh u`, `sinh u`, `1 − tanh² u` |
//! | `atan2(y, x)` | `(x·y′ − y·x′)/(x² + y²)`, ENTIRE across the branch cut |
//!
//! Kinks keep a Lipschitz bound: `|u|` across 0 has derivative in `hull(u′, −u′)`, `min` and
//! `max` that decide nothing in `hull(u′, w′)`. Steps (`sign`, `heaviside`, `floor`, `ceil`,
//! comparisons, logic, an undecided `if`) have derivative 0 where their value is one value
//! over the interval and ENTIRE where it may jump ([`Jet::step`]).

use super::bounds::Interval;
use super::jet::Jet;
use super::trig::atan2_continuous;
use crate::ast::{BinOp, Func};

/// `ln 10` as an interval around the exact value.
fn ln_10() -> Interval {
    let l = std::f64::consts::LN_10;
    Interval::outward(l, l)
}

impl Jet {
    /// The chain rule: value `v`, derivative `f′(u)·u′`.
    fn chain(self, v: Interval, df: Interval) -> Jet {
        Jet::new(v, df * self.d)
    }

    /// `eᵘ`.
    #[must_use]
    pub fn exp(self) -> Jet {
        let v = self.v.exp();
        self.chain(v, v)
    }

    /// `ln u`.
    #[must_use]
    pub fn ln(self) -> Jet {
        Jet::new(self.v.ln(), self.d / self.v)
    }

    /// `log₁₀ u`.
    #[must_use]
    pub fn log10(self) -> Jet {
        Jet::new(self.v.log10(), self.d / (self.v * ln_10()))
    }

    /// `√u`; the derivative is ENTIRE where `u` reaches 0.
    #[must_use]
    pub fn sqrt(self) -> Jet {
        let v = self.v.sqrt();
        Jet::new(v, self.d / (Interval::point(2.0) * v))
    }

    /// `∛u`; the derivative is ENTIRE where `u` reaches 0.
    #[must_use]
    pub fn cbrt(self) -> Jet {
        let v = self.v.cbrt();
        Jet::new(v, self.d / (Interval::point(3.0) * v.sqr()))
    }

    /// `sin u`.
    #[must_use]
    pub fn sin(self) -> Jet {
        self.chain(self.v.sin(), self.v.cos())
    }

    /// `cos u`.
    #[must_use]
    pub fn cos(self) -> Jet {
        self.chain(self.v.cos(), -self.v.sin())
    }

    /// `tan u`.
    #[must_use]
    pub fn tan(self) -> Jet {
        let v = self.v.tan();
        self.chain(v, Interval::ONE + v.sqr())
    }

    /// `asin u`.
    #[must_use]
    pub fn asin(self) -> Jet {
        let root = (Interval::ONE - self.v.sqr()).sqrt();
        Jet::new(self.v.asin(), self.d / root)
    }

    /// `acos u`.
    #[must_use]
    pub fn acos(self) -> Jet {
        let root = (Interval::ONE - self.v.sqr()).sqrt();
        Jet::new(self.v.acos(), -(self.d / root))
    }

    /// `atan u`.
    #[must_use]
    pub fn atan(self) -> Jet {
        Jet::new(self.v.atan(), self.d / (Interval::ONE + self.v.sqr()))
    }

    /// `atan2(self, x)`: derivative `(x·y′ − y·x′)/(x² + y²)`, ENTIRE where the box meets the
    /// branch cut (`x <= 0`, `y = 0`), across which the angle jumps by 2π.
    #[must_use]
    pub fn atan2(self, x: Jet) -> Jet {
        let y = self;
        let v = y.v.atan2(x.v);
        if !atan2_continuous(y.v, x.v) {
            return Jet::new(v, Interval::ENTIRE);
        }
        Jet::new(v, (x.v * y.d - y.v * x.d) / (x.v.sqr() + y.v.sqr()))
    }

    /// `sinh u`.
    #[must_use]
    pub fn sinh(self) -> Jet {
        self.chain(self.v.sinh(), self.v.cosh())
    }

    /// `cosh u`.
    #[must_use]
    pub fn cosh(self) -> Jet {
        self.chain(self.v.cosh(), self.v.sinh())
    }

    /// `tanh u`.
    #[must_use]
    pub fn tanh(self) -> Jet {
        let v = self.v.tanh();
        self.chain(v, Interval::ONE - v.sqr())
    }

    /// `|u|`: `±u` where `u` keeps its sign, else derivative `hull(u′, −u′)` (a Lipschitz
    /// bound: `|u|` is absolutely continuous).
    #[must_use]
    pub fn abs(self) -> Jet {
        let v = self.v.abs();
        let d = if self.v.is_nonnegative() {
            self.d
        } else if self.v.is_nonpositive() {
            -self.d
        } else {
            self.d.hull(-self.d)
        };
        Jet::new(v, d)
    }

    /// `sign u`: a step.
    #[must_use]
    pub fn sign(self) -> Jet {
        Jet::step(self.v.sign())
    }

    /// `heaviside u`: a step.
    #[must_use]
    pub fn heaviside(self) -> Jet {
        Jet::step(self.v.heaviside())
    }

    /// `⌊u⌋`: a step.
    #[must_use]
    pub fn floor(self) -> Jet {
        Jet::step(self.v.floor())
    }

    /// `⌈u⌉`: a step.
    #[must_use]
    pub fn ceil(self) -> Jet {
        Jet::step(self.v.ceil())
    }

    /// `min(u, w)`: the one certainly smaller, else derivative `hull(u′, w′)`.
    #[must_use]
    pub fn min(self, w: Jet) -> Jet {
        if self.v.is_entire() || w.v.is_entire() {
            Jet::ENTIRE
        } else if self.v.hi() <= w.v.lo() {
            self
        } else if w.v.hi() <= self.v.lo() {
            w
        } else {
            Jet::new(self.v.min(w.v), self.d.hull(w.d))
        }
    }

    /// `max(u, w)`: the one certainly larger, else derivative `hull(u′, w′)`.
    #[must_use]
    pub fn max(self, w: Jet) -> Jet {
        if self.v.is_entire() || w.v.is_entire() {
            Jet::ENTIRE
        } else if self.v.lo() >= w.v.hi() {
            self
        } else if w.v.lo() >= self.v.hi() {
            w
        } else {
            Jet::new(self.v.max(w.v), self.d.hull(w.d))
        }
    }

    /// A comparison `< <= > >= == !=`: a step.
    ///
    /// # Panics
    /// When `op` is not a comparison.
    #[must_use]
    pub fn compare(self, op: BinOp, w: Jet) -> Jet {
        Jet::step(self.v.compare(op, w.v))
    }

    /// `not u`: a step.
    #[must_use]
    pub fn logical_not(self) -> Jet {
        Jet::step(self.v.logical_not())
    }

    /// `u and w`: a step.
    #[must_use]
    pub fn logical_and(self, w: Jet) -> Jet {
        Jet::step(self.v.logical_and(w.v))
    }

    /// `u or w`: a step.
    #[must_use]
    pub fn logical_or(self, w: Jet) -> Jet {
        Jet::step(self.v.logical_or(w.v))
    }

    /// `if(self, a, b)`: `a` or `b` where the condition is decided over the interval, else
    /// the hull of the values with an ENTIRE derivative (the result may jump between them).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{BinOp, Interval, Jet};
    /// let x = Jet::variable(Interval::new(0.3, 0.5));
    /// let c = x.compare(BinOp::Gt, Jet::constant(0.2));
    /// assert_eq!(c.select(x, -x), x); // decided: the derivative stays 1
    /// ```
    #[must_use]
    pub fn select(self, a: Jet, b: Jet) -> Jet {
        if self.v.is_true() {
            a
        } else if self.v.is_false() {
            b
        } else {
            Jet::new(a.v.hull(b.v), Interval::ENTIRE)
        }
    }

    /// `f(u)` for a one-argument built-in, as [`Func::apply1`] computes it pointwise.
    ///
    /// # Panics
    /// For `atan2`, `min`, `max` and `if`.
    #[must_use]
    pub fn apply1(self, f: Func) -> Jet {
        match f {
            Func::Sin => self.sin(),
            Func::Cos => self.cos(),
            Func::Tan => self.tan(),
            Func::Asin => self.asin(),
            Func::Acos => self.acos(),
            Func::Atan => self.atan(),
            Func::Sinh => self.sinh(),
            Func::Cosh => self.cosh(),
            Func::Tanh => self.tanh(),
            Func::Exp => self.exp(),
            Func::Log | Func::Ln => self.ln(),
            Func::Log10 => self.log10(),
            Func::Sqrt => self.sqrt(),
            Func::Cbrt => self.cbrt(),
            Func::Abs => self.abs(),
            Func::Sign => self.sign(),
            Func::Floor => self.floor(),
            Func::Ceil => self.ceil(),
            Func::Heaviside => self.heaviside(),
            Func::Atan2 | Func::Min | Func::Max | Func::If => {
                panic!("{} does not take one argument", f.name())
            }
        }
    }

    /// `f(self, w)` for `atan2`, `min` and `max`, as [`Func::apply2`] computes it.
    ///
    /// # Panics
    /// For the other functions.
    #[must_use]
    pub fn apply2(self, f: Func, w: Jet) -> Jet {
        match f {
            Func::Atan2 => self.atan2(w),
            Func::Min => self.min(w),
            Func::Max => self.max(w),
            _ => panic!("{} does not take two arguments", f.name()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(lo: f64, hi: f64) -> Jet {
        Jet::variable(Interval::new(lo, hi))
    }

    #[test]
    fn chain_rule() {
        let s = (Jet::constant(3.0) * t(0.0, 0.1)).sin(); // 3 cos 3t ∈ [3 cos 0.3, 3]
        assert!(s.d.contains(3.0) && s.d.contains(3.0 * 0.3f64.cos()) && s.is_increasing());
        let e = (-t(0.0, 1.0)).exp(); // −e^(−t)
        assert!(e.is_decreasing() && e.d.contains(-1.0) && e.d.contains(-(-1f64).exp()));
        assert!(t(0.0, 1.0).sqrt().d.is_entire());
        assert!(t(1.0, 4.0).sqrt().d.contains(0.25) && t(1.0, 4.0).sqrt().d.contains(0.5));
        let a = t(-0.5, 0.5).asin();
        assert!(a.d.contains(1.0) && a.d.hi() < 1.2);
        assert!(t(0.5, 1.0).asin().d.is_entire());
    }

    #[test]
    fn kinks_keep_a_lipschitz_bound() {
        let k = (t(0.0, 1.0) - Jet::constant(0.3)).abs();
        assert!(k.d.contains(-1.0) && k.d.contains(1.0) && k.d.width() < 2.0 + 1e-14);
        let m = t(0.0, 1.0).min(Jet::constant(0.5));
        assert_eq!(m.d, Interval::new(0.0, 1.0));
        assert_eq!(t(0.0, 1.0).max(Jet::constant(2.0)), Jet::constant(2.0));
        assert_eq!(t(2.0, 3.0).abs(), t(2.0, 3.0));
    }

    #[test]
    fn steps_jump_or_stay() {
        assert!(t(-1.0, 1.0).sign().d.is_entire());
        assert_eq!(t(0.5, 1.0).sign().d, Interval::ZERO);
        assert_eq!(t(0.2, 0.7).floor(), Jet::constant(0.0));
        let c = t(0.0, 1.0).compare(BinOp::Lt, Jet::constant(0.5));
        assert!(c.d.is_entire() && c.v == Interval::UNDECIDED);
        let x = t(0.0, 1.0);
        let undecided = c.select(x, -x);
        assert!(undecided.d.is_entire() && undecided.v.contains(-1.0));
        assert_eq!(x.logical_not().v, Interval::UNDECIDED);
        assert_eq!(t(1.0, 2.0).logical_and(t(3.0, 4.0)), Jet::constant(1.0));
    }

    #[test]
    fn atan2_across_the_cut_has_no_derivative() {
        // the angle of (cos t, sin t) on [0, 1] has derivative 1
        let s = t(0.0, 1.0);
        let a = s.sin().atan2(s.cos());
        assert!(a.d.contains(1.0) && a.is_increasing());
        let y = t(-0.1, 0.1);
        assert!(y.atan2(Jet::constant(-1.0)).d.is_entire());
        assert!(!y.atan2(Jet::constant(1.0)).d.is_entire());
    }
}
