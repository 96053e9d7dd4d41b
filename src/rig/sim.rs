//! The stepping simulator: [`RigSim`], for the CLI and for a co-simulation host (the FMU).
//!
//! # Independence of the communication grid
//! The simulator integrates *segments* of its own: each starts at a node (the initial state,
//! an event, a multiple of `segment_length`, a jump of the excitation, or a change of the
//! held inputs) and ends at the next of these. [`RigSim::advance_to`] only computes segments
//! until one covers the requested time and moves a clock; the state reported at a time t is
//! one re-integration step from the last accepted node before t. So neither the nodes nor the
//! reported states depend on where the host puts its communication points: with the same
//! inputs, a host stepping at 1e-5 s and one stepping at 1 s get the same numbers at shared
//! points (bitwise, up to the core's warm-started solve, which is deterministic too).
//! Setting an input to a *different* value starts a new segment at the current time.
//!
//! # Events
//! Hybrid formulation (see [`super::dynamics`] for the phases):
//! - Slip(s) → the speed reaches 0 (s·ω ≤ 0) *and* the drive no longer exceeds the running
//!   torque at rest, s·T_a ≤ T_f(0⁺) = μ_c·R·P + the grease's yield torque
//!   ([`Joint::boundary_torque`], the ω → 0⁺ limit of eq. 11): if |T_a| ≤ k_b·T_f(0⁺) the
//!   joint sticks, otherwise it reverses at once into Slip(sign T_a).
//! - Stick → |T_a| > k_b·T_f(0⁺): breakaway into Slip(sign T_a).
//!
//! At each event ω is set to exactly 0 (its located value is within the event tolerance of 0).
//!
//! # Why the stop needs the one-sided limit (Filippov)
//! The friction law is set-valued at rest: T_f ∈ [−T_f(0⁺), T_f(0⁺)] at ω = 0 (k_b·T_f(0⁺)
//! once stuck) and −sign(ω)·T(|ω|) in motion. At ω = 0 in direction s the one-sided limit of
//! the acceleration is J·ω̇(0⁺) = s·T_a − T_f(0⁺): where it is positive the trajectory leaves
//! ω = 0 in direction s and can never return there while it stays positive, so a zero of the
//! integrated ω is not a stop. With the grease's running torque T(ω) = T_f(0⁺) + c·ω^n, n < 1
//! (Herschel–Bulkley), the slope at rest is infinite: just after a breakaway with
//! s·T_a − T_f(0⁺) = ΔT the joint creeps at ω* = (ΔT/c)^{1/n}, far below the integrator's
//! atol, with a relaxation time J·ω*/(n·ΔT) → 0. The integrated ω then dips below 0 within the
//! tolerance; taking that as an event restarted the slip from ω = 0 at once, a thousand times
//! in a row (the cold day's "stick/slip chattering" refusal). With the stop tested on the
//! one-sided limit, such a dip is integrated through (for s·ω < 0 the friction is the
//! continuous extension −s·T_f(0⁺), which pushes ω back into direction s), so the law is
//! integrated as it is, unregularised, and the answer converges to the event-exact trajectory
//! as the tolerance shrinks (tests/rig_cold.rs). Where the drive has fallen below T_f(0⁺) when
//! ω reaches 0 (every genuine stop or reversal) the rule is the previous one, bit for bit.

use super::config::RigConfig;
use super::dynamics::{physical, to_state, Dynamics, Phase, State, ANGLE, DISSIPATION, SPEED, TIME, TORQUE, WORK};
use super::excitation::{Excitation, Held, Inputs, SineCommand, SineDrive, StepLoad};
use super::integrate::{locate, segment, sub_step, Dense, TINY};
use super::params::Formulation;
use super::RigError;
use crate::fidelity::{Envelope, Evaluator, Fidelity, Level};
use crate::joint::Joint;
use crate::load_sharing::start::StartCut;
use super::linear_loop::Loop;
use std::cell::RefCell;
use crate::fmt::Num;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// One start point of integration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Node {
    /// Time at which integration restarts (s).
    pub time: f64,
    /// (θ, ω, T_a, W, D), see [`super::dynamics`].
    pub state: [f64; 5],
    /// Stick, slip (with direction) or smooth at the start point.
    pub phase: Phase,
    /// First step of the next segment (0: automatic).
    pub step: f64,
    /// Warm start of the core's solve.
    pub logit: f64,
}

