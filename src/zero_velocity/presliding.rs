//! The single-state elasto-plastic presliding law (Dupont, Hayward, Armstrong, Altpeter,
//! "Single state elastoplastic friction models", IEEE TAC 47(5), 2002), with the sliding
//! torque of the paper's model (eq. 11) as its steady state.
//!
//! The state τ (N·m) is the elastic presliding torque, signed as the deflection: the friction
//! torque on the pin is −τ (plus damping). Along a deflection increment dΔ (rad) in
//! direction s = sign(dΔ), with u = s·τ (the torque component along the motion),
//!
//! ```text
//!   du/dΔ = k                      for u ≤ τ_ba = β·T   (purely elastic: loading below the
//!                                                        elastic limit and every unloading)
//!   du/dΔ = k·(T − u)/(T − τ_ba)   for u > τ_ba         (elasto-plastic transition)
//! ```
//!
//! with T = T_ss(P, |ω|) = μ(P, |ω|)·R·|P| the model's sliding torque (eqs. 10–11), the
//! stiffness k = T/φ_s (φ_s, `presliding_angle`: the deflection at which the elastic torque
//! would reach T) and β the elastic limit. In Dupont's notation ż = ẋ·(1 − α(z, ẋ)·z/z_ss)
//! with α = (T/u)·(u − τ_ba)/(T − τ_ba) between the elastic limit and the bound: 0 at τ_ba,
//! 1 at T, continuous, so the law has no drift below β·T (a purely elastic range) and its
//! steady sliding state is u = T exactly. The right-hand side is Lipschitz in u, which an
//! implicit solver needs under Model Exchange.
//!
//! Exact update over an increment Δ with T held (what the Co-Simulation step does): elastic
//! up to τ_ba, then T − u decays as exp(−|Δ|/((1 − β)·φ_s)); from any start, for any Δ, the
//! result lies between the start and T, so the update is unconditionally stable and bounded.
//! A state beyond the bound (the load dropped while the joint was held) relaxes towards T by
//! the same exponential as soon as the joint moves on; until then the output is clamped at T.
//!
//! The friction torque on the pin is
//!
//! ```text
//!   torque = −( clamp(τ, −T, T) + c·ż ),   c = t_d·k (or 2ζ√(kJ) below),   ż = ω·max(g, 0),
//! ```
//!
//! where g = (du/dΔ)/k in the direction of ω (1 in the elastic range, 0 at the bound) and t_d
//! the damping time. In steady sliding τ = ±T and ż = 0: the torque is the model's
//! −sign(ω)·μRP bit for bit. The damping adds to the held torque up to the bound: the
//! torque never exceeds the sliding torque.
//!
//! Damping with the host's inertia ([`Presliding::damping`]). With the body's inertia J on
//! the pin (`host_inertia`, 0 = not given) the presliding spring k and J form an oscillator of
//! natural frequency ω_n = √(k/J); the damping is then c = 2ζ·√(k·J) with ζ = 0.7
//! ([`HOST_DAMPING_RATIO`]) instead of t_d·k, so a heavy body settles within a few periods
//! and a dither near ω_n is amplified by at most 1/(2ζ·√(1 − ζ²)) ≈ 1.0. When the host's step h
//! is known (Co-Simulation: the last communication step) c is capped for an explicit host
//! (symplectic Euler, the torque held over the step): that host steps the oscillator with
//! the matrix of trace 2 − a − b and determinant 1 − a, a = h·c/J, b = h²·k/J; its eigenvalues
//! are real and positive (the motion decays without sign alternation) when a < 1 and
//! a + b < 2, so c ≤ [`EXPLICIT_MARGIN`]·(J/h)·min(1, 2 − b) (0 when b ≥ 2: a body that light
//! is outside every explicit envelope at that step).
//!
//! A host that couples in parallel ([`HostCoupling::Parallel`]: libcosim, Ecos and other
//! Jacobi masters step every FMU, then exchange the values) integrates the torque the joint
//! computed at the previous communication point: a one-step delay in the loop. In stick the
//! body J under the spring k and damper c, stepped by symplectic Euler with that delayed
//! torque, has the characteristic polynomial
//!
//! ```text
//!   z³ − 2z² + (1 + a + b)·z − a = 0,     a = h·c/J,  b = h²·k/J
//! ```
//!
//! (the sequential loop's is z² − (2 − a − b)·z + (1 − a)). By Jury's test it is stable only when
//! a < 1 and b < a·(1 − a) ≤ 1/4, whatever the damping: a stiff presliding spring cannot be held
//! by a light body at a large step (J = 20 kg·m², 60 kN, 10 ms is b = 0.67). Its three roots sum
//! to 2, so they are all real and positive (no sign alternation, no chatter) only up to
//! b = 1/27, the triple root z = 2/3 ([`PARALLEL_LOOP_GAIN`]). Under parallel coupling with the
//! host's inertia and step known the stiffness is therefore capped at k ≤ (1/27)·J/h² (the
//! presliding angle widened to T·h²·27/J where the cap binds) and the damping is
//! c = 2ζ√(k·J) at that stiffness, a = 2ζ√b ≤ 0.27: at the cap the loop's spectral radius is
//! 0.80 per step for a host integrating by symplectic Euler, 0.86 by explicit Euler, 0.84
//! exactly with the torque held (checked in the tests); below the cap the loop is the
//! oscillator of the sequential host, slower per step. The sequential law is unchanged bit for
//! bit.

