//! The units of both FMUs (one definition each) and the display factors they share.

use fmi_layer::core::variables::{DisplayUnit, UnitDef, Variable};

/// Degrees per radian, 180/π (display units `deg`, `deg/s`).
pub const DEG: f64 = 57.29577951308232;
/// Revolutions per minute per rad/s, 60/(2π) (display unit `rpm`).
pub const RPM: f64 = 9.549296585513721;

/// Every unit of both FMUs, with its SI base units and display units: PinJoint's, then
/// the rig's own (the order of the UnitDefinitions).
pub static ALL: &[UnitDef] = &[
    UnitDef { name: "rad", quantity: "Angle", kg: 0, m: 0, s: 0, rad: 1, k: 0, display: &[DisplayUnit { name: "deg", factor: DEG, offset: 0.0 }] },
    UnitDef {
        name: "rad/s", quantity: "AngularVelocity",
        kg: 0,
        m: 0,
        s: -1,
        rad: 1,
        k: 0, display: &[DisplayUnit { name: "deg/s", factor: DEG, offset: 0.0 }, DisplayUnit { name: "rpm", factor: RPM, offset: 0.0 }],
    },
    UnitDef { name: "N", quantity: "Force", kg: 1, m: 1, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kN", factor: 1e-3, offset: 0.0 }] },
    UnitDef { name: "N.m", quantity: "Torque", kg: 1, m: 2, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kN.m", factor: 1e-3, offset: 0.0 }] },
    UnitDef {
        name: "m", quantity: "Length",
        kg: 0,
        m: 1,
        s: 0,
        rad: 0,
        k: 0, display: &[DisplayUnit { name: "mm", factor: 1e3, offset: 0.0 }, DisplayUnit { name: "um", factor: 1e6, offset: 0.0 }],
    },
    UnitDef {
        name: "Pa", quantity: "Pressure",
        kg: 1,
        m: -1,
        s: -2,
        rad: 0,
        k: 0, display: &[DisplayUnit { name: "MPa", factor: 1e-6, offset: 0.0 }, DisplayUnit { name: "GPa", factor: 1e-9, offset: 0.0 }],
    },
    UnitDef { name: "Pa.s", quantity: "DynamicViscosity", kg: 1, m: -1, s: -1, rad: 0, k: 0, display: &[DisplayUnit { name: "mPa.s", factor: 1e3, offset: 0.0 }] },
    UnitDef { name: "1/Pa", quantity: "PressureViscosityCoefficient", kg: -1, m: 1, s: 2, rad: 0, k: 0, display: &[DisplayUnit { name: "1/GPa", factor: 1e9, offset: 0.0 }] },
    UnitDef { name: "1/m2", quantity: "AsperityDensity", kg: 0, m: -2, s: 0, rad: 0, k: 0, display: &[] },
    UnitDef { name: "N.m/s", quantity: "TorqueRate", kg: 1, m: 2, s: -3, rad: 0, k: 0, display: &[] },
    UnitDef { name: "W", quantity: "Power", kg: 1, m: 2, s: -3, rad: 0, k: 0, display: &[] },
    UnitDef { name: "J", quantity: "Energy", kg: 1, m: 2, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kJ", factor: 1e-3, offset: 0.0 }] },
    UnitDef { name: "K", quantity: "ThermodynamicTemperature", kg: 0, m: 0, s: 0, rad: 0, k: 1, display: &[DisplayUnit { name: "degC", factor: 1.0, offset: -273.15 }] },
    UnitDef { name: "1/m", quantity: "InverseLength", kg: 0, m: -1, s: 0, rad: 0, k: 0, display: &[] },
    UnitDef { name: "Hz", quantity: "Frequency", kg: 0, m: 0, s: -1, rad: 0, k: 0, display: &[] },
    UnitDef { name: "s", quantity: "Time", kg: 0, m: 0, s: 1, rad: 0, k: 0, display: &[DisplayUnit { name: "ms", factor: 1e3, offset: 0.0 }] },
    UnitDef { name: "kg.m2", quantity: "MomentOfInertia", kg: 1, m: 2, s: 0, rad: 0, k: 0, display: &[] },
    UnitDef {
        name: "N.m/rad", quantity: "RotationalStiffness",
        kg: 1,
        m: 2,
        s: -2,
        rad: -1,
        k: 0, display: &[DisplayUnit { name: "N.m/deg", factor: 1.0 / DEG, offset: 0.0 }],
    },
    UnitDef { name: "N.m.s/rad", quantity: "RotationalDampingConstant", kg: 1, m: 2, s: -1, rad: -1, k: 0, display: &[] },
];

/// The units `vars` use, in [`ALL`]'s order (a model's `UnitDefinitions`).
pub fn used_by(vars: &[Variable]) -> Vec<UnitDef> {
    ALL.iter().filter(|u| vars.iter().any(|v| v.unit == Some(u.name))).copied().collect()
}