/// Everything needed to resume a simulation: with the same configuration and excitation,
/// [`RigSim::set_state`] continues exactly as the original would.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RigState {
    /// The start point of the next integration segment.
    pub node: Node,
    /// Communication time (≥ node.time), s.
    pub time: f64,
    /// The load and command angle in force at `time`.
    pub inputs: Inputs,
}

/// Number of f64 in [`RigState::to_bytes`].
const STATE_WORDS: usize = 14;

impl RigState {
    /// Compact little-endian encoding (14 × f64 = 112 bytes).
    pub fn to_bytes(&self) -> Vec<u8> {
        let n = &self.node;
        let phase = match n.phase {
            Phase::Slip(s) => f64::from(s),
            Phase::Stick => 0.0,
            Phase::Smooth => 2.0,
        };
        let words: [f64; STATE_WORDS] = [
            n.time,
            n.state[0],
            n.state[1],
            n.state[2],
            n.state[3],
            n.state[4],
            phase,
            n.step,
            n.logit,
            self.time,
            self.inputs.load.map_or(0.0, |_| 1.0),
            self.inputs.load.unwrap_or(0.0),
            self.inputs.command_angle.map_or(0.0, |_| 1.0),
            self.inputs.command_angle.unwrap_or(0.0),
        ];
        words.iter().flat_map(|w| w.to_le_bytes()).collect()
    }

    /// Inverse of [`RigState::to_bytes`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, RigError> {
        if bytes.len() != 8 * STATE_WORDS {
            return Err(RigError::State(format!("expected {} bytes, got {}", 8 * STATE_WORDS, bytes.len())));
        }
        let w: Vec<f64> = bytes.chunks_exact(8).map(|c| f64::from_le_bytes(c.try_into().unwrap())).collect();
        let phase = match w[6] {
            1.0 => Phase::Slip(1),
            -1.0 => Phase::Slip(-1),
            0.0 => Phase::Stick,
            2.0 => Phase::Smooth,
            x => return Err(RigError::State(format!("bad phase code {x}"))),
        };
        Ok(Self {
            node: Node { time: w[0], state: [w[1], w[2], w[3], w[4], w[5]], phase, step: w[7], logit: w[8] },
            time: w[9],
            inputs: Inputs { load: (w[10] != 0.0).then_some(w[11]), command_angle: (w[12] != 0.0).then_some(w[13]) },
        })
    }
}

/// The rig's outputs at one time (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// Simulation time (s).
    pub time: f64,
    /// Actuator command angle θ_cmd (rad).
    pub command_angle: f64,
    /// Pin angle θ (rad).
    pub angle: f64,
    /// Pin angular velocity ω (rad/s).
    pub angular_velocity: f64,
    /// What the actuator's torque transducer reads: the actuator torque T_a (= J ω̇ − T_f).
    pub torque: f64,
    /// Friction torque on the pin, signed (opposes ω; in stick the reaction −T_a).
    pub friction_torque: f64,
    /// The core's μ(P, |ω|) (μ_c in stick: the capacity, not the mobilised |T_a|/(R P)); 0 at zero load.
    pub friction_coefficient: f64,
    /// The core's central film thickness h_c (m); NaN at zero load (no contact).
    pub film_thickness: f64,
    /// The core's 1/γ1; NaN at zero load.
    pub fluid_load_fraction: f64,
    /// Hybrid: in a stick phase. Regularised: |ω| ≤ ω_reg.
    pub stuck: bool,
    /// Radial load P (N).
    pub load: f64,
    /// W = ∫T_a ω dt (J).
    pub actuator_work: f64,
    /// D = ∫|T_f ω| dt (J).
    pub friction_dissipation: f64,
    /// ½ J ω² (J).
    pub kinetic_energy: f64,
}

/// Integrator steps one [`RigSim::advance_to`] may take (≈ 1000 strokes of the 1 Hz rig at
/// the default tolerances; tens of seconds of work at most). Beyond it the advance fails with
/// [`RigError::WorkLimit`] instead of running on for minutes (an FMU host would hang); the
/// simulation is then left part-way and must be restored from a saved state or rebuilt.
pub const ADVANCE_STEP_LIMIT: u64 = 2_000_000;

