//! Integrated articulation mode: the paper's torsion-actuator rig (section 4) around the joint.
//!
//! A servo-hydraulic torsional actuator in angle control swings the pin through sine strokes
//! while the friction core gives the joint's torque at the current load and speed; at each
//! stroke end the joint may stick until the actuator torque exceeds the breakaway torque.
//!
//! - [`params`]: the `[rig]` constants, their equations and the reasoning for the defaults;
//!   [`config`]: one file with the model's sections and `[rig]`.
//! - [`excitation`]: command angle and load as functions of time, and held (FMU) inputs.
//! - [`dynamics`]: the ODE of each phase (slip, stick, regularised) and the friction torque.
//! - [`integrate`]: segments with `ode_solvers` (Dopri5, Dop853, RK4), event location.
//! - `linear_loop`: the loop linearised about a slip and its matrix exponential (modal form).
//! - `lawson`: Dopri5 in Lawson (integrating-factor) form, the linearised loop solved exactly
//!   (`dopri5-dense` in slip).
//! - `steady`: the loop's steady response to the sine command (`dopri5-dense` integrates the
//!   deviation from it).
//! - [`sim`]: [`RigSim`], the stepping simulator (state get/set, serialisation).
//! - [`analysis`]: the paper's cycle-average friction coefficient (eq. 11), energy balance.
//!
//! ```
//! use pinjoint::rig::{RigConfig, RigSim, cycle_average_friction_coefficient};
//! let mut cfg = RigConfig::default();
//! cfg.rig.frequency = 0.3;
//! let mut sim = RigSim::new(&cfg).unwrap();
//! let trace = sim.run(2.0 / 0.3, 1e-3 / 0.3).unwrap(); // two cycles, 1000 samples a cycle
//! let mu = cycle_average_friction_coefficient(&trace, 0.3, cfg.model.geometry.pin_radius, 1).unwrap();
//! assert!(mu > 0.1 && mu < 0.125, "{mu}");
//! ```

pub mod analysis;
pub mod config;
pub mod dynamics;
pub mod excitation;
pub mod integrate;
pub mod params;
pub mod record;
pub mod sim;
pub(crate) mod lawson;
pub(crate) mod linear_loop;
pub(crate) mod steady;

pub use analysis::{cycle_average_friction_coefficient, energy_residual, run_cycles};
pub use config::RigConfig;
pub use dynamics::Phase;
pub use excitation::{Excitation, FnExcitation, Inputs, SineCommand, SineDrive, StepLoad};
pub use params::{Formulation, Method, RigParams, RIG_PARAMS};
pub use sim::{Node, RigSim, RigState, Sample, Stats};

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
    /// A saved state given to [`RigSim::set_state`] is malformed, or a shared fidelity level was
    /// built for other model parameters.
    #[error("invalid rig state: {0}")]
    State(String),
    /// One advance took more integrator steps than [`sim::ADVANCE_STEP_LIMIT`].
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
    /// [`RigSim::run`] asked for more samples than it may hold (or a bad interval).
    #[error("sampling to t = {t_end} s every {interval} s needs more than {limit} samples or a bad interval (it must be a finite number > 0 s)")]
    Samples {
        /// End time of the run (s).
        t_end: f64,
        /// Sampling interval asked for (s).
        interval: f64,
        /// Largest number of samples allowed.
        limit: usize,
    },
    /// The fidelity level asked for could not be built ([`RigSim::set_fidelity`]).
    #[error(transparent)]
    Fidelity(#[from] crate::fidelity::FidelityError),
}
