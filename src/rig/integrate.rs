//! Integrating one phase with `ode_solvers`, stopping at the first event, and locating it.
//!
//! A *segment* runs the chosen method from a node (t₀, y₀) towards t₁ and keeps every accepted
//! step as a node. After each accepted step `solout` tests the phase's event predicate; the
//! first node where it holds stops the run. The event time is then located inside the last
//! step by the Illinois (modified regula falsi) method, each trial state being one
//! *re-integration* from the step's start node to the trial time: for a one-step method a
//! shorter step from the same node is as accurate as the accepted one, so event states and
//! output states have the method's own accuracy (no lower-order interpolant, and Dop853 keeps
//! its 8th order although `ode_solvers` 0.6 does not expose its dense output). Event times are
//! located to `event_tolerance` and the state returned is the one just *past* the event, where
//! the predicate holds — so a breakaway always starts with |T_a| above the breakaway torque and
//! a stick never starts with the speed still in the old direction (no chattering).
//!
//! `Dopri5Dense` runs Dopri5 in slip phases on u = (y − y_s(t))/scale, the deviation from the
//! loop's steady response to the sine command (`rig/steady.rs`; an exact change of
//! variables, taken when the excitation is a sine), and keeps each step's continuous extension
//! (order 4, `ode_solvers`' continuous output model): the trial states of event location, and
//! the simulator's states between nodes, are read from it instead of re-integrated.
//!
//! RK4 takes uniform steps of at most `rk4_step`, the step shortened so the segment end is hit.
//!
//! # Bounded work and memory
//! A segment keeps at most [`MAX_SEGMENT_NODES`] accepted steps: when that many are taken
//! before t₁ (a stiff phase, a tiny `rk4_step` in a long segment) the segment simply ends at
//! its last node and the next one starts there, so memory is bounded by what is kept
//! (≤ 14.7 MB; `Dopri5Dense` also keeps each step's five interpolation vectors in
//! `ode_solvers`' model, ≈ 300 B a step with their allocations: ≤ 80 MB), never by span/step. Step attempts (accepted + rejected) of the adaptive methods
//! are bounded by [`MAX_SEGMENT_ATTEMPTS`]. The caller ([`super::sim::RigSim`]) bounds the
//! number of segments per call, so one call does bounded work.

use super::dynamics::{Dynamics, Phase, State, TIME};
use super::excitation::SineCommand;
use super::lawson::{self, LawsonDense};
use super::linear_loop::{Loop, Propagator};
use super::steady::Steady;
use super::params::{Method, RigParams};
use super::RigError;
use ode_solvers::continuous_output_model::ContinuousOutputModel;
use ode_solvers::{Dop853, Dopri5, OutputType, Rk4, System};

/// The continuous extension of a segment's accepted steps ([`Method::Dopri5Dense`]), with the
/// change of variables back to y (see `rig/steady.rs`).
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)] // one per segment, a few hundred bytes either way
pub(crate) enum Dense {
    /// `ode_solvers`' Dopri5 model in the integrated variables u = (y − shift)/scale.
    Model { model: ContinuousOutputModel<f64, State>, shift: Option<Steady> },
    /// The Lawson form's (`rig/lawson.rs`), in the deviations z = y − y_s.
    Lawson { dense: LawsonDense, shift: Steady },
}

impl Dense {
    /// The state y at `t` (within the steps integrated), its time component exactly `t`.
    pub fn evaluate(&self, t: f64) -> Option<State> {
        let mut y = match self {
            Dense::Model { model, shift } => {
                let u = model.evaluate(t)?;
                shift.map_or(u, |s| s.state_of(t, &u))
            }
            Dense::Lawson { dense, shift } => dense.evaluate(t)? + shift.at(t).0,
        };
        y[TIME] = t;
        Some(y)
    }
}

/// For [`Method::Dopri5Dense`] in a slip (or the regularised) phase driven by a sine command:
/// the linearised loop's steady response to integrate the deviation from, with the constant
/// part of the friction, s·μ_c·R·P at the load at `t0`, and its linear part in the speed
/// (see `rig/steady.rs`), and that loop. None otherwise.
fn steady(rig: &RigParams, d: &Dynamics, t0: f64) -> Option<(Steady, Loop)> {
    if rig.method != Method::Dopri5Dense {
        return None;
    }
    let command = d.excitation.sine()?;
    let load = d.load(t0).ok()?;
    let (torque, lin) = match d.phase {
        Phase::Slip(s) => (f64::from(s) * d.joint.boundary_torque(load), linearised(rig, d, load, command)),
        Phase::Smooth => (0.0, Loop::new(rig, 0.0)),
        Phase::Stick => return None,
    };
    let st = Steady::new(rig, command, torque, &lin);
    st.scale.iter().all(|x| x.is_finite()).then_some((st, lin))
}