/// Largest simulated time (s, ≈ 116 days): beyond it the double-precision resolution of t
/// (TINY·t ≥ 1 ms) would let segments degenerate into Euler slivers.
pub const MAX_TIME: f64 = 1e7;

/// Most samples [`RigSim::run`] returns in one vector (≈ 2.4 GB of samples).
pub const MAX_RUN_SAMPLES: usize = 20_000_000;

/// Counters of what the integration did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Stats {
    /// Integration segments (continuous pieces between stick/slip events, at most
    /// `MAX_SEGMENT_NODES` steps each).
    pub segments: u64,
    /// Accepted integrator steps.
    pub steps: u64,
    /// Slip → stick.
    pub sticks: u64,
    /// Stick → slip.
    pub breakaways: u64,
    /// Slip → slip through ω = 0 without sticking.
    pub reversals: u64,
    /// Longest run of consecutive events closer than 10 event tolerances (chatter indicator).
    pub max_event_burst: u64,
    /// Friction evaluations outside the envelope of the fidelity level ([`RigSim::set_fidelity`]),
    /// answered by the full solve.
    pub fallbacks: u64,
    /// Right-hand-side evaluations, including the re-integration steps to sample and event times.
    pub evaluations: u64,
    /// Full friction solves (the core's load-sharing Newton solve), including those of samples.
    pub friction_solves: u64,
    /// Residual evaluations of the solves inside the equations of motion (their Newton
    /// iterations with line-search trials; the samples' solves are counted in
    /// `friction_solves` only).
    pub solve_residuals: u64,
}

impl Stats {
    /// Add what `d` did to the counters.
    fn add(&mut self, d: &Dynamics) {
        self.fallbacks += d.fallbacks.get();
        self.evaluations += d.evaluations.get();
        self.friction_solves += d.solves.get();
        self.solve_residuals += d.residuals.get();
    }
}

#[derive(Debug, Clone)]
struct Segment {
    phase: Phase,
    logit: f64,
    /// Accepted nodes from the segment start, all before `end`.
    nodes: Vec<(f64, State)>,
    end: f64,
    next: Node,
    /// [`super::params::Method::Dopri5Dense`]: the continuous extension of the accepted steps
    /// (covering `nodes[0].0` up to `end`).
    dense: Option<Dense>,
}

/// The rig simulator.
#[derive(Clone)]
pub struct RigSim {
    config: RigConfig,
    joint: Joint,
    base: Arc<dyn Excitation>,
    inputs: Inputs,
    node: Node,
    time: f64,
    segment: Option<Segment>,
    stats: Stats,
    burst: u64,
    /// The friction fidelity ([`RigSim::set_fidelity`]); None: the full solve.
    fidelity: Option<Arc<Evaluator>>,
    /// The start table cut at the last load integrated, kept across segments (a cache: its
    /// values are functions of the load alone, so results do not depend on it).
    start_cut: Option<StartCut>,
    /// The loop linearised at the last load (`Method::Dopri5Dense`), kept likewise.
    linear: Option<(f64, Loop)>,
}

impl std::fmt::Debug for RigSim {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RigSim")
            .field("config", &self.config)
            .field("inputs", &self.inputs)
            .field("node", &self.node)
            .field("time", &self.time)
            .field("stats", &self.stats)
            .finish_non_exhaustive()
    }
}

/// Consecutive near-coincident events beyond which the run is declared chattering.
const MAX_BURST: u64 = 1000;

impl RigSim {
    /// The paper's rig: θ_cmd = A sin(2πft) and the constant load of `config.rig`, starting at
    /// rest on the command (θ = θ_cmd(0) = 0, ω = 0, T_a = 0) at t = 0.
    pub fn new(config: &RigConfig) -> Result<Self, RigError> {
        let r = &config.rig;
        let drive = SineDrive {
            command: SineCommand { amplitude: r.amplitude, frequency: r.frequency },
            load: StepLoad::constant(r.load),
        };
        Self::with_excitation(config, Arc::new(drive))
    }

