//! Core library: bytes -> 21 parameters (in, around and outside their ranges), load,
//! angular velocity, warm-start guess -> validate / Joint::new / evaluate(_from).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| pinjoint_fuzz::checks::core::check(data));
