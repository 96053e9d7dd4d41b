//! What the joint refuses: an operating point the model cannot take ([`ModelError`]), and for
//! the one-shot [`super::evaluate`] a rejected parameter set too ([`EvaluateError`]).

use thiserror::Error;

/// An operating point the model cannot take.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// The load (N) is not a finite number > 0.
    #[error("load = {} N is invalid: the load must be a finite number > 0 N", crate::fmt::Num(*.0))]
    Load(f64),
    /// The angular velocity (rad/s) is NaN or infinite.
    #[error("angular velocity = {} rad/s is invalid: it must be a finite number", crate::fmt::Num(*.0))]
    Speed(f64),
    /// The load exceeds what the asperity model (eq. 19) can carry at rest: the film
    /// thickness h_c would be ≤ 0.
    #[error(
        "load = {l} N is beyond the asperity model's capacity of {capacity:.6e} N for these parameters: \
         at rest eq. 19 would put the mean planes of the surfaces through each other (h_c <= 0)",
        l = crate::fmt::Num(*.load)
    )]
    BeyondCapacity {
        /// The load asked for (N).
        load: f64,
        /// The largest load the asperity model carries for these parameters (N).
        capacity: f64,
    },
    /// The paper's model only (`model.paper = true`): the central film would be thicker than
    /// the diametral clearance 2(R_b − R), the widest gap the bush leaves around the pin: the
    /// line-contact film of eq. 12 has left the geometry it was derived for (a lubricant too
    /// viscous for this speed and load: a low temperature, a high speed or a light load). The
    /// complete model hands the film to the journal bearing there ([`crate::composite`]).
    #[error(
        "the model gives film_thickness = {h} m at load = {l} N, angular velocity = {w} rad/s, more than the \
         diametral clearance 2(R_b - R) = {c} m the bush leaves around the pin: the line-contact film (eq. 12) \
         does not hold here (lubricant too viscous for this speed and load: temperature too low, speed too high or load too light)",
        h = crate::fmt::Num(*.film),
        c = crate::fmt::Num(*.limit),
        l = crate::fmt::Num(*.load),
        w = crate::fmt::Num(*.omega)
    )]
    FilmBeyondClearance {
        /// The central film thickness h_c the model gives (m).
        film: f64,
        /// The diametral clearance 2(R_b − R) (m).
        limit: f64,
        /// Load at the point (N).
        load: f64,
        /// Angular velocity at the point (rad/s).
        omega: f64,
    },
    /// A model quantity overflowed or became NaN at this operating point.
    #[error(
        "the model gives {quantity} = {value} at load = {l} N, angular velocity = {w} rad/s: \
         outside its numerical range for these parameters",
        l = crate::fmt::Num(*.load),
        w = crate::fmt::Num(*.omega)
    )]
    NotFinite {
        /// Name of the quantity that is not finite.
        quantity: &'static str,
        /// Its value (NaN or ±∞).
        value: f64,
        /// Load at the point (N).
        load: f64,
        /// Angular velocity at the point (rad/s).
        omega: f64,
    },
}

/// Why [`evaluate`](super::evaluate) failed: the parameters, or the operating point.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EvaluateError {
    /// The parameter set was rejected ([`Joint::new`](super::Joint::new)).
    #[error(transparent)]
    Params(#[from] crate::params::ParamError),
    /// The operating point was rejected ([`Joint::evaluate`](super::Joint::evaluate)).
    #[error(transparent)]
    Model(#[from] ModelError),
}