    /// A rig driven by any excitation, starting at rest on the command at t = 0.
    pub fn with_excitation(config: &RigConfig, excitation: Arc<dyn Excitation>) -> Result<Self, RigError> {
        config.validate()?;
        let joint = Joint::new(&config.model)?;
        let angle = excitation.command(0.0).0;
        let phase = match config.rig.formulation {
            Formulation::Hybrid => Phase::Stick,
            Formulation::Regularised => Phase::Smooth,
        };
        let node = Node { time: 0.0, state: [angle, 0.0, 0.0, 0.0, 0.0], phase, step: 0.0, logit: f64::NAN };
        let mut sim = Self {
            config: *config,
            joint,
            base: excitation,
            inputs: Inputs::default(),
            node,
            time: 0.0,
            segment: None,
            stats: Stats::default(),
            burst: 0,
            fidelity: None,
            start_cut: None,
            linear: None,
        };
        sim.node.phase = sim.resolve(&sim.node)?;
        Ok(sim)
    }

    /// Evaluate the friction at `fidelity` (built over `envelope` to `tolerance`, see
    /// [`Evaluator::new`]) from now on. `table` and `boundary` answer inside the envelope; outside
    /// it (and always at `full`) the warm-started full solve answers, as without this call;
    /// [`Stats::fallbacks`] counts those calls. Returns the evaluator (what `auto` picked, its bound).
    pub fn set_fidelity(&mut self, fidelity: Fidelity, tolerance: f64, envelope: Envelope) -> Result<&Evaluator, RigError> {
        let ev = Evaluator::new(&self.config.model, fidelity, tolerance, envelope)?;
        self.fidelity = Some(Arc::new(ev));
        self.segment = None;
        Ok(self.fidelity.as_deref().expect("just set"))
    }

    /// The fidelity level set by [`RigSim::set_fidelity`].
    pub fn fidelity(&self) -> Option<&Evaluator> {
        self.fidelity.as_deref()
    }

    /// The level set by [`RigSim::set_fidelity`], shared (a clone of the handle, not of the table).
    pub fn shared_fidelity(&self) -> Option<Arc<Evaluator>> {
        self.fidelity.clone()
    }

    /// Use a level another simulator built with [`RigSim::set_fidelity`], without building it
    /// again (the evaluator is read-only here, so sharing it changes no result). It must have
    /// been built for the same model parameters (`config.model`): checked by the evaluator's
    /// parameter set.
    pub fn share_fidelity(&mut self, evaluator: Arc<Evaluator>) -> Result<(), RigError> {
        if evaluator.joint().params() != &self.config.model {
            return Err(RigError::State("the shared fidelity level was built for other model parameters".into()));
        }
        self.fidelity = Some(evaluator);
        self.segment = None;
        Ok(())
    }

    /// The envelope the built-in sine drive of `config` visits: the load ±10 % (at least
    /// ±1 N) and speeds from 1e-3 rad/s to twice the command's peak speed 2πfA (at least
    /// 1e-2 rad/s). Slower speeds occur only around reversals and fall back to the full solve.
    pub fn drive_envelope(config: &RigConfig) -> Result<Envelope, RigError> {
        let r = &config.rig;
        let p = r.load.max(10.0);
        let peak = (std::f64::consts::TAU * r.frequency * r.amplitude).max(5e-3);
        Ok(Envelope::new((0.9 * p).min(p - 1.0), (1.1 * p).max(p + 1.0), 1e-3, 2.0 * peak)?)
    }

    /// The configuration the simulation was built with.
    pub fn config(&self) -> &RigConfig {
        &self.config
    }
    /// The friction model of the pin joint.
    pub fn joint(&self) -> &Joint {
        &self.joint
    }
    /// Current (communication) time.
    pub fn time(&self) -> f64 {
        self.time
    }
    /// Counters of what the integration has done so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }
    /// The load and command angle currently in force.
    pub fn inputs(&self) -> Inputs {
        self.inputs
    }

