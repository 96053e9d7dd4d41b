//! The position loop's steady response to the sine command, for `Method::Dopri5Dense`.
//!
//! Without friction and saturation the loop of [`super::params`] is linear:
//! θ(s)/θ_cmd(s) = G(s) = (K_p + K_d s)/(τ_s J s³ + J s² + K_d s + K_p) (the derivative term acts
//! on θ̇_cmd − ω, so the command enters as K_p + K_d s). Its steady response to
//! θ_cmd = A sin Ωt is θ = Im(G(iΩ) A e^{iΩt}), ω = θ̇, T_a = J θ̈. A constant friction torque
//! −s·T_c (slip in direction s) adds the constant offsets T_a = s·T_c, θ = −s·T_c/K_p.
//!
//! `Dopri5Dense` integrates u = (y − y_s(t))/scale instead of y: an exact change of variables
//! (u̇ = (f(t, y_s + scale·u) − ẏ_s)/scale), so the equations are the same, friction,
//! saturation and all. What it removes is the large, fast-varying forcing of the command
//! through the loop (K_p·θ̇_cmd ≈ 26,000 N·m/s at 1 Hz): an explicit method's local error
//! contains terms like h⁶·A⁵·ḃ (A the loop's Jacobian, |λ| ≈ 490 1/s; b the forcing), which set
//! Dopri5's steps to ≈ 2.4 ms at tolerance 1e-5 however smooth the stroke is. Measured at
//! mid-stroke (t = 0.62 s, 20 kN, 1 Hz) over a 2.4 ms step: the speed's local error falls from
//! 1.2e-5 to 2.8e-8 rad/s and the actuator torque's from 8.6e-5 to 1.6e-6 N·m.
//! `scale` is 1 + the size of each component's steady response (θ: 1 + |G|A, ω: 1 + Ω|G|A,
//! T_a: 1 + T_c + JΩ²|G|A; W, D and t unscaled), so that the error norm's absolute tolerance
//! on u allows what its relative tolerance on y allowed.

use super::dynamics::State;
use super::excitation::SineCommand;
use super::linear_loop::{Loop, Propagator};
use super::params::RigParams;

/// y_s(t) and its rate for one segment, with the integration scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Steady {
    /// Ω = 2πf (rad/s).
    omega: f64,
    /// G(iΩ)·A, real and imaginary parts (rad).
    amp: (f64, f64),
    /// s·T_c (N·m): the constant friction's offset of T_a.
    torque: f64,
    /// Its offset of θ, −s·T_c/K_p (rad).
    angle: f64,
    /// J (kg·m²).
    inertia: f64,
    /// d (N·m·s/rad): the friction's linear part in the speed, J ω̇ = T_a − s·T_c + d·ω.
    damping: f64,
    /// The command's amplitude A (rad), for [`Self::at_with_command`].
    command_amplitude: f64,
    /// Per-component scale of u.
    pub scale: State,
    /// The loop's free response from the segment's start ([`Self::with_free_response`]).
    free: Option<Free>,
}

/// The free response of the linearised loop ([`Loop`]) from a deviation δ₀ at t₀:
/// e^{A(t−t₀)}δ₀ on the (θ, ω, T_a) part, by the loop's [`Propagator`].
#[derive(Debug, Clone, Copy, PartialEq)]
struct Free {
    t0: f64,
    /// δ₀ on the (θ, ω, T_a) part, 0 elsewhere.
    delta: State,
    lin: Loop,
    propagator: Propagator,
}

impl Free {
    /// The free response of `lin` from `delta` at `t0`; None when its free response does not
    /// decay or δ₀ is not finite.
    fn new(lin: &Loop, t0: f64, delta: [f64; 3]) -> Option<Self> {
        if !delta.iter().all(|x| x.is_finite()) {
            return None;
        }
        let delta = State::from([delta[0], delta[1], delta[2], 0.0, 0.0, 0.0]);
        Some(Self { t0, delta, lin: *lin, propagator: Propagator::new(lin)? })
    }

    /// (e^{A(t−t₀)}δ₀, A·e^{A(t−t₀)}δ₀).
    #[inline]
    fn at(&self, t: f64) -> ([f64; 3], [f64; 3]) {
        let y = self.propagator.propagate(t - self.t0, &self.delta);
        let y = [y[0], y[1], y[2]];
        (y, self.lin.apply_matrix(&y))
    }
}

