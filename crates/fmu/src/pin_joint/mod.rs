//! The PinJoint FMU: the friction torque of the joint as an FMI 2.0
//! Co-Simulation slave. Inputs angle, angular velocity and load; outputs the
//! torque and the model's other quantities; parameters the 26 keys of the
//! parameter file plus the zero-velocity treatment ([`zero_velocity`]).

// Modules in dependency order, lowest first: the zero-velocity rows and friction, the variable
// table, the outputs at a set of values, the directional derivatives, the model, its page.
pub mod zero_velocity;
pub mod variables;
mod evaluate;
pub mod partials;
pub mod model;
pub mod doc;

use fmi_layer::core::variables::ModelInfo;
use std::sync::LazyLock;

/// The PinJoint model's description for the registry: its variable table
/// ([`variables::TABLE`]), units, default experiment (0 to 10 s, step 1 ms), documentation
/// page and constructor; Co-Simulation and Model Exchange.
pub static INFO: LazyLock<ModelInfo> = LazyLock::new(|| ModelInfo {
    model_exchange: true,
    directional_derivatives: true,
    // Model Exchange: the presliding state's stick and slip modes change at step events.
    step_events: true,
    ..crate::model_info(
        "PinJoint",
        "Frictional torque of a grease-lubricated aircraft landing-gear pin joint (mixed lubrication: \
         Greenwood-Williamson asperity contact and Moes film thickness with load sharing)",
        (variables::table(), &variables::UNITS),
        (0.0, 10.0, 1e-3),
        || Box::new(model::PinJointModel::new()),
        || doc::index_html(&INFO),
    )
});