    /// Move the joint to lubricant temperature `temperature` (K), keeping the state: from
    /// now on the simulator integrates exactly as one built with that temperature in
    /// `config.model` (and the same fidelity) and resumed from this state with
    /// [`RigSim::set_state`]. The joint moves by [`Joint::at_temperature`] (a few logarithms:
    /// the start table and the temperature-independent groups are kept); a table or boundary
    /// level is built again there ([`Evaluator::set_temperature`]). The integration restarts
    /// at the current time, as after any input change. An invalid temperature is an error
    /// naming it, and nothing changes.
    pub fn set_temperature(&mut self, temperature: f64) -> Result<(), RigError> {
        if temperature.to_bits() == self.config.model.lubricant.temperature.to_bits() {
            return Ok(());
        }
        let joint = self.joint.at_temperature(temperature)?;
        let fidelity = match self.fidelity.as_deref() {
            Some(ev) => {
                let mut ev = ev.clone();
                ev.set_temperature(temperature)?;
                Some(Arc::new(ev))
            }
            None => None,
        };
        self.joint = joint;
        self.fidelity = fidelity;
        self.config.model.lubricant.temperature = temperature;
        self.segment = None;
        self.start_cut = None;
        self.linear = None;
        self.burst = 0;
        Ok(())
    }

    /// The resumable state.
    pub fn state(&self) -> RigState {
        RigState { node: self.node, time: self.time, inputs: self.inputs }
    }

    /// Resume from a state taken from a simulator with the same configuration and excitation.
    /// Every value is checked as the setters check it and for consistency with this
    /// configuration; a rejected state leaves the simulator untouched.
    pub fn set_state(&mut self, state: &RigState) -> Result<(), RigError> {
        self.check_state(state)?;
        self.node = state.node;
        self.time = state.time;
        self.inputs = state.inputs;
        self.segment = None;
        Ok(())
    }

    /// The checks of [`Self::set_state`].
    fn check_state(&self, state: &RigState) -> Result<(), RigError> {
        let bad = |what: String| Err(RigError::State(what));
        let n = &state.node;
        for (name, t) in [("node time", n.time), ("time", state.time)] {
            if !(t.is_finite() && t.abs() <= MAX_TIME) {
                return bad(format!("{name} = {} s is not a finite number within ±{} s", Num(t), Num(MAX_TIME)));
            }
        }
        // The node starts the segment that covers `time`: at most one segment behind it.
        let lag = state.time - n.time;
        if !(lag >= 0.0 && lag <= 2.0 * self.config.rig.segment_length) {
            return bad(format!(
                "time = {} s is not within one segment ({} s) after the node time {} s",
                Num(state.time),
                Num(self.config.rig.segment_length),
                Num(n.time)
            ));
        }
        for (name, v) in ["angle", "angular_velocity", "torque", "actuator_work", "friction_dissipation"].iter().zip(n.state) {
            if !v.is_finite() {
                return bad(format!("{name} = {} is not a finite number", Num(v)));
            }
        }
        if !(n.step.is_finite() && n.step >= 0.0 && n.step <= self.config.rig.segment_length) {
            return bad(format!("step = {} s is not within 0..{} s", Num(n.step), Num(self.config.rig.segment_length)));
        }
        let regularised = self.config.rig.formulation == Formulation::Regularised;
        if regularised != (n.phase == Phase::Smooth) {
            return bad(format!("phase {:?} does not belong to the {:?} formulation", n.phase, self.config.rig.formulation));
        }
        Self::check_inputs(&state.inputs)
    }

    fn held(&self) -> Held {
        Held { base: self.base.clone(), inputs: self.inputs }
    }

    fn check_inputs(inputs: &Inputs) -> Result<(), RigError> {
        if let Some(p) = inputs.load
            && !p.is_finite()
        {
            return Err(RigError::Load { time: f64::NAN, value: p });
        }
        if let Some(a) = inputs.command_angle
            && !a.is_finite()
        {
            return Err(RigError::Command(a));
        }
        Ok(())
    }

