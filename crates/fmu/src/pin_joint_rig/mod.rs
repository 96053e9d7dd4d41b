//! The PinJointRig FMU: the integrated articulation mode ([`pinjoint::rig`]) as an
//! FMI 2.0 Co-Simulation slave. Inputs the load and, optionally, the command
//! angle; parameters the stroke, every `[rig]` constant and every model parameter;
//! outputs the rig's angle, speed, recorded and friction torques, the core's
//! quantities and the energy balance. Served by the same shared library as
//! PinJoint (`fmi2Instantiate` picks the model by GUID).

// Modules in dependency order, lowest first: the settings, the variable table, the FMU
// state, the model, its page.
pub mod settings;
pub mod variables;
pub mod state;
pub mod model;
pub mod doc;

use fmi_layer::core::variables::ModelInfo;
use std::sync::LazyLock;

/// The PinJointRig model's description for the registry: its variable table
/// ([`variables::TABLE`]), units, default experiment (0 to 3 s, step 1 ms), documentation
/// page and constructor; Co-Simulation only.
pub static INFO: LazyLock<ModelInfo> = LazyLock::new(|| {
    crate::model_info(
        "PinJointRig",
        "Landing-gear pin joint on the paper's torsion-actuator rig: a servo-hydraulic actuator in angle control \
         swings the pin (sine strokes or a command input) against the mixed-lubrication friction torque, \
         with stick and breakaway at reversals; the recorded torque is what the rig's transducer reads",
        (variables::table(), &variables::UNITS),
        (0.0, 3.0, 1e-3),
        || Box::new(model::RigModel::new()),
        || doc::index_html(&INFO),
    )
});