use super::jet::Scalar;
use super::error::ZeroVelocityError;

/// Default presliding angle φ_s (rad): the elastic deflection at which the presliding torque
/// would reach the sliding torque. 1.5e-3 rad is 42 µm of tangential displacement at the
/// paper's pin radius (28 mm): the soft end of the presliding displacements reported for
/// lubricated metal contacts (micrometres to tens of micrometres), chosen so that an explicit
/// host with J ≥ 20 kg·m² stays stable at 10 ms steps up to 60 kN (see the envelope in the
/// documentation).
pub const DEFAULT_PRESLIDING_ANGLE: f64 = 1.5e-3;

/// Default elastic limit β: the fraction of the sliding torque up to which presliding is
/// purely elastic (no drift under any drive that stays below β·T_s).
pub const DEFAULT_ELASTIC_LIMIT: f64 = 0.95;

/// Default damping time t_d (s): the presliding damping is c = t_d·k.
pub const DEFAULT_DAMPING_TIME: f64 = 0.01;

/// The damping ratio ζ of the presliding mode when the host gives its inertia: 0.7, near
/// critical (the fastest decay without overshoot of note; a resonant drive is amplified by
/// 1/(2ζ√(1 − ζ²)) = 1.0).
pub const HOST_DAMPING_RATIO: f64 = 0.7;

/// The fraction of the explicit host's no-sign-alternation bound the host-inertia damping is
/// capped at ([`Presliding::damping`]): 0.9.
pub const EXPLICIT_MARGIN: f64 = 0.9;

/// Under parallel coupling ([`HostCoupling::Parallel`]) the largest loop gain b = h²·k/J the
/// presliding stiffness is allowed ([`Presliding::stiffness`]): 1/27, the largest at which the
/// delayed loop's three roots are all real and positive (module doc).
pub const PARALLEL_LOOP_GAIN: f64 = 1.0 / 27.0;

/// The largest host inertia accepted (kg·m²): 1e9.
pub const MAX_HOST_INERTIA: f64 = 1e9;

/// How the host couples the joint's torque to its body: which step's torque it integrates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HostCoupling {
    /// The host sets the angle and speed, steps the joint, reads the torque and integrates
    /// its body with it over the same step (fmpy loops, Simulink, Gauss–Seidel masters);
    /// code 0, the default.
    #[default]
    Sequential,
    /// The host steps the joint and its body together and exchanges the values after the
    /// step (Jacobi masters: libcosim/OSP, Ecos, many SSP and distributed masters): the body
    /// integrates the torque of the previous communication point; code 1.
    Parallel,
}

impl HostCoupling {
    /// Its code (the FMU's `zero_velocity.host_coupling`, the Python API): 0 sequential, 1 parallel.
    pub fn code(self) -> i64 {
        match self {
            HostCoupling::Sequential => 0,
            HostCoupling::Parallel => 1,
        }
    }

    /// The coupling of `code`, if it is one.
    pub fn from_code(code: i64) -> Option<Self> {
        match code {
            0 => Some(HostCoupling::Sequential),
            1 => Some(HostCoupling::Parallel),
            _ => None,
        }
    }

    /// Its name: `sequential` or `parallel`.
    pub fn as_str(self) -> &'static str {
        match self {
            HostCoupling::Sequential => "sequential",
            HostCoupling::Parallel => "parallel",
        }
    }
}

