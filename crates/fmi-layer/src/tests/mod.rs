//! Tests of the layer through its exported functions, with a small test-only model
//! ([`linear`]): continuous states under Model Exchange, directional derivatives, local
//! variables and the ModelStructure of a model with a state, for FMI 2.0 and FMI 3.0.

mod fmi2_states;
mod fmi3_states;
mod host;
mod linear;
mod lookup;
mod rules;
mod xml_states;
