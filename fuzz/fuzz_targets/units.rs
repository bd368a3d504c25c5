//! libFuzzer entry for [`mechkit_fuzz::units`].
#![no_main]

libfuzzer_sys::fuzz_target!(init: mechkit_fuzz_targets::catch_stack_overflows(), |data: &[u8]| mechkit_fuzz::units(data));
