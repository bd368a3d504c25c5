//! The intermediate form of a compiled formula: a list of instructions in static single
//! assignment, each reading earlier results. Constants are folded and common sub-expressions
//! shared before any code runs, so the interpreter and the native code compute exactly the
//! same operations in the same order.

use std::collections::HashMap;

use super::domain::Domain;
use crate::ast::{BinOp, Expr, Func};
use crate::scope::{Binding, Scope, builtin_constant};

/// One instruction; operands are indices of earlier instructions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Inst {
    Const(f64),
    Load(u32),
    Neg(u32),
    Not(u32),
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    /// `<`, `<=`, `>`, `>=`, `==`, `!=`: 1 or 0.
    Cmp(BinOp, u32, u32),
    And(u32, u32),
    Or(u32, u32),
    /// `a^b` by [`crate::ast::pow`].
    Pow(u32, u32),
    /// `a*a`.
    Square(u32),
    Call1(Func, u32),
    Call2(Func, u32, u32),
    /// `if(c, a, b)`.
    Select(u32, u32, u32),
    /// The operand whose bits, read as a signed integer, are smaller (`max`: larger): for
    /// non-negative numbers the smaller (larger) one. Branch-free in native code.
    MinBits(u32, u32),
    /// See [`Inst::MinBits`].
    MaxBits(u32, u32),
}

/// Hashable identity of an instruction (floats by their bits).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Const(u64),
    Load(u32),
    Op(u8, u32, u32, u32, Option<Func>),
}

fn op_code(op: BinOp) -> u8 {
    match op {
        BinOp::Lt => 20,
        BinOp::Le => 21,
        BinOp::Gt => 22,
        BinOp::Ge => 23,
        BinOp::Eq => 24,
        BinOp::Ne => 25,
        _ => 26,
    }
}

fn key(i: Inst) -> Key {
    match i {
        Inst::Const(c) => Key::Const(c.to_bits()),
        Inst::Load(s) => Key::Load(s),
        Inst::Neg(a) => Key::Op(1, a, 0, 0, None),
        Inst::Not(a) => Key::Op(2, a, 0, 0, None),
        Inst::Add(a, b) => Key::Op(3, a, b, 0, None),
        Inst::Sub(a, b) => Key::Op(4, a, b, 0, None),
        Inst::Mul(a, b) => Key::Op(5, a, b, 0, None),
        Inst::Div(a, b) => Key::Op(6, a, b, 0, None),
        Inst::Cmp(op, a, b) => Key::Op(op_code(op), a, b, 0, None),
        Inst::And(a, b) => Key::Op(7, a, b, 0, None),
        Inst::Or(a, b) => Key::Op(8, a, b, 0, None),
        Inst::Pow(a, b) => Key::Op(9, a, b, 0, None),
        Inst::Square(a) => Key::Op(11, a, 0, 0, None),
        Inst::Call1(f, a) => Key::Op(13, a, 0, 0, Some(f)),
        Inst::Call2(f, a, b) => Key::Op(14, a, b, 0, Some(f)),
        Inst::Select(c, a, b) => Key::Op(15, c, a, b, None),
        Inst::MinBits(a, b) => Key::Op(16, a, b, 0, None),
        Inst::MaxBits(a, b) => Key::Op(17, a, b, 0, None),
    }
}

/// A formula as instructions; its value is that of instruction `result`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ir {
    pub insts: Vec<Inst>,
    pub result: u32,
    pub slots: usize,
}

/// Instructions under construction: each distinct instruction once (common sub-expressions
/// shared), operations on constants folded. The formula builder below and the loop kernels'
/// builder both grow one.
#[derive(Debug, Clone, Default)]
pub(super) struct Dag {
    pub insts: Vec<Inst>,
    seen: HashMap<Key, u32>,
}

impl Dag {
    /// The index of `i`, pushed if it is new.
    pub fn push(&mut self, i: Inst) -> u32 {
        let k = key(i);
        if let Some(&r) = self.seen.get(&k) {
            return r;
        }
        let r = u32::try_from(self.insts.len()).expect("fewer than 2^32 instructions");
        self.insts.push(i);
        self.seen.insert(k, r);
        r
    }

    /// The value of instruction `r` when it is a constant.
    pub fn constant(&self, r: u32) -> Option<f64> {
        match self.insts[r as usize] {
            Inst::Const(c) => Some(c),
            _ => None,
        }
    }

    /// Pushes `i`, or its value when all its operands are constants.
    pub fn fold(&mut self, i: Inst) -> u32 {
        let ops = operands(i);
        if !ops.is_empty() && ops.iter().all(|r| self.constant(*r).is_some()) {
            let mut regs = vec![0.0; self.insts.len()];
            for r in &ops {
                regs[*r as usize] = self.constant(*r).expect("checked");
            }
            return self.push(Inst::Const(execute(i, &regs, &[])));
        }
        self.push(i)
    }
}

