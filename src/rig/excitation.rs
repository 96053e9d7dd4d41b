//! What drives the rig: the command angle θ_cmd(t) and the radial load P(t).
//!
//! The built-in excitation is the paper's: θ_cmd = A·sin(2π f t) at a constant load. Any other
//! (a host simulation's load history, a recorded command) implements [`Excitation`]. Jumps in
//! either signal must be announced by [`Excitation::next_discontinuity`] so that the integrator
//! stops on them instead of stepping across them.

use std::f64::consts::TAU;
use std::sync::Arc;

/// Command and load as functions of time.
pub trait Excitation: Send + Sync {
    /// Radial load P(t) (N, finite, ≥ 0).
    fn load(&self, t: f64) -> f64;
    /// Command angle θ_cmd(t) (rad) and its rate θ̇_cmd(t) (rad/s).
    fn command(&self, t: f64) -> (f64, f64);
    /// The first time strictly after `t` at which the load or the command jumps (∞ if none).
    fn next_discontinuity(&self, _t: f64) -> f64 {
        f64::INFINITY
    }
    /// The command when it is exactly a [`SineCommand`] at all times (None otherwise): lets
    /// `Method::Dopri5Dense` integrate the deviation from the loop's steady response to it.
    fn sine(&self) -> Option<SineCommand> {
        None
    }
}

/// θ_cmd = A·sin(2π f t), θ̇_cmd = 2π f A·cos(2π f t).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SineCommand {
    /// Stroke amplitude A (rad).
    pub amplitude: f64,
    /// Stroke frequency f (Hz).
    pub frequency: f64,
}

impl SineCommand {
    /// The commanded angle (rad) and angular velocity (rad/s) at time `t` (s).
    pub fn at(&self, t: f64) -> (f64, f64) {
        let w = TAU * self.frequency;
        let (s, c) = crate::numerics::fast_math::sin_cos(w * t);
        (self.amplitude * s, self.amplitude * w * c)
    }
}

/// A piecewise-constant load: `initial` before the first step, `steps[i].1` from `steps[i].0` on.
#[derive(Debug, Clone, PartialEq)]
pub struct StepLoad {
    /// The load (N) before the first step.
    pub initial: f64,
    /// (time, load) pairs in increasing time.
    pub steps: Vec<(f64, f64)>,
}

impl StepLoad {
    /// A load that never changes (N).
    pub fn constant(load: f64) -> Self {
        Self { initial: load, steps: Vec::new() }
    }
    /// The load (N) at time `t` (s): the last step at or before `t`.
    pub fn at(&self, t: f64) -> f64 {
        self.steps.iter().rev().find(|(ts, _)| t >= *ts).map_or(self.initial, |s| s.1)
    }
    /// The time (s) of the first step after `t`, or +∞ if none.
    pub fn next_step(&self, t: f64) -> f64 {
        self.steps.iter().map(|s| s.0).find(|&ts| ts > t).unwrap_or(f64::INFINITY)
    }
}

/// The paper's excitation: a sine command and a (piecewise-constant) load.
#[derive(Debug, Clone, PartialEq)]
pub struct SineDrive {
    /// The angle command θ_cmd(t).
    pub command: SineCommand,
    /// The radial load P(t).
    pub load: StepLoad,
}

impl Excitation for SineDrive {
    fn load(&self, t: f64) -> f64 {
        self.load.at(t)
    }
    fn command(&self, t: f64) -> (f64, f64) {
        self.command.at(t)
    }
    fn next_discontinuity(&self, t: f64) -> f64 {
        self.load.next_step(t)
    }
    fn sine(&self) -> Option<SineCommand> {
        Some(self.command)
    }
}

/// Closures for the load and the command (e.g. a host's signals); `jumps` lists the times where
/// either is discontinuous.
pub struct FnExcitation<L, C> {
    /// The load P(t) (N).
    pub load: L,
    /// The command (θ_cmd, θ̇_cmd)(t) (rad, rad/s).
    pub command: C,
    /// Times (s) where the load or the command jumps; the integrator restarts there.
    pub jumps: Vec<f64>,
}

impl<L, C> Excitation for FnExcitation<L, C>
where
    L: Fn(f64) -> f64 + Send + Sync,
    C: Fn(f64) -> (f64, f64) + Send + Sync,
{
    fn load(&self, t: f64) -> f64 {
        (self.load)(t)
    }
    fn command(&self, t: f64) -> (f64, f64) {
        (self.command)(t)
    }
    fn next_discontinuity(&self, t: f64) -> f64 {
        self.jumps.iter().copied().filter(|&s| s > t).fold(f64::INFINITY, f64::min)
    }
}

/// Values a host (the FMU) sets at a communication point and holds until the next one
/// (zero-order hold). `None` leaves the underlying excitation's signal in place.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct Inputs {
    /// Radial load (N): its magnitude is the load (a signed reaction component is accepted).
    pub load: Option<f64>,
    /// Command angle (rad), held constant (θ̇_cmd = 0) over the step.
    pub command_angle: Option<f64>,
}

/// An excitation with held inputs laid over it.
#[derive(Clone)]
pub(crate) struct Held {
    pub base: Arc<dyn Excitation>,
    pub inputs: Inputs,
}

impl Excitation for Held {
    fn load(&self, t: f64) -> f64 {
        self.inputs.load.unwrap_or_else(|| self.base.load(t))
    }
    fn command(&self, t: f64) -> (f64, f64) {
        match self.inputs.command_angle {
            Some(a) => (a, 0.0),
            None => self.base.command(t),
        }
    }
    fn next_discontinuity(&self, t: f64) -> f64 {
        self.base.next_discontinuity(t)
    }
    fn sine(&self) -> Option<SineCommand> {
        if self.inputs.command_angle.is_some() { None } else { self.base.sine() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn sine_and_steps() {
        let c = SineCommand { amplitude: 0.5, frequency: 2.0 };
        let (a, r) = c.at(0.125); // quarter period
        assert!((a - 0.5).abs() < 1e-15 && r.abs() < 1e-12);
        let l = StepLoad { initial: 5e3, steps: vec![(1.0, 60e3), (2.0, 0.0)] };
        assert_eq!((l.at(0.5), l.at(1.0), l.at(3.0)), (5e3, 60e3, 0.0));
        assert_eq!((l.next_step(0.0), l.next_step(1.0), l.next_step(2.0)), (1.0, 2.0, f64::INFINITY));
    }
}
