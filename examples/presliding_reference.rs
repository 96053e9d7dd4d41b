//! The presliding law of the core library driven through a scene, as the PinJoint FMU drives
//! it under Co-Simulation: the reference the FMU (tests/fmu_harness/test_presliding_agreement.py)
//! and the Python package (python/tests/test_presliding.py) are held to, bit for bit.
//!
//! Reads CSV rows `angle,angular_velocity,load,step,sets_angle` (rad, rad/s, N, s, 0/1) from
//! standard input; the joint starts at rest at angle 0 with the default parameters and law.
//! For each row it prints `torque_before,torque_after,presliding_torque` in the shortest
//! round-trip form: the torque after the host set the inputs, after the step, and the state.
//! `sets_angle` = 1 means the host set the angle this step (from then on the angle drives the
//! state); 0 that it did not (then angular_velocity·step does, until the angle is set).

use pinjoint::zero_velocity::{Presliding, PreslidingJoint};
use pinjoint::{Joint, Params};
use std::io::{BufRead, Write};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let joint = Joint::new(&Params::default())?;
    let law = Presliding::default();
    let mut state = PreslidingJoint::new(law, 0.0);
    let mut driven = false;
    let out = std::io::stdout();
    let mut out = out.lock();
    for line in std::io::stdin().lock().lines() {
        let line = line?;
        let x: Vec<f64> = line.split(',').map(|s| s.trim().parse()).collect::<Result<_, _>>()?;
        let [angle, omega, load, step, sets] = x[..] else { return Err(format!("5 columns expected: {line}").into()) };
        driven |= sets == 1.0;
        let bound = if load == 0.0 { 0.0 } else { joint.evaluate(load, omega)?.torque };
        let before = if driven { state.torque_at(angle, omega, bound) } else { state.torque_at(state.reference_angle(), omega, bound) };
        if driven {
            state.commit(angle, bound);
        } else {
            state.advance(omega, step, bound);
            let reference = state.reference_angle() + omega * step;
            state.set_state(state.presliding_torque(), reference);
        }
        let after = state.torque_at(state.reference_angle(), omega, bound);
        writeln!(out, "{before:?},{after:?},{:?}", state.presliding_torque())?;
    }
    Ok(())
}
