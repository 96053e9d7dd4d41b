//! The rig's equations of motion in each phase, and the friction torque from the core.
//!
//! State vector y = (θ, ω, T_a, W, D, t):
//! - θ (rad), ω (rad/s): pin angle and speed; T_a (N·m): actuator torque;
//! - W = ∫ T_a·ω dt (J): work done by the actuator on the rotating parts;
//! - D = ∫ −T_f·ω dt (J): energy dissipated by friction (T_f the friction torque on the pin);
//! - t itself (ṫ = 1), so that the system is autonomous: `ode_solvers` 0.6.2's Dop853 evaluates
//!   its 12th stage at x instead of x + h (its table has c₁₂ = 0, DOP853 has c₁₂ = 1), which
//!   ruins its error estimate for time-dependent right-hand sides (it then crawls at ~1e-6 s
//!   steps). With time as a state the method never uses its stage times.
//!
//! Energy balance: W − D = ½Jω² − ½Jω₀² exactly for the ODE, so the residual of the integrated
//! W, D and ω measures the integration error.
//!
//! Phases:
//! - `Slip(s)`, s = ±1: J ω̇ = T_a + T_f with T_f = −s·μ(P, max(s·ω, 0))·R·P. The friction is that
//!   of motion in direction s, extended continuously (μ(P, 0) = μ_c) past ω = 0 so that the
//!   integrator can step over the reversal, which is then located as an event (s·ω = 0).
//! - `Stick`: θ̇ = ω̇ = 0; only the actuator lag evolves; the joint reacts T_f = −T_a.
//! - `Smooth` (regularised formulation): T_f = −μ(P,|ω|)·R·P·tanh(ω/ω_reg), one ODE throughout.
//!
//! In every phase: T_d = clamp(K_p (θ_cmd − θ) + K_d (θ̇_cmd − ω), ±T_max), τ_s Ṫ_a = T_d − T_a.
//! Zero load means no contact and no friction (the core needs P > 0).

use super::excitation::Excitation;
use super::params::RigParams;
use crate::fidelity::{Evaluation, Evaluator, Source};
use crate::joint::{Joint, LoadTerms, ModelError};
use crate::load_sharing::start::StartCut;
use super::linear_loop::Loop;
use serde::{Deserialize, Serialize};
use std::cell::{Cell, RefCell};

pub use super::state::State;
pub(crate) use super::state::{physical, to_state, ANGLE, DISSIPATION, SPEED, TIME, TORQUE, WORK};

/// Which equations hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Phase {
    /// Sliding in direction `s` (+1 or −1).
    Slip(i8),
    /// ω = 0, |T_a| within the breakaway torque.
    Stick,
    /// The regularised formulation's single phase.
    Smooth,
}

/// The friction on the pin at one state.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Friction {
    /// Signed friction torque on the pin (N·m).
    pub torque: f64,
    /// The friction core's outputs (None at zero load).
    pub op: Option<Evaluation>,
}

/// The right-hand side for one phase.
pub(crate) struct Dynamics<'a> {
    pub joint: &'a Joint,
    pub rig: &'a RigParams,
    pub excitation: &'a dyn Excitation,
    pub phase: Phase,
    /// Warm start of the core's load-sharing solve (its last logit), for
    /// [`Self::operating_point`] (the table level's fallbacks).
    pub guess: Cell<f64>,
    /// The core's load terms at the last load met (the drive's load is often constant).
    pub load_terms: Cell<Option<LoadTerms>>,
    /// The start table cut at that load ([`Joint::friction_cut_at`]); the owner may hand a
    /// kept one in and take it back (its values depend on the load alone).
    pub cut: RefCell<Option<StartCut>>,
    /// The loop linearised at a load (`Method::Dopri5Dense`), kept as `cut` is.
    pub linear: Cell<Option<(f64, Loop)>>,
    /// First invalid load met (time, value); the derivative is NaN from then on.
    pub fault: Cell<Option<(f64, f64)>>,
    /// First friction evaluation the model could not answer (load, speed, why); the
    /// derivative is NaN from then on and the integration reports [`RigError::Model`].
    pub model_fault: RefCell<Option<(f64, f64, ModelError)>>,
    /// A table or boundary level answering inside its envelope (None: the full solve always).
    pub level: Option<&'a Evaluator>,
    /// Evaluations outside that level's envelope, answered by the full solve.
    pub fallbacks: Cell<u64>,
    /// Right-hand-side evaluations ([`Self::derivative`] calls).
    pub evaluations: Cell<u64>,
    /// Full friction solves ([`Self::torque`] without a level, [`Self::operating_point`] outside one).
    pub solves: Cell<u64>,
    /// Residual evaluations those solves took ([`crate::joint::Friction::evaluations`]).
    pub residuals: Cell<u64>,
}

