//! Dormand–Prince 5(4) in Lawson (integrating-factor) form, for the slip phases of
//! `Method::Dopri5Dense`.
//!
//! In slip the rig's deviation z = y − y_s(t) from the linearised loop's steady response
//! (`rig/steady.rs`) obeys ż = L z + F(t, z), where L is the linearised loop's matrix A on the
//! (θ, ω, T_a) part (zero on W, D and t) and F(t, z) = f(t, y_s + z) − ẏ_s − L z is what the
//! friction's departure from its linear part, the saturation and the energy integrals add
//! (Lawson, *Generalized Runge–Kutta processes for stable systems with large Lipschitz
//! constants*, SIAM J. Numer. Anal. 4, 1967). With v(t) = e^{−L(t−tₙ)} z(t) over a step,
//! v̇ = e^{−L(t−tₙ)} F(t, e^{L(t−tₙ)} v), which Dopri5 integrates: its stages are
//! Zᵢ = e^{cᵢhL}(zₙ + h Σⱼ aᵢⱼ Kⱼ), Kⱼ = e^{−cⱼhL} F(tₙ + cⱼh, Zⱼ), and zₙ₊₁ = Z₇.
//!
//! The linear part is then solved exactly, whatever the step: the loop's 78 Hz mode (the
//! eigenvalues −83 ± 482i 1/s of the default rig) no longer bounds an explicit method's
//! step by its stability, and the transient it rings with after every breakaway costs no
//! steps. The step is set by how fast F varies: at the default rig's 20 kN the friction is
//! within 1 % of linear in the speed, so F is small and smooth. For F = 0 the method is
//! exact; in general it keeps Dopri5's order (5, and 4 for its continuous extension and the
//! embedded error estimate), which the tests below check against an independent integration.
//!
//! e^{τA} is taken in modal form, V diag(e^{λₖτ}) V⁻¹, with A's eigenvalues from
//! [`Loop`] (distinct and decaying, else this method is not used) and eigenvectors
//! (1, λ, Jλ² − dλ) read from A's rows.
//!
//! The step-size control is `ode_solvers`' Dopri5's (Hairer's): the same PI controller
//! (safety 0.9, β = 0.04, factors 0.2–10), error norm and tolerances, measured on the
//! deviation divided by the integration scale of `rig/steady.rs`.

use super::dynamics::State;
use super::linear_loop::Propagator;
#[cfg(test)]
use super::linear_loop::Loop;
#[cfg(test)]
use nalgebra::{Matrix3, Vector3};

/// Monomial coefficients of the cubic through σ = 0, 3/10, 4/5, 1 (Dopri5's c₁, c₃, c₄, c₇):
/// gₖ = Σᵢ `FIT[k][i]`·Gᵢ (the inverse Vandermonde matrix, exact fractions).
const FIT: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [-67.0 / 12.0, 160.0 / 21.0, -15.0 / 4.0, 12.0 / 7.0],
    [35.0 / 4.0, -120.0 / 7.0, 65.0 / 4.0, -55.0 / 7.0],
    [-25.0 / 6.0, 200.0 / 21.0, -25.0 / 2.0, 50.0 / 7.0],
];

