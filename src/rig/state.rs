//! The rig's integrated state vector: the five physical values (angle, speed, actuator
//! torque, actuator work, friction dissipation) and the time, with their indices. Its own
//! file so that the linearised loop (`linear_loop`) and the phase equations (`dynamics`)
//! can both use it without using each other.

/// The integrated state: angle, speed, actuator torque, actuator work, friction dissipation, time.
pub type State = ode_solvers::SVector<f64, 6>;
/// Index in [`State`] of θ, the pin's angle (rad).
pub(crate) const ANGLE: usize = 0;
/// Index in [`State`] of ω, the pin's speed (rad/s).
pub(crate) const SPEED: usize = 1;
/// Index in [`State`] of T_a, the actuator torque (N·m).
pub(crate) const TORQUE: usize = 2;
/// Index in [`State`] of W, the actuator's work (J).
pub(crate) const WORK: usize = 3;
/// Index in [`State`] of D, the friction's dissipation (J).
pub(crate) const DISSIPATION: usize = 4;
/// Index in [`State`] of t, the time (s).
pub(crate) const TIME: usize = 5;

/// The integrated state from the five physical values and the time.
pub(crate) fn to_state(v: &[f64; 5], t: f64) -> State {
    State::from([v[0], v[1], v[2], v[3], v[4], t])
}

/// The five physical values of a state.
pub(crate) fn physical(y: &State) -> [f64; 5] {
    [y[0], y[1], y[2], y[3], y[4]]
}
