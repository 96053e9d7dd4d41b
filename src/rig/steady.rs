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
    /// The command's amplitude A (rad), for [`Self::at_with_command`].
    command_amplitude: f64,
    /// Per-component scale of u.
    pub scale: State,
}

impl Steady {
    /// The steady response to `command` with the constant friction torque −`signed_torque`
    /// (s·T_c; 0 for none).
    pub fn new(rig: &RigParams, command: SineCommand, signed_torque: f64) -> Self {
        let w = std::f64::consts::TAU * command.frequency;
        let (j, tau, kp, kd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain);
        // G(iΩ) = (kp + i kd Ω)/((kp − J Ω²) + i (kd Ω − τ J Ω³)).
        let (nr, ni) = (kp, kd * w);
        let (dr, di) = (kp - j * w * w, kd * w - tau * j * w * w * w);
        let den = dr * dr + di * di;
        let a = command.amplitude;
        let amp = (a * (nr * dr + ni * di) / den, a * (ni * dr - nr * di) / den);
        let size = amp.0.hypot(amp.1);
        let scale = State::from([1.0 + size, 1.0 + w * size, 1.0 + signed_torque.abs() + j * w * w * size, 1.0, 1.0, 1.0]);
        Self { omega: w, amp, torque: signed_torque, angle: -signed_torque / kp, inertia: j, command_amplitude: a, scale }
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
        let (s, c) = (w * t).sin_cos();
        let a = self.command_amplitude;
        let command = (a * s, a * w * c);
        // Im((iΩ)^k·(ar + i ai)·e^{iΩt}) for k = 0..3.
        let (ar, ai) = self.amp;
        let im0 = ar * s + ai * c;
        let im1 = w * (ar * c - ai * s);
        let im2 = -w * w * im0;
        let im3 = -w * w * im1;
        let j = self.inertia;
        (State::from([im0 + self.angle, im1, j * im2 + self.torque, 0.0, 0.0, 0.0]), State::from([im1, im2, j * im3, 0.0, 0.0, 0.0]), command)
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

    /// y_s solves the frictionless (constant friction) unsaturated loop: θ̇ = ω,
    /// J ω̇ = T_a − s·T_c, τ Ṫ_a = K_p(θ_cmd − θ) + K_d(θ̇_cmd − ω) − T_a, to round-off; and
    /// deviation_of/state_of are inverse.
    #[test]
    fn steady_response_solves_the_linear_loop() {
        let rig = RigParams::default();
        let cmd = SineCommand { amplitude: 0.7, frequency: 1.3 };
        let tc = -67.2;
        let st = Steady::new(&rig, cmd, tc);
        for k in 0..50u32 {
            let t = 0.037 * f64::from(k);
            let (y, dy) = st.at(t);
            let (c, cr) = cmd.at(t);
            let (_, _, (c2, cr2)) = st.at_with_command(t);
            assert_eq!((c2.to_bits(), cr2.to_bits()), (c.to_bits(), cr.to_bits()), "t = {t}");
            let r0 = dy[0] - y[1];
            let r1 = rig.inertia * dy[1] - (y[2] - tc);
            let r2 = rig.servo_time_constant * dy[2]
                - (rig.position_gain * (c - y[0]) + rig.velocity_gain * (cr - y[1]) - y[2]);
            assert!(r0.abs() < 1e-12 && r1.abs() < 1e-11 && r2.abs() < 1e-10, "t = {t}: {r0:e} {r1:e} {r2:e}");
            let u = State::from([0.1, -2.0, 3.0, 4.0, 5.0, t]);
            assert!((st.deviation_of(t, &st.state_of(t, &u)) - u).norm() < 1e-13);
        }
        // The lag of θ behind the command at 1.3 Hz is small but not zero (|G| ≈ 1).
        assert!((st.amp.0.hypot(st.amp.1) / 0.7 - 1.0).abs() < 0.05 && st.amp.1 != 0.0);
    }
}