    /// Integrate to `t_next` (≥ the current time) with `inputs` held from the current time on.
    pub fn advance_to(&mut self, t_next: f64, inputs: &Inputs) -> Result<(), RigError> {
        if !(t_next.is_finite() && t_next <= MAX_TIME) || t_next < self.time {
            return Err(RigError::Time { now: self.time, requested: t_next });
        }
        Self::check_inputs(inputs)?;
        if *inputs != self.inputs {
            // New held values: restart integration from the current time.
            if self.time > self.node.time {
                let (y, phase, logit) = self.state_at(self.time)?;
                self.node = Node { time: self.time, state: physical(&y), phase, step: 0.0, logit };
            }
            self.inputs = *inputs;
            self.segment = None;
            self.node.phase = self.resolve(&self.node)?;
        }
        // Integrate first (bounded), then move the clock: a refused advance leaves `time`.
        // Refused at once when the joint can never slip (its breakaway torque exceeds the
        // actuator's limit: it creeps all the time) and the creep steps exceed the budget.
        if let Some(e) = self.stiff(t_next, self.time)
            && let RigError::Stiff { time_constant, load, .. } = &e
        {
            let never_slips = Dynamics::new(&self.joint, &self.config.rig, &self.held(), Phase::Smooth, 0.0).breakaway_torque(*load)
                > self.config.rig.torque_limit;
            if never_slips && (t_next - self.time) / (3.0 * time_constant) > ADVANCE_STEP_LIMIT as f64 {
                return Err(e);
            }
        }
        let start = self.stats.steps;
        self.cover_within(t_next, Some(start + ADVANCE_STEP_LIMIT)).map_err(|e| match e {
            RigError::WorkLimit { reached, steps, .. } => {
                self.stiff(t_next, reached).unwrap_or(RigError::WorkLimit { requested: t_next, reached, steps: steps - start })
            }
            e => e,
        })?;
        self.time = t_next;
        Ok(())
    }

    /// For the regularised formulation, the error saying that an advance to `requested`
    /// is beyond the step budget because of the creep band's stiffness (None otherwise).
    fn stiff(&self, requested: f64, reached: f64) -> Option<RigError> {
        let rig = &self.config.rig;
        if rig.formulation != Formulation::Regularised {
            return None;
        }
        let exc = self.held();
        let d = Dynamics::new(&self.joint, rig, &exc, Phase::Smooth, 0.0);
        let load = d.load(reached).ok()?;
        let tau = rig.inertia * rig.regularisation_speed / d.breakaway_torque(load);
        Some(RigError::Stiff { requested, reached, load, time_constant: tau, limit: ADVANCE_STEP_LIMIT })
    }

    /// The outputs at the current time.
    pub fn sample(&mut self) -> Result<Sample, RigError> {
        let t = self.time;
        let (y, phase, logit) = self.state_at(t)?;
        self.observe(t, &y, phase, logit)
    }

    /// Run on the built-in or given excitation and sample every `interval` from the current
    /// time to `t_end` (both included when they fall on the grid), holding the current inputs.
    pub fn run(&mut self, t_end: f64, interval: f64) -> Result<Vec<Sample>, RigError> {
        let t0 = self.time;
        let count = (t_end - t0) / interval + 1e-9;
        if !(interval > 0.0 && count.is_finite() && count < MAX_RUN_SAMPLES as f64) {
            return Err(RigError::Samples { t_end, interval, limit: MAX_RUN_SAMPLES });
        }
        let n = count.max(0.0).floor() as usize;
        let inputs = self.inputs;
        let mut out = Vec::with_capacity(n + 1);
        out.push(self.sample()?);
        for k in 1..=n {
            self.advance_to(t0 + k as f64 * interval, &inputs)?;
            out.push(self.sample()?);
        }
        Ok(out)
    }

    /// Phase to start a segment with from `node` (re-checks stick against the current load).
    fn resolve(&self, node: &Node) -> Result<Phase, RigError> {
        if self.config.rig.formulation == Formulation::Regularised {
            return Ok(Phase::Smooth);
        }
        let exc = self.held();
        let d = Dynamics::new(&self.joint, &self.config.rig, &exc, node.phase, node.logit);
        let load = d.load(node.time).map_err(|p| RigError::Load { time: node.time, value: p })?;
        let (w, ta) = (node.state[SPEED], node.state[TORQUE]);
        Ok(match node.phase {
            Phase::Slip(s) if f64::from(s) * w >= 0.0 => node.phase,
            Phase::Slip(_) | Phase::Smooth => Phase::Slip(if w > 0.0 { 1 } else { -1 }),
            Phase::Stick => {
                if ta.abs() > d.breakaway_torque(load) {
                    Phase::Slip(if ta > 0.0 { 1 } else { -1 })
                } else {
                    Phase::Stick
                }
            }
        })
    }

