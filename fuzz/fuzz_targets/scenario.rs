//! libFuzzer entry for [`mechkit_fuzz::scenario`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::scenario(data));
