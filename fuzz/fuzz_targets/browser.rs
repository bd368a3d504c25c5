//! libFuzzer entry for [`mechkit_fuzz::browser`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::browser(data));