impl Steady {
    /// The steady response to `command` with the constant friction torque −`signed_torque`
    /// (s·T_c; 0 for none).
    pub fn new(rig: &RigParams, command: SineCommand, signed_torque: f64, lin: &Loop) -> Self {
        let damping = lin.damping;
        let w = std::f64::consts::TAU * command.frequency;
        let (j, tau, kp, kd, dd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain, damping);
        // G(iΩ) = (kp + i kd Ω)/((kp − J Ω² + d τ Ω²) + i (kd Ω − τ J Ω³ − d Ω)), the
        // characteristic polynomial being (J s² − d s)(τ s + 1) + K_d s + K_p.
        let (nr, ni) = (kp, kd * w);
        let (dr, di) = (kp - j * w * w + dd * tau * w * w, kd * w - tau * j * w * w * w - dd * w);
        let den = dr * dr + di * di;
        let a = command.amplitude;
        let amp = (a * (nr * dr + ni * di) / den, a * (ni * dr - nr * di) / den);
        let size = amp.0.hypot(amp.1);
        let scale = State::from([1.0 + size, 1.0 + w * size, 1.0 + signed_torque.abs() + j * w * w * size, 1.0, 1.0, 1.0]);
        Self { omega: w, amp, torque: signed_torque, angle: -signed_torque / kp, inertia: j, damping, command_amplitude: a, scale, free: None }
    }

    /// (y_s(t), ẏ_s(t)); the W, D and t components are 0.
    pub fn at(&self, t: f64) -> (State, State) {
        let (ys, rate, _) = self.at_with_command(t);
        (ys, rate)
    }

    /// [`Self::at`] and the command (θ_cmd, θ̇_cmd) at `t` from the same sin/cos: bit for bit
    /// [`SineCommand::at`] of the command this response was built for (Ω = 2π f formed the same
    /// way), so the right-hand side needs one sin/cos an evaluation instead of two.
    pub fn at_with_command(&self, t: f64) -> (State, State, (f64, f64)) {
        let w = self.omega;
        let (s, c) = crate::numerics::fast_math::sin_cos(w * t);
        let a = self.command_amplitude;
        let command = (a * s, a * w * c);
        // Im((iΩ)^k·(ar + i ai)·e^{iΩt}) for k = 0..3.
        let (ar, ai) = self.amp;
        let im0 = ar * s + ai * c;
        let im1 = w * (ar * c - ai * s);
        let im2 = -w * w * im0;
        let im3 = -w * w * im1;
        let (j, d) = (self.inertia, self.damping);
        // T_a = J θ̈ − d θ̇ + s·T_c.
        let (mut ys, mut rate) = (
            State::from([im0 + self.angle, im1, j * im2 - d * im1 + self.torque, 0.0, 0.0, 0.0]),
            State::from([im1, im2, j * im3 - d * im2, 0.0, 0.0, 0.0]),
        );
        if let Some(f) = &self.free {
            let (y, dy) = f.at(t);
            for r in 0..3 {
                ys[r] += y[r];
                rate[r] += dy[r];
            }
        }
        (ys, rate, command)
    }

    /// This response plus the loop's free response from the deviation of `y0` from it at
    /// `t0` (see [`Free`]): the shift then equals `y0` at `t0`, and what is integrated is
    /// what the friction's departure from `lin` and the saturation add. Unchanged when the
    /// loop's free response does not decay ([`Loop::decays`]) or when the deviation is at most
    /// `negligible` of every component's scale (nothing worth subtracting).
    pub fn with_free_response(mut self, lin: &Loop, t0: f64, y0: &State, negligible: f64) -> Self {
        self.free = None;
        let ys = self.at(t0).0;
        let delta = [y0[0] - ys[0], y0[1] - ys[1], y0[2] - ys[2]];
        if (0..3).any(|r| (delta[r] / self.scale[r]).abs() > negligible) {
            self.free = Free::new(lin, t0, delta);
        }
        self
    }

    /// y from u at time t.
    pub fn state_of(&self, t: f64, u: &State) -> State {
        u.component_mul(&self.scale) + self.at(t).0
    }

