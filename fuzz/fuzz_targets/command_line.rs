//! libFuzzer entry for [`mechkit_fuzz::command_line`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::command_line(data));