impl<'a> Dynamics<'a> {
    pub fn new(joint: &'a Joint, rig: &'a RigParams, excitation: &'a dyn Excitation, phase: Phase, guess: f64) -> Self {
        Self {
            joint,
            rig,
            excitation,
            phase,
            guess: Cell::new(guess),
            load_terms: Cell::new(None),
            cut: RefCell::new(None),
            linear: Cell::new(None),
            fault: Cell::new(None),
            model_fault: RefCell::new(None),
            level: None,
            fallbacks: Cell::new(0),
            evaluations: Cell::new(0),
            solves: Cell::new(0),
            residuals: Cell::new(0),
        }
    }

    /// The load magnitude |P| at `t` (a negative value is a signed reaction component: its
    /// magnitude is the load), checked (Err with the value if not finite).
    pub fn load(&self, t: f64) -> Result<f64, f64> {
        let p = self.excitation.load(t);
        if p.is_finite() { Ok(p.abs()) } else { Err(p) }
    }

    /// The core at (P, speed ≥ 0): the fidelity level inside its envelope, else the full
    /// solve warm-started; None at zero load, and None (recorded in `model_fault`) where
    /// the model has no answer.
    pub fn operating_point(&self, load: f64, speed: f64) -> Option<Evaluation> {
        if load == 0.0 {
            return None;
        }
        // Inside the envelope, a table cell answered by the complete solve is no fallback.
        let mut fallback = false;
        if let Some(level) = self.level {
            if let Some(e) = level.evaluate_inside(load, speed) {
                return Some(e);
            }
            fallback = !level.table().is_some_and(|t| t.solved_at(load.abs(), speed));
            if fallback {
                self.fallbacks.set(self.fallbacks.get() + 1);
            }
        }
        let g = self.guess.get();
        self.solves.set(self.solves.get() + 1);
        let op = match self.joint.evaluate_from(load, speed, g.is_finite().then_some(g)) {
            Ok(op) => op,
            Err(e) => {
                let mut fault = self.model_fault.borrow_mut();
                if fault.is_none() {
                    *fault = Some((load, speed, e));
                }
                return None;
            }
        };
        if op.logit.is_finite() {
            self.guess.set(op.logit);
        }
        let source = if fallback { Source::Fallback } else { Source::Full };
        Some(Evaluation::from_point(&op, source))
    }

    /// The friction torque magnitude μ R P at (P, speed ≥ 0) for the equations of motion: the
    /// fidelity level inside its envelope, else the full solve from the start table cut at
    /// the load ([`Joint::friction_cut_at`]: the torque of [`Joint::evaluate`] to the solve's
    /// stopping rule, a function of (P, speed) alone), with the load terms and the cut kept
    /// while the load is unchanged. 0 at zero load; on a model error, 0 with the error
    /// recorded in `model_fault`, as [`Self::operating_point`].
    pub fn torque(&self, load: f64, speed: f64) -> f64 {
        if load == 0.0 {
            return 0.0;
        }
        if self.level.is_some() {
            return self.operating_point(load, speed).map_or(0.0, |o| o.torque);
        }
        let fail = |e: ModelError| {
            let mut fault = self.model_fault.borrow_mut();
            if fault.is_none() {
                *fault = Some((load, speed, e));
            }
            0.0
        };
        let mut cut = self.cut.borrow_mut();
        let lt = match (self.load_terms.get(), cut.as_mut()) {
            (Some(lt), Some(_)) if lt.load == load.abs() => lt,
            (_, c) => match self.joint.load_terms(load) {
                Ok(lt) => {
                    self.load_terms.set(Some(lt));
                    if let Some(c) = c {
                        self.joint.recut(c, &lt);
                    }
                    lt
                }
                Err(e) => return fail(e),
            },
        };
        let cut = cut.get_or_insert_with(|| self.joint.start_cut(&lt));
        self.solves.set(self.solves.get() + 1);
        match self.joint.friction_cut_at(&lt, cut, speed) {
            Ok(f) => {
                self.residuals.set(self.residuals.get() + u64::from(f.evaluations));
                f.torque
            }
            Err(e) => fail(e),
        }
    }