    /// u from y at time t.
    pub fn deviation_of(&self, t: f64, y: &State) -> State {
        (y - self.at(t).0).component_div(&self.scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The residuals of the linearised loop θ̇ = ω, J ω̇ = T_a − s·T_c + d·ω,
    /// τ Ṫ_a = K_p(θ_cmd − θ) + K_d(θ̇_cmd − ω) − T_a at (y, ẏ), each relative to the size of
    /// its terms.
    fn loop_residuals(rig: &RigParams, cmd: SineCommand, tc: f64, d: f64, t: f64, y: &State, dy: &State) -> [f64; 3] {
        loop_residuals_floor(rig, cmd, tc, d, t, y, dy, [0.0; 3])
    }

    /// [`loop_residuals`] relative to at least `floor` (per equation).
    #[allow(clippy::too_many_arguments)]
    fn loop_residuals_floor(rig: &RigParams, cmd: SineCommand, tc: f64, d: f64, t: f64, y: &State, dy: &State, floor: [f64; 3]) -> [f64; 3] {
        let (c, cr) = cmd.at(t);
        let (j, tau, kp, kd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain);
        let rel = |r: f64, terms: &[f64], floor: f64| r.abs() / terms.iter().map(|x| x.abs()).sum::<f64>().max(floor).max(1e-300);
        [
            rel(dy[0] - y[1], &[dy[0], y[1]], floor[0]),
            rel(j * dy[1] - (y[2] - tc + d * y[1]), &[j * dy[1], y[2], tc, d * y[1]], floor[1]),
            rel(tau * dy[2] - (kp * (c - y[0]) + kd * (cr - y[1]) - y[2]), &[tau * dy[2], kp * c, kp * y[0], kd * cr, kd * y[1], y[2]], floor[2]),
        ]
    }

    /// y_s solves the loop (constant friction, with and without the friction's linear part d,
    /// unsaturated) to round-off; deviation_of/state_of are inverse; with a free response the
    /// shift starts at the given state and still solves the loop, and its rate is its
    /// derivative.
    #[test]
    fn steady_response_solves_the_linear_loop() {
        let rig = RigParams::default();
        let cmd = SineCommand { amplitude: 0.7, frequency: 1.3 };
        let tc = -67.2;
        for d in [0.0, 3.1, -25.0] {
            let lin = Loop::new(&rig, d);
            assert!(lin.decays(), "{d}");
            let st = Steady::new(&rig, cmd, tc, &lin);
            for k in 0..50u32 {
                let t = 0.037 * f64::from(k);
                let (y, dy) = st.at(t);
                let (c, cr) = cmd.at(t);
                let (_, _, (c2, cr2)) = st.at_with_command(t);
                assert_eq!((c2.to_bits(), cr2.to_bits()), (c.to_bits(), cr.to_bits()), "t = {t}");
                let r = loop_residuals(&rig, cmd, tc, d, t, &y, &dy);
                assert!(r.iter().all(|x| *x < 1e-13), "d = {d}, t = {t}: {r:?}");
                let u = State::from([0.1, -2.0, 3.0, 4.0, 5.0, t]);
                assert!((st.deviation_of(t, &st.state_of(t, &u)) - u).norm() < 1e-13);
            }
            // With the free response from a deviation at t0.
            let y0 = State::from([0.01, -0.3, 25.0, 0.0, 0.0, 0.2]);
            let sf = st.with_free_response(&lin, 0.2, &y0, 0.0);
            assert!(sf.free.is_some());
            let (y, _) = sf.at(0.2);
            for r in 0..3 {
                assert!((y[r] - y0[r]).abs() < 1e-12 * (1.0 + y0[r].abs()), "{r}: {} vs {}", y[r], y0[r]);
            }
            // As the free response decays, its rounding (from the start's size) is measured
            // against the terms' size at the start.
            let (y, dy) = sf.at(0.2);
            let (c, cr) = cmd.at(0.2);
            let (j, tau, kp, kd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain);
            let floor = [
                dy[0].abs() + y[1].abs(),
                (j * dy[1]).abs() + y[2].abs() + tc.abs() + (d * y[1]).abs(),
                (tau * dy[2]).abs() + (kp * c).abs() + (kp * y[0]).abs() + (kd * cr).abs() + (kd * y[1]).abs() + y[2].abs(),
            ];
            for k in 0..50u32 {
                let t = 0.2 + 0.0013 * f64::from(k);
                let (y, dy) = sf.at(t);
                let r = loop_residuals_floor(&rig, cmd, tc, d, t, &y, &dy, floor);
                // Sylvester's modes P_k·δ₀ are ~10× δ₀ and cancel: rounding at ~1e-11 (an
                // error in the formulas would show at O(1)).
                assert!(r.iter().all(|x| *x < 1e-10), "d = {d}, t = {t}: {r:?}");
                let e = 1e-7;
                let fd = (sf.at(t + e).0 - sf.at(t - e).0) / (2.0 * e);
                for r in 0..3 {
                    assert!((fd[r] - dy[r]).abs() < 1e-5 * (1.0 + dy[r].abs()), "t = {t}, {r}: {} vs {}", fd[r], dy[r]);
                }
            }
            // A deviation below `negligible` of the scale is not subtracted.
            let small = st.at(0.2).0 + State::from([1e-9, 0.0, 0.0, 0.0, 0.0, 0.0]);
            assert!(st.with_free_response(&lin, 0.2, &small, 1e-6).free.is_none());
        }
        // A loop destabilised by a friction falling fast enough with speed has no free response.
        assert!(!Loop::new(&rig, 200.0).decays());
        let st = Steady::new(&rig, cmd, tc, &Loop::new(&rig, 0.0));
        // The lag of θ behind the command at 1.3 Hz is small but not zero (|G| ≈ 1).
        assert!((st.amp.0.hypot(st.amp.1) / 0.7 - 1.0).abs() < 0.05 && st.amp.1 != 0.0);
    }
}
