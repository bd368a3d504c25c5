//! Loop kernels: see [`Kernel`].

use std::sync::Arc;

use super::Program;
use super::ir::{Dag, Inst, execute, operands};
use crate::ast::{BinOp, Func};

/// A value inside a [`KernelBuilder`]'s body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Val(pub(super) u32);

/// Builds the body of a [`Kernel`]: values are combined with IEEE operations in the order
/// given (nothing is reassociated; constants are folded, repeated operations shared).
#[derive(Debug, Clone)]
pub struct KernelBuilder {
    pub(super) dag: Dag,
    /// The value each slot takes at the end of an iteration.
    stores: Vec<u32>,
}

impl KernelBuilder {
    /// A body over `slots` slots; each starts as its value at the start of the iteration.
    pub fn new(slots: usize) -> Self {
        let mut dag = Dag::default();
        let stores = (0..slots)
            .map(|s| dag.push(Inst::Load(u32::try_from(s).expect("slot index fits u32"))))
            .collect();
        Self { dag, stores }
    }

    fn fold(&mut self, i: Inst) -> Val {
        Val(self.dag.fold(i))
    }

    /// The slot's current value: its value at the start of the iteration, or the last value
    /// [`KernelBuilder::set`] gave it.
    pub fn get(&self, slot: usize) -> Val {
        Val(self.stores[slot])
    }

    /// Gives the slot a new value; later [`KernelBuilder::get`]s see it, and it is what the
    /// slot holds at the end of the iteration.
    pub fn set(&mut self, slot: usize, v: Val) {
        self.stores[slot] = v.0;
    }

    /// Adds `count` slots after the others, each starting as its value at the start of the
    /// iteration; returns the first one's index (for outputs whose number is known only
    /// once the body computing them is built).
    pub fn add_slots(&mut self, count: usize) -> usize {
        let first = self.stores.len();
        for s in first..first + count {
            let load = self
                .dag
                .push(Inst::Load(u32::try_from(s).expect("slot index fits u32")));
            self.stores.push(load);
        }
        first
    }

    /// A constant.
    pub fn constant(&mut self, c: f64) -> Val {
        Val(self.dag.push(Inst::Const(c)))
    }

    /// Number of instructions built so far (the slots' loads included): a measure of the
    /// work a pass over the body costs.
    pub fn len(&self) -> usize {
        self.dag.insts.len()
    }

    /// Whether nothing has been built (a body over no slots).
    pub fn is_empty(&self) -> bool {
        self.dag.insts.is_empty()
    }

    /// The value, when it is a constant.
    pub fn as_constant(&self, v: Val) -> Option<f64> {
        self.dag.constant(v.0)
    }

