//! The interface an instance was created for (FMI 2.0 `fmi2Type`, FMI 3.0 the instantiation
//! function): a leaf module, so that the error types (`crate::error`) can name it without
//! depending on the instance.

/// The interface the host instantiated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interface {
    /// Co-Simulation (`fmi2CoSimulation`, `fmi3InstantiateCoSimulation`): the FMU advances
    /// its own time with `fmi2DoStep`; continuous states, if any, are internal.
    CoSimulation,
    /// Model Exchange (`fmi2ModelExchange`, `fmi3InstantiateModelExchange`): the host's
    /// integrator owns the continuous states (FMI 2.0 §3, FMI 3.0 §3); no event indicators.
    ModelExchange,
}
