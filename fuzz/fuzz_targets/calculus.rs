//! libFuzzer entry for [`mechkit_fuzz::calculus`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::calculus(data));
