//! What a scene cannot do, as a typed error naming the quantity, its value and unit.

use crate::fidelity::FidelityError;
use crate::joint::ModelError;
use crate::params::ParamError;
use thiserror::Error;

/// Why a free-fall scene could not be set up or run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SceneError {
    /// A scene parameter is outside its admissible range (or not a finite number).
    #[error("parameter scene.{name} = {v} {unit} is invalid: {rule}", v = crate::fmt::Num(*.value))]
    Invalid {
        /// The parameter's name in the `[scene]` table.
        name: &'static str,
        /// The rejected value, in `unit`.
        value: f64,
        /// Its SI unit ("" for a number).
        unit: &'static str,
        /// What it must be.
        rule: String,
    },
    /// The `[scene]` TOML text could not be read.
    #[error("the scene parameters could not be read: {0}")]
    Parse(String),
    /// The joint model refuses its parameters at this temperature (e.g. below the paper model's
    /// lowest admissible temperature): the scene was not run.
    #[error("the joint model refuses temperature = {t} K ({c} C): {source}", t = crate::fmt::Num(*.temperature), c = crate::fmt::Num(((*.temperature - 273.15) * 1e6).round() / 1e6))]
    Temperature {
        /// The temperature asked for (K).
        temperature: f64,
        /// The model's reason.
        source: ParamError,
    },
    /// The joint model's parameters are invalid (whatever the temperature).
    #[error("the joint's parameters are invalid: {0}")]
    Params(#[from] ParamError),
    /// The fidelity level could not be built for the scene's envelope.
    #[error("the joint's fidelity level could not be built: {0}")]
    Fidelity(FidelityError),
    /// The joint model has no answer at an operating point the leg reached (the run stops there).
    #[error(
        "the joint model has no answer at t = {t} s (angle = {a} rad, angular velocity = {w} rad/s, pin load = {p} N): {source}",
        t = crate::fmt::Num(*.time),
        a = crate::fmt::Num(*.angle),
        w = crate::fmt::Num(*.omega),
        p = crate::fmt::Num(*.load)
    )]
    Joint {
        /// Time of the step (s).
        time: f64,
        /// The leg's angle φ (rad).
        angle: f64,
        /// Its angular velocity ω (rad/s).
        omega: f64,
        /// The pin load P (N).
        load: f64,
        /// The model's reason.
        source: ModelError,
    },
    /// The integration left the finite numbers (a guard: the step limits of
    /// [`super::params::FreeFallParams::validate`] are meant to prevent it).
    #[error(
        "the integration is no longer finite after t = {t} s (angle = {a} rad, angular velocity = {w} rad/s, pin load = {p} N, friction torque = {f} N.m): reduce scene.step",
        t = crate::fmt::Num(*.time),
        a = crate::fmt::Num(*.angle),
        w = crate::fmt::Num(*.omega),
        p = crate::fmt::Num(*.load),
        f = crate::fmt::Num(*.friction)
    )]
    NotFinite {
        /// Time of the step (s).
        time: f64,
        /// The leg's angle φ at its start (rad).
        angle: f64,
        /// Its angular velocity ω (rad/s).
        omega: f64,
        /// The pin load P (N).
        load: f64,
        /// The trunnion friction torque (N·m).
        friction: f64,
    },
    /// The lock links' breakaway torque could not be evaluated.
    #[error("the lock links' breakaway torque at lock_link_load = {p} N has no answer: {source}", p = crate::fmt::Num(*.load))]
    Breakaway {
        /// The lock-link pivot load (N).
        load: f64,
        /// The model's reason.
        source: ModelError,
    },
}

impl SceneError {
    /// A [`FidelityError`] at the operating point (`time`, `angle`, `omega`, `load`): the
    /// model's error as [`SceneError::Joint`], anything else as [`SceneError::Fidelity`].
    pub(crate) fn at_point(e: FidelityError, time: f64, angle: f64, omega: f64, load: f64) -> Self {
        match e {
            FidelityError::Model(source) => SceneError::Joint { time, angle, omega, load, source },
            other => SceneError::Fidelity(other),
        }
    }
}
