//! Loop kernels in native code: the body of a [`Kernel`](super::Kernel) inside a counted loop,
//! the slots in registers (loaded once before the loop, stored once after it), the constants
//! built into the code. Shared between equal bodies like formulas' code ([`super::cache`]).

#![allow(unsafe_code)]

use std::sync::{Arc, Mutex};

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{AbiParam, InstBuilder, MemFlagsData, types};
use cranelift_jit::JITModule;
use cranelift_module::Module;

use super::cache::{self, Cache, Word};
use super::jit::{Jit, emit_insts, err, slot_offset};
use super::kernel::Body;

/// Compiled kernels, shared by equal bodies.
static KERNELS: Cache<NativeKernel> = Cache::new();

/// A loop kernel in executable memory: `fn(slots, n)` runs the body `n` times with the slots
/// in registers (loaded once before the loop, stored once after it).
pub(super) struct NativeKernel {
    func: extern "C" fn(*mut f64, u64),
    module: Mutex<Option<JITModule>>,
}

impl std::fmt::Debug for NativeKernel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("NativeKernel")
    }
}

impl Drop for NativeKernel {
    fn drop(&mut self) {
        if let Some(m) = self.module.get_mut().ok().and_then(Option::take) {
            // SAFETY: as for `Native`: `func` is private to `self` and dies with it.
            unsafe { m.free_memory() };
        }
    }
}

impl NativeKernel {
    /// The native code of `body`, shared as [`Native::shared`].
    pub(super) fn shared(body: &Body) -> Result<Arc<NativeKernel>, String> {
        let mut key = cache::key(&body.insts, true);
        key.extend(body.stores.iter().map(|&s| Word::extra(s)));
        key.push(Word::extra(u32::try_from(body.slots).map_err(|e| err(&e))?));
        KERNELS.get_or_compile(key, || NativeKernel::compile(body))
    }

    pub(super) fn compile(body: &Body) -> Result<NativeKernel, String> {
        let mut m = Jit::new(&body.insts)?;
        let ptr = m.pointer_type();
        let mut sig = m.module.make_signature();
        sig.params.push(AbiParam::new(ptr));
        sig.params.push(AbiParam::new(types::I64));
        let code = m.define(sig, |b, refs| {
            let entry = b.create_block();
            let header = b.create_block();
            let looped = b.create_block();
            let exit = b.create_block();
            b.append_block_params_for_function_params(entry);
            b.switch_to_block(entry);
            let slots = b.block_params(entry)[0];
            let n = b.block_params(entry)[1];
            let vars: Vec<_> = (0..body.slots).map(|_| b.declare_var(types::F64)).collect();
            for (s, var) in vars.iter().enumerate() {
                let s = u32::try_from(s).map_err(|e| err(&e))?;
                let v = b
                    .ins()
                    .load(types::F64, MemFlagsData::trusted(), slots, slot_offset(s)?);
                b.def_var(*var, v);
            }
            let counter = b.declare_var(types::I64);
            let zero = b.ins().iconst(types::I64, 0);
            b.def_var(counter, zero);
            b.ins().jump(header, &[]);

            b.switch_to_block(header);
            let i = b.use_var(counter);
            let done = b.ins().icmp(IntCC::Equal, i, n);
            b.ins().brif(done, exit, &[], looped, &[]);

            b.switch_to_block(looped);
            let regs = emit_insts(
                b,
                &body.insts,
                refs,
                &mut |b, s| Ok(b.use_var(vars[s as usize])),
                &mut |b, _, c| Ok(b.ins().f64const(c)),
            )?;
            for (var, r) in vars.iter().zip(&body.stores) {
                b.def_var(*var, regs[*r as usize]);
            }
            let i = b.use_var(counter);
            let i1 = b.ins().iadd_imm_u(i, 1);
            b.def_var(counter, i1);
            b.ins().jump(header, &[]);

            b.switch_to_block(exit);
            for (s, var) in vars.iter().enumerate() {
                let s = u32::try_from(s).map_err(|e| err(&e))?;
                let v = b.use_var(*var);
                b.ins()
                    .store(MemFlagsData::trusted(), v, slots, slot_offset(s)?);
            }
            b.ins().return_(&[]);
            Ok(())
        })?;
        // SAFETY: the function was built above with the signature (pointer, i64) -> () and
        // the C calling convention of the host, which is what this type says.
        let func = unsafe { std::mem::transmute::<*const u8, extern "C" fn(*mut f64, u64)>(code) };
        Ok(NativeKernel {
            func,
            module: Mutex::new(Some(m.module)),
        })
    }

    /// Runs the body `n` times on `slots` (its length checked by the caller).
    #[inline]
    pub(super) fn call(&self, slots: &mut [f64], n: u64) {
        (self.func)(slots.as_mut_ptr(), n);
    }
}
