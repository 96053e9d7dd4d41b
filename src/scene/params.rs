//! The free-fall scene's parameters: an illustrative narrow-body main gear (assumed, not from a
//! specific aircraft), with their admissible ranges.

use super::error::SceneError;
use crate::fidelity::Fidelity;
use serde::{Deserialize, Serialize};

/// Largest number of steps one run may take (end_time / step): bounds the run's time and the
/// memory of its time series (five numbers a step, 40 MB at the limit).
pub const MAX_STEPS: f64 = 1e6;

/// Largest number of trunnion pins or lock-link pivots.
pub const MAX_JOINTS: u32 = 16;

/// The scene: a main gear's leg released from the up position, swinging down about its trunnion
/// under gravity, slowed by the retraction actuator throttled as a damper, with a lock spring
/// near the down position. Every number is illustrative of a narrow-body main gear (assumed, not
/// from a specific aircraft; no published gear data is used).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FreeFallParams {
    /// m, the leg (strut, wheels, brakes), kg.
    pub leg_mass: f64,
    /// l, trunnion to the leg's centre of gravity, m.
    pub cg_distance: f64,
    /// J, the leg's moment of inertia about the trunnion, kg·m² (≥ m l²).
    pub inertia: f64,
    /// g, m/s².
    pub gravity: f64,
    /// φ_up, the release angle from the down-locked position, rad.
    pub up_angle: f64,
    /// c1, the actuator throttle's laminar part: torque −c1·ω, N·m·s/rad.
    pub damper_linear: f64,
    /// c2, the orifice part: torque −c2·ω·|ω|, N·m·s²/rad².
    pub damper_quadratic: f64,
    /// φ_e, the lock spring acts for φ < φ_e, rad.
    pub lock_spring_angle: f64,
    /// T_l, the lock spring's constant assist toward down for φ < φ_e, N·m.
    pub lock_spring_torque: f64,
    /// Share of the leg's reaction each trunnion pin carries (dimensionless, in [0, 1]).
    pub trunnion_load_share: f64,
    /// Number of trunnion pins, each giving the same friction torque (0: no trunnion friction).
    pub trunnion_joints: u32,
    /// The lock spring's torque about the lock-link pivots, driving them over centre, N·m.
    pub lock_link_torque: f64,
    /// Radial load on each lock-link pivot from the lock spring, N.
    pub lock_link_load: f64,
    /// Number of lock-link pivots the lock spring must turn.
    pub lock_link_pivots: u32,
    /// The joints' (grease's) temperature, K: the default of [`FreeFallParams::run`]. The damper
    /// is temperature-independent (a simplification of the scene, stated).
    pub temperature: f64,
    /// h, the step of the semi-implicit Euler integration, s.
    pub step: f64,
    /// t_max: the leg is reported not locked if φ > 0 then, s.
    pub end_time: f64,
    /// The fidelity of the joint's sliding torque (default `full`, the complete solve).
    pub fidelity: Fidelity,
    /// The relative error the `table`, `boundary` and `auto` fidelities are held to.
    pub tolerance: f64,
}

impl Default for FreeFallParams {
    fn default() -> Self {
        FreeFallParams {
            leg_mass: 600.0,
            cg_distance: 1.5,
            inertia: 1500.0,
            gravity: 9.81,
            up_angle: 1.4,
            damper_linear: 2000.0,
            damper_quadratic: 4000.0,
            lock_spring_angle: 0.087,
            lock_spring_torque: 300.0,
            trunnion_load_share: 0.5,
            trunnion_joints: 2,
            lock_link_torque: 40.0,
            lock_link_load: 1500.0,
            lock_link_pivots: 2,
            temperature: 293.15,
            step: 1e-3,
            end_time: 30.0,
            fidelity: Fidelity::Full,
            tolerance: 1e-4,
        }
    }
}

/// The `[scene]` table of a scene file, nothing else.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    #[serde(default)]
    scene: FreeFallParams,
}

