//! libFuzzer entry for [`mechkit_fuzz::expression`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::expression(data));
