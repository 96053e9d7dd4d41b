//! The PinJoint FMU: the friction torque of the joint as an FMI 2.0
//! Co-Simulation slave. Inputs angle, angular velocity and load; outputs the
//! torque and the model's other quantities; parameters the 26 keys of the
//! parameter file plus the zero-velocity band ([`zero_speed`]).

pub mod doc;
pub mod model;
pub mod variables;
pub mod zero_speed;

use fmi_layer::fmi2::variables::ModelInfo;
use std::sync::LazyLock;

/// The PinJoint model's description for the registry: its variable table
/// ([`variables::table`]), units, default experiment (0 to 10 s, step 1 ms), documentation
/// page and constructor; Co-Simulation and Model Exchange.
pub static INFO: LazyLock<ModelInfo> = LazyLock::new(|| ModelInfo {
    model_name: "PinJoint",
    model_identifier: "PinJoint",
    description: "Frictional torque of a grease-lubricated aircraft landing-gear pin joint (mixed lubrication: \
                  Greenwood-Williamson asperity contact and Moes film thickness with load sharing)",
    version: env!("CARGO_PKG_VERSION"),
    units: variables::UNITS,
    variables: variables::table(),
    default_experiment: (0.0, 10.0, 1e-3),
    create: || Box::new(model::PinJointModel::new()),
    documentation: doc::index_html,
    model_exchange: true,
    legal: crate::LEGAL,
});
