//! Sequences of FMI 2.0 calls through the exported fmi2* functions.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| pinjoint_fuzz::checks::fmi::check(data));
