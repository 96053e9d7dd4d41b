//! One parameter set at one temperature at a fidelity level: the sliding torque
//! T = μ(P, |ω|)·R·|P| (eq. 11) that bounds the presliding law, computed exactly as the
//! scalar front ends compute it.
//!
//! The scalar law is the `Presliding` object of the Python package and the PinJoint FMU's
//! step: the sliding torque of the cold complete solve ([`Joint::evaluate`], no warm start,
//! so the answer depends on the inputs alone), 0 for an unloaded joint; at the table,
//! boundary and auto levels the level's answer inside its envelope and the cold complete
//! solve elsewhere (the vectorised `Joint.evaluate` of the Python package). A [`Model`]
//! answers bit for bit as that scalar path, because it calls the same functions.

use super::error::BatchError;
use crate::fidelity::{Envelope, Evaluator, Fidelity, Level, Located, StribeckTable};
use crate::joint::{Joint, ModelError};

/// The fidelity a batch runs at: the level, its tolerance and its envelope (as the scalar
/// [`Evaluator::new`] takes them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// The level asked for (`Auto` resolves per parameter set and temperature).
    pub fidelity: Fidelity,
    /// Largest relative error accepted (table, boundary, auto).
    pub tolerance: f64,
    /// Loads (N) and speed magnitudes (rad/s) where table and boundary answer.
    pub envelope: Envelope,
}

impl Default for Settings {
    /// Full fidelity; tolerance 1e-4 and the envelope [`Envelope::SERVICE`] (1–100 kN,
    /// 0.01–100 rad/s and down to rest: the Python package's default for the complete model)
    /// for the other levels. For the paper's model take [`Envelope::default_for_all`] of the
    /// batch's parameter sets ([`Envelope::PAPER_RIG`]): its film passes the clearance at light
    /// loads and high speeds, where no table can be built.
    fn default() -> Self {
        Settings { fidelity: Fidelity::Full, tolerance: 1e-4, envelope: Envelope::SERVICE }
    }
}

impl Settings {
    /// Check the tolerance and envelope as [`Evaluator::new`] does.
    pub fn validate(&self) -> Result<(), BatchError> {
        crate::fidelity::validate_tolerance(self.tolerance).map_err(BatchError::Fidelity)?;
        self.envelope.validate().map_err(BatchError::Fidelity)
    }
}

/// The sliding torque of one parameter set at one temperature.
#[derive(Debug, Clone)]
pub struct Model {
    joint: Joint,
    /// The table or boundary level (None at full, and where auto chose full).
    level: Option<Evaluator>,
}

impl Model {
    /// `joint` (built at the temperature wanted) at the level of `settings`.
    pub fn build(joint: Joint, settings: &Settings) -> Result<Self, crate::fidelity::FidelityError> {
        if settings.fidelity == Fidelity::Full {
            return Ok(Model { joint, level: None });
        }
        let ev = Evaluator::with_joint(joint.clone(), settings.fidelity, settings.tolerance, settings.envelope)?;
        let level = (ev.chosen() != Level::Full).then_some(ev);
        Ok(Model { joint, level })
    }

    /// `joint` at the full level (the complete solve: a few logarithms to build), whatever
    /// the settings ask: for keys beyond the batch's budget of tables
    /// ([`super::cache::LEVELS_MAX`]).
    pub fn full(joint: Joint) -> Self {
        Model { joint, level: None }
    }

    /// Whether a table answers (the table level, or `auto`'s choice of it): what the batch's
    /// budget [`super::cache::LEVELS_MAX`] counts (a boundary level is a few numbers).
    pub fn has_table(&self) -> bool {
        self.level.as_ref().is_some_and(|ev| ev.chosen() == Level::Table)
    }

    /// The joint (its parameters, capacity and temperature).
    pub fn joint(&self) -> &Joint {
        &self.joint
    }

    /// The level in use (what auto chose).
    pub fn level(&self) -> Level {
        self.level.as_ref().map_or(Level::Full, Evaluator::chosen)
    }

    /// The sliding torque T(P, |ω|) (N·m) at `load` (N, its magnitude) and `omega` (rad/s):
    /// 0 for `load` = 0; the level inside its envelope, else the cold complete solve.
    /// Errors: a load at or beyond the asperity model's capacity, and every error of
    /// [`Joint::evaluate`]. The inputs must be finite (the batch checks them first).
    #[inline]
    pub fn sliding_torque(&self, load: f64, omega: f64) -> Result<f64, ModelError> {
        self.sliding_torque_located(load, omega, self.locate(load, omega))
    }

    /// Locate (`load`, `omega`) in the level ([`Evaluator::locate_torque`]: at the table
    /// level its cell, brought into the cache meanwhile), for
    /// [`Model::sliding_torque_located`].
    #[inline]
    pub fn locate(&self, load: f64, omega: f64) -> Located {
        self.level.as_ref().map_or(Located::OUTSIDE, |ev| ev.locate_torque(load, omega))
    }

    /// The table whose answers are this model's sliding torque wherever it gives one: at the
    /// table level of the complete model (whose film is not checked against the clearance:
    /// `Evaluator::torque_inside`), and only where the table's load range lies inside
    /// (0, [`Joint::capacity`]) (always: a table is built by solving beyond its range's ends),
    /// so that the model's own checks of the load pass wherever the table answers. Then
    /// `table.torque_located(|P|, ω, table.locate_torque(|P|, ω))`, when it is `Some`, is
    /// [`Model::sliding_torque`] bit for bit (what the level answers), and elsewhere
    /// [`Model::sliding_torque`] answers.
    #[inline]
    pub fn torque_table(&self) -> Option<&StribeckTable> {
        if self.joint.is_paper() {
            return None;
        }
        let table = self.level.as_ref().and_then(Evaluator::table)?;
        let range = table.envelope();
        (range.load_min > 0.0 && range.load_max < self.joint.capacity()).then_some(table)
    }

    /// [`Model::sliding_torque`] at (`load`, `omega`) located by [`Model::locate`] as `at`,
    /// bit for bit.
    #[inline]
    pub fn sliding_torque_located(&self, load: f64, omega: f64, at: Located) -> Result<f64, ModelError> {
        let capacity = self.joint.capacity();
        if load.abs() >= capacity {
            return Err(ModelError::BeyondCapacity { load: load.abs(), capacity });
        }
        if load == 0.0 {
            return Ok(0.0);
        }
        // The level's torque alone (bit for bit its evaluation's torque: `Evaluator::torque_inside`).
        if let Some(t) = self.level.as_ref().and_then(|ev| ev.torque_located(load, omega, at)) {
            return Ok(t);
        }
        self.joint.evaluate(load, omega).map(|op| op.torque)
    }
}