    /// Make the current segment cover `t`, within [`ADVANCE_STEP_LIMIT`] steps.
    fn cover(&mut self, t: f64) -> Result<(), RigError> {
        self.cover_within(t, Some(self.stats.steps + ADVANCE_STEP_LIMIT))
    }

    /// [`Self::cover`], refusing to go on once the step count passes `limit` (checked per
    /// segment, which keeps at most [`super::integrate::MAX_SEGMENT_NODES`] steps): a host
    /// must never hang in one call.
    fn cover_within(&mut self, t: f64, limit: Option<u64>) -> Result<(), RigError> {
        // Each segment counts at least one step (slivers take none), so the loop is bounded.
        let mut segments = 0u64;
        loop {
            if self.segment.is_none() {
                segments += 1;
                if limit.is_some_and(|l| self.stats.steps > l || segments > ADVANCE_STEP_LIMIT) {
                    return Err(RigError::WorkLimit { requested: t, reached: self.node.time, steps: self.stats.steps });
                }
                self.segment = Some(self.compute_segment()?);
            }
            let seg = self.segment.as_ref().unwrap();
            if t < seg.end {
                return Ok(());
            }
            self.node = seg.next;
            self.segment = None;
        }
    }

    /// (y, phase, logit) at `t` inside the covering segment.
    fn state_at(&mut self, t: f64) -> Result<(State, Phase, f64), RigError> {
        self.cover(t)?;
        let seg = self.segment.as_ref().unwrap();
        let i = seg.nodes.partition_point(|(tn, _)| *tn <= t).max(1) - 1;
        let (ti, yi) = seg.nodes[i];
        if let Some(y) = seg.dense.as_ref().filter(|_| t > ti).and_then(|m| m.evaluate(t)) {
            // The step from node i, read from its continuous extension (no evaluation).
            let mut y = y;
            y[TIME] = t;
            return Ok((y, seg.phase, seg.logit));
        }
        let exc = self.held();
        let mut d = Dynamics::new(&self.joint, &self.config.rig, &exc, seg.phase, seg.logit);
        d.level = self.fidelity.as_deref().filter(|e| e.chosen() != Level::Full);
        let y = sub_step(&self.config.rig, &d, ti, yi, t)?;
        self.stats.add(&d);
        Ok((y, seg.phase, seg.logit))
    }

