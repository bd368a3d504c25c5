//! libFuzzer entry for [`mechkit_fuzz::units`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::units(data));