/// The loop linearised about a slip at `load` ([`Loop`]): d from the friction's secant from
/// rest to the command's peak speed, kept in `d.linear` for the load; d = 0 where the model
/// has no answer there or where the loop with d would not decay (the friction rising enough
/// with speed to destabilise it).
fn linearised(rig: &RigParams, d: &Dynamics, load: f64, command: SineCommand) -> Loop {
    if let Some((p, lin)) = d.linear.get()
        && p == load
    {
        return lin;
    }
    let w_ref = std::f64::consts::TAU * command.frequency * command.amplitude.abs();
    let slope = match d.joint.evaluate(load, w_ref) {
        Ok(op) if load > 0.0 && w_ref > 0.0 => -(op.torque - d.joint.boundary_torque(load)) / w_ref,
        _ => 0.0,
    };
    let lin = Some(Loop::new(rig, if slope.is_finite() { slope } else { 0.0 })).filter(Loop::decays).unwrap_or_else(|| Loop::new(rig, 0.0));
    d.linear.set(Some((load, lin)));
    lin
}

/// The accepted steps of one segment.
#[derive(Debug, Clone)]
pub(crate) struct Run {
    /// (t, y) at the start and after every accepted step; the last one is where the run stopped.
    pub nodes: Vec<(f64, State)>,
    /// Whether the event predicate stopped the run (it holds at the last node).
    pub stopped: bool,
    /// Step size to start the next segment with.
    pub h_next: f64,
    /// [`Method::Dopri5Dense`]: the continuous extension over every accepted step.
    pub dense: Option<Dense>,
}

/// Adapter giving `ode_solvers` the right-hand side and the stop test.
struct Stepper<'a, 'b> {
    dynamics: &'a Dynamics<'b>,
    outside: &'a dyn Fn(f64, &State) -> bool,
    hit: &'a mut bool,
    /// Accepted steps so far; the run stops (`full`) at [`MAX_SEGMENT_NODES`].
    accepted: usize,
    full: &'a mut bool,
    /// The change of variables y = y_s(t) + scale·u, when the integrated state is u.
    shift: Option<Steady>,
}

impl System<f64, State> for Stepper<'_, '_> {
    fn system(&self, t: f64, y: &State, dy: &mut State) {
        *dy = match &self.shift {
            None => self.dynamics.derivative(t, y),
            Some(s) => {
                // The time is the state's own (unshifted, unscaled) component.
                let tt = y[TIME];
                let (ys, rate, command) = s.at_with_command(tt);
                (self.dynamics.derivative_commanded(&(y.component_mul(&s.scale) + ys), command) - rate).component_div(&s.scale)
            }
        };
    }
    fn solout(&mut self, t: f64, y: &State, _dy: &State) -> bool {
        let y = self.shift.map_or(*y, |s| s.state_of(y[TIME], y));
        if (self.outside)(t, &y) {
            *self.hit = true;
        }
        self.accepted += 1;
        if self.accepted >= MAX_SEGMENT_NODES {
            *self.full = true;
        }
        *self.hit || *self.full
    }
}

fn check(d: &Dynamics, t: f64, y: &State) -> Result<(), RigError> {
    if let Some((tf, p)) = d.fault.get() {
        return Err(RigError::Load { time: tf, value: p });
    }
    if let Some((load, speed, source)) = d.model_fault.borrow().clone() {
        return Err(RigError::Model { time: t, load, speed, source });
    }
    if y.iter().any(|v| !v.is_finite()) {
        return Err(RigError::Integration { time: t, message: "non-finite state".into() });
    }
    Ok(())
}

/// Most accepted steps (nodes after the first) one segment keeps; a segment that reaches it
/// ends there (see the module documentation). 262,144 nodes of 7 f64: 14.7 MB. A default 0.05 s
/// segment creeping throughout at 60 kN (regularised, steps ≈ the 0.25 µs creep time constant)
/// needs ≈ 2e5 steps, below it (an estimate, not a measurement).
pub const MAX_SEGMENT_NODES: usize = 1 << 18;
/// Most step attempts (accepted and rejected) of one adaptive run.
pub const MAX_SEGMENT_ATTEMPTS: u32 = 4 * MAX_SEGMENT_NODES as u32;
/// Relative time span below which a step is taken by forward Euler.
pub(crate) const TINY: f64 = 1e-10;

