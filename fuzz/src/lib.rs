//! What every libFuzzer binary does once at start, before libFuzzer installs its handlers.

use std::ffi::{c_int, c_void};
use std::ptr::null_mut;

/// Bytes of the alternate signal stack: room for libFuzzer's crash report (it writes the
/// input and a stack trace from the handler).
const ALT_STACK: usize = 1 << 20;

/// Makes a stack overflow a reported crash. libFuzzer's `SIGSEGV` handler runs on the
/// faulting stack unless the handler before it asked for an alternate one, and on an
/// exhausted stack it faults again: the process died with a silent SIGSEGV and no input
/// written (a `calculus` run on 2026-12-05). This gives the main thread an alternate stack
/// and a `SIGSEGV` handler that runs on it; libFuzzer keeps the flag and hands the signal to
/// this handler, which aborts, and libFuzzer's `SIGABRT` handler, running on the same stack,
/// reports a deadly signal and writes the input to `fuzz/artifacts`.
pub fn catch_stack_overflows() {
    // SAFETY: plain POSIX calls on memory this function owns for the life of the process;
    // the handler only calls `abort`, which is async-signal-safe.
    unsafe {
        let stack = libc::mmap(
            null_mut(),
            ALT_STACK,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        );
        if stack == libc::MAP_FAILED {
            return;
        }
        let alt = libc::stack_t {
            ss_sp: stack,
            ss_flags: 0,
            ss_size: ALT_STACK,
        };
        if libc::sigaltstack(&alt, null_mut()) != 0 {
            return;
        }
        let mut action: libc::sigaction = std::mem::zeroed();
        action.sa_sigaction = on_segv as *const () as usize;
        action.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK;
        libc::sigemptyset(&mut action.sa_mask);
        libc::sigaction(libc::SIGSEGV, &action, null_mut());
    }
}

extern "C" fn on_segv(_: c_int, _: *mut libc::siginfo_t, _: *mut c_void) {
    // SAFETY: async-signal-safe; ends the process through libFuzzer's SIGABRT handler.
    unsafe { libc::abort() }
}
