//! Proptest strategies shared by the property tests of several crates.

use proptest::prelude::*;

/// Log-uniform in [`lo`, `hi`): uniform in ln x. The tests of the library's operating points
/// (complete.rs, edges.rs, one_answer.rs) and of the FMU's edges (fmu_edges.rs) draw from it.
pub fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

/// Log-uniform in [`lo`, `hi`) through the decimal exponent: uniform in log10 x, mapped back
/// by `10^e` (so not bit for bit the values of [`log_uniform`]). The tests of the temperature
/// path (properties.rs, temperature_validity.rs, fmu_temperature_validity.rs) draw from it,
/// imported as `log_uniform`, so that their saved regression seeds replay the same cases.
pub fn log10_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e))
}
