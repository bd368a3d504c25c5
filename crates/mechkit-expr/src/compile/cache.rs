//! Native code shared between equal bodies: compiling a formula or a kernel with Cranelift
//! costs tens of microseconds and maps, protects and later unmaps executable pages, which on
//! several threads stalls them all (every unmap interrupts the other cores). A sweep builds
//! the same scenario again for each of its runs; the instructions of most of its formulas do
//! not change from run to run, so their code is compiled once and shared.
//!
//! The key is the exact instruction list. A formula's code reads its constants from a table
//! that goes with each program, so formulas that differ only in a constant's value (a sweep
//! over a drag coefficient) share it; a loop kernel's constants are built into its code (the
//! fused loops keep them in registers), so kernels share code only when their constants are
//! equal bit for bit. At most [`MOST`] bodies of each kind
//! are kept; past that the table is emptied (code still in use lives on with its users).

use std::collections::HashMap;
use std::sync::{Arc, Mutex, PoisonError};

use super::ir::Inst;
use crate::ast::{BinOp, Func};

/// Bodies kept per table.
pub(super) const MOST: usize = 256;

/// One instruction by identity: its kind, a constant's bits, its operands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(super) struct Word {
    tag: u8,
    bits: u64,
    operands: [u32; 3],
    func: Option<Func>,
    op: Option<BinOp>,
}

impl Word {
    fn new(tag: u8, operands: [u32; 3]) -> Word {
        Word {
            tag,
            bits: 0,
            operands,
            func: None,
            op: None,
        }
    }

    /// A word that is not an instruction (a kernel's store, its slot count).
    pub(super) fn extra(value: u32) -> Word {
        Word::new(u8::MAX, [value, 0, 0])
    }
}

/// The identity of an instruction list; with `constants`, the constants' values are part of
/// it (code with the values built in), else only their places (code that reads them).
pub(super) fn key(insts: &[Inst], constants: bool) -> Vec<Word> {
    insts
        .iter()
        .map(|&i| match i {
            Inst::Const(c) => Word {
                bits: if constants { c.to_bits() } else { 0 },
                ..Word::new(0, [0; 3])
            },
            Inst::Load(s) => Word::new(1, [s, 0, 0]),
            Inst::Neg(a) => Word::new(2, [a, 0, 0]),
            Inst::Not(a) => Word::new(3, [a, 0, 0]),
            Inst::Add(a, b) => Word::new(4, [a, b, 0]),
            Inst::Sub(a, b) => Word::new(5, [a, b, 0]),
            Inst::Mul(a, b) => Word::new(6, [a, b, 0]),
            Inst::Div(a, b) => Word::new(7, [a, b, 0]),
            Inst::Cmp(op, a, b) => Word {
                op: Some(op),
                ..Word::new(8, [a, b, 0])
            },
            Inst::And(a, b) => Word::new(9, [a, b, 0]),
            Inst::Or(a, b) => Word::new(10, [a, b, 0]),
            Inst::Pow(a, b) => Word::new(11, [a, b, 0]),
            Inst::Square(a) => Word::new(12, [a, 0, 0]),
            Inst::Call1(f, a) => Word {
                func: Some(f),
                ..Word::new(13, [a, 0, 0])
            },
            Inst::Call2(f, a, b) => Word {
                func: Some(f),
                ..Word::new(14, [a, b, 0])
            },
            Inst::Select(c, a, b) => Word::new(15, [c, a, b]),
            Inst::MinBits(a, b) => Word::new(16, [a, b, 0]),
            Inst::MaxBits(a, b) => Word::new(17, [a, b, 0]),
        })
        .collect()
}

/// Compiled bodies by their identity.
pub(super) struct Cache<T> {
    map: Mutex<Option<HashMap<Vec<Word>, Arc<T>>>>,
}

impl<T> Cache<T> {
    /// An empty table.
    pub(super) const fn new() -> Self {
        Cache {
            map: Mutex::new(None),
        }
    }

    /// The code of the body `key`: shared when it was compiled before, else `compile`d (outside
    /// the lock, so threads compile different bodies at the same time) and kept.
    pub(super) fn get_or_compile(
        &self,
        key: Vec<Word>,
        compile: impl FnOnce() -> Result<T, String>,
    ) -> Result<Arc<T>, String> {
        let lock = || self.map.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(hit) = lock().as_ref().and_then(|m| m.get(&key)) {
            return Ok(Arc::clone(hit));
        }
        let fresh = Arc::new(compile()?);
        let mut guard = lock();
        let map = guard.get_or_insert_with(HashMap::new);
        if map.len() >= MOST {
            map.clear();
        }
        Ok(Arc::clone(map.entry(key).or_insert(fresh)))
    }

    /// Bodies kept now.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.map
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .as_ref()
            .map_or(0, HashMap::len)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Formula, MapScope, Program};

    fn program(text: &str, k: f64) -> Program {
        let scope = MapScope::new().constant("k", k).slot("x", 0);
        Formula::parse(text)
            .unwrap()
            .compile(&scope)
            .unwrap()
            .native()
    }

    /// A formula compiled twice gets the same code, and so does one that differs only in a
    /// constant's value (down to its last bit), each computing its own value; one that
    /// differs in an operation gets its own.
    #[test]
    fn equal_bodies_share_code_and_different_ones_do_not() {
        let a = program("-k*x + sin(x)", 2.0);
        let b = program("-k*x + sin(x)", 2.0);
        let c = program("-k*x + sin(x)", f64::from_bits(2.0f64.to_bits() + 1));
        let d = program("-k*x - sin(x)", 2.0);
        let (na, nb) = (a.native_code().unwrap(), b.native_code().unwrap());
        assert!(Arc::ptr_eq(na, nb));
        assert!(Arc::ptr_eq(na, c.native_code().unwrap()));
        assert!(!Arc::ptr_eq(na, d.native_code().unwrap()));
        let x = [0.3];
        assert_eq!(a.eval(&x), -2.0 * 0.3 + 0.3f64.sin());
        assert_eq!(c.eval(&x), c.eval_interpreted(&x));
        assert_ne!(c.eval(&x), a.eval(&x));
        assert_eq!(d.eval(&x), -2.0 * 0.3 - 0.3f64.sin());
    }

    /// Past [`MOST`] bodies the table starts again; code in use stays valid.
    #[test]
    fn the_table_is_bounded() {
        let first = program("k*x^3", -1.0);
        for i in 0..MOST + 10 {
            let p = program("k*x^3 + 1", i as f64);
            assert_eq!(p.eval(&[2.0]), 8.0 * i as f64 + 1.0);
        }
        assert!(super::super::jit::programs_kept() <= MOST);
        assert_eq!(first.eval(&[2.0]), -8.0);
    }
}
