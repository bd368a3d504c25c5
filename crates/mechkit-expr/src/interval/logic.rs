//! Comparisons, logic, `if` and `min`/`max` over intervals.
//!
//! A comparison or logical operation is 1 or 0 at each point; over a box it is `[1, 1]` when
//! certainly true, `[0, 0]` when certainly false and [`Interval::UNDECIDED`] `[0, 1]`
//! otherwise. Truth follows the formulas: a number is true when it is not 0, so an interval
//! is *certainly true* when it does not contain 0 and *certainly false* when it is `[0, 0]`.
//! ENTIRE (unknown, perhaps NaN) is neither, and every comparison with it is undecided.

use super::bounds::Interval;
use crate::ast::BinOp;

fn truth(b: bool) -> Interval {
    if b { Interval::ONE } else { Interval::ZERO }
}

impl Interval {
    /// Whether every value is non-zero (true in a formula's `if`, `and`, `or`).
    pub fn is_true(self) -> bool {
        !self.contains_zero()
    }

    /// Whether every value is zero (false in a formula).
    pub fn is_false(self) -> bool {
        self.lo() == 0.0 && self.hi() == 0.0
    }

    /// `self op other` for a comparison `< <= > >= == !=`: `[1, 1]`, `[0, 0]` or `[0, 1]`.
    ///
    /// # Panics
    /// When `op` is not a comparison.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{BinOp, Interval};
    /// let x = Interval::new(0.3, 0.5);
    /// assert_eq!(x.compare(BinOp::Gt, Interval::point(0.2)), Interval::ONE);
    /// assert_eq!(x.compare(BinOp::Gt, Interval::point(0.4)), Interval::UNDECIDED);
    /// assert_eq!(Interval::ENTIRE.compare(BinOp::Ne, x), Interval::UNDECIDED);
    /// ```
    #[must_use]
    pub fn compare(self, op: BinOp, other: Interval) -> Interval {
        assert!(op.is_comparison(), "{} is not a comparison", op.symbol());
        if self.is_entire() || other.is_entire() {
            return Interval::UNDECIDED; // NaN compares false, even with ±∞
        }
        let (a, b) = (self, other);
        let decided = match op {
            BinOp::Lt => lt(a, b),
            BinOp::Le => le(a, b),
            BinOp::Gt => lt(b, a),
            BinOp::Ge => le(b, a),
            BinOp::Eq => eq(a, b),
            BinOp::Ne => eq(a, b).map(|t| !t),
            _ => unreachable!("checked above"),
        };
        decided.map_or(Interval::UNDECIDED, truth)
    }

    /// `not x`: 1 where `x` is 0, else 0.
    #[must_use]
    pub fn logical_not(self) -> Interval {
        if self.is_false() {
            Interval::ONE
        } else if self.is_true() {
            Interval::ZERO
        } else {
            Interval::UNDECIDED
        }
    }

    /// `x and y`.
    #[must_use]
    pub fn logical_and(self, other: Interval) -> Interval {
        if self.is_false() || other.is_false() {
            Interval::ZERO
        } else if self.is_true() && other.is_true() {
            Interval::ONE
        } else {
            Interval::UNDECIDED
        }
    }

    /// `x or y`.
    #[must_use]
    pub fn logical_or(self, other: Interval) -> Interval {
        if self.is_true() || other.is_true() {
            Interval::ONE
        } else if self.is_false() && other.is_false() {
            Interval::ZERO
        } else {
            Interval::UNDECIDED
        }
    }

    /// `if(self, a, b)`: `a` where the condition is certainly true, `b` where certainly
    /// false, else the hull of both.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let (a, b) = (Interval::point(1.0), Interval::point(-1.0));
    /// assert_eq!(Interval::new(0.5, 2.0).select(a, b), a);
    /// assert_eq!(Interval::new(0.0, 2.0).select(a, b), Interval::new(-1.0, 1.0));
    /// ```
    #[must_use]
    pub fn select(self, a: Interval, b: Interval) -> Interval {
        if self.is_true() {
            a
        } else if self.is_false() {
            b
        } else {
            a.hull(b)
        }
    }

    /// `min(x, y)`, exact; ENTIRE if either is (the point function keeps NaN).
    #[must_use]
    pub fn min(self, other: Interval) -> Interval {
        if self.is_entire() || other.is_entire() {
            return Interval::ENTIRE;
        }
        Interval::raw(self.lo().min(other.lo()), self.hi().min(other.hi()))
    }

    /// `max(x, y)`, exact; ENTIRE if either is.
    #[must_use]
    pub fn max(self, other: Interval) -> Interval {
        if self.is_entire() || other.is_entire() {
            return Interval::ENTIRE;
        }
        Interval::raw(self.lo().max(other.lo()), self.hi().max(other.hi()))
    }
}

