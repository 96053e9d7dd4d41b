//! The `boundary` level: μ = μ_c, the fluid carrying nothing (with the complete model, plus
//! the grease's yield torque at rest over R·P: the rest state's torque at any speed).
//!
//! Valid where the fluid's share of the load is negligible. The answer at any speed is
//! the rest state of the same load: μ = μ_c (exact at ω = 0), 1/γ1 = 0, 1/γ2 = 1, and the
//! film h_c of the rest solution (eq. 19 alone), from the 1-D rest table. Its error grows
//! with speed (the fluid's share 1/γ1 grows roughly like ω in the boundary regime) and
//! falls with load, so over an envelope it is largest near the fast, light corner — or, if
//! the envelope reaches past the Stribeck minimum, near that minimum.
//!
//! # Error measurement
//! The level is compared with the complete solve on a 17 × 49 grid uniform in
//! (ln P, ln |ω|) that includes the envelope's edges and corners, then on a 9 × 9 grid
//! spanning the two grid steps around the worst point, which pins an interior maximum.
//! The errors are smooth in (ln P, ln |ω|); the advertised bound is [`SAFETY`] × the
//! largest measured error.

use super::check::ErrorReport;
use super::envelope::{lerp_log, solve_at, Envelope};
use super::error::FidelityError;
use super::evaluation::{Evaluation, Source};
use super::rest::RestTable;
use super::table::{rest_evaluation, rest_torque};
use crate::composite::RestYield;
use crate::joint::Joint;

/// Advertised bound = `SAFETY` × the largest measured error.
pub const SAFETY: f64 = 1.25;
const GRID_LOADS: usize = 17;
const GRID_SPEEDS: usize = 49;
const LOCAL: usize = 9;

/// The boundary level over an envelope.
#[derive(Debug, Clone)]
pub struct BoundaryLevel {
    envelope: Envelope,
    rest: RestTable,
    rest_yield: RestYield,
    mu_c: f64,
    radius: f64,
    roughness: f64,
    report: ErrorReport,
}

impl BoundaryLevel {
    /// Build the rest table (h_c to `film_target` relative) and measure the level's error
    /// over `envelope` against the complete solve.
    pub fn build(joint: &Joint, envelope: &Envelope, film_target: f64) -> Result<Self, FidelityError> {
        let p = joint.params();
        let rest = RestTable::build(joint, envelope.load_min, envelope.load_max, film_target)?;
        let mut level = Self {
            envelope: *envelope,
            rest,
            rest_yield: joint.rest_yield(),
            mu_c: p.friction.boundary_friction_coefficient,
            radius: p.geometry.pin_radius,
            roughness: joint.composite_roughness(),
            report: ErrorReport::default(),
        };
        level.report = level.measure(joint)?;
        Ok(level)
    }

    fn measure(&self, joint: &Joint) -> Result<ErrorReport, FidelityError> {
        let env = &self.envelope;
        let mut report = ErrorReport::default();
        let (mut worst, mut wa, mut wb) = (-1.0, 0, 0);
        for a in 0..GRID_LOADS {
            let load = lerp_log(env.load_min, env.load_max, a as f64 / (GRID_LOADS - 1) as f64);
            let mut guess = None;
            for b in 0..GRID_SPEEDS {
                let omega = lerp_log(env.speed_min, env.speed_max, b as f64 / (GRID_SPEEDS - 1) as f64);
                let op = solve_at(joint, load, omega, guess)?;
                guess = Some(op.logit);
                let e = report.add(&self.interior(load, omega), &op);
                if e > worst {
                    (worst, wa, wb) = (e, a, b);
                }
            }
        }
        // Local grid over the two steps around the worst point, in fractions of the envelope.
        let (fa, fb) = (wa as f64 / (GRID_LOADS - 1) as f64, wb as f64 / (GRID_SPEEDS - 1) as f64);
        let (da, db) = (1.0 / (GRID_LOADS - 1) as f64, 1.0 / (GRID_SPEEDS - 1) as f64);
        for a in 0..LOCAL {
            let load = lerp_log(env.load_min, env.load_max, fa - da + 2.0 * da * a as f64 / (LOCAL - 1) as f64);
            for b in 0..LOCAL {
                let omega = lerp_log(env.speed_min, env.speed_max, fb - db + 2.0 * db * b as f64 / (LOCAL - 1) as f64);
                let op = solve_at(joint, load, omega, None)?;
                report.add(&self.interior(load, omega), &op);
            }
        }
        let rest_error = self.rest.measured_error();
        report.film_thickness = report.film_thickness.max(rest_error);
        Ok(report)
    }

    #[inline(always)]
    fn interior(&self, load: f64, omega: f64) -> Evaluation {
        let h = self.rest.film_clamped(load);
        let mut e = rest_evaluation(load, h, self.mu_c, self.radius, self.roughness, &self.rest_yield, Source::Boundary);
        e.angular_velocity = omega;
        e
    }

    /// The boundary answer, or `None` outside the envelope (ω = 0 with the load in range
    /// is the rest state, answered exactly for μ).
    #[inline]
    pub fn evaluate(&self, load: f64, omega: f64) -> Option<Evaluation> {
        if self.envelope.contains(load, omega) {
            Some(self.interior(load, omega))
        } else if omega == 0.0 && self.envelope.contains_load(load) {
            let h = self.rest.film(load)?;
            Some(rest_evaluation(load, h, self.mu_c, self.radius, self.roughness, &self.rest_yield, Source::Rest))
        } else {
            None
        }
    }

    /// The sliding torque (N·m) of [`Self::evaluate`] at (`load` > 0, `omega`), bit for bit its
    /// `torque`, without the film; `None` where [`Self::evaluate`] is.
    #[inline]
    pub fn torque(&self, load: f64, omega: f64) -> Option<f64> {
        let inside = self.envelope.contains(load, omega) || (omega == 0.0 && self.envelope.contains_load(load) && self.rest.contains(load));
        inside.then(|| rest_torque(load, self.mu_c, self.radius, &self.rest_yield))
    }

    /// Largest errors measured against the complete solve over the envelope.
    pub fn measured(&self) -> &ErrorReport {
        &self.report
    }

    /// The advertised bound: [`SAFETY`] × the largest measured error.
    pub fn error_bound(&self) -> f64 {
        SAFETY * self.report.max()
    }
}
