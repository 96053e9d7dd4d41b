//! The clearance torque and the yield torque (see [`super`] for the equations).

use std::f64::consts::PI;

use super::integrals::{newtonian_integral, newtonian_integral_pair, power_law_integral};
use super::table::PowerLawTable;
use crate::rheology::grease::GreaseRheology;

/// The clearance torque's three parts (N·m), all ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ClearanceTorque {
    /// τ_y (2π − 2θ_c) R² B: the yield stress over the arc.
    pub yield_part: f64,
    /// K (U/c)ⁿ Jₙ R² B: the grease's shear-thinning part.
    pub power_law_part: f64,
    /// η_b (U/c) J₁ R² B: the base oil's Newtonian part.
    pub newtonian_part: f64,
}

impl ClearanceTorque {
    /// The sum of the parts (N·m).
    pub fn total(&self) -> f64 {
        self.yield_part + self.power_law_part + self.newtonian_part
    }
}

/// The clearance torque's parts (N·m) for the rheology `rheology` at sliding speed
/// `sliding_speed` = |ω| R (m/s; its sign is ignored), pin radius `radius` R (m), bush
/// length `length` B (m), radial clearance `clearance` c (m), eccentricity ratio of the gap
/// `eps_g` (clamped to [0, [`super::MAX_ECCENTRICITY`]]) and contact half-angle `theta_c` (rad,
/// clamped to [0, π]). At U = 0 only the yield part remains ([`yield_torque`]).
pub fn clearance_torque_parts(rheology: &GreaseRheology, sliding_speed: f64, radius: f64, length: f64, clearance: f64, eps_g: f64, theta_c: f64) -> ClearanceTorque {
    let u = sliding_speed.abs();
    let r2b = radius * radius * length;
    let t = theta_c.clamp(0.0, PI);
    let yield_part = rheology.yield_stress * (2.0 * PI - 2.0 * t) * r2b;
    if u == 0.0 {
        return ClearanceTorque { yield_part, ..ClearanceTorque::default() };
    }
    let rate = u / clearance;
    let j1 = newtonian_integral(eps_g, t);
    let newtonian_part = rheology.base_viscosity * rate * j1 * r2b;
    let power_law_part = if rheology.consistency > 0.0 {
        let n = rheology.flow_index;
        let jn = if n == 1.0 { j1 } else { power_law_integral(eps_g, t, n) };
        rheology.consistency * rate.powf(n) * jn * r2b
    } else {
        0.0
    };
    ClearanceTorque { yield_part, power_law_part, newtonian_part }
}

/// The clearance's geometry: pin radius R, bush length B and radial clearance c (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClearanceGeometry {
    /// R, pin radius (m).
    pub radius: f64,
    /// B, bush length (m).
    pub length: f64,
    /// c, radial clearance (m).
    pub clearance: f64,
}

/// As [`clearance_torque_parts`] (same parts, same clamps), with Jₙ from `table`
/// ([`PowerLawTable`]: the model's hot path, a lookup instead of the 12-node rule, and more
/// accurate near ε = 1) when the table's flow index is the rheology's; otherwise exactly
/// [`clearance_torque_parts`].
pub fn clearance_torque_tabulated(table: &PowerLawTable, rheology: &GreaseRheology, geometry: &ClearanceGeometry, sliding_speed: f64, eps_g: f64, theta_c: f64) -> ClearanceTorque {
    let ClearanceGeometry { radius, length, clearance } = *geometry;
    let n = rheology.flow_index;
    if n != table.flow_index() || n == 1.0 || rheology.consistency <= 0.0 || sliding_speed == 0.0 {
        return clearance_torque_parts(rheology, sliding_speed, radius, length, clearance, eps_g, theta_c);
    }
    let r2b = radius * radius * length;
    let t = theta_c.clamp(0.0, PI);
    let rate = u_rate(sliding_speed, clearance);
    ClearanceTorque {
        yield_part: rheology.yield_stress * (2.0 * PI - 2.0 * t) * r2b,
        power_law_part: rheology.consistency * rate.powf(n) * table.integral(eps_g, t) * r2b,
        newtonian_part: rheology.base_viscosity * rate * newtonian_integral(eps_g, t) * r2b,
    }
}

