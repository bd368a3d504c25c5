//! Derivatives of a kernel's values, as more values of the same kernel: forward-mode
//! differentiation of its instructions, so a Jacobian is compiled with the body it belongs
//! to and shares its sub-expressions (`r`, `1/r^3`) with it.

use super::ir::Inst;
use super::kernel::{KernelBuilder, Val};
use crate::ast::{BinOp, Func};

/// An instruction without a derivative the kernel can express.
struct NoRule;

impl KernelBuilder {
    /// `∂y/∂x` for each `y` of `outputs`, where `x` is a value of this body (usually a slot's
    /// starting value, [`KernelBuilder::get`]): `Some(None)` where the derivative is zero by
    /// structure (`y` does not depend on `x`), `None` when some instruction on the way has no
    /// derivative the kernel can express.
    ///
    /// Steps (`sign`, `floor`, `heaviside`, comparisons) have derivative zero; `abs` has
    /// `sign`; `min`, `max` and `if` take the derivative of the branch they select. Where the
    /// function is not differentiable (`sqrt` at 0) the value is what the formula gives there
    /// (infinite or NaN), as for any formula evaluated outside its domain.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::KernelBuilder;
    /// let mut b = KernelBuilder::new(2);
    /// let x = b.get(0);
    /// let y = b.mul(x, x);
    /// let s = b.call(mechkit_expr::Func::Sin, y);
    /// let d = b.derivatives(&[s], x).unwrap()[0].unwrap();
    /// b.set(1, d);
    /// let mut slots = [0.5, 0.0];
    /// b.finish().run(&mut slots, 1);
    /// assert!((slots[1] - 2.0 * 0.5 * (0.25f64).cos()).abs() < 1e-15);
    /// ```
    pub fn derivatives(&mut self, outputs: &[Val], x: Val) -> Option<Vec<Option<Val>>> {
        let last = outputs.iter().map(|v| v.0).max().unwrap_or(0);
        let mut tangent: Vec<Option<Val>> = vec![None; last as usize + 1];
        if x.0 <= last {
            tangent[x.0 as usize] = Some(self.constant(1.0));
        }
        for i in (x.0 + 1)..=last {
            let inst = self.dag.insts[i as usize];
            tangent[i as usize] = self.tangent(inst, Val(i), &tangent).ok()?;
        }
        Some(
            outputs
                .iter()
                .map(|v| {
                    if v.0 < x.0 {
                        None
                    } else {
                        tangent[v.0 as usize]
                    }
                })
                .collect(),
        )
    }

    /// The tangent of instruction `inst` (whose value is `y`), from its operands' tangents
    /// (`None`: zero by structure).
    fn tangent(&mut self, inst: Inst, y: Val, t: &[Option<Val>]) -> Result<Option<Val>, NoRule> {
        let d = |r: u32| t[r as usize];
        let v = Val;
        Ok(match inst {
            Inst::Const(_)
            | Inst::Load(_)
            | Inst::Not(_)
            | Inst::Cmp(..)
            | Inst::And(..)
            | Inst::Or(..) => None,
            Inst::Neg(a) => d(a).map(|da| self.neg(da)),
            Inst::Add(a, b) => self.sum(d(a), d(b)),
            Inst::Sub(a, b) => match (d(a), d(b)) {
                (da, None) => da,
                (None, Some(db)) => Some(self.neg(db)),
                (Some(da), Some(db)) => Some(self.sub(da, db)),
            },
            Inst::Mul(a, b) => {
                let l = d(a).map(|da| self.times(da, v(b)));
                let r = d(b).map(|db| self.times(v(a), db));
                self.sum(l, r)
            }
            // (a/b)' = (a' - y b')/b
            Inst::Div(a, b) => {
                let yb = d(b).map(|db| self.times(y, db));
                let num = match (d(a), yb) {
                    (da, None) => da,
                    (None, Some(s)) => Some(self.neg(s)),
                    (Some(da), Some(s)) => Some(self.sub(da, s)),
                };
                num.map(|n| self.div(n, v(b)))
            }
            Inst::Square(a) => d(a).map(|da| {
                let two = self.constant(2.0);
                let ta = self.mul(two, v(a));
                self.times(ta, da)
            }),
            Inst::Pow(a, b) => self.power(v(a), v(b), y, d(a), d(b)),
            Inst::Call1(f, a) => match d(a) {
                None => None,
                Some(da) => self.outer(f, v(a), y)?.map(|g| self.times(g, da)),
            },
            Inst::Call2(f, a, b) => match f {
                Func::Min | Func::Max => {
                    let op = if f == Func::Min { BinOp::Le } else { BinOp::Ge };
                    self.branch(op, v(a), v(b), d(a), d(b))
                }
                // atan2(p, q)' = (q p' - p q')/(p² + q²)
                Func::Atan2 => {
                    let l = d(a).map(|dp| self.times(v(b), dp));
                    let r = d(b).map(|dq| self.times(v(a), dq));
                    let num = match (l, r) {
                        (l, None) => l,
                        (None, Some(r)) => Some(self.neg(r)),
                        (Some(l), Some(r)) => Some(self.sub(l, r)),
                    };
                    num.map(|n| {
                        let (pp, qq) = (self.square(v(a)), self.square(v(b)));
                        let den = self.add(pp, qq);
                        self.div(n, den)
                    })
                }
                _ => return Err(NoRule),
            },
            Inst::Select(c, a, b) => match (d(a), d(b)) {
                (None, None) => None,
                (da, db) => {
                    let zero = self.constant(0.0);
                    Some(self.select(v(c), da.unwrap_or(zero), db.unwrap_or(zero)))
                }
            },
            Inst::MinBits(a, b) => self.branch(BinOp::Le, v(a), v(b), d(a), d(b)),
            Inst::MaxBits(a, b) => self.branch(BinOp::Ge, v(a), v(b), d(a), d(b)),
        })
    }