/// `a < b` for every pair, for none, or undecided.
fn lt(a: Interval, b: Interval) -> Option<bool> {
    if a.hi() < b.lo() {
        Some(true)
    } else if a.lo() >= b.hi() {
        Some(false)
    } else {
        None
    }
}

fn le(a: Interval, b: Interval) -> Option<bool> {
    if a.hi() <= b.lo() {
        Some(true)
    } else if a.lo() > b.hi() {
        Some(false)
    } else {
        None
    }
}

fn eq(a: Interval, b: Interval) -> Option<bool> {
    if a.is_point() && b.is_point() && a.lo() == b.lo() {
        Some(true)
    } else if a.hi() < b.lo() || b.hi() < a.lo() {
        Some(false)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const OPS: [BinOp; 6] = [
        BinOp::Lt,
        BinOp::Le,
        BinOp::Gt,
        BinOp::Ge,
        BinOp::Eq,
        BinOp::Ne,
    ];

    fn i(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    #[test]
    fn comparisons_decide_only_when_certain() {
        let (x, y) = (i(0.0, 1.0), i(1.0, 2.0));
        assert_eq!(x.compare(BinOp::Le, y), Interval::ONE);
        assert_eq!(x.compare(BinOp::Lt, y), Interval::UNDECIDED);
        assert_eq!(y.compare(BinOp::Ge, x), Interval::ONE);
        assert_eq!(y.compare(BinOp::Lt, x), Interval::ZERO);
        assert_eq!(x.compare(BinOp::Eq, i(3.0, 4.0)), Interval::ZERO);
        assert_eq!(x.compare(BinOp::Ne, i(3.0, 4.0)), Interval::ONE);
        let p = Interval::point(2.0);
        assert_eq!(p.compare(BinOp::Eq, p), Interval::ONE);
        assert_eq!(p.compare(BinOp::Ne, p), Interval::ZERO);
        // ∞ against ENTIRE: NaN >= −∞ is false, so nothing is decided
        let minus_inf = Interval::point(f64::NEG_INFINITY);
        for op in OPS {
            assert_eq!(Interval::ENTIRE.compare(op, minus_inf), Interval::UNDECIDED);
        }
    }

    #[test]
    fn logic_and_select() {
        let (t, f, u) = (i(0.5, 2.0), Interval::ZERO, i(-1.0, 1.0));
        assert_eq!(t.logical_not(), Interval::ZERO);
        assert_eq!(f.logical_not(), Interval::ONE);
        assert_eq!(u.logical_not(), Interval::UNDECIDED);
        assert_eq!(t.logical_and(u), Interval::UNDECIDED);
        assert_eq!(f.logical_and(u), Interval::ZERO);
        assert_eq!(t.logical_or(u), Interval::ONE);
        assert_eq!(f.logical_or(f), Interval::ZERO);
        assert_eq!(Interval::ENTIRE.logical_or(f), Interval::UNDECIDED);
        assert_eq!(Interval::ENTIRE.select(t, f), i(0.0, 2.0));
        assert_eq!(i(-0.0, 0.0).select(t, f), f);
    }

    #[test]
    fn min_and_max() {
        assert_eq!(i(0.0, 3.0).min(i(1.0, 2.0)), i(0.0, 2.0));
        assert_eq!(i(0.0, 3.0).max(i(1.0, 2.0)), i(1.0, 3.0));
        assert!(Interval::ENTIRE.min(Interval::ONE).is_entire());
    }

    proptest! {
        #[test]
        fn comparisons_hold_their_points(
            a in -2.0f64..2.0, b in -2.0f64..2.0, wa in 0.0f64..1.0, wb in 0.0f64..1.0,
            s in 0.0f64..=1.0, t in 0.0f64..=1.0, point in any::<bool>(),
        ) {
            let (wa, wb) = if point { (0.0, 0.0) } else { (wa, wb) };
            let (x, y) = (i(a, a + wa), i(b, b + wb));
            let (px, py) = ((a + wa * s).min(a + wa), (b + wb * t).min(b + wb));
            for op in OPS {
                prop_assert!(x.compare(op, y).contains(op.apply(px, py)));
            }
            prop_assert!(x.logical_and(y).contains(BinOp::And.apply(px, py)));
            prop_assert!(x.logical_or(y).contains(BinOp::Or.apply(px, py)));
            let not = if px == 0.0 { 1.0 } else { 0.0 };
            prop_assert!(x.logical_not().contains(not));
            prop_assert!(x.select(x, y).contains(crate::ast::select(px, px, py)));
        }
    }
}