/// The parameters of the presliding law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Presliding {
    /// φ_s (rad, > 0): deflection at which the elastic torque would reach the sliding torque.
    pub angle: f64,
    /// β (dimensionless, in [0, 1)): elastic limit as a fraction of the sliding torque.
    pub elastic_limit: f64,
    /// t_d (s, ≥ 0): damping time, c = t_d·k (when `host_inertia` is 0).
    pub damping_time: f64,
    /// J (kg·m², ≥ 0): the host's inertia on the pin, 0 = not given. When given, the damping
    /// is c = 2ζ√(k·J), capped for an explicit host at `step` ([`Presliding::damping`]).
    pub host_inertia: f64,
    /// h (s, ≥ 0): the host's step the host-inertia damping is capped for; 0 = not known (no
    /// cap). Not a parameter: the front ends set it from the host's steps.
    pub step: f64,
    /// How the host couples ([`HostCoupling`]): under parallel coupling, with the host's
    /// inertia and step known, the stiffness is capped for the delayed loop
    /// ([`Presliding::stiffness`]) and the damping is not capped for the sequential one.
    pub coupling: HostCoupling,
}

impl Default for Presliding {
    fn default() -> Self {
        Presliding {
            angle: DEFAULT_PRESLIDING_ANGLE,
            elastic_limit: DEFAULT_ELASTIC_LIMIT,
            damping_time: DEFAULT_DAMPING_TIME,
            host_inertia: 0.0,
            step: 0.0,
            coupling: HostCoupling::Sequential,
        }
    }
}

/// The parameter names, as every front end spells them.
pub const ANGLE_NAME: &str = "zero_velocity.presliding_angle";
/// See [`ANGLE_NAME`].
pub const ELASTIC_LIMIT_NAME: &str = "zero_velocity.elastic_limit";
/// See [`ANGLE_NAME`].
pub const DAMPING_TIME_NAME: &str = "zero_velocity.damping_time";
/// See [`ANGLE_NAME`].
pub const HOST_INERTIA_NAME: &str = "zero_velocity.host_inertia";
/// See [`ANGLE_NAME`].
pub const HOST_COUPLING_NAME: &str = "zero_velocity.host_coupling";

/// Whether `x` is not > 0 (0, negative or NaN): an unloaded bound, or no elastic fraction.
#[inline]
fn unloaded(x: f64) -> bool {
    x.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
}

impl Presliding {
    /// The law with these parameters, checked ([`Presliding::validate`]).
    pub fn new(angle: f64, elastic_limit: f64, damping_time: f64) -> Result<Self, ZeroVelocityError> {
        let p = Presliding { angle, elastic_limit, damping_time, ..Presliding::default() };
        p.validate()?;
        Ok(p)
    }

    /// The law with the host's inertia `host_inertia` (kg·m², 0 = not given), checked.
    pub fn with_host_inertia(self, host_inertia: f64) -> Result<Self, ZeroVelocityError> {
        let p = Presliding { host_inertia, ..self };
        p.validate()?;
        Ok(p)
    }

    /// The law under the host's coupling `coupling`.
    #[must_use]
    pub fn with_coupling(self, coupling: HostCoupling) -> Self {
        Presliding { coupling, ..self }
    }

    /// The law with the host's step `step` (s; 0 or anything not a finite number > 0: not
    /// known), for the explicit cap of the host-inertia damping.
    #[must_use]
    pub fn at_step(self, step: f64) -> Self {
        Presliding { step: if step.is_finite() && step > 0.0 { step } else { 0.0 }, ..self }
    }

