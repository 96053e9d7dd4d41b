//! The core target's checks on cases moved into the envelope (checks::core::check_in_envelope):
//! parameters within a factor 16 of their defaults, loads 1 µN to 10 GN, |ω| <= 1e7 rad/s,
//! invalid values kept. Every output must be finite there.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| pinjoint_fuzz::checks::core::check_in_envelope(data));