/// Dormand–Prince 5(4): nodes, coefficients, the 5th-order weights (the 7th stage's row),
/// the error weights b − b̂ and the continuous extension's (Hairer, Nørsett and Wanner,
/// *Solving ODEs I*, II.5 and II.6; the same tables as `ode_solvers`).
mod tableau {
    pub const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
    pub const A: [[f64; 6]; 7] = [
        [0.0; 6],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
        [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
        [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
        [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
    ];
    pub const E: [f64; 7] = [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];
    #[allow(dead_code)] // Hairer's continuous extension, replaced by exponential quadrature
    pub const D: [f64; 7] = [
        -12715105075.0 / 11282082432.0,
        0.0,
        87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0,
        701980252875.0 / 199316789632.0,
        -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0,
    ];
}

/// One accepted step's continuous extension by exponential quadrature: with G(σ) the cubic
/// through F at σ = 0, 3/10, 4/5, 1 (the stages' values, σ = (t − tₙ)/h),
/// z(tₙ + θh) = e^{θhL}zₙ + h∫₀^θ e^{(θ−σ)hL}G(σ)dσ + θ·m, m making it zₙ₊₁ at θ = 1 (m is
/// of the order of the step's error). The linear part is exact between nodes as at them;
/// only F, which varies slowly, is interpolated, so its accuracy does not fall with h|λ|
/// as a polynomial in the turning frame's would (Hairer's 4th-order extension of Dopri5,
/// used there, gave 2.6e-4 torque errors at 0.5 ms samples for 1.0e-4 at the nodes).
#[derive(Debug, Clone, PartialEq)]
struct DenseStep {
    t: f64,
    h: f64,
    z: State,
    g: [State; 4],
    mismatch: State,
}

/// The continuous extension of a run's accepted steps (deviations z).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LawsonDense {
    propagator: Propagator,
    steps: Vec<DenseStep>,
}

impl LawsonDense {
    /// z at `t` within the steps integrated (None outside them).
    pub fn evaluate(&self, t: f64) -> Option<State> {
        let first = self.steps.first()?;
        let last = self.steps.last()?;
        if !(t >= first.t && t <= last.t + last.h) {
            return None;
        }
        // The last step starting at or before t.
        let k = self.steps.partition_point(|s| s.t <= t).max(1) - 1;
        let s = &self.steps[k];
        let th = if s.h > 0.0 { ((t - s.t) / s.h).clamp(0.0, 1.0) } else { 0.0 };
        Some(self.propagator.propagate(th * s.h, &s.z) + self.propagator.quadrature(th, s.h, &s.g) + s.mismatch * th)
    }
}

/// Tolerances and bounds of one run.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Control {
    pub rtol: f64,
    pub atol: f64,
    /// Per-component scale: the error of component i is measured on zᵢ/scaleᵢ.
    pub scale: State,
    pub h_max: f64,
    /// Most step attempts (accepted and rejected).
    pub max_attempts: u32,
}

/// What a run gives: the accepted (t, z), the start included, and their continuous extension.
pub(crate) type Run = (Vec<f64>, Vec<State>, LawsonDense);

/// Largest |Re λ|·h of a step (see [`integrate`]).
const MAX_DECAY_PER_STEP: f64 = 10.0;

/// RMS of (xᵢ/skᵢ).
fn norm(x: &State, sk: &State) -> f64 {
    (x.component_div(sk).norm_squared() / 6.0).sqrt()
}

/// Integrate ż = Lz + F(t, z) from (t0, z0) towards t1 with first step `h0` (0: chosen from
/// the start), calling `stop(t, z)` after every accepted step; the run ends at t1 or at the
/// first accepted step `stop` returns true for. `f` is F; the time is also z's last component.
/// Err (with a message) on a non-finite error estimate persisting to a step-size underflow,
/// or when `max_attempts` steps were tried.
#[allow(clippy::too_many_arguments)]
pub(crate) fn integrate(
    p: &Propagator,
    f: &mut dyn FnMut(f64, &State) -> State,
    t0: f64,
    z0: State,
    t1: f64,
    h0: f64,
    ctl: &Control,
    stop: &mut dyn FnMut(f64, &State) -> bool,
) -> Result<Run, String> {
    use tableau::{A, C, E};
    let (mut t, mut z) = (t0, z0);
    // Kⱼ = e^{−cⱼhL}(F(tₙ + cⱼh, Zⱼ) − Fₙ): the step's initial forcing Fₙ is integrated
    // exactly (Zᵢ = e^{cᵢhL}Vᵢ + ∫₀^{cᵢh} e^{sL}Fₙ ds), so K₁ = 0 and the method's frame turns
    // only what changes in F over the step (Krogstad's generalised integrating factor of
    // degree 0). Without it (plain Lawson) a constant F turned by e^{−τL} is a 78 Hz
    // integrand that the embedded estimate misses at h|λ| ≳ 3 (measured: errors of 1e-4
    // at tolerance 1e-5 with the estimate satisfied).
    let mut k = [State::zeros(); 7];
    let mut forcing = f(t, &z);
    let sk = |a: &State, b: &State| State::from_fn(|i, _| ctl.atol * ctl.scale[i] + ctl.rtol * a[i].abs().max(b[i].abs()));
    let mut h = if h0 > 0.0 { h0 } else { initial_step(p, f, t, &z, &forcing, t1 - t0, &sk) };
    // The stages are formed in the frame of tₙ, where a mode decaying as e^{λτ} is scaled up by
    // e^{−λcⱼh}: beyond |Re λ|·h = 10 (a factor 2e4, four digits of the stage values) the
    // rounding of a fast mode would swamp the slow ones. The default rig's fastest decay,
    // 167 1/s, allows 60 ms (more than a segment); a stiffer loop gets shorter steps.
    let h_max = ctl.h_max.min(MAX_DECAY_PER_STEP / p.fastest_decay());
    h = h.min(h_max).min(t1 - t0);
    let (mut ts, mut zs, mut steps) = (vec![t0], vec![z0], Vec::new());
    let (alpha, beta, safety, facc1, facc2): (f64, f64, f64, f64, f64) = (0.2 - 0.04 * 0.75, 0.04, 0.9, 1.0 / 0.2, 1.0 / 10.0);
    let (mut fac_old, mut rejected) = (1e-4f64, false);
    let mut attempts = 0u32;
    loop {
        attempts += 1;
        if attempts > ctl.max_attempts {
            return Err(format!("more than {} step attempts", ctl.max_attempts));
        }
        if 0.1 * h.abs() <= f64::EPSILON * t.abs() || !h.is_finite() {
            return Err(format!("step size underflow at t = {t}"));
        }
        let last = t + 1.01 * h >= t1;
        if last {
            h = t1 - t;
        }
        // Stages 2..7 in the frame of tₙ: Vᵢ = zₙ + h Σ aᵢⱼKⱼ, Zᵢ = e^{cᵢhL}Vᵢ, Kᵢ = e^{−cᵢhL}F(Zᵢ).
        let mut raw_last = State::zeros();
        let mut raws = [forcing; 4];
        let mut z_next = z;
        for s in 1..7 {
            let mut v = z;
            for (j, kj) in k.iter().enumerate().take(s).skip(1) {
                if A[s][j] != 0.0 {
                    v += kj * (h * A[s][j]);
                }
            }
            let e = p.modal(C[s] * h);
            let zs_ = p.apply(&e, &v) + p.integral(C[s] * h, &forcing);
            let raw = f(t + C[s] * h, &zs_);
            match s {
                2 => raws[1] = raw,
                3 => raws[2] = raw,
                6 => raws[3] = raw,
                _ => {}
            }
            let inv = e.map(|x| x.inv());
            k[s] = p.apply(&inv, &(raw - forcing));
            if s == 6 {
                (z_next, raw_last) = (zs_, raw);
            }
        }
        // The error estimate, brought to tₙ₊₁'s frame.
        let mut err_v = State::zeros();
        for (j, kj) in k.iter().enumerate().skip(1) {
            if E[j] != 0.0 {
                err_v += kj * (h * E[j]);
            }
        }
        let err_z = p.propagate(h, &err_v);
        let err = norm(&err_z, &sk(&z, &z_next));
        // The PI controller of `ode_solvers` 0.6 (Hairer's DOPRI5).
        let fac11 = if err.is_finite() { err.powf(alpha) } else { f64::INFINITY };
        let fac = facc2.max(facc1.min(fac11 * fac_old.powf(-beta) / safety));
        let mut h_new = h / fac;
        if err <= 1.0 {
            fac_old = err.max(1e-4);
            h_new = h_new.min(h_max);
            if rejected {
                h_new = h_new.min(h);
            }
            rejected = false;
            // The continuous extension (see `DenseStep`).
            let g: [State; 4] = std::array::from_fn(|kk| (0..4).fold(State::zeros(), |acc, i| acc + raws[i] * FIT[kk][i]));
            let end = p.propagate(h, &z) + p.quadrature(1.0, h, &g);
            steps.push(DenseStep { t, h, z, g, mismatch: z_next - end });
            t = if last { t1 } else { t + h };
            z = z_next;
            z[5] = t;
            // FSAL: F at zₙ₊₁ is the next step's forcing.
            forcing = raw_last;
            ts.push(t);
            zs.push(z);
            if stop(t, &z) || last {
                return Ok((ts, zs, LawsonDense { propagator: *p, steps }));
            }
        } else {
            h_new = h / facc1.min(fac11 / safety);
            rejected = true;
        }
        h = if h_new.is_finite() { h_new } else { 0.1 * h };
    }
}

/// Hairer's starting step (*Solving ODEs I*, II.4) on ż = Lz + F, with the norms of the
/// error test; two evaluations of F.
fn initial_step(
    p: &Propagator,
    f: &mut dyn FnMut(f64, &State) -> State,
    t: f64,
    z: &State,
    f0: &State,
    span: f64,
    sk: &dyn Fn(&State, &State) -> State,
) -> f64 {
    let scale = sk(z, z);
    let (d0, d1) = (norm(z, &scale), norm(f0, &scale));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 }.min(span);
    let z1 = p.propagate(h0, z) + p.integral(h0, f0);
    let f1 = f(t + h0, &z1);
    let d2 = norm(&(f1 - f0), &scale) / h0;
    let h1 = if d1.max(d2) <= 1e-15 { (h0 * 1e-3).max(1e-6) } else { (0.01 / d1.max(d2)).powf(0.2) };
    (100.0 * h0).min(h1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rig::params::RigParams;

    fn loop_and_propagator(d: f64) -> (RigParams, Loop, Propagator) {
        let rig = RigParams::default();
        let lin = Loop::new(&rig, d);
        let p = Propagator::new(&lin).expect("the default loop decays");
        (rig, lin, p)
    }

    fn matrix(rig: &RigParams, d: f64) -> Matrix3<f64> {
        let (j, tau, kp, kd) = (rig.inertia, rig.servo_time_constant, rig.position_gain, rig.velocity_gain);
        Matrix3::new(0.0, 1.0, 0.0, 0.0, d / j, 1.0 / j, -kp / tau, -kd / tau, -1.0 / tau)
    }

    /// The modal e^{τA} against nalgebra's matrix exponential (scaling and squaring, an
    /// independent method), on both sides of τ = 0.
    #[test]
    fn the_propagator_is_the_matrix_exponential() {
        for d in [0.0, 3.1, -20.0] {
            let (rig, _, p) = loop_and_propagator(d);
            let a = matrix(&rig, d);
            let x = State::from([0.013, -0.7, 31.0, 5.0, 6.0, 7.0]);
            for tau in [0.0, 1e-4, 2.5e-3, -2.5e-3, 0.011, 0.05] {
                let reference = (a * tau).exp() * Vector3::new(x[0], x[1], x[2]);
                let got = p.propagate(tau, &x);
                for r in 0..3 {
                    let size = reference.iter().map(|v| v.abs()).fold(0.0, f64::max) + x.iter().take(3).map(|v| v.abs()).fold(0.0, f64::max);
                    assert!((got[r] - reference[r]).abs() <= 1e-12 * size, "d {d} tau {tau} row {r}: {} vs {}", got[r], reference[r]);
                }
                assert_eq!((got[3], got[4], got[5]), (5.0, 6.0, 7.0));
            }
            // ∫₀^τ e^{sA} ds·x = A⁻¹(e^{τA} − I)x, and τx on W, D, t; small τ by its series.
            for tau in [1e-12, 1e-7, 2.5e-3, 0.05] {
                let reference = a.try_inverse().unwrap() * ((a * tau).exp() - Matrix3::identity()) * Vector3::new(x[0], x[1], x[2]);
                let series = Vector3::new(x[0], x[1], x[2]) * tau + a * Vector3::new(x[0], x[1], x[2]) * (0.5 * tau * tau);
                let reference = if tau < 1e-9 { series } else { reference };
                let got = p.integral(tau, &x);
                let size = reference.iter().map(|v| v.abs()).fold(0.0, f64::max);
                for r in 0..3 {
                    assert!((got[r] - reference[r]).abs() <= 1e-10 * size, "d {d} tau {tau} row {r}: {} vs {}", got[r], reference[r]);
                }
                assert_eq!((got[3], got[4], got[5]), (5.0 * tau, 6.0 * tau, 7.0 * tau));
            }
            // e^{τA} e^{−τA} = I.
            let back = p.propagate(-0.02, &p.propagate(0.02, &x));
            assert!((back - x).norm() < 1e-11 * x.norm(), "{back:?}");
        }
    }

    fn control(tol: f64, h_max: f64) -> Control {
        Control { rtol: tol, atol: tol, scale: State::repeat(1.0), h_max, max_attempts: 100_000 }
    }

    /// For ż = Lz (+ a constant rate on W and t) the method is exact: any step, to round-off.
    #[test]
    fn linear_problems_are_solved_exactly_in_a_few_steps() {
        let (rig, _, p) = loop_and_propagator(3.1);
        let z0 = State::from([0.02, 0.4, -30.0, 1.0, 0.0, 0.0]);
        let mut f = |_t: f64, _z: &State| State::from([0.0, 0.0, 0.0, 2.0, 0.0, 1.0]);
        let (ts, zs, dense) = integrate(&p, &mut f, 0.0, z0, 0.3, 0.0, &control(1e-6, 1.0), &mut |_, _| false).unwrap();
        // Steps of the largest size allowed, 10/|Re λ| (60 ms here): nothing else limits them.
        let cap = (0.3 * p.fastest_decay() / MAX_DECAY_PER_STEP).ceil() as usize;
        assert!(ts.len() - 1 <= cap + 1, "{} steps for {cap}", ts.len() - 1);
        let exact = |t: f64| {
            let b = (matrix(&rig, 3.1) * t).exp() * Vector3::new(z0[0], z0[1], z0[2]);
            State::from([b[0], b[1], b[2], 1.0 + 2.0 * t, 0.0, t])
        };
        let z1 = zs.last().unwrap();
        assert!((z1 - exact(0.3)).norm() < 1e-12 * 30.0, "{z1:?} vs {:?}", exact(0.3));
        for t in [0.0, 0.01, 0.123, 0.3] {
            let z = dense.evaluate(t).unwrap();
            assert!((z - exact(t)).norm() < 1e-11 * 30.0, "t = {t}: {z:?} vs {:?}", exact(t));
        }
        assert!(dense.evaluate(0.31).is_none() && dense.evaluate(-0.01).is_none());
    }

    /// A problem coupling the loop to a nonlinear, time-dependent F: fixed steps h and h/2
    /// against a Dop853 (`ode_solvers`) integration of ż = Az + F at 1e-13 give the ratios of
    /// a 5th-order method at the nodes and of a 4th-order one for the continuous extension.
    #[test]
    fn fifth_order_at_the_nodes_and_fourth_in_between() {
        // A slower loop (|λ| ≈ 5–20 1/s), so that steps of 10–20 ms are in the asymptotic
        // regime (h|λ| < 1) with errors far above round-off.
        let rig = RigParams { inertia: 5.0, position_gain: 600.0, velocity_gain: 200.0, servo_time_constant: 0.05, ..RigParams::default() };
        let lin = Loop::new(&rig, 3.1);
        let p = Propagator::new(&lin).unwrap();
        let a = matrix(&rig, 3.1);
        // The time is read from the state (ode_solvers' Dop853 evaluates its last stage at the
        // wrong time: `rig/dynamics.rs`).
        let nonlinear = |_: f64, z: &State| {
            let t = z[5];
            State::from([0.0, 4.0 * (z[1] * z[1]).tanh() + 3.0 * (7.0 * t).sin(), 50.0 * (3.0 * t).cos(), z[1] * z[2], 0.0, 1.0])
        };
        let full = |t: f64, z: &State| {
            let b = a * Vector3::new(z[0], z[1], z[2]);
            nonlinear(t, z) + State::from([b[0], b[1], b[2], 0.0, 0.0, 0.0])
        };
        struct Sys<F: Fn(f64, &State) -> State>(F);
        impl<F: Fn(f64, &State) -> State> ode_solvers::System<f64, State> for Sys<F> {
            fn system(&self, t: f64, y: &State, dy: &mut State) {
                *dy = (self.0)(t, y);
            }
        }
        let z0 = State::from([0.01, 0.5, -20.0, 0.0, 0.0, 0.0]);
        let reference = |t_end: f64| {
            let mut s = ode_solvers::Dop853::from_param(
                Sys(full), 0.0, t_end, t_end, z0, 1e-13, 1e-13, 0.9, 0.0, 0.333, 6.0, t_end, 0.0, 10_000_000, u32::MAX, ode_solvers::OutputType::Sparse,
            );
            s.integrate().unwrap();
            *s.y_out().last().unwrap()
        };
        let t_end = 1.0;
        // The continuous extension's error: its largest over 0.1 ≤ t ≤ 0.2 (every θ).
        let grid: Vec<f64> = (0..=50).map(|i| 0.1 + 0.002 * f64::from(i)).collect();
        let node_ref = reference(t_end);
        let mid_ref: Vec<State> = grid.iter().map(|&t| reference(t)).collect();
        let errors = |h: f64| {
            let mut f = |t: f64, z: &State| nonlinear(t, z);
            let (_, zs, dense) = integrate(&p, &mut f, 0.0, z0, t_end, h, &control(1e10, h), &mut |_, _| false).unwrap();
            ((zs.last().unwrap() - node_ref).norm(), grid.iter().zip(&mid_ref).map(|(&t, r)| (dense.evaluate(t).unwrap() - r).norm()).fold(0.0, f64::max))
        };
        let (e1, m1) = errors(0.02);
        let (e2, m2) = errors(0.01);
        let (node_ratio, mid_ratio) = (e1 / e2, m1 / m2);
        eprintln!("nodes: {e1:e} / {e2:e} = {node_ratio}; continuous extension: {m1:e} / {m2:e} = {mid_ratio}");
        assert!(node_ratio > 20.0 && node_ratio < 50.0, "nodes: {e1:e} / {e2:e} = {node_ratio}");
        assert!(mid_ratio > 12.0, "continuous extension: {m1:e} / {m2:e} = {mid_ratio}");
    }

    /// A stiff loop (τ_s = 1e-6 s: a mode decaying at ~1e6 1/s) gets steps of at most
    /// 10/|Re λ| and still solves a linear problem exactly.
    #[test]
    fn a_stiff_loop_keeps_its_precision() {
        let rig = RigParams { servo_time_constant: 1e-6, ..RigParams::default() };
        let lin = Loop::new(&rig, 0.0);
        let p = Propagator::new(&lin).expect("decays");
        assert!(p.fastest_decay() > 1e5, "{}", p.fastest_decay());
        let z0 = State::from([0.02, 0.4, -30.0, 0.0, 0.0, 0.0]);
        let mut f = |_t: f64, _z: &State| State::from([0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        let (ts, zs, _) = integrate(&p, &mut f, 0.0, z0, 0.01, 0.0, &control(1e-6, 1.0), &mut |_, _| false).unwrap();
        let steps: Vec<f64> = ts.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(steps.iter().all(|&h| h * p.fastest_decay() <= 10.0 * (1.0 + 1e-12)), "{steps:?}");
        let exact = (matrix(&rig, 0.0) * 0.01).exp() * Vector3::new(z0[0], z0[1], z0[2]);
        let z1 = zs.last().unwrap();
        for r in 0..3 {
            assert!((z1[r] - exact[r]).abs() <= 1e-9 * (1.0 + exact[r].abs()), "row {r}: {} vs {}", z1[r], exact[r]);
        }
    }

    /// The controller keeps the error near the tolerance and `stop` ends the run at the step.
    #[test]
    fn adaptive_steps_meet_the_tolerance_and_stop_where_asked() {
        let (_, _, p) = loop_and_propagator(0.0);
        let mut f = |t: f64, z: &State| State::from([0.0, 200.0 * (40.0 * t).sin() - 5.0 * z[1] * z[1].abs(), 0.0, 0.0, 0.0, 1.0]);
        let z0 = State::from([0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let run = |tol: f64| integrate(&p, &mut f.clone(), 0.0, z0, 0.5, 0.0, &control(tol, 1.0), &mut |_, _| false).unwrap();
        let (_, loose, _) = run(1e-6);
        let (ts, tight, _) = run(1e-11);
        let e_loose = (loose.last().unwrap() - tight.last().unwrap()).norm();
        assert!(e_loose < 1e-4 && e_loose > 0.0, "{e_loose:e}");
        assert!(ts.len() > 10);
        let (ts, _, _) = integrate(&p, &mut f, 0.0, z0, 0.5, 0.0, &control(1e-8, 1.0), &mut |t, _| t > 0.1).unwrap();
        let end = *ts.last().unwrap();
        assert!(end > 0.1 && end < 0.2 && ts[ts.len() - 2] <= 0.1, "{end}");
    }
}
