//! libFuzzer entry for [`mechkit_fuzz::python_front`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| mechkit_fuzz::python_front(data));
