//! Every `fmi2*` function of the FMI 2.0 standard, exported with C linkage.

pub mod common;
pub mod cosim;
pub(crate) mod fmu_state;
pub(crate) mod guard;
pub mod model_exchange;
pub(crate) mod values;

pub use guard::{force_panic_in, pinjoint_test_force_panic};