    /// Breakaway torque k_b·μ_c·R·P.
    pub fn breakaway_torque(&self, load: f64) -> f64 {
        self.rig.breakaway_factor * self.joint.boundary_torque(load)
    }

    /// Torque demand of the position loop, saturated, for the command (θ_cmd, θ̇_cmd) at the time.
    fn demand(&self, (cmd, rate): (f64, f64), angle: f64, speed: f64) -> f64 {
        let r = self.rig;
        (r.position_gain * (cmd - angle) + r.velocity_gain * (rate - speed)).clamp(-r.torque_limit, r.torque_limit)
    }

    /// Friction on the pin in this phase at (t, y) with load P.
    pub fn friction(&self, load: f64, y: &State) -> Friction {
        let w = y[SPEED];
        match self.phase {
            Phase::Slip(s) => {
                let s = f64::from(s);
                let op = self.operating_point(load, (s * w).max(0.0));
                Friction { torque: -s * op.map_or(0.0, |o| o.torque), op }
            }
            Phase::Stick => Friction { torque: -y[TORQUE], op: self.operating_point(load, 0.0) },
            Phase::Smooth => {
                let op = self.operating_point(load, w.abs());
                let t = op.map_or(0.0, |o| o.torque);
                Friction { torque: -t * (w / self.rig.regularisation_speed).tanh(), op }
            }
        }
    }

    /// The signed friction torque on the pin in this phase at (t, y) with load P, as
    /// [`Self::friction`]'s `torque` (to the solver tolerance: the operating point may start
    /// from the last root), without the operating point.
    pub fn friction_torque(&self, load: f64, y: &State) -> f64 {
        let w = y[SPEED];
        match self.phase {
            Phase::Slip(s) => {
                let s = f64::from(s);
                -s * self.torque(load, (s * w).max(0.0))
            }
            Phase::Stick => -y[TORQUE],
            Phase::Smooth => -self.torque(load, w.abs()) * (w / self.rig.regularisation_speed).tanh(),
        }
    }

    /// dy/dt. The time is taken from the state (y[TIME]), not from the integrator.
    pub fn derivative(&self, _t: f64, y: &State) -> State {
        self.derivative_commanded(y, self.excitation.command(y[TIME]))
    }

    /// [`Self::derivative`] with the command (θ_cmd, θ̇_cmd) at y[TIME] given (bit for bit
    /// `excitation.command(y[TIME])`, e.g. from the steady response's own sin/cos).
    pub fn derivative_commanded(&self, y: &State, command: (f64, f64)) -> State {
        self.evaluations.set(self.evaluations.get() + 1);
        let t = y[TIME];
        let load = match self.load(t) {
            Ok(p) => p,
            Err(p) => {
                if self.fault.get().is_none() {
                    self.fault.set(Some((t, p)));
                }
                return State::repeat(f64::NAN);
            }
        };
        let r = self.rig;
        let (w, ta) = (y[SPEED], y[TORQUE]);
        let torque_rate = (self.demand(command, y[ANGLE], w) - ta) / r.servo_time_constant;
        if self.phase == Phase::Stick {
            return State::from([0.0, 0.0, torque_rate, 0.0, 0.0, 1.0]);
        }
        let tf = self.friction_torque(load, y);
        if self.model_fault.borrow().is_some() {
            return State::repeat(f64::NAN);
        }
        State::from([w, (ta + tf) / r.inertia, torque_rate, ta * w, -tf * w, 1.0])
    }
}

impl ode_solvers::System<f64, State> for &Dynamics<'_> {
    fn system(&self, t: f64, y: &State, dy: &mut State) {
        *dy = self.derivative(t, y);
    }
}