    fn compute_segment(&mut self) -> Result<Segment, RigError> {
        let rig = self.config.rig;
        let node = self.node;
        let exc = self.held();
        let t0 = node.time;
        let boundary = ((t0 / rig.segment_length) * (1.0 + 1e-12)).floor() + 1.0;
        let t1 = (boundary * rig.segment_length).min(exc.next_discontinuity(t0));
        let phase = node.phase;
        let mut d = Dynamics::new(&self.joint, &rig, &exc, phase, node.logit);
        d.level = self.fidelity.as_deref().filter(|e| e.chosen() != Level::Full);
        d.cut = RefCell::new(self.start_cut.take());
        d.linear.set(self.linear);
        let y0 = to_state(&node.state, t0);
        let breakaway = |t: f64| d.load(t).map_or(0.0, |p| d.breakaway_torque(p));
        let rest = |t: f64| d.load(t).map_or(0.0, |p| d.joint.boundary_torque(p));
        let event = |t: f64, y: &State| -> (f64, bool) {
            match phase {
                Phase::Slip(s) => {
                    let s = f64::from(s);
                    let g = -s * y[SPEED];
                    // The speed's zero ends the slip only where the friction law's one-sided
                    // limit at rest lets the joint stop: s·T_a ≤ T_f(0⁺) (Filippov). Where the
                    // drive exceeds the running torque at rest the slip accelerates away from
                    // ω = 0, and a zero crossing is the integrator's error within its
                    // tolerance (a creep speed below atol): no event.
                    (g, g >= 0.0 && s * y[TORQUE] <= rest(t))
                }
                Phase::Stick => {
                    let g = y[TORQUE].abs() - breakaway(t);
                    (g, g > 0.0)
                }
                Phase::Smooth => (-1.0, false),
            }
        };
        let outside = |t: f64, y: &State| event(t, y).1;
        if t1 - t0 <= TINY * t0.abs().max(1.0) {
            // A sliver between an event and a boundary: nothing to integrate, step across it.
            let y1 = sub_step(&rig, &d, t0, y0, t1)?;
            let mut next = Node { time: t1, state: physical(&y1), ..node };
            next.phase = self.resolve(&next)?;
            self.stats.add(&d);
            return Ok(Segment { phase, logit: node.logit, nodes: vec![(t0, y0)], end: t1, next, dense: None });
        }
        let run = segment(&rig, &d, t0, y0, t1, node.step, &outside)?;
        self.stats.segments += 1;
        self.stats.steps += run.nodes.len() as u64 - 1;
        let mut nodes = run.nodes;
        let dense = run.dense;
        let logit = node.logit;
        let (end, next) = if run.stopped {
            let b = nodes.pop().unwrap();
            let a = *nodes.last().unwrap();
            let (te, mut ye) = locate(&rig, &d, a, b, &event, dense.as_ref())?;
            ye[SPEED] = 0.0;
            let load = d.load(te).map_err(|p| RigError::Load { time: te, value: p })?;
            let ta = ye[TORQUE];
            let new_phase = if ta.abs() <= d.breakaway_torque(load) {
                self.stats.sticks += 1;
                Phase::Stick
            } else {
                match phase {
                    Phase::Stick => self.stats.breakaways += 1,
                    _ => self.stats.reversals += 1,
                }
                Phase::Slip(if ta > 0.0 { 1 } else { -1 })
            };
            if te - t0 < 10.0 * rig.event_tolerance {
                self.burst += 1;
                self.stats.max_event_burst = self.stats.max_event_burst.max(self.burst);
                if self.burst > MAX_BURST {
                    return Err(RigError::Chatter { time: te });
                }
            } else {
                self.burst = 0;
            }
            (te, Node { time: te, state: physical(&ye), phase: new_phase, step: 0.0, logit: d.guess.get() })
        } else {
            let (t, y) = *nodes.last().unwrap();
            if nodes.len() > 1 {
                nodes.pop();
            }
            let mut next = Node { time: t, state: physical(&y), phase, step: run.h_next, logit: d.guess.get() };
            next.phase = self.resolve(&next)?;
            (t, next)
        };
        self.stats.add(&d);
        self.start_cut = d.cut.take();
        self.linear = d.linear.get();
        Ok(Segment { phase, logit, nodes, end, next, dense })
    }

    /// The outputs at (t, y) in `phase`.
    fn observe(&mut self, t: f64, y: &State, phase: Phase, logit: f64) -> Result<Sample, RigError> {
        let exc = self.held();
        let rig = &self.config.rig;
        let mut d = Dynamics::new(&self.joint, rig, &exc, phase, logit);
        d.level = self.fidelity.as_deref().filter(|e| e.chosen() != Level::Full);
        let load = d.load(t).unwrap_or(f64::NAN);
        let (command_angle, _) = exc.command(t);
        let fr = if load.is_finite() { Some(d.friction(load, y)) } else { None };
        self.stats.add(&d);
        if let Some((load, speed, source)) = d.model_fault.borrow().clone() {
            return Err(RigError::Model { time: t, load, speed, source });
        }
        let op = fr.and_then(|f| f.op);
        let w = y[SPEED];
        Ok(Sample {
            time: t,
            command_angle,
            angle: y[ANGLE],
            angular_velocity: w,
            torque: y[TORQUE],
            friction_torque: fr.map_or(f64::NAN, |f| f.torque),
            friction_coefficient: op.map_or(0.0, |o| o.friction_coefficient),
            film_thickness: op.map_or(f64::NAN, |o| o.film_thickness),
            fluid_load_fraction: op.map_or(f64::NAN, |o| o.fluid_load_fraction),
            stuck: match phase {
                Phase::Stick => true,
                Phase::Slip(_) => false,
                Phase::Smooth => w.abs() <= rig.regularisation_speed,
            },
            load,
            actuator_work: y[WORK],
            // D = ∫|T_f ω| dt ≥ 0 by definition; the integrand is −T_f·ω, which round-off
            // past an event can make −1e-45 J: never report a negative dissipation.
            friction_dissipation: y[DISSIPATION].max(0.0),
            kinetic_energy: 0.5 * rig.inertia * w * w,
        })
    }
}
