//! libFuzzer entry for [`mechkit_fuzz::options`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::options(data));