/// Integrate from (t0, y0) to t1 with `h0` as first step (0: automatic), stopping at the first
/// accepted step where `outside` holds.
pub(crate) fn segment(
    rig: &RigParams,
    d: &Dynamics,
    t0: f64,
    y0: State,
    t1: f64,
    h0: f64,
    outside: &dyn Fn(f64, &State) -> bool,
) -> Result<Run, RigError> {
    let span = t1 - t0;
    let mut y0 = y0;
    y0[TIME] = t0;
    let mut hit = false;
    let mut dense = None;
    let nodes: Vec<(f64, State)> = match rig.method {
        Method::Rk4 => {
            // `as` saturates; span ≤ segment_length and rk4_step ≥ its minimum keep n ≤ 1e9.
            let n = ((span / rig.rk4_step) * (1.0 - 1e-12)).ceil().max(1.0) as usize;
            let kept = n.min(MAX_SEGMENT_NODES);
            let mut nodes = Vec::with_capacity(kept + 1);
            nodes.push((t0, y0));
            let (mut ta, mut ya) = (t0, y0);
            for k in 1..=kept {
                let tb = if k == n { t1 } else { t0 + span * (k as f64 / n as f64) };
                let yb = sub_step(rig, d, ta, ya, tb)?;
                nodes.push((tb, yb));
                (ta, ya) = (tb, yb);
                if outside(tb, &yb) {
                    hit = true;
                    break;
                }
            }
            nodes
        }
        Method::Dopri5 | Method::Dop853 | Method::Dopri5Dense => {
            let h = h0.min(span).max(0.0);
            let mut full = false;
            let linear = steady(rig, d, t0);
            let lawson = linear.and_then(|(st, lin)| matches!(d.phase, Phase::Slip(_)).then(|| Propagator::new(&lin).map(|p| (st, lin, p))).flatten());
            let fail = |message: String| match check(d, t0, &y0) {
                Err(e) => e,
                Ok(()) => RigError::Integration { time: t0, message },
            };
            let (xs, ys, model) = match lawson {
                Some((st, lin, p)) => lawson_run(rig, d, (st, lin, p), (t0, y0), t1, h, span, outside, (&mut hit, &mut full)).map_err(fail)?,
                None => {
                    // A deviation below the tolerance is not worth a free response.
                    let shift = linear.map(|(st, lin)| st.with_free_response(&lin, t0, &y0, rig.rtol.min(rig.atol)));
                    let stepper = Stepper { dynamics: d, outside, hit: &mut hit, accepted: 0, full: &mut full, shift };
                    adaptive(rig, stepper, t0, y0, t1, h, span).map_err(|e| fail(e.to_string()))?
                }
            };
            dense = model;
            let mut nodes: Vec<(f64, State)> = xs.into_iter().zip(ys).collect();
            if !hit && !full {
                // The last step was aimed at t1; remove rounding in its time.
                if let Some(last) = nodes.last_mut() {
                    last.0 = t1;
                }
            }
            nodes
        }
    };
    let Some(&(t_last, y_last)) = nodes.last() else {
        return Err(RigError::Integration { time: t0, message: "no step taken".into() });
    };
    check(d, t_last, &y_last)?;
    let n = nodes.len();
    let h_next = match n {
        0 | 1 => 0.0,
        2 => nodes[1].0 - nodes[0].0,
        _ => (nodes[n - 1].0 - nodes[n - 2].0).max(nodes[n - 2].0 - nodes[n - 3].0),
    };
    Ok(Run { nodes, stopped: hit, h_next, dense })
}

