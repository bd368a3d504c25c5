//! libFuzzer entry for [`mechkit_fuzz::image`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::image(data));
