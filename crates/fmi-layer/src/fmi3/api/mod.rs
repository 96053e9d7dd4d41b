//! Every `fmi3*` function of the FMI 3.0 standard but the two instantiation functions that
//! need the model registry ([`crate::export_fmi3!`]), exported with C linkage. Each is a thin
//! shim: it reads its C arguments and runs a body of the core ([`crate::core`]) through the
//! core's guard (NULL or dead instance, the state mask, error logging, panic containment).
//!
//! Unsupported parts of the standard (clocks, scheduled execution, configuration mode,
//! adjoint derivatives, output derivatives, Float32/8-/16-bit/unsigned/String/
//! Binary variables) are refused with a message naming why.

// The functions of each interface, as in the FMI 2.0 shim.
pub mod cosim;
pub mod fmu_state;
pub mod model_exchange;
pub mod common;

pub use common::*;
pub use cosim::*;
pub use fmu_state::*;
pub use model_exchange::*;