/// A slip segment of [`Method::Dopri5Dense`] in Lawson form (`rig/lawson.rs`): the deviation
/// z = y − y_s from the linearised loop's steady response `st`, the loop `lin` (propagator
/// `p`) solved exactly; same tolerances, bounds and stop test as [`adaptive`].
#[allow(clippy::too_many_arguments)]
fn lawson_run(
    rig: &RigParams,
    d: &Dynamics,
    (st, lin, p): (Steady, Loop, Propagator),
    (t0, y0): (f64, State),
    t1: f64,
    h: f64,
    h_max: f64,
    outside: &dyn Fn(f64, &State) -> bool,
    (hit, full): (&mut bool, &mut bool),
) -> Result<Accepted, String> {
    // F(t, z) = f(t, y_s + z) − ẏ_s − Lz; the time is z's own component.
    let mut remainder = |_: f64, z: &State| {
        let tt = z[TIME];
        let (ys, rate, command) = st.at_with_command(tt);
        let mut y = z + ys;
        y[TIME] = tt;
        let mut r = d.derivative_commanded(&y, command) - rate;
        let lz = lin.apply_matrix(&[z[0], z[1], z[2]]);
        for i in 0..3 {
            r[i] -= lz[i];
        }
        r
    };
    let mut accepted = 0usize;
    let mut stop = |t: f64, z: &State| {
        let mut y = z + st.at(t).0;
        y[TIME] = t;
        if outside(t, &y) {
            *hit = true;
        }
        accepted += 1;
        if accepted >= MAX_SEGMENT_NODES {
            *full = true;
        }
        *hit || *full
    };
    let mut z0 = y0 - st.at(t0).0;
    z0[TIME] = t0;
    let ctl = lawson::Control { rtol: rig.rtol, atol: rig.atol, scale: st.scale, h_max, max_attempts: MAX_SEGMENT_ATTEMPTS };
    let (ts, zs, dense) = lawson::integrate(&p, &mut remainder, t0, z0, t1, h, &ctl, &mut stop)?;
    let mut ys: Vec<State> = ts.iter().zip(&zs).map(|(&t, z)| {
        let mut y = z + st.at(t).0;
        y[TIME] = t;
        y
    }).collect();
    ys[0] = y0;
    Ok((ts, ys, Some(Dense::Lawson { dense, shift: st })))
}

/// Accepted (t, y) of one adaptive run, with the continuous extension for [`Method::Dopri5Dense`].
type Accepted = (Vec<f64>, Vec<State>, Option<Dense>);

/// Run Dopri5 or Dop853 in sparse mode (Dopri5Dense: with its continuous output model);
/// returns the accepted (t, y), the start included.
fn adaptive(
    rig: &RigParams,
    f: Stepper,
    t0: f64,
    y0: State,
    t1: f64,
    h: f64,
    h_max: f64,
) -> Result<Accepted, ode_solvers::dop_shared::IntegrationError> {
    // n_stiff = u32::MAX disables the stiffness abort: the regularised formulation is stiff by
    // design and must be integrated anyway (with small steps).
    match rig.method {
        Method::Dopri5 => {
            let mut s = Dopri5::from_param(
                f, t0, t1, 0.0, y0, rig.rtol, rig.atol, 0.9, 0.04, 0.2, 10.0, h_max, h, MAX_SEGMENT_ATTEMPTS, u32::MAX, OutputType::Sparse,
            );
            s.integrate()?;
            Ok((s.x_out().clone(), s.y_out().clone(), None))
        }
        Method::Dopri5Dense => {
            // The same method and controller as Dopri5 (the same accepted steps); the continuous
            // mode keeps every step's interpolation coefficients and, unlike the sparse mode,
            // does not record the start point.
            let shift = f.shift;
            let u0 = shift.map_or(y0, |st| st.deviation_of(t0, &y0));
            let mut s = Dopri5::from_param(
                f, t0, t1, 0.0, u0, rig.rtol, rig.atol, 0.9, 0.04, 0.2, 10.0, h_max, h, MAX_SEGMENT_ATTEMPTS, u32::MAX, OutputType::Continuous,
            );
            let mut model = ContinuousOutputModel::new();
            s.integrate_with_continuous_output_model(&mut model)?;
            let mut xs = Vec::with_capacity(s.x_out().len() + 1);
            xs.push(t0);
            xs.extend_from_slice(s.x_out());
            let mut ys = Vec::with_capacity(xs.len());
            ys.push(y0);
            ys.extend(s.y_out().iter().map(|u| shift.map_or(*u, |st| st.state_of(u[TIME], u))));
            Ok((xs, ys, Some(Dense::Model { model, shift })))
        }
        _ => {
            let mut s = Dop853::from_param(
                f, t0, t1, 0.0, y0, rig.rtol, rig.atol, 0.9, 0.0, 0.333, 6.0, h_max, h, MAX_SEGMENT_ATTEMPTS, u32::MAX, OutputType::Sparse,
            );
            s.integrate()?;
            Ok((s.x_out().clone(), s.y_out().clone(), None))
        }
    }
}

