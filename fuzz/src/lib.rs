//! The checks of the fuzz targets; `crates/fmu/tests/fuzz_regressions.rs` of the main crate
//! includes `checks.rs` by path to replay `fuzz/regressions/` without libFuzzer.
pub mod checks;