struct Builder<'a> {
    scope: &'a dyn Scope,
    dag: Dag,
    slots: usize,
}

impl Builder<'_> {
    fn push(&mut self, i: Inst) -> u32 {
        self.dag.push(i)
    }

    fn constant(&self, r: u32) -> Option<f64> {
        self.dag.constant(r)
    }

    fn fold(&mut self, i: Inst) -> u32 {
        self.dag.fold(i)
    }

    /// `a^n` (n ≥ 1) by repeated squaring, in plain multiplications: `x^12` is
    /// `((x^2)^2*x^2)^2`... three squarings and one product, and its parts are shared.
    fn power(&mut self, a: u32, n: u32) -> u32 {
        if n == 1 {
            return a;
        }
        let half = self.power(a, n / 2);
        let square = self.fold(Inst::Square(half));
        if n % 2 == 1 {
            self.fold(Inst::Mul(square, a))
        } else {
            square
        }
    }

    fn emit(&mut self, e: &Expr) -> Result<u32, String> {
        Ok(match e {
            Expr::Num(x) => self.push(Inst::Const(*x)),
            Expr::Var(name) => match self.scope.lookup(name) {
                Some(Binding::Const(c)) => self.push(Inst::Const(c)),
                Some(Binding::Slot(s)) => {
                    self.slots = self.slots.max(s + 1);
                    self.push(Inst::Load(u32::try_from(s).expect("slot index fits u32")))
                }
                None => self.push(Inst::Const(
                    builtin_constant(name).ok_or_else(|| name.clone())?,
                )),
            },
            Expr::Neg(a) => {
                let a = self.emit(a)?;
                self.fold(Inst::Neg(a))
            }
            Expr::Not(a) => {
                let a = self.emit(a)?;
                self.fold(Inst::Not(a))
            }
            Expr::Binary(BinOp::Pow, a, b) => {
                let a = self.emit(a)?;
                let b = self.emit(b)?;
                match self.constant(b) {
                    Some(0.0) => self.push(Inst::Const(1.0)),
                    Some(n) if n.fract() == 0.0 && n.abs() <= 64.0 => {
                        let p = self.power(a, n.abs() as u32);
                        if n < 0.0 {
                            let one = self.push(Inst::Const(1.0));
                            self.fold(Inst::Div(one, p))
                        } else {
                            p
                        }
                    }
                    _ => self.fold(Inst::Pow(a, b)),
                }
            }
            Expr::Binary(op, a, b) => {
                let a = self.emit(a)?;
                let b = self.emit(b)?;
                self.fold(match op {
                    BinOp::Add => Inst::Add(a, b),
                    BinOp::Sub => Inst::Sub(a, b),
                    BinOp::Mul => Inst::Mul(a, b),
                    BinOp::Div => Inst::Div(a, b),
                    BinOp::And => Inst::And(a, b),
                    BinOp::Or => Inst::Or(a, b),
                    cmp => Inst::Cmp(*cmp, a, b),
                })
            }
            Expr::Call(Func::If, args) => {
                let c = self.emit(&args[0])?;
                let a = self.emit(&args[1])?;
                let b = self.emit(&args[2])?;
                self.fold(Inst::Select(c, a, b))
            }
            Expr::Call(f @ (Func::Min | Func::Max), args) => {
                let mut acc = self.emit(&args[0])?;
                for a in &args[1..] {
                    let b = self.emit(a)?;
                    acc = self.fold(Inst::Call2(*f, acc, b));
                }
                acc
            }
            Expr::Call(Func::Atan2, args) => {
                let a = self.emit(&args[0])?;
                let b = self.emit(&args[1])?;
                self.fold(Inst::Call2(Func::Atan2, a, b))
            }
            Expr::Call(f, args) => {
                let a = self.emit(&args[0])?;
                self.fold(Inst::Call1(*f, a))
            }
        })
    }
}

impl Ir {
    /// Builds the instructions of `e`, resolving names with `scope` (then `pi` and `e`).
    /// `Err` is the first undefined name.
    pub fn build(e: &Expr, scope: &dyn Scope) -> Result<Ir, String> {
        let mut b = Builder {
            scope,
            dag: Dag::default(),
            slots: 0,
        };
        let result = b.emit(e)?;
        let mut ir = Ir {
            insts: b.dag.insts,
            result,
            slots: b.slots,
        };
        ir.prune();
        Ok(ir)
    }

    /// Drops instructions nothing reads (left over from folding) and renumbers.
    fn prune(&mut self) {
        let n = self.insts.len();
        let mut live = vec![false; n];
        live[self.result as usize] = true;
        for i in (0..n).rev() {
            if live[i] {
                for r in operands(self.insts[i]) {
                    live[r as usize] = true;
                }
            }
        }
        let mut new_index = vec![0u32; n];
        let mut out = Vec::new();
        for i in 0..n {
            if live[i] {
                new_index[i] = u32::try_from(out.len()).expect("fits");
                out.push(remap(self.insts[i], &new_index));
            }
        }
        self.insts = out;
        self.result = new_index[self.result as usize];
    }

