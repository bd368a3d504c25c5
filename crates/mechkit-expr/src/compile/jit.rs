//! Native code for compiled formulas through Cranelift.
//!
//! Each instruction of the [`Ir`] becomes the same IEEE operation (add, multiply, divide,
//! negate, absolute value, square root, floor, ceiling, ordered comparisons, select), and every
//! other function is a call to the very Rust function the interpreter uses, so both paths
//! agree bit for bit. Floating-point contraction (fused multiply-add) is never introduced.

#![allow(unsafe_code)]

use std::sync::{Arc, Mutex};

use cranelift_codegen::ir::condcodes::FloatCC;
use std::collections::HashMap;

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{
    AbiParam, FuncRef, InstBuilder, MemFlagsData, Signature, UserFuncName, Value, types,
};
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{Linkage, Module, default_libcall_names};

use super::cache::{self, Cache, Word};
use super::ir::{Inst, Ir};
use crate::ast::{BinOp, Func};

/// Whether native code is wanted: `MECHKIT_JIT=0` turns it off (to compare, or to debug).
pub(super) fn enabled() -> bool {
    std::env::var("MECHKIT_JIT").map_or(true, |v| v != "0")
}

/// A function in executable memory and the module that owns that memory.
pub(super) struct Native {
    func: extern "C" fn(*const f64, *const f64) -> f64,
    module: Mutex<Option<JITModule>>,
}

impl std::fmt::Debug for Native {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Native")
    }
}

impl Drop for Native {
    fn drop(&mut self) {
        if let Some(m) = self.module.get_mut().ok().and_then(Option::take) {
            // SAFETY: `func` points into this module's memory and is dropped with `self`; no
            // other copy of it exists (it is private), so nothing can call it afterwards.
            unsafe { m.free_memory() };
        }
    }
}

macro_rules! externs1 {
    ($($f:ident => $name:literal),* $(,)?) => {
        fn call1_symbol(f: Func) -> (&'static str, *const u8) {
            $(
                #[allow(non_snake_case)]
                extern "C" fn $f(x: f64) -> f64 {
                    Func::$f.apply1(x)
                }
            )*
            match f {
                $(Func::$f => ($name, $f as *const u8),)*
                other => unreachable!("{} is not a one-argument function", other.name()),
            }
        }
    };
}

externs1! {
    Sin => "mk_sin", Cos => "mk_cos", Tan => "mk_tan", Asin => "mk_asin", Acos => "mk_acos",
    Atan => "mk_atan", Sinh => "mk_sinh", Cosh => "mk_cosh", Tanh => "mk_tanh", Exp => "mk_exp",
    Log => "mk_log", Ln => "mk_ln", Log10 => "mk_log10", Sqrt => "mk_sqrt", Cbrt => "mk_cbrt",
    Abs => "mk_abs", Sign => "mk_sign", Floor => "mk_floor", Ceil => "mk_ceil",
    Heaviside => "mk_heaviside",
}

extern "C" fn mk_atan2(a: f64, b: f64) -> f64 {
    Func::Atan2.apply2(a, b)
}
extern "C" fn mk_min(a: f64, b: f64) -> f64 {
    Func::Min.apply2(a, b)
}
extern "C" fn mk_max(a: f64, b: f64) -> f64 {
    Func::Max.apply2(a, b)
}
extern "C" fn mk_pow(a: f64, b: f64) -> f64 {
    crate::ast::pow(a, b)
}

fn call2_symbol(f: Func) -> (&'static str, *const u8) {
    match f {
        Func::Atan2 => ("mk_atan2", mk_atan2 as *const u8),
        Func::Min => ("mk_min", mk_min as *const u8),
        Func::Max => ("mk_max", mk_max as *const u8),
        other => unreachable!("{} is not a two-argument function", other.name()),
    }
}