impl FreeFallParams {
    /// Every parameter in its range, or the first that is not, named with its value and unit:
    /// m, l > 0; J ≥ m l² (a leg's inertia about the trunnion is at least its mass's at the
    /// centre of gravity); g, c1, c2, T_l, the lock-link torque ≥ 0; 0 < φ_up < π;
    /// 0 ≤ φ_e < π; the load share in [0, 1]; the lock-link load > 0; the temperature > 0 K
    /// (the joint model checks its own range); h > 0, t_max > 0 and t_max/h ≤ [`MAX_STEPS`];
    /// h at most the damper's relaxation time J/(c1 + 2 c2 ω_max) and half the pendulum's
    /// time scale √(J/(m g l));
    /// at most [`MAX_JOINTS`] pins and 1 to [`MAX_JOINTS`] lock-link pivots; tolerance > 0.
    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |name: &'static str, value: f64, unit: &'static str, rule: &str| Err(SceneError::Invalid { name, value, unit, rule: rule.into() });
        // The first of `fields` (name, value, unit) that is not finite or fails `ok`, refused with `rule`.
        let each = |fields: &[(&'static str, f64, &'static str)], ok: fn(f64) -> bool, rule: &str| {
            fields.iter().find(|&&(_, v, _)| !(v.is_finite() && ok(v))).map_or(Ok(()), |&(name, v, unit)| bad(name, v, unit, rule))
        };
        let positive = [
            ("leg_mass", self.leg_mass, "kg"),
            ("cg_distance", self.cg_distance, "m"),
            ("lock_link_load", self.lock_link_load, "N"),
            ("temperature", self.temperature, "K"),
            ("step", self.step, "s"),
            ("end_time", self.end_time, "s"),
            ("tolerance", self.tolerance, ""),
        ];
        each(&positive, |v| v > 0.0, "it must be a finite number > 0")?;
        let non_negative = [
            ("gravity", self.gravity, "m/s2"),
            ("damper_linear", self.damper_linear, "N.m.s/rad"),
            ("damper_quadratic", self.damper_quadratic, "N.m.s2/rad2"),
            ("lock_spring_torque", self.lock_spring_torque, "N.m"),
            ("lock_link_torque", self.lock_link_torque, "N.m"),
        ];
        each(&non_negative, |v| v >= 0.0, "it must be a finite number >= 0")?;
        let point_mass = self.leg_mass * self.cg_distance * self.cg_distance;
        if !(self.inertia.is_finite() && self.inertia >= point_mass) {
            return bad("inertia", self.inertia, "kg.m2", &format!("it must be a finite number >= leg_mass * cg_distance^2 = {} kg.m2", crate::fmt::Num(point_mass)));
        }
        if !(self.up_angle > 0.0 && self.up_angle < std::f64::consts::PI) {
            return bad("up_angle", self.up_angle, "rad", "it must be a number in (0, pi) rad");
        }
        if !(self.lock_spring_angle >= 0.0 && self.lock_spring_angle < std::f64::consts::PI) {
            return bad("lock_spring_angle", self.lock_spring_angle, "rad", "it must be a number in [0, pi) rad");
        }
        if !(0.0..=1.0).contains(&self.trunnion_load_share) {
            return bad("trunnion_load_share", self.trunnion_load_share, "", "it must be a number in [0, 1]");
        }
        if self.trunnion_joints > MAX_JOINTS {
            return bad("trunnion_joints", f64::from(self.trunnion_joints), "", &format!("it must be an integer in [0, {MAX_JOINTS}]"));
        }
        if !(1..=MAX_JOINTS).contains(&self.lock_link_pivots) {
            return bad("lock_link_pivots", f64::from(self.lock_link_pivots), "", &format!("it must be an integer in [1, {MAX_JOINTS}]"));
        }
        // The explicit steps must resolve the leg's fastest rates: the damper's relaxation
        // J/(c1 + 2 c2 ω_max) (ω_max the energy bound of `speed_bound`) and the pendulum's
        // √(J/(m g l)); beyond them semi-implicit Euler oscillates or diverges.
        let damping_rate = (self.damper_linear + 2.0 * self.damper_quadratic * self.speed_bound()) / self.inertia;
        // Every quantity is finite here (checked above).
        if self.step * damping_rate > 1.0 {
            return bad(
                "step",
                self.step,
                "s",
                &format!("it must be at most J/(c1 + 2 c2 w_max) = {} s, the damper's relaxation time (w_max = {} rad/s from energy)", crate::fmt::Num(1.0 / damping_rate), crate::fmt::Num(self.speed_bound())),
            );
        }
        let pendulum = (self.leg_mass * self.gravity * self.cg_distance / self.inertia).sqrt();
        if self.step * pendulum > 0.5 {
            return bad("step", self.step, "s", &format!("it must be at most 0.5 sqrt(J/(m g l)) = {} s, half the pendulum's time scale", crate::fmt::Num(0.5 / pendulum)));
        }
        let steps = (self.end_time / self.step).ceil();
        if steps > MAX_STEPS {
            return bad(
                "end_time",
                self.end_time,
                "s",
                &format!("end_time / step = {} steps at step = {} s; at most {MAX_STEPS:e} steps are allowed", crate::fmt::Num(steps), crate::fmt::Num(self.step)),
            );
        }
        Ok(())
    }

    /// A bound on the leg's speed |ω| (rad/s) from energy: ½Jω² ≤ m g l (1 − cos φ_up) +
    /// T_l·min(φ_e, φ_up) (friction and damper only take energy out).
    pub fn speed_bound(&self) -> f64 {
        let work = self.leg_mass * self.gravity * self.cg_distance * (1.0 - self.up_angle.cos()) + self.lock_spring_torque * self.lock_spring_angle.min(self.up_angle);
        (2.0 * work / self.inertia).sqrt()
    }

    /// The number of steps to the end time, ⌈t_max/h⌉ (the parameters valid).
    pub fn steps(&self) -> usize {
        (self.end_time / self.step).ceil() as usize
    }

    /// Parse a scene file: a `[scene]` table whose keys are this struct's fields (missing keys
    /// keep their defaults; `fidelity` is one of `full`, `table`, `boundary`, `auto`), checked.
    pub fn from_toml_str(text: &str) -> Result<Self, SceneError> {
        let f: SceneFile = toml::from_str(text).map_err(|e| SceneError::Parse(crate::params::parse_message(text, &e)))?;
        f.scene.validate()?;
        Ok(f.scene)
    }
}