    /// The value when the formula reads no variables.
    pub fn as_constant(&self) -> Option<f64> {
        match self.insts[self.result as usize] {
            Inst::Const(c) => Some(c),
            _ => None,
        }
    }
}

pub(super) fn operands(i: Inst) -> Vec<u32> {
    match i {
        Inst::Const(_) | Inst::Load(_) => vec![],
        Inst::Neg(a) | Inst::Not(a) | Inst::Square(a) | Inst::Call1(_, a) => vec![a],
        Inst::Add(a, b)
        | Inst::Sub(a, b)
        | Inst::Mul(a, b)
        | Inst::Div(a, b)
        | Inst::Cmp(_, a, b)
        | Inst::And(a, b)
        | Inst::Or(a, b)
        | Inst::Pow(a, b)
        | Inst::Call2(_, a, b)
        | Inst::MinBits(a, b)
        | Inst::MaxBits(a, b) => vec![a, b],
        Inst::Select(c, a, b) => vec![c, a, b],
    }
}

pub(super) fn remap(i: Inst, m: &[u32]) -> Inst {
    let r = |x: u32| m[x as usize];
    match i {
        Inst::Const(_) | Inst::Load(_) => i,
        Inst::Neg(a) => Inst::Neg(r(a)),
        Inst::Not(a) => Inst::Not(r(a)),
        Inst::Add(a, b) => Inst::Add(r(a), r(b)),
        Inst::Sub(a, b) => Inst::Sub(r(a), r(b)),
        Inst::Mul(a, b) => Inst::Mul(r(a), r(b)),
        Inst::Div(a, b) => Inst::Div(r(a), r(b)),
        Inst::Cmp(op, a, b) => Inst::Cmp(op, r(a), r(b)),
        Inst::And(a, b) => Inst::And(r(a), r(b)),
        Inst::Or(a, b) => Inst::Or(r(a), r(b)),
        Inst::Pow(a, b) => Inst::Pow(r(a), r(b)),
        Inst::Square(a) => Inst::Square(r(a)),
        Inst::Call1(f, a) => Inst::Call1(f, r(a)),
        Inst::Call2(f, a, b) => Inst::Call2(f, r(a), r(b)),
        Inst::Select(c, a, b) => Inst::Select(r(c), r(a), r(b)),
        Inst::MinBits(a, b) => Inst::MinBits(r(a), r(b)),
        Inst::MaxBits(a, b) => Inst::MaxBits(r(a), r(b)),
    }
}

/// The value of one instruction given the values of the earlier ones (`regs`) and the
/// variables, over any [`Domain`]. With `f64` this is the definition of every operation: the
/// native code must agree with it bit for bit; over intervals and jets it encloses it.
#[inline]
pub(crate) fn execute<T: Domain>(i: Inst, regs: &[T], vars: &[T]) -> T {
    let g = |r: u32| regs[r as usize];
    match i {
        Inst::Const(c) => T::constant(c),
        Inst::Load(s) => vars[s as usize],
        Inst::Neg(a) => -g(a),
        Inst::Not(a) => g(a).not(),
        Inst::Add(a, b) => g(a) + g(b),
        Inst::Sub(a, b) => g(a) - g(b),
        Inst::Mul(a, b) => g(a) * g(b),
        Inst::Div(a, b) => g(a) / g(b),
        Inst::Cmp(op, a, b) => g(a).compare(op, g(b)),
        Inst::And(a, b) => g(a).and(g(b)),
        Inst::Or(a, b) => g(a).or(g(b)),
        Inst::Pow(a, b) => g(a).pow(g(b)),
        Inst::Square(a) => g(a).square(),
        Inst::Call1(f, a) => g(a).call1(f),
        Inst::Call2(f, a, b) => g(a).call2(f, g(b)),
        Inst::Select(c, a, b) => g(c).select(g(a), g(b)),
        Inst::MinBits(a, b) => g(a).min_bits(g(b)),
        Inst::MaxBits(a, b) => g(a).max_bits(g(b)),
    }
}

impl Ir {
    /// Interprets the instructions over any [`Domain`] (registers on the machine stack for
    /// short programs).
    #[inline]
    pub fn run<T: Domain>(&self, vars: &[T]) -> T {
        let zero = T::constant(0.0);
        match self.insts.len() {
            0..=8 => self.run_in(vars, &mut [zero; 8]),
            9..=32 => self.run_in(vars, &mut [zero; 32]),
            n => self.run_in(vars, &mut vec![zero; n]),
        }
    }

    #[inline]
    fn run_in<T: Domain>(&self, vars: &[T], regs: &mut [T]) -> T {
        for (k, i) in self.insts.iter().enumerate() {
            regs[k] = execute(*i, regs, vars);
        }
        regs[self.result as usize]
    }
}