/// [`clearance_torque_tabulated`] outside the arc |θ| ≤ `theta_c`, and the torque the same
/// lubricant's flow (its power-law and Newtonian parts; the yield part is the rest torque's)
/// would transmit over that arc (the whole clearance's minus the outside's, ≥ 0):
/// (outside, arc), N·m.
///
/// The outside's yield part is the whole circumference's, τ_y·2π·R²·B: the contact arc takes
/// the grease's flow from the clearance, not its yield (so that no part of the torque falls as
/// the arc widens with the load, [`crate::composite`]).
pub fn clearance_and_arc_torque(table: &PowerLawTable, rheology: &GreaseRheology, geometry: &ClearanceGeometry, sliding_speed: f64, eps_g: f64, theta_c: f64) -> (ClearanceTorque, f64) {
    let n = rheology.flow_index;
    if theta_c > 0.0 && !(n != table.flow_index() || n == 1.0 || rheology.consistency <= 0.0 || sliding_speed == 0.0) {
        // The tabulated route of both calls below, sharing the rate's power and the
        // eccentricity's terms: the same numbers, bit for bit (test
        // `arc_torque_pair_is_two_calls_bit_for_bit`).
        let ClearanceGeometry { radius, length, clearance } = *geometry;
        let r2b = radius * radius * length;
        let t = theta_c.clamp(0.0, PI);
        let rate = u_rate(sliding_speed, clearance);
        let k_rate = rheology.consistency * rate.powf(n);
        let eta_rate = rheology.base_viscosity * rate;
        let (jn_whole, jn_outside) = table.integral_pair(eps_g, t);
        let (j1_whole, j1_outside) = newtonian_integral_pair(eps_g, t);
        let outside = ClearanceTorque {
            yield_part: yield_torque(rheology, radius, length, 0.0),
            power_law_part: k_rate * jn_outside * r2b,
            newtonian_part: eta_rate * j1_outside * r2b,
        };
        let whole_flow = k_rate * jn_whole * r2b + eta_rate * j1_whole * r2b;
        return (outside, (whole_flow - (outside.power_law_part + outside.newtonian_part)).max(0.0));
    }
    let outside = clearance_torque_tabulated(table, rheology, geometry, sliding_speed, eps_g, theta_c);
    let outside = ClearanceTorque { yield_part: yield_torque(rheology, geometry.radius, geometry.length, 0.0), ..outside };
    if theta_c <= 0.0 {
        return (outside, 0.0);
    }
    let whole = clearance_torque_tabulated(table, rheology, geometry, sliding_speed, eps_g, 0.0);
    let flow = |t: &ClearanceTorque| t.power_law_part + t.newtonian_part;
    (outside, (flow(&whole) - flow(&outside)).max(0.0))
}

/// The shear rate U/c of the sliding speed's magnitude (1/s).
#[inline]
fn u_rate(sliding_speed: f64, clearance: f64) -> f64 {
    sliding_speed.abs() / clearance
}

/// The clearance torque (N·m): the sum of [`clearance_torque_parts`].
pub fn clearance_torque(rheology: &GreaseRheology, sliding_speed: f64, radius: f64, length: f64, clearance: f64, eps_g: f64, theta_c: f64) -> f64 {
    clearance_torque_parts(rheology, sliding_speed, radius, length, clearance, eps_g, theta_c).total()
}

/// The grease's yield torque at rest, τ_y (2π − 2θ_c) R² B (N·m): what the grease in the
/// clearance adds to the breakaway torque.
pub fn yield_torque(rheology: &GreaseRheology, radius: f64, length: f64, theta_c: f64) -> f64 {
    rheology.yield_stress * (2.0 * PI - 2.0 * theta_c.clamp(0.0, PI)) * radius * radius * length
}

