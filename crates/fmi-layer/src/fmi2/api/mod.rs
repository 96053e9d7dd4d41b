//! Every `fmi2*` function of the FMI 2.0 standard, exported with C linkage.

// Files in dependency order, lowest first: `guard` (the state-machine and panic guard every
// export runs through), the functions of each interface, then `common` (which uses them).
pub(crate) mod guard;
pub mod cosim;
pub(crate) mod fmu_state;
pub mod model_exchange;
pub(crate) mod values;
pub mod common;

pub use guard::{force_panic_in, pinjoint_test_force_panic};