/// The state at t1 ≥ t0 by one step of the method from (t0, y0) (an adaptive method may split
/// it if its error test rejects the full step).
pub(crate) fn sub_step(rig: &RigParams, d: &Dynamics, t0: f64, y0: State, t1: f64) -> Result<State, RigError> {
    // Dopri5Dense re-integrates (event location) exactly as Dopri5.
    let rig = &RigParams { method: if rig.method == Method::Dopri5Dense { Method::Dopri5 } else { rig.method }, ..*rig };
    let h = t1 - t0;
    let mut y0 = y0;
    y0[TIME] = t0;
    if h <= 0.0 {
        return Ok(y0);
    }
    if h <= TINY * t0.abs().max(1.0) {
        // Below what an adaptive method can take at this t (it would report a step-size
        // underflow): one Euler step, error O(h²·|y''|) far below any tolerance.
        let y = y0 + d.derivative(t0, &y0) * h;
        check(d, t1, &y)?;
        return Ok(y);
    }
    let y = match rig.method {
        Method::Rk4 => {
            let mut s = Rk4::new(d, t0, y0, t1, h);
            s.integrate().map_err(|e| RigError::Integration { time: t0, message: e.to_string() })?;
            *s.y_out().last().ok_or_else(|| RigError::Integration { time: t0, message: "no step taken".into() })?
        }
        _ => {
            let never = |_: f64, _: &State| false;
            let (mut hit, mut full) = (false, false);
            let stepper = Stepper { dynamics: d, outside: &never, hit: &mut hit, accepted: 0, full: &mut full, shift: None };
            let (_, ys, _) = adaptive(rig, stepper, t0, y0, t1, h, h).map_err(|e| match check(d, t0, &y0) {
                Err(e) => e,
                Ok(()) => RigError::Integration { time: t0, message: e.to_string() },
            })?;
            if full {
                return Err(RigError::Integration { time: t0, message: "one step split into too many sub-steps".into() });
            }
            *ys.last().ok_or_else(|| RigError::Integration { time: t0, message: "no step taken".into() })?
        }
    };
    check(d, t1, &y)?;
    Ok(y)
}

/// Locate the event in (ta, tb]: `g` is continuous, `outside` ⇔ the event has happened;
/// `outside` is false at ta and true at tb. Returns the first trial time found with `outside`
/// true within `tol` of the last time found with it false, and the state there. Each trial
/// state is one re-integration step from (ta, ya), or with `dense` (the continuous extension
/// of the step from ta to tb, [`Method::Dopri5Dense`]) read from it without evaluations.
pub(crate) fn locate(
    rig: &RigParams,
    d: &Dynamics,
    (ta, ya): (f64, State),
    (tb, yb): (f64, State),
    event: &dyn Fn(f64, &State) -> (f64, bool),
    dense: Option<&Dense>,
) -> Result<(f64, State), RigError> {
    let tol = rig.event_tolerance;
    let (mut a, mut b, mut y_b) = (ta, tb, yb);
    let mut ga = event(ta, &ya).0;
    let mut gb = event(tb, &yb).0;
    let mut side = 0i8;
    let mut iterations = 0;
    while b - a > tol {
        iterations += 1;
        if iterations > 200 {
            return Err(RigError::Integration { time: a, message: "event location did not converge".into() });
        }
        let width = b - a;
        // Illinois step, bisection when it would not shrink the bracket or lands on an end.
        let mut t = if gb != ga && ga.is_finite() && gb.is_finite() { (a * gb - b * ga) / (gb - ga) } else { 0.5 * (a + b) };
        if !(t > a && t < b) || iterations % 4 == 0 {
            t = 0.5 * (a + b);
        }
        // Never closer than tol/4 to an end: each trial shrinks the bracket by at least that.
        t = t.clamp(a + 0.25 * tol.min(0.5 * width), b - 0.25 * tol.min(0.5 * width));
        let y = match dense.and_then(|m| m.evaluate(t)) {
            Some(mut y) => {
                y[TIME] = t;
                y
            }
            None => sub_step(rig, d, ta, ya, t)?,
        };
        let (g, out) = event(t, &y);
        if out {
            b = t;
            gb = g;
            y_b = y;
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            a = t;
            ga = g;
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
    }
    Ok((b, y_b))
}
