//! libFuzzer entry for [`mechkit_fuzz::data_file`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::data_file(data));
