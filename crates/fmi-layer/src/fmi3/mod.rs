//! The FMI 3.0 shim over the version-neutral core ([`crate::core`]), Co-Simulation and Model
//! Exchange: the exported `fmi3*` functions ([`api`]), their C types ([`types`]) and the
//! FMI 3.0 modelDescription.xml generator ([`xml`]), as Reference-FMUs keeps
//! `fmi3Functions.c` over one `cosimulation.c`. The models are the core's
//! ([`Model`](crate::core::model::Model) trait, [`ModelInfo`](crate::core::variables::ModelInfo)
//! table), the same ones the FMI 2.0 shim serves; this module names nothing of FMI 2.0.
//!
//! What the core gives both standards, so that they behave alike: the instance (value
//! checks, output range checks, model messages), the state machine with one mask per function
//! (FMI 3.0's step mode is the FMI 2.0 `stepComplete` state; event and continuous-time mode are
//! the Model Exchange states of both), the panic containment of every export, logging by
//! category, and the FMU state with its serialized byte format and CRC (an FMU state
//! serialized through FMI 3.0 reads back through FMI 2.0 and vice versa, for the same model).
//!
//! Mapping of the table's types: Real → Float64, Integer → Int32, Boolean → Boolean,
//! Enumeration → Enumeration (accessed with `fmi3GetInt64`/`fmi3SetInt64`). No clocks, no
//! scheduled execution, no event mode in Co-Simulation (`hasEventMode = false`).

pub mod types;
pub mod xml;
pub mod api;

/// Export `fmi3InstantiateModelExchange` and `fmi3InstantiateCoSimulation` for the models
/// `$registry()` returns (a `fn() -> Vec<&'static ModelInfo>`), at the root of the model
/// library, as `export_fmi2!` does for FMI 2.0. Every other `fmi3*` function is
/// exported by this crate itself.
///
/// ```ignore
/// fmi_layer::export_fmi3!(crate::registry);
/// ```
#[macro_export]
macro_rules! export_fmi3 {
    ($registry:path) => {
        /// `fmi3InstantiateModelExchange` (FMI 3.0) for the models of this library: finds the
        /// model whose instantiation token is `instantiationToken` and returns a new Model
        /// Exchange instance of it in the `instantiated` state. Returns NULL (with the reason
        /// logged when `logMessage` is given) for an empty instance name, a NULL or unknown
        /// token, or a model that offers Co-Simulation only.
        ///
        /// # Safety
        /// Pointers as in the FMI 3.0 standard; NULL is handled everywhere.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3InstantiateModelExchange(instance_name: $crate::fmi3::types::Fmi3String, instantiation_token: $crate::fmi3::types::Fmi3String, resource_path: $crate::fmi3::types::Fmi3String, _visible: $crate::fmi3::types::Fmi3Boolean, logging_on: $crate::fmi3::types::Fmi3Boolean, instance_environment: *mut ::std::ffi::c_void, log_message: ::std::option::Option<$crate::fmi3::types::Fmi3LogMessageCallback>) -> *mut ::std::ffi::c_void {
            let interface = $crate::core::instance::Interface::ModelExchange;
            // SAFETY: forwarded from the host under the same contract.
            unsafe { $crate::fmi3::api::common::instantiate_from(&$registry(), interface, instance_name, instantiation_token, resource_path, logging_on, 0, instance_environment, log_message) }
        }

        /// `fmi3InstantiateCoSimulation` (FMI 3.0) for the models of this library: finds the
        /// model whose instantiation token is `instantiationToken` and returns a new
        /// Co-Simulation instance of it in the `instantiated` state. Returns NULL (with the
        /// reason logged when `logMessage` is given) for an empty instance name, a NULL or
        /// unknown token, or `eventModeUsed = true` (`hasEventMode = false`); early return and
        /// intermediate update are not used.
        ///
        /// # Safety
        /// Pointers as in the FMI 3.0 standard; NULL is handled everywhere.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3InstantiateCoSimulation(instance_name: $crate::fmi3::types::Fmi3String, instantiation_token: $crate::fmi3::types::Fmi3String, resource_path: $crate::fmi3::types::Fmi3String, _visible: $crate::fmi3::types::Fmi3Boolean, logging_on: $crate::fmi3::types::Fmi3Boolean, event_mode_used: $crate::fmi3::types::Fmi3Boolean, _early_return_allowed: $crate::fmi3::types::Fmi3Boolean, _required_intermediate_variables: *const u32, _n_required_intermediate_variables: usize, instance_environment: *mut ::std::ffi::c_void, log_message: ::std::option::Option<$crate::fmi3::types::Fmi3LogMessageCallback>, _intermediate_update: *mut ::std::ffi::c_void) -> *mut ::std::ffi::c_void {
            let interface = $crate::core::instance::Interface::CoSimulation;
            // SAFETY: forwarded from the host under the same contract.
            unsafe { $crate::fmi3::api::common::instantiate_from(&$registry(), interface, instance_name, instantiation_token, resource_path, logging_on, event_mode_used, instance_environment, log_message) }
        }
    };
}
