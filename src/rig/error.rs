//! Why a rig simulation could not go on: [`RigError`], the error of every rig call.

use crate::params::ParamError;
use thiserror::Error;

/// Why a rig simulation could not go on.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RigError {
    /// A model or rig parameter was rejected.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The load input is NaN or infinite.
    #[error("load = {value} N at t = {time} s is invalid: it must be a finite number (its magnitude is the load)")]
    Load {
        /// Simulation time at which the load was given (s).
        time: f64,
        /// The rejected load (N).
        value: f64,
    },
    /// The command angle (rad) is NaN or infinite.
    #[error("command angle = {0} rad is invalid: it must be a finite number")]
    Command(f64),
    #[error("cannot advance from t = {now} s to t = {requested} s: time must be finite, at most 1e7 s (sim::MAX_TIME) and not go back")]
    /// The requested time is not finite, exceeds `sim::MAX_TIME`, or lies before the current time.
    Time {
        /// Current simulation time (s).
        now: f64,
        /// Time asked to advance to (s).
        requested: f64,
    },
    #[error("integration failed at t = {time} s: {message}")]
    /// The ODE integrator failed (step size underflow, non-finite state).
    Integration {
        /// Simulation time at the failure (s).
        time: f64,
        /// The integrator's description of the failure.
        message: String,
    },
    #[error("stick/slip chattering at t = {time} s: more than 1000 consecutive events within 10 event tolerances")]
    /// Stick and slip events alternate without the time advancing.
    Chatter {
        /// Simulation time at which the chattering was detected (s).
        time: f64,
    },
    /// A saved state given to [`RigSim::set_state`](super::RigSim::set_state) is malformed, or a shared fidelity level was
    /// built for other model parameters.
    #[error("invalid rig state: {0}")]
    State(String),
    /// One advance took more integrator steps than [`sim::ADVANCE_STEP_LIMIT`](super::sim::ADVANCE_STEP_LIMIT).
    #[error(
        "advancing to t = {requested} s stopped at t = {reached} s after {steps} integrator steps (the limit of one advance): \
         take shorter communication steps, or looser tolerances / a longer rk4_step"
    )]
    WorkLimit {
        /// Time asked to advance to (s).
        requested: f64,
        /// Time reached when the limit stopped the advance (s).
        reached: f64,
        /// Integrator steps taken in the advance.
        steps: u64,
    },
    /// The regularised formulation is stiff at this load: explicit steps are limited to about
    /// its creep time constant, and the advance needs more than the step budget.
    #[error(
        "advancing to t = {requested} s needs more than {limit} integrator steps (stopped at t = {reached} s): the regularised \
         formulation is stiff at load = {load} N (creep time constant J*omega_reg/(k_b*mu_c*R*P) = {time_constant} s bounds \
         the explicit step); use formulation = hybrid, raise rig.regularisation_speed, or take shorter communication steps"
    )]
    Stiff {
        /// Time asked to advance to (s).
        requested: f64,
        /// Time reached when the advance stopped (s).
        reached: f64,
        /// Load at which the formulation is stiff (N).
        load: f64,
        /// Creep time constant J·ω_reg/(k_b·μ_c·R·P) (s).
        time_constant: f64,
        /// The step budget of one advance.
        limit: u64,
    },
    /// The friction model has no answer at a load/speed the rig reached (e.g. a load beyond
    /// the asperity model's capacity, or one so small that the film overflows).
    #[error("friction model at t = {time} s (load = {load} N, speed = {speed} rad/s): {source}")]
    Model {
        /// Simulation time of the failure (s).
        time: f64,
        /// Load at that time (N).
        load: f64,
        /// Angular speed at that time (rad/s).
        speed: f64,
        /// The friction model's error.
        source: crate::joint::ModelError,
    },
    /// [`RigSim::run`](super::RigSim::run) asked for more samples than it may hold (or a bad interval).
    #[error("sampling to t = {t_end} s every {interval} s needs more than {limit} samples or a bad interval (it must be a finite number > 0 s)")]
    Samples {
        /// End time of the run (s).
        t_end: f64,
        /// Sampling interval asked for (s).
        interval: f64,
        /// Largest number of samples allowed.
        limit: usize,
    },
    /// The fidelity level asked for could not be built ([`RigSim::set_fidelity`](super::RigSim::set_fidelity)).
    #[error(transparent)]
    Fidelity(#[from] crate::fidelity::FidelityError),
}