    /// `a + b`.
    pub fn add(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::Add(a.0, b.0))
    }

    /// `a - b`.
    pub fn sub(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::Sub(a.0, b.0))
    }

    /// `a * b`.
    pub fn mul(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::Mul(a.0, b.0))
    }

    /// `a / b`.
    pub fn div(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::Div(a.0, b.0))
    }

    /// `-a`.
    pub fn neg(&mut self, a: Val) -> Val {
        self.fold(Inst::Neg(a.0))
    }

    /// `a * a`.
    pub fn square(&mut self, a: Val) -> Val {
        self.fold(Inst::Square(a.0))
    }

    /// A one-argument function (`sqrt` and `abs` are single instructions in native code).
    pub fn call(&mut self, f: Func, a: Val) -> Val {
        self.fold(Inst::Call1(f, a.0))
    }

    /// A comparison, 1 or 0 (`op` one of `<`, `<=`, `>`, `>=`, `==`, `!=`).
    pub fn compare(&mut self, op: BinOp, a: Val, b: Val) -> Val {
        assert!(
            matches!(
                op,
                BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge | BinOp::Eq | BinOp::Ne
            ),
            "{} is not a comparison",
            op.symbol()
        );
        self.fold(Inst::Cmp(op, a.0, b.0))
    }

    /// `if(c, a, b)`: `a` where `c` is not 0, else `b`.
    pub fn select(&mut self, c: Val, a: Val, b: Val) -> Val {
        self.fold(Inst::Select(c.0, a.0, b.0))
    }

    /// The smaller of two non-negative numbers, without a branch: in general the operand
    /// whose bits, read as a signed integer, are smaller (so both evaluators agree on every
    /// input, NaN and negative numbers included).
    pub fn min_nonnegative(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::MinBits(a.0, b.0))
    }

    /// The larger of two non-negative numbers; see [`KernelBuilder::min_nonnegative`].
    pub fn max_nonnegative(&mut self, a: Val, b: Val) -> Val {
        self.fold(Inst::MaxBits(a.0, b.0))
    }

    /// The value of a compiled formula whose slot `s` reads `args[s]`: its instructions are
    /// copied into the body (no call), so they share registers and sub-expressions with the
    /// rest of it.
    pub fn inline(&mut self, program: &Program, args: &[Val]) -> Val {
        let ir = &program.ir;
        assert!(
            args.len() >= ir.slots,
            "the formula reads {} slots, {} given",
            ir.slots,
            args.len()
        );
        let mut map: Vec<u32> = Vec::with_capacity(ir.insts.len());
        for inst in &ir.insts {
            let v = match *inst {
                Inst::Load(s) => args[s as usize].0,
                Inst::Const(c) => self.dag.push(Inst::Const(c)),
                other => self.fold(super::ir::remap(other, &map)).0,
            };
            map.push(v);
        }
        Val(map[ir.result as usize])
    }

    /// The kernel (interpreted; [`Kernel::native`] attaches native code).
    pub fn finish(self) -> Kernel {
        let slots = self.stores.len();
        let insts = self.dag.insts;
        let n = insts.len();
        // the loads come first, one per slot in slot order (those of slots added later were
        // built later; a load has no operands, so moving it ahead keeps every value after
        // what it uses)
        let mut loads = vec![0usize; slots];
        for (i, inst) in insts.iter().enumerate() {
            if let Inst::Load(s) = inst {
                loads[*s as usize] = i;
            }
        }
        let mut live = vec![false; n];
        for r in &self.stores {
            live[*r as usize] = true;
        }
        for i in (0..n).rev() {
            if live[i] {
                for r in operands(insts[i]) {
                    live[r as usize] = true;
                }
            }
        }
        let mut new_index = vec![0u32; n];
        let mut kept = Vec::new();
        for &i in &loads {
            new_index[i] = u32::try_from(kept.len()).expect("fits");
            kept.push(insts[i]);
        }
        for i in 0..n {
            if live[i] && !matches!(insts[i], Inst::Load(_)) {
                new_index[i] = u32::try_from(kept.len()).expect("fits");
                kept.push(super::ir::remap(insts[i], &new_index));
            }
        }
        let stores = self.stores.iter().map(|r| new_index[*r as usize]).collect();
        Kernel {
            body: Body {
                insts: kept,
                stores,
                slots,
            },
            native: None,
        }
    }
}

/// The instructions of a kernel's body and where each slot's new value comes from.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Body {
    pub insts: Vec<Inst>,
    pub stores: Vec<u32>,
    pub slots: usize,
}

/// A loop kernel: a body of assignments to a fixed set of slots, built once from formulas and
/// plain arithmetic, then run many times with the slots held in registers.
///
/// This is what a fixed-step simulation needs to run at the speed of a hand-written loop: one
/// step (the update, every force, the sums for the energy ledger) becomes one straight-line
/// body, and [`Kernel::run`] repeats it `n` times without returning to the caller. The body
/// reads the slots' values at the start of an iteration and assigns their new values at its
/// end, all at once.
///
/// Like [`crate::Program`], a kernel has two evaluators that agree bit for bit: an interpreter
/// and native code (Cranelift, feature `jit`, attached by [`Kernel::native`]).
///
/// # Example
/// ```
/// use mechkit_expr::{KernelBuilder, Formula, MapScope};
/// // x' = v, v' = -x with Euler-Cromer steps of 0.01: slots [x, v]
/// let force = Formula::parse("-k*x").unwrap()
///     .compile(&MapScope::new().constant("k", 1.0).slot("x", 0)).unwrap();
/// let mut b = KernelBuilder::new(2);
/// let (x, v) = (b.get(0), b.get(1));
/// let a = b.inline(&force, &[x]);
/// let h = b.constant(0.01);
/// let dv = b.mul(h, a);
/// let v1 = b.add(v, dv);
/// let dx = b.mul(h, v1);
/// let x1 = b.add(x, dx);
/// b.set(0, x1);
/// b.set(1, v1);
/// let kernel = b.finish().native();
/// let mut slots = [1.0, 0.0];
/// kernel.run(&mut slots, 628);
/// assert!((slots[0] - 1.0).abs() < 0.01 && slots[1].abs() < 0.01);
/// ```
#[derive(Debug, Clone)]
pub struct Kernel {
    body: Body,
    #[cfg(feature = "jit")]
    native: Option<Arc<super::jit_kernel::NativeKernel>>,
    #[cfg(not(feature = "jit"))]
    native: Option<Arc<()>>,
}