    /// φ_s a finite number > 0 (at most 1 rad), β in [0, 1), t_d a finite number in [0, 1e3] s,
    /// J in [0, 1e9] kg·m²; the error names the parameter, its value and unit.
    pub fn validate(&self) -> Result<(), ZeroVelocityError> {
        let bad = |name: &'static str, value: f64, unit: &'static str, rule: &'static str| {
            Err(ZeroVelocityError::Invalid { name, value, unit, rule })
        };
        if !(self.angle > 0.0 && self.angle <= 1.0) {
            return bad(ANGLE_NAME, self.angle, "rad", "it must be a number in (0, 1] rad");
        }
        if !(self.elastic_limit >= 0.0 && self.elastic_limit < 1.0) {
            return bad(ELASTIC_LIMIT_NAME, self.elastic_limit, "", "it must be a number in [0, 1)");
        }
        if !(self.damping_time >= 0.0 && self.damping_time <= 1e3) {
            return bad(DAMPING_TIME_NAME, self.damping_time, "s", "it must be a number in [0, 1000] s");
        }
        if !(self.host_inertia >= 0.0 && self.host_inertia <= MAX_HOST_INERTIA) {
            return bad(HOST_INERTIA_NAME, self.host_inertia, "kg.m2", "it must be a number in [0, 1e9] kg.m2 (0: not given)");
        }
        Ok(())
    }

    /// The presliding damping c (N·m·s/rad) at the stiffness `k`: t_d·k without the host's
    /// inertia; with it (J > 0) 2ζ√(k·J), capped at the step h when known by
    /// [`EXPLICIT_MARGIN`]·(J/h)·min(1, 2 − h²·k/J) (module doc: the explicit host's
    /// no-sign-alternation bound) under sequential coupling; under parallel coupling not
    /// capped (k is: [`Presliding::stiffness`]; a = h·c/J = 2ζ√b ≤ 0.27 there).
    #[inline]
    pub fn damping<S: Scalar>(&self, k: S) -> S {
        let j = self.host_inertia;
        if j <= 0.0 {
            return S::c(self.damping_time) * k;
        }
        let c = S::c(2.0 * HOST_DAMPING_RATIO) * (k * S::c(j)).sqrt();
        let h = self.step;
        if h <= 0.0 || self.coupling == HostCoupling::Parallel {
            return c;
        }
        let room = S::c(2.0) - k * S::c(h * h / j);
        let room = if room.re() > 1.0 { S::c(1.0) } else if room.re() < 0.0 { S::c(0.0) } else { room };
        let cap = S::c(EXPLICIT_MARGIN * j / h) * room;
        if cap.re() < c.re() { cap } else { c }
    }

    /// Stiffness k = T/φ_s (N·m/rad) at the sliding torque `bound` = T; under parallel
    /// coupling with the host's inertia J and step h known, at most
    /// [`PARALLEL_LOOP_GAIN`]·J/h² (module doc: the delayed loop's real-root bound).
    #[inline]
    pub fn stiffness<S: Scalar>(&self, bound: S) -> S {
        let k = bound / S::c(self.angle);
        if self.coupling == HostCoupling::Parallel && self.host_inertia > 0.0 && self.step > 0.0 {
            let cap = PARALLEL_LOOP_GAIN * self.host_inertia / (self.step * self.step);
            if k.re() > cap {
                return S::c(cap);
            }
        }
        k
    }

    /// The exact update of the presliding torque `tau` (N·m) over a deflection increment
    /// `delta` (rad) at the sliding torque `bound` = T (N·m) held over the increment. At T ≤ 0
    /// (unloaded) the joint holds nothing: 0.
    #[inline]
    pub fn deflect<S: Scalar>(&self, tau: S, delta: S, bound: S) -> S {
        if unloaded(bound.re()) {
            return S::c(0.0);
        }
        let d = delta.re();
        if d == 0.0 {
            return tau;
        }
        // Return mapping: a state beyond the bound (the bound fell with the load or the speed
        // since it was committed) is projected onto it first: the contact cannot hold more.
        let tau = clamp(tau, bound);
        let s = S::c(if d > 0.0 { 1.0 } else { -1.0 });
        let u0 = s * tau;
        let a = s * delta;
        let k = self.stiffness(bound);
        let limit = S::c(self.elastic_limit) * bound;
        let span = bound - limit;
        let u = if u0.re() < limit.re() {
            let elastic = u0 + k * a;
            if elastic.re() <= limit.re() { elastic } else { bound - span * (-(elastic - limit) / span).exp() }
        } else if S::VALUE_ONLY && u0.re() == bound.re() {
            // At the bound already (a state the bound fell below, projected onto it): T − 0·e^x
            // is T for the x ≤ 0 here, bit for bit, without the exponential.
            bound
        } else {
            bound - (bound - u0) * (-(k * a) / span).exp()
        };
        s * u
    }

    /// g = (du/dΔ)/k in direction `dir` (> 0 or < 0) at the presliding torque `tau`: 1 in the
    /// elastic range, (T − u)/(T − β·T) beyond it (0 at the bound, negative above it); 0 when
    /// unloaded.
    #[inline]
    pub fn fraction<S: Scalar>(&self, tau: S, dir: f64, bound: S) -> S {
        if unloaded(bound.re()) {
            return S::c(0.0);
        }
        let u = if dir < 0.0 { -tau } else { tau };
        let limit = S::c(self.elastic_limit) * bound;
        if u.re() <= limit.re() {
            S::c(1.0)
        } else {
            (bound - u) / (bound - limit)
        }
    }

    /// The direction the fraction g is taken in: that of ω; at ω = 0 the unloading direction
    /// (where g = 1 in the elastic range), so the ω-derivatives at rest are the elastic ones
    /// (∂torque/∂ω = −t_d·k, ∂(dτ/dt)/∂ω = k), and the values (0 rate, no damping) are unchanged.
    #[inline]
    pub(crate) fn direction<S: Scalar>(&self, tau: S, omega: S) -> f64 {
        let w = omega.re();
        if w != 0.0 {
            w
        } else if tau.re() > 0.0 {
            -1.0
        } else {
            1.0
        }
    }

    /// dτ/dt = k·ω·g at angular velocity `omega` (rad/s): the Model Exchange derivative of the
    /// state (N·m/s).
    #[inline]
    pub fn rate<S: Scalar>(&self, tau: S, omega: S, bound: S) -> S {
        if unloaded(bound.re()) {
            return S::c(0.0);
        }
        let dir = self.direction(tau, omega);
        let u = if dir < 0.0 { -tau } else { tau };
        if u.re() < -bound.re() {
            // Beyond the bound behind the motion (after the bound fell): besides unloading
            // elastically, the excess relaxes over the transition's length (1 − β)·φ_s, as an
            // excess ahead of the motion does. Written without dividing by T, which may be tiny.
            let excess = -bound - u;
            return omega * (self.stiffness(bound) + excess / S::c((1.0 - self.elastic_limit) * self.angle));
        }
        self.stiffness(bound) * omega * self.fraction(tau, dir, bound)
    }

    /// The friction torque on the pin (N·m): −clamp(clamp(τ, −T, T) + c·ω·max(g, 0), −T, T),
    /// c the damping ([`Presliding::damping`]).
    #[inline]
    pub fn torque<S: Scalar>(&self, tau: S, omega: S, bound: S) -> S {
        if unloaded(bound.re()) {
            return S::c(0.0);
        }
        let held = clamp(tau, bound);
        let g = self.fraction(tau, self.direction(tau, omega), bound);
        if unloaded(g.re()) {
            return -held;
        }
        // The elastic deflection rate is at most ω (g > 1 only relaxes an excess state).
        let g = if g.re() > 1.0 { S::c(1.0) } else { g };
        // The contact transmits at most the sliding torque: the damping adds to the held
        // torque up to the bound (Coulomb's limit on the whole friction torque).
        -clamp(held + self.damping(self.stiffness(bound)) * omega * g, bound)
    }

    /// The power the joint dissipates (W) at the presliding torque `tau`, `omega` and `bound`:
    /// the friction's power −torque·ω less the rate τ·ż at which elastic energy is stored,
    /// τ·ω·(1 − g⁺) + c·g⁺·ω² ≥ 0 (τ clamped to the bound). In steady sliding (g = 0) it is
    /// |torque·ω| = T·|ω| bit for bit; in the elastic range (g = 1) only the damping c·ω².
    pub fn dissipation<S: Scalar>(&self, tau: S, omega: S, bound: S) -> S {
        let w = omega.re();
        if unloaded(bound.re()) || w == 0.0 {
            return S::c(0.0);
        }
        let held = clamp(tau, bound);
        let g = self.fraction(tau, w, bound);
        if unloaded(g.re()) {
            return abs(held * omega);
        }
        let c = self.damping(self.stiffness(bound));
        let g = if g.re() > 1.0 { S::c(1.0) } else { g };
        // The friction's power F·ω (F = −torque, the damping capped at the bound) less the
        // elastic power held·ż stored in the deflection: the plastic part and the damping part.
        let total = clamp(held + c * omega * g, bound);
        let plastic = held * omega * (S::c(1.0) - g);
        let plastic = if plastic.re() > 0.0 { plastic } else { S::c(0.0) };
        let damping = (total - held) * omega;
        let damping = if damping.re() > 0.0 { damping } else { S::c(0.0) };
        plastic + damping
    }
}

/// τ limited to [−T, T].
#[inline]
fn clamp<S: Scalar>(tau: S, bound: S) -> S {
    if tau.re() > bound.re() {
        bound
    } else if tau.re() < -bound.re() {
        -bound
    } else {
        tau
    }
}

/// |x|.
#[inline]
fn abs<S: Scalar>(x: S) -> S {
    if x.re() < 0.0 { -x } else { x }
}