    /// `a' + b'` with structural zeros dropped.
    fn sum(&mut self, a: Option<Val>, b: Option<Val>) -> Option<Val> {
        match (a, b) {
            (a, None) => a,
            (None, b) => b,
            (Some(a), Some(b)) => Some(self.add(a, b)),
        }
    }

    /// `a * b`, without multiplying by an exact 1.
    fn times(&mut self, a: Val, b: Val) -> Val {
        match (self.as_constant(a), self.as_constant(b)) {
            (Some(1.0), _) => b,
            (_, Some(1.0)) => a,
            _ => self.mul(a, b),
        }
    }

    /// The derivative of the operand `op` picks: `a'` where `a op b`, else `b'`.
    fn branch(
        &mut self,
        op: BinOp,
        a: Val,
        b: Val,
        da: Option<Val>,
        db: Option<Val>,
    ) -> Option<Val> {
        if da.is_none() && db.is_none() {
            return None;
        }
        let zero = self.constant(0.0);
        let c = self.compare(op, a, b);
        Some(self.select(c, da.unwrap_or(zero), db.unwrap_or(zero)))
    }

    /// `(a^b)' = b a^(b-1) a' + a^b ln(a) b'`.
    fn power(&mut self, a: Val, b: Val, y: Val, da: Option<Val>, db: Option<Val>) -> Option<Val> {
        let l = da.map(|da| {
            let one = self.constant(1.0);
            let bm1 = self.sub(b, one);
            let p = self.fold_pow(a, bm1);
            let bp = self.times(b, p);
            self.times(bp, da)
        });
        let r = db.map(|db| {
            let ln = self.call(Func::Ln, a);
            let yl = self.mul(y, ln);
            self.times(yl, db)
        });
        self.sum(l, r)
    }

    /// `a^b` as the formulas compute it.
    fn fold_pow(&mut self, a: Val, b: Val) -> Val {
        Val(self.dag.fold(Inst::Pow(a.0, b.0)))
    }

    /// `f'(a)` given `y = f(a)`: `None` for steps (zero).
    fn outer(&mut self, f: Func, a: Val, y: Val) -> Result<Option<Val>, NoRule> {
        let one = self.constant(1.0);
        let g = match f {
            Func::Sin => self.call(Func::Cos, a),
            Func::Cos => {
                let s = self.call(Func::Sin, a);
                self.neg(s)
            }
            // 1 + tan²
            Func::Tan => {
                let yy = self.square(y);
                self.add(one, yy)
            }
            Func::Asin | Func::Acos => {
                let aa = self.square(a);
                let s = self.sub(one, aa);
                let r = self.call(Func::Sqrt, s);
                let g = self.div(one, r);
                if f == Func::Acos { self.neg(g) } else { g }
            }
            Func::Atan => {
                let aa = self.square(a);
                let s = self.add(one, aa);
                self.div(one, s)
            }
            Func::Sinh => self.call(Func::Cosh, a),
            Func::Cosh => self.call(Func::Sinh, a),
            Func::Tanh => {
                let yy = self.square(y);
                self.sub(one, yy)
            }
            Func::Exp => y,
            Func::Ln | Func::Log => self.div(one, a),
            Func::Log10 => {
                let ln10 = self.constant(std::f64::consts::LN_10);
                let s = self.mul(a, ln10);
                self.div(one, s)
            }
            // 1/(2 sqrt a), 1/(3 cbrt(a)²)
            Func::Sqrt => {
                let two = self.constant(2.0);
                let s = self.mul(two, y);
                self.div(one, s)
            }
            Func::Cbrt => {
                let three = self.constant(3.0);
                let yy = self.square(y);
                let s = self.mul(three, yy);
                self.div(one, s)
            }
            Func::Abs => self.call(Func::Sign, a),
            Func::Sign | Func::Floor | Func::Ceil | Func::Heaviside => return Ok(None),
            Func::Atan2 | Func::Min | Func::Max | Func::If => return Err(NoRule),
        };
        Ok(Some(g))
    }
}

#[cfg(test)]
#[path = "derivative_tests.rs"]
mod tests;