impl Kernel {
    /// The same kernel with native code attached, when the `jit` feature is on, the host is
    /// supported and `MECHKIT_JIT` is not `0`; otherwise unchanged (the interpreter serves).
    #[must_use]
    pub fn native(mut self) -> Kernel {
        #[cfg(feature = "jit")]
        if self.native.is_none() && super::jit::enabled() {
            self.native = super::jit_kernel::NativeKernel::shared(&self.body).ok();
        }
        self
    }

    /// Whether [`Kernel::run`] runs native code.
    pub fn is_native(&self) -> bool {
        self.native.is_some()
    }

    /// Number of slots the body reads and writes.
    pub fn slots(&self) -> usize {
        self.body.slots
    }

    /// Number of instructions in the body (loads included).
    pub fn len(&self) -> usize {
        self.body.insts.len()
    }

    /// Whether the body has no instructions (a kernel over no slots).
    pub fn is_empty(&self) -> bool {
        self.body.insts.is_empty()
    }

    /// Runs the body `n` times on `slots` (which must hold [`Kernel::slots`] values).
    pub fn run(&self, slots: &mut [f64], n: u64) {
        assert_eq!(slots.len(), self.body.slots, "one value per slot");
        #[cfg(feature = "jit")]
        if let Some(native) = &self.native {
            native.call(slots, n);
            return;
        }
        self.run_interpreted(slots, n);
    }

