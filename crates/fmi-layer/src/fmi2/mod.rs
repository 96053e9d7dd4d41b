//! The FMI 2.0 shim over the version-neutral core ([`crate::core`]): the exported `fmi2*`
//! functions ([`api`]), their C types ([`types`]) and the FMI 2.0 modelDescription.xml
//! generator ([`xml`]), as Reference-FMUs keeps `fmi2Functions.c` over one
//! `cosimulation.c`. Everything the two standards share (the instance, the model trait, the
//! variable table, the state machine, logging, the FMU state) is the core's; this module only
//! spells FMI 2.0's functions, types and elements, and names nothing of FMI 3.0.
//!
//! A model plugs in through the core's [`Model`](crate::core::model::Model) trait plus a
//! [`ModelInfo`](crate::core::variables::ModelInfo) (variable table, units, default
//! experiment). `fmi2Instantiate` finds the model by GUID among the models the library
//! registers with [`crate::export_fmi2!`], so one shared library can serve several FMUs, each
//! packaged with its own modelDescription.xml and a copy of the library named for its model
//! identifier.

pub mod types;
pub mod api;
pub mod xml;

/// Export `fmi2Instantiate` for the models `$registry()` returns (a
/// `fn() -> Vec<&'static ModelInfo>`), at the root of the model library. Every other
/// `fmi2*` function is exported by this crate itself; this is the one entry point that
/// must choose a model, so the registry is passed in here, as rust-fmi's `export_fmu!`
/// does, and the generic layer never names a model.
///
/// ```ignore
/// fmi_layer::export_fmi2!(crate::registry);
/// ```
#[macro_export]
macro_rules! export_fmi2 {
    ($registry:path) => {
        /// `fmi2Instantiate` (FMI 2.0 §2.1.5) for the models of this library: finds the model
        /// whose GUID is `fmuGUID` and returns a new instance of it, every variable at its start
        /// value, in the `instantiated` state. Returns NULL for NULL `functions` or logger, an
        /// empty instance name, an `fmuType` that is not 0 or 1 (or Model Exchange for a
        /// Co-Simulation-only model), or a GUID of no model of this library (logged, except
        /// when there is no logger). A resource location that is not a URI is only a warning.
        ///
        /// # Safety
        /// Pointers as in the FMI 2.0 standard; NULL is handled everywhere.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Instantiate(instance_name: $crate::fmi2::types::Fmi2String, fmu_type: ::std::ffi::c_int, guid: $crate::fmi2::types::Fmi2String, resource_location: $crate::fmi2::types::Fmi2String, functions: *const $crate::fmi2::types::Fmi2CallbackFunctions, _visible: $crate::fmi2::types::Fmi2Boolean, logging_on: $crate::fmi2::types::Fmi2Boolean) -> $crate::fmi2::types::Fmi2Component {
            // SAFETY: forwarded from the host under the same contract.
            unsafe { $crate::fmi2::api::common::instantiate_from(&$registry(), instance_name, fmu_type, guid, resource_location, functions, logging_on) }
        }
    };
}