fn float_cc(op: BinOp) -> FloatCC {
    match op {
        BinOp::Lt => FloatCC::LessThan,
        BinOp::Le => FloatCC::LessThanOrEqual,
        BinOp::Gt => FloatCC::GreaterThan,
        BinOp::Ge => FloatCC::GreaterThanOrEqual,
        BinOp::Eq => FloatCC::Equal,
        // Rust's `!=` is true for NaN: unordered or not equal
        BinOp::Ne => FloatCC::NotEqual,
        other => unreachable!("{} is not a comparison", other.symbol()),
    }
}

/// A JIT module with the Rust functions the instructions call, declared.
pub(super) struct Jit {
    pub(super) module: JITModule,
    externals: HashMap<&'static str, cranelift_module::FuncId>,
}

pub(super) fn err(e: &dyn std::fmt::Display) -> String {
    e.to_string()
}

impl Jit {
    pub(super) fn new(insts: &[Inst]) -> Result<Jit, String> {
        let mut flags = settings::builder();
        flags
            .set("use_colocated_libcalls", "false")
            .map_err(|e| err(&e))?;
        flags.set("is_pic", "false").map_err(|e| err(&e))?;
        flags.set("opt_level", "speed").map_err(|e| err(&e))?;
        let isa = cranelift_native::builder()
            .map_err(ToString::to_string)?
            .finish(settings::Flags::new(flags))
            .map_err(|e| err(&e))?;
        let mut jb = JITBuilder::with_isa(isa, default_libcall_names());
        let mut symbols: Vec<(&'static str, *const u8)> = vec![("mk_pow", mk_pow as *const u8)];
        for i in insts {
            match i {
                Inst::Call1(f, _)
                    if !matches!(f, Func::Abs | Func::Sqrt | Func::Floor | Func::Ceil) =>
                {
                    symbols.push(call1_symbol(*f));
                }
                Inst::Call2(f, ..) => symbols.push(call2_symbol(*f)),
                _ => {}
            }
        }
        symbols.sort_by_key(|(n, _)| *n);
        symbols.dedup_by_key(|(n, _)| *n);
        for (name, ptr) in &symbols {
            jb.symbol(*name, *ptr);
        }
        let mut module = JITModule::new(jb);
        let f64_sig = |n: usize, module: &JITModule| {
            let mut s: Signature = module.make_signature();
            for _ in 0..n {
                s.params.push(AbiParam::new(types::F64));
            }
            s.returns.push(AbiParam::new(types::F64));
            s
        };
        let mut externals = HashMap::new();
        for (name, _) in &symbols {
            let sig = match *name {
                "mk_pow" | "mk_atan2" | "mk_min" | "mk_max" => f64_sig(2, &module),
                _ => f64_sig(1, &module),
            };
            let fid = module
                .declare_function(name, Linkage::Import, &sig)
                .map_err(|e| err(&e))?;
            externals.insert(*name, fid);
        }
        Ok(Jit { module, externals })
    }

    /// Compiles the function built by `body` with signature `sig`; returns its address.
    pub(super) fn define(
        &mut self,
        sig: Signature,
        body: impl FnOnce(&mut FunctionBuilder, &HashMap<&'static str, FuncRef>) -> Result<(), String>,
    ) -> Result<*const u8, String> {
        let module = &mut self.module;
        let id = module
            .declare_function("formula", Linkage::Local, &sig)
            .map_err(|e| err(&e))?;
        let mut ctx = module.make_context();
        ctx.func.signature = sig;
        ctx.func.name = UserFuncName::user(0, id.as_u32());
        let mut fctx = FunctionBuilderContext::new();
        {
            let mut b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
            let mut refs = HashMap::new();
            for (name, fid) in &self.externals {
                refs.insert(*name, module.declare_func_in_func(*fid, b.func));
            }
            body(&mut b, &refs)?;
            b.seal_all_blocks();
            b.finalize(module.target_config());
        }
        let disasm = std::env::var("MECHKIT_JIT_DISASM").is_ok();
        if disasm {
            ctx.set_disasm(true);
        }
        module
            .define_function(id, &mut ctx)
            .map_err(|e| format!("{e:?}"))?;
        if disasm && let Some(code) = ctx.compiled_code().and_then(|c| c.vcode.clone()) {
            eprintln!("{code}");
        }
        module.clear_context(&mut ctx);
        module.finalize_definitions().map_err(|e| err(&e))?;
        Ok(module.get_finalized_function(id))
    }

    pub(super) fn pointer_type(&self) -> types::Type {
        self.module.target_config().pointer_type()
    }
}

/// The value of a program's constant: the k-th `Const` of its instructions, of value c.
pub(super) type ConstantFn<'a> =
    &'a mut dyn FnMut(&mut FunctionBuilder, usize, f64) -> Result<Value, String>;

/// Emits `insts` (SSA: operands are earlier instructions); `load` gives the value of a slot,
/// `constant` that of the k-th constant.
pub(super) fn emit_insts(
    b: &mut FunctionBuilder,
    insts: &[Inst],
    refs: &HashMap<&'static str, FuncRef>,
    load: &mut dyn FnMut(&mut FunctionBuilder, u32) -> Result<Value, String>,
    constant: ConstantFn<'_>,
) -> Result<Vec<Value>, String> {
    let one = b.ins().f64const(1.0);
    let zero = b.ins().f64const(0.0);
    let mut regs: Vec<Value> = Vec::with_capacity(insts.len());
    let mut constants = 0;
    for inst in insts {
        let r = |k: u32| regs[k as usize];
        let v = match *inst {
            Inst::Const(c) => {
                constants += 1;
                constant(b, constants - 1, c)?
            }
            Inst::Load(s) => load(b, s)?,
            Inst::Neg(a) => b.ins().fneg(r(a)),
            Inst::Not(a) => {
                let c = b.ins().fcmp(FloatCC::Equal, r(a), zero);
                b.ins().select(c, one, zero)
            }
            Inst::Add(x, y) => b.ins().fadd(r(x), r(y)),
            Inst::Sub(x, y) => b.ins().fsub(r(x), r(y)),
            Inst::Mul(x, y) => b.ins().fmul(r(x), r(y)),
            Inst::Div(x, y) => b.ins().fdiv(r(x), r(y)),
            Inst::Square(x) => b.ins().fmul(r(x), r(x)),
            Inst::Cmp(op, x, y) => {
                let c = b.ins().fcmp(float_cc(op), r(x), r(y));
                b.ins().select(c, one, zero)
            }
            Inst::And(x, y) | Inst::Or(x, y) => {
                let cx = b.ins().fcmp(FloatCC::NotEqual, r(x), zero);
                let cy = b.ins().fcmp(FloatCC::NotEqual, r(y), zero);
                let c = if matches!(inst, Inst::And(..)) {
                    b.ins().band(cx, cy)
                } else {
                    b.ins().bor(cx, cy)
                };
                b.ins().select(c, one, zero)
            }
            // a select on a comparison tests the comparison itself (it is 1 or 0, so
            // `c != 0` is the comparison): one compare instead of two
            Inst::Select(c, x, y) => {
                let cond = match insts[c as usize] {
                    Inst::Cmp(op, p, q) => b.ins().fcmp(float_cc(op), r(p), r(q)),
                    _ => b.ins().fcmp(FloatCC::NotEqual, r(c), zero),
                };
                b.ins().select(cond, r(x), r(y))
            }
            Inst::MinBits(x, y) | Inst::MaxBits(x, y) => {
                let flags = MemFlagsData::new();
                let ix = b.ins().bitcast(types::I64, flags, r(x));
                let iy = b.ins().bitcast(types::I64, flags, r(y));
                let cc = if matches!(inst, Inst::MinBits(..)) {
                    IntCC::SignedLessThan
                } else {
                    IntCC::SignedGreaterThan
                };
                let c = b.ins().icmp(cc, ix, iy);
                let pick = b.ins().select(c, ix, iy);
                b.ins().bitcast(types::F64, flags, pick)
            }
            Inst::Call1(Func::Abs, x) => b.ins().fabs(r(x)),
            Inst::Call1(Func::Sqrt, x) => b.ins().sqrt(r(x)),
            Inst::Call1(Func::Floor, x) => b.ins().floor(r(x)),
            Inst::Call1(Func::Ceil, x) => b.ins().ceil(r(x)),
            Inst::Call1(f, x) => {
                let call = b.ins().call(refs[call1_symbol(f).0], &[r(x)]);
                b.inst_results(call)[0]
            }
            Inst::Call2(f, x, y) => {
                let call = b.ins().call(refs[call2_symbol(f).0], &[r(x), r(y)]);
                b.inst_results(call)[0]
            }
            Inst::Pow(x, y) => {
                let call = b.ins().call(refs["mk_pow"], &[r(x), r(y)]);
                b.inst_results(call)[0]
            }
        };
        regs.push(v);
    }
    Ok(regs)
}

pub(super) fn slot_offset(s: u32) -> Result<i32, String> {
    i32::try_from(8 * u64::from(s)).map_err(|e| err(&e))
}

/// Compiled formulas, shared by equal instruction lists.
static PROGRAMS: Cache<Native> = Cache::new();

/// Formulas whose code is kept now.
#[cfg(test)]
pub(super) fn programs_kept() -> usize {
    PROGRAMS.len()
}

/// A program's native code and the values of its constants, which the code reads from
/// memory: programs that differ only in their constants' values share the code.
#[derive(Debug, Clone)]
pub(super) struct Attached {
    pub(super) code: Arc<Native>,
    constants: Arc<[f64]>,
}

impl Attached {
    /// Calls the native code. `vars` must hold every slot the program reads (checked by the
    /// caller).
    #[inline]
    pub(super) fn call(&self, vars: &[f64]) -> f64 {
        (self.code.func)(vars.as_ptr(), self.constants.as_ptr())
    }
}

impl Native {
    /// The native code of `ir` with its constants: the code compiled before for the same
    /// instructions (constants' values aside), else compiled now ([`Native::compile`]) and
    /// kept for the next.
    pub(super) fn shared(ir: &Ir) -> Result<Attached, String> {
        let mut key = cache::key(&ir.insts, false);
        key.push(Word::extra(ir.result));
        let code = PROGRAMS.get_or_compile(key, || Native::compile(ir))?;
        let constants = ir
            .insts
            .iter()
            .filter_map(|i| match i {
                Inst::Const(c) => Some(*c),
                _ => None,
            })
            .collect();
        Ok(Attached { code, constants })
    }

    /// Compiles `ir` as `fn(vars, constants) -> f64`, the k-th constant read from
    /// `constants[k]`.
    pub(super) fn compile(ir: &Ir) -> Result<Native, String> {
        let mut m = Jit::new(&ir.insts)?;
        let mut sig = m.module.make_signature();
        sig.params.push(AbiParam::new(m.pointer_type()));
        sig.params.push(AbiParam::new(m.pointer_type()));
        sig.returns.push(AbiParam::new(types::F64));
        let code = m.define(sig, |b, refs| {
            let block = b.create_block();
            b.switch_to_block(block);
            b.append_block_params_for_function_params(block);
            let vars = b.block_params(block)[0];
            let table = b.block_params(block)[1];
            let regs = emit_insts(
                b,
                &ir.insts,
                refs,
                &mut |b, s| {
                    Ok(b.ins()
                        .load(types::F64, MemFlagsData::trusted(), vars, slot_offset(s)?))
                },
                &mut |b, k, _| {
                    let k = u32::try_from(k).map_err(|e| err(&e))?;
                    Ok(b.ins()
                        .load(types::F64, MemFlagsData::trusted(), table, slot_offset(k)?))
                },
            )?;
            let result = regs[ir.result as usize];
            b.ins().return_(&[result]);
            Ok(())
        })?;
        // SAFETY: the function was built above with the signature (pointer, pointer) -> f64
        // and the C calling convention of the host, which is what this type says.
        let func = unsafe {
            std::mem::transmute::<*const u8, extern "C" fn(*const f64, *const f64) -> f64>(code)
        };
        Ok(Native {
            func,
            module: Mutex::new(Some(m.module)),
        })
    }
}
