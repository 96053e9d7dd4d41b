//! Every `fmi2*` function of the FMI 2.0 standard but `fmi2Instantiate` (which needs the
//! model registry: [`crate::export_fmi2!`]), exported with C linkage. Each is a thin shim: it
//! reads its C arguments and runs a body of the core ([`crate::core`]) through the core's
//! guard (NULL or dead instance, the state mask, error logging, panic containment).

// The functions of each interface, as in the FMI 3.0 shim; `common` also re-exports the FMU state
// functions (the path the root tests import them by).
pub mod cosim;
pub mod fmu_state;
pub mod model_exchange;
pub mod common;

pub use common::*;
pub use cosim::*;
pub use fmu_state::*;
pub use model_exchange::*;

pub use crate::core::guard::{force_panic_in, pinjoint_test_force_panic};