    /// Runs the body `n` times with the interpreter, whatever is attached.
    pub fn run_interpreted(&self, slots: &mut [f64], n: u64) {
        assert_eq!(slots.len(), self.body.slots, "one value per slot");
        let mut regs = vec![0.0; self.body.insts.len()];
        for _ in 0..n {
            for (k, i) in self.body.insts.iter().enumerate() {
                regs[k] = execute(*i, &regs, slots);
            }
            for (s, r) in slots.iter_mut().zip(&self.body.stores) {
                *s = regs[*r as usize];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Formula, MapScope};

    /// Slots added after the body is built: interpreted and native, as the first ones.
    #[test]
    fn slots_added_late_are_loaded_and_stored_like_the_first() {
        let mut b = KernelBuilder::new(2);
        let (x, y) = (b.get(0), b.get(1));
        let s = b.add(x, y);
        let p = b.mul(x, y);
        let first = b.add_slots(2);
        assert_eq!(first, 2);
        let carried = b.get(3);
        let q = b.mul(p, carried);
        b.set(first, s);
        b.set(first + 1, q);
        let k = b.finish();
        let mut interpreted = [2.0, 3.0, 0.0, 10.0];
        k.run_interpreted(&mut interpreted, 1);
        assert_eq!(interpreted, [2.0, 3.0, 5.0, 60.0]);
        let mut native = [2.0, 3.0, 0.0, 10.0];
        k.native().run(&mut native, 1);
        assert_eq!(native, interpreted);
    }

    /// A damped oscillator with a formula force, Euler-Cromer: slots [t, x, v, work].
    fn oscillator() -> Kernel {
        let scope = MapScope::new()
            .constant("k", 4.0)
            .constant("b", 0.3)
            .slot("x", 0)
            .slot("v", 1)
            .slot("t", 2);
        let f = Formula::parse("-k*x - b*v*abs(v) + 0.1*sin(t)")
            .unwrap()
            .compile(&scope)
            .unwrap();
        let mut b = KernelBuilder::new(4);
        let (t, x, v, w) = (b.get(0), b.get(1), b.get(2), b.get(3));
        let h = b.constant(1e-3);
        let force = b.inline(&f, &[x, v, t]);
        let dv = b.mul(h, force);
        let v1 = b.add(v, dv);
        let dx = b.mul(h, v1);
        let x1 = b.add(x, dx);
        let t1 = b.add(t, h);
        let p = b.mul(force, v1);
        let dw = b.mul(h, p);
        let w1 = b.add(w, dw);
        b.set(0, t1);
        b.set(1, x1);
        b.set(2, v1);
        b.set(3, w1);
        b.finish()
    }

    #[test]
    fn native_and_interpreted_kernels_agree_bit_for_bit() {
        let k = oscillator();
        let native = k.clone().native();
        if cfg!(feature = "jit") && std::env::var("MECHKIT_JIT").as_deref() != Ok("0") {
            assert!(native.is_native());
        }
        let mut a = [0.0, 1.0, 0.0, 0.0];
        let mut b = a;
        k.run_interpreted(&mut a, 5000);
        native.run(&mut b, 5000);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(x.to_bits(), y.to_bits());
        }
        assert!((a[0] - 5.0).abs() < 1e-9, "t = {}", a[0]);
        // the same steps written out in Rust
        let (mut t, mut x, mut v, mut w) = (0.0_f64, 1.0_f64, 0.0_f64, 0.0_f64);
        for _ in 0..5000 {
            let f = -4.0 * x - 0.3 * v * v.abs() + 0.1 * t.sin();
            let v1 = v + 1e-3 * f;
            x += 1e-3 * v1;
            w += 1e-3 * (f * v1);
            t += 1e-3;
            v = v1;
        }
        assert_eq!([t, x, v, w].map(f64::to_bits), a.map(f64::to_bits));
    }

    #[test]
    fn slots_are_assigned_at_the_end_of_an_iteration() {
        // a swap: both reads see the old values
        let mut b = KernelBuilder::new(2);
        let (x, y) = (b.get(0), b.get(1));
        b.set(0, y);
        b.set(1, x);
        let k = b.finish().native();
        let mut s = [1.0, 2.0];
        k.run(&mut s, 3);
        assert_eq!(s, [2.0, 1.0]);
        k.run(&mut s, 0);
        assert_eq!(s, [2.0, 1.0]);
    }

    #[test]
    fn constants_fold_and_dead_code_is_dropped() {
        let mut b = KernelBuilder::new(1);
        let two = b.constant(2.0);
        let three = b.constant(3.0);
        let six = b.mul(two, three);
        assert_eq!(b.as_constant(six), Some(6.0));
        let x = b.get(0);
        let _unused = b.call(Func::Sin, x);
        let y = b.mul(x, six);
        b.set(0, y);
        let k = b.finish();
        // load, the constant 6, the product
        assert_eq!(k.len(), 3);
        let mut s = [1.0];
        k.run(&mut s, 4);
        assert_eq!(s, [1296.0]);
    }

    #[test]
    fn bitwise_extremes_agree_everywhere_and_are_min_and_max_of_non_negative_numbers() {
        let mut b = KernelBuilder::new(4);
        let (x, y) = (b.get(0), b.get(1));
        let lo = b.min_nonnegative(x, y);
        let hi = b.max_nonnegative(x, y);
        b.set(2, lo);
        b.set(3, hi);
        let k = b.finish();
        let native = k.clone().native();
        let values = [
            0.0,
            -0.0,
            1e-300,
            0.5,
            2.0,
            1e300,
            f64::INFINITY,
            -1.0,
            f64::NAN,
        ];
        for &x in &values {
            for &y in &values {
                let (mut a, mut n) = ([x, y, 0.0, 0.0], [x, y, 0.0, 0.0]);
                k.run_interpreted(&mut a, 1);
                native.run(&mut n, 1);
                assert_eq!(a.map(f64::to_bits), n.map(f64::to_bits), "{x} {y}");
                if x >= 0.0 && y >= 0.0 && x.is_sign_positive() && y.is_sign_positive() {
                    assert_eq!((a[2], a[3]), (x.min(y), x.max(y)));
                }
            }
        }
    }

    #[test]
    fn comparisons_and_selects_match() {
        let mut b = KernelBuilder::new(2);
        let (x, m) = (b.get(0), b.get(1));
        let c = b.compare(BinOp::Lt, x, m);
        let m1 = b.select(c, x, m);
        let one = b.constant(0.37);
        let x1 = b.add(x, one);
        let s = b.call(Func::Sin, x1);
        b.set(0, s);
        b.set(1, m1);
        let k = b.finish();
        let native = k.clone().native();
        let (mut a, mut n) = ([0.5, 10.0], [0.5, 10.0]);
        k.run_interpreted(&mut a, 100);
        native.run(&mut n, 100);
        assert_eq!(a.map(f64::to_bits), n.map(f64::to_bits));
    }
}
