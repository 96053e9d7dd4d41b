//! TEMPORARY ADAPTER (branch `complete`): the agreed API of the grease in the clearance.
//! Replaced by the `journal` branch's module at merge; nothing here is meant to land.

use std::f64::consts::PI;

/// Placeholder default τ_y (Pa).
pub const DEFAULT_YIELD_STRESS: f64 = 300.0;
/// Placeholder default K (Pa·s^n).
pub const DEFAULT_CONSISTENCY: f64 = 10.0;
/// Placeholder default n.
pub const DEFAULT_FLOW_INDEX: f64 = 0.4;
/// Placeholder E_y/R (K).
pub const DEFAULT_YIELD_ACTIVATION: f64 = 2000.0;
/// Placeholder E_K/R (K).
pub const DEFAULT_CONSISTENCY_ACTIVATION: f64 = 2000.0;
/// Source text.
pub const GREASE_SOURCE: &str = "placeholder";

/// The clearance's rheology at one temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rheology {
    /// τ_y (Pa).
    pub yield_stress: f64,
    /// K (Pa·s^n).
    pub consistency: f64,
    /// n.
    pub flow_index: f64,
    /// η_b (Pa·s).
    pub base_viscosity: f64,
}

const GL: [(f64, f64); 8] = [
    (-0.9602898564975363, 0.1012285362903763),
    (-0.7966664774136267, 0.2223810344533745),
    (-0.5255324099163290, 0.3137066458778873),
    (-0.1834346424956498, 0.3626837833783620),
    (0.1834346424956498, 0.3626837833783620),
    (0.5255324099163290, 0.3137066458778873),
    (0.7966664774136267, 0.2223810344533745),
    (0.9602898564975363, 0.1012285362903763),
];

/// Torque of the clearance outside |θ| ≤ θ_c, N·m.
pub fn clearance_torque(r: &Rheology, u: f64, radius: f64, b: f64, c: f64, eps: f64, theta_c: f64) -> f64 {
    let k = ((1.0 - eps) / (1.0 + eps)).sqrt();
    let psi_c = ((theta_c * 0.5).tan() / k).atan();
    let span = 0.5 * PI - psi_c;
    let s = (1.0 - eps * eps).sqrt();
    let newton = r.base_viscosity * u / c * 2.0 * (2.0 / s) * span;
    let power = if r.consistency > 0.0 && u > 0.0 {
        let mut acc = 0.0;
        for (x, wt) in GL {
            let psi = psi_c + 0.5 * span * (x + 1.0);
            let g = (1.0 - eps) / (psi.cos().powi(2) + k * k * psi.sin().powi(2));
            acc += wt * g.powf(1.0 - r.flow_index);
        }
        r.consistency * (u / c).powf(r.flow_index) * 2.0 * (2.0 / s) * 0.5 * span * acc
    } else {
        0.0
    };
    (newton + power) * radius * radius * b + yield_torque(r, radius, b, theta_c)
}

/// Yield torque τ_y (2π − 2θ_c) R² B, N·m.
pub fn yield_torque(r: &Rheology, radius: f64, b: f64, theta_c: f64) -> f64 {
    r.yield_stress * (2.0 * PI - 2.0 * theta_c) * radius * radius * b
}
