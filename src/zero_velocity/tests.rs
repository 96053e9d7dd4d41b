//! Tests of the zero-velocity laws against independent references: a fine Runge–Kutta
//! integration of the presliding ODE, the semigroup identity of an exact update, central
//! differences for the partials, and the limits (elastic range, steady sliding).

use super::band;
use super::jet::Jet;
use super::joint::{bound_jet, bound_partials, state_partials, PreslidingJoint};
use super::presliding::Presliding;
use super::{ZeroVelocityError, ZeroVelocityModel};

fn law() -> Presliding {
    Presliding::new(1.5e-3, 0.9, 0.01).unwrap()
}

/// du/dΔ of the law written out directly (the reference for the exact update).
fn slope(l: &Presliding, u: f64, t: f64) -> f64 {
    let k = t / l.angle;
    let lim = l.elastic_limit * t;
    if u <= lim { k } else { k * (t - u) / (t - lim) }
}

/// τ after `delta` by classical RK4 in n steps (u along the motion).
fn rk4(l: &Presliding, tau: f64, delta: f64, t: f64, n: usize) -> f64 {
    let s = delta.signum();
    let h = delta.abs() / n as f64;
    let mut u = s * tau;
    for _ in 0..n {
        let k1 = slope(l, u, t);
        let k2 = slope(l, u + 0.5 * h * k1, t);
        let k3 = slope(l, u + 0.5 * h * k2, t);
        let k4 = slope(l, u + h * k3, t);
        u += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    s * u
}

/// A deterministic sequence in [0, 1) (SplitMix64), so the cases are reproducible.
struct Draw(u64);
impl Draw {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

#[test]
fn the_update_is_the_exact_solution_of_the_ode() {
    let mut d = Draw(1);
    for _ in 0..400 {
        let beta = d.range(0.0, 0.99);
        let l = Presliding::new(d.range(1e-4, 1e-2), beta, 0.01).unwrap();
        let t = d.range(1.0, 300.0);
        let tau = d.range(-1.2, 1.2) * t;
        let delta = d.range(-4.0, 4.0) * l.angle;
        let exact = l.deflect(tau, delta, t);
        // RK4 loses order across the kink at the elastic limit: many small steps. A state
        // beyond the bound is first projected onto it (the update's return mapping).
        let reference = rk4(&l, tau.clamp(-t, t), delta, t, 20_000);
        assert!((exact - reference).abs() <= 1e-7 * t, "beta {beta} tau {tau} delta {delta} T {t}: {exact} vs {reference}");
    }
}

#[test]
fn two_updates_in_one_direction_are_one_update() {
    let mut d = Draw(2);
    let l = law();
    for _ in 0..1000 {
        let t = d.range(1.0, 300.0);
        let tau = d.range(-1.0, 1.0) * t;
        let s = if d.next() < 0.5 { -1.0 } else { 1.0 };
        let (a, b) = (s * d.range(0.0, 3.0) * l.angle, s * d.range(0.0, 3.0) * l.angle);
        let once = l.deflect(tau, a + b, t);
        let twice = l.deflect(l.deflect(tau, a, t), b, t);
        assert!((once - twice).abs() <= 1e-12 * t, "{once} vs {twice}");
    }
}

#[test]
fn the_update_is_bounded_for_any_increment() {
    let l = law();
    let t = 67.2;
    for &tau in &[-t, -0.5 * t, 0.0, 0.93 * t, t] {
        for &delta in &[1e300, -1e300, 1.0, -1.0, 1e-300, -1e-300, 5e-324, f64::MAX, f64::MIN] {
            let next = l.deflect(tau, delta, t);
            assert!(next.is_finite() && next.abs() <= t, "tau {tau} delta {delta}: {next}");
        }
    }
    // Beyond the bound (the load dropped): projected onto it, then the increment: never
    // beyond it, and a reversal unloads from the bound, not from the excess.
    for &delta in &[1e-6, 1e-3, 1.0, 1e300] {
        assert_eq!(l.deflect(1.5 * t, delta, t), t);
        let back = l.deflect(1.5 * t, -delta, t);
        assert!(back < t && back >= -t, "{back}");
        assert!((back - l.deflect(t, -delta, t)).abs() <= 1e-12 * t);
    }
    // So friction never pushes along a reversal for longer than the elastic unloading from
    // the bound (2 phi_s): after a load drop from 60 kN to 6 kN, unloading from the projected
    // state crosses zero within phi_s.
    let (high, low) = (201.6, 20.16);
    let crossed = l.deflect(-high, l.angle * 1.000_001, low);
    assert!(crossed >= 0.0, "{crossed}");
    // A huge slide ends exactly at the bound, in both directions.
    assert_eq!(l.deflect(0.0, 1.0, t), t);
    assert_eq!(l.deflect(0.0, -1.0, t), -t);
    // Unloaded: nothing is held.
    assert_eq!(l.deflect(30.0, 1e-3, 0.0), 0.0);
}

#[test]
fn below_the_elastic_limit_cycles_return_to_their_start() {
    let l = law();
    let t = 201.6;
    let k = t / l.angle;
    // A cycle whose peak stays at 0.85 T < beta T = 0.9 T: purely elastic, no drift.
    let mut tau = 0.2 * t;
    let amplitude = 0.65 * t / k;
    for _ in 0..1000 {
        tau = l.deflect(tau, amplitude, t);
        assert!(tau <= 0.9 * t);
        tau = l.deflect(tau, -amplitude, t);
    }
    assert!((tau - 0.2 * t).abs() < 1e-9 * t, "{tau}");
}

#[test]
fn in_steady_sliding_the_torque_is_the_models_bit_for_bit() {
    let l = Presliding::default();
    for &t in &[16.8, 67.2, 201.6] {
        for &w in &[1e-6_f64, 0.01, 0.2, 4.4, -0.2, -83.8] {
            let mut j = PreslidingJoint::new(l, 0.0);
            // Slide 2 degrees in the direction of w, in 100 steps.
            for i in 1..=100 {
                j.commit(w.signum() * 0.035 * f64::from(i) / 100.0, t);
            }
            let torque = j.torque_at(j.reference_angle(), w, t);
            assert_eq!(torque.to_bits(), crate::joint::opposing(t, w).to_bits(), "T {t} w {w}");
        }
    }
}

#[test]
fn the_rate_is_the_derivative_of_the_update() {
    let mut d = Draw(3);
    let l = law();
    for _ in 0..500 {
        let t = d.range(1.0, 300.0);
        let tau = d.range(-1.0, 1.0) * t;
        let w = d.range(-2.0, 2.0);
        let dt = 1e-9;
        let fd = (l.deflect(tau, w * dt, t) - tau) / dt;
        let rate = l.rate(tau, w, t);
        assert!((fd - rate).abs() <= 1e-5 * (rate.abs() + t), "{fd} vs {rate}");
    }
    assert_eq!(l.rate(10.0, 0.0, 67.2), 0.0);
}

#[test]
fn the_torque_never_exceeds_the_sliding_torque() {
    let mut d = Draw(4);
    let l = Presliding::default();
    for _ in 0..2000 {
        let t = d.range(0.0, 300.0);
        let tau = d.range(-2.0, 2.0) * t;
        let w = d.range(-10.0, 10.0);
        let torque = l.torque(tau, w, t);
        // Never beyond the sliding torque: the damping is capped there.
        assert!(torque.abs() <= t, "{torque} T {t} w {w}");
        // At rest only the held torque, never above the bound.
        assert!(l.torque(tau, 0.0, t).abs() <= t);
    }
}

/// Central differences of a function of three inputs.
fn central(f: impl Fn([f64; 3]) -> f64, x: [f64; 3], h: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| {
        let (mut a, mut b) = (x, x);
        a[i] += h[i];
        b[i] -= h[i];
        (f(a) - f(b)) / (2.0 * h[i])
    })
}

/// A smooth sliding torque with known partials for the partial-derivative checks.
fn bound_of(load: f64, w: f64) -> f64 {
    0.12 * 0.028 * load.abs() * (1.0 - 0.05 * (1.0 - (-w.abs()).exp()))
}

#[test]
fn the_partials_match_central_differences_in_stick_transition_and_slip() {
    let l = law();
    let mut d = Draw(5);
    let mut checked = [0; 3];
    for _ in 0..3000 {
        let load = d.range(5e3, 60e3);
        let w = d.range(-1.0, 1.0);
        let committed = d.range(-1.0, 1.0) * bound_of(load, w);
        let j = PreslidingJoint::at_state(l, committed, 0.1);
        let angle = 0.1 + d.range(-3.0, 3.0) * l.angle;
        let (t, dw, dp) = bound_partials(|p, w| Ok::<_, ()>(bound_of(p, w)), load, w).unwrap();
        let jet = j.torque_partials(angle, w, bound_jet(t, dw, dp));
        assert_eq!(jet.v, j.torque_at(angle, w, t));
        let f = |x: [f64; 3]| j.torque_at(x[0], x[1], bound_of(x[2], x[1]));
        let h = [1e-9, 1e-7, 1e-3];
        let fd = central(f, [angle, w, load], h);
        // Skip points within reach of a kink (the elastic limit, the bound, omega = 0).
        let kinked = (0..3).any(|i| {
            let (mut a, mut b) = ([angle, w, load], [angle, w, load]);
            a[i] += 4.0 * h[i];
            b[i] -= 4.0 * h[i];
            let lin = |x: [f64; 3]| f(x);
            let curvature = (lin(a) + lin(b) - 2.0 * lin([angle, w, load])).abs();
            curvature > 1e-6 * (1.0 + jet.v.abs()) || a[1].signum() != b[1].signum()
        });
        if kinked {
            continue;
        }
        let tau = j.held_at(angle, t);
        let phase = if tau.abs() <= l.elastic_limit * t { 0 } else if tau.abs() < t * (1.0 - 1e-12) { 1 } else { 2 };
        checked[phase] += 1;
        // The angle partial is the tangent for the next increment, in the direction of motion
        // (that of omega), from the held torque: a one-sided difference that way after
        // committing there (where omega and the increment agree, the exact partial).
        let s = w.signum();
        let mut next = j;
        next.commit(angle, t);
        let g = |a: f64| next.torque_at(a, w, t);
        let one_sided = (g(angle + s * 1e-10) - g(angle)) / (s * 1e-10);
        if (angle - 0.1) * w > 0.0 {
            assert!((one_sided - fd[0]).abs() <= 1e-4 * fd[0].abs() + 1e-14 * (1.0 + jet.v.abs()) / 1e-10, "{one_sided} vs {}", fd[0]);
        }
        let fd = [one_sided, fd[1], fd[2]];
        let h = [1e-10, h[1], h[2]];
        for i in 0..3 {
            // Relative agreement, plus the differences' own rounding noise.
            let noise = 1e-14 * (1.0 + jet.v.abs()) / h[i];
            let scale = jet.d[i].abs().max(fd[i].abs());
            assert!((jet.d[i] - fd[i]).abs() <= 2e-5 * scale + noise, "input {i} phase {phase}: {} vs {}", jet.d[i], fd[i]);
        }
    }
    assert!(checked.iter().all(|&n| n > 50), "cases per phase (stick, transition, slip): {checked:?}");
}

#[test]
fn model_exchange_partials_match_central_differences() {
    let l = law();
    let mut d = Draw(6);
    for _ in 0..2000 {
        let load = d.range(5e3, 60e3);
        let w = d.range(-1.0, 1.0);
        let tau = d.range(-1.1, 1.1) * bound_of(load, w);
        let (t, dw, dp) = bound_partials(|p, w| Ok::<_, ()>(bound_of(p, w)), load, w).unwrap();
        let (torque, rate) = state_partials(&l, tau, w, Jet::with(t, [0.0, dw, dp]));
        let ft = |x: [f64; 3]| l.torque(x[0], x[1], bound_of(x[2], x[1]));
        let fr = |x: [f64; 3]| l.rate(x[0], x[1], bound_of(x[2], x[1]));
        let h = [1e-6, 1e-7, 1e-3];
        let x = [tau, w, load];
        for (jet, f) in [(torque, &ft as &dyn Fn([f64; 3]) -> f64), (rate, &fr)] {
            let fd = central(f, x, h);
            let smooth = (0..3).all(|i| {
                let (mut a, mut b) = (x, x);
                a[i] += 4.0 * h[i];
                b[i] -= 4.0 * h[i];
                (f(a) + f(b) - 2.0 * f(x)).abs() <= 1e-6 * (1.0 + jet.v.abs()) && a[1].signum() == b[1].signum()
            });
            if !smooth {
                continue;
            }
            for i in 0..3 {
                let noise = 1e-14 * (1.0 + jet.v.abs()) / h[i];
                let scale = jet.d[i].abs().max(fd[i].abs());
                assert!((jet.d[i] - fd[i]).abs() <= 2e-5 * scale + noise, "input {i}: {} vs {}", jet.d[i], fd[i]);
            }
        }
    }
}

#[test]
fn the_parameters_are_checked_by_name_value_and_unit() {
    let e = Presliding::new(-1.0, 0.9, 0.01).unwrap_err().to_string();
    assert_eq!(e, "parameter zero_velocity.presliding_angle = -1 rad is out of range: it must be a number in (0, 1] rad");
    let e = Presliding::new(1e-3, 1.0, 0.01).unwrap_err().to_string();
    assert_eq!(e, "parameter zero_velocity.elastic_limit = 1 is out of range: it must be a number in [0, 1)");
    let e = Presliding::new(1e-3, 0.5, f64::NAN).unwrap_err().to_string();
    assert_eq!(e, "parameter zero_velocity.damping_time = NaN s is out of range: it must be a number in [0, 1000] s");
    assert!(Presliding::new(1e-3, 0.0, 0.0).is_ok());
    assert!(matches!(ZeroVelocityModel::parse("sticky"), Err(ZeroVelocityError::UnknownModel(_))));
    assert_eq!(ZeroVelocityModel::default(), ZeroVelocityModel::Presliding);
    for m in [ZeroVelocityModel::Band, ZeroVelocityModel::Presliding] {
        assert_eq!(ZeroVelocityModel::from_code(m.code()), Some(m));
        assert_eq!(ZeroVelocityModel::parse(m.as_str()), Ok(m));
    }
}

#[test]
fn the_band_law_is_the_ramp_and_the_sign() {
    assert_eq!(band::torque(0.005, 0.01, 70.0, 68.0), -34.0);
    assert_eq!(band::torque(-0.0025, 0.01, 70.0, 68.0), 17.0);
    assert_eq!(band::torque(0.01, 0.01, 70.0, 68.0), -70.0);
    assert_eq!(band::torque(-3.0, 0.01, 70.0, 68.0), 70.0);
    assert_eq!(band::torque(0.0, 0.0, 70.0, 68.0), 0.0);
    let e = band::check_band(-1.0).unwrap_err().to_string();
    assert_eq!(e, "parameter zero_velocity.speed_band = -1 rad/s is out of range: it must be a finite number >= 0");
}

#[test]
fn the_dissipation_is_nonnegative_and_the_sliding_power_in_steady_sliding() {
    let mut d = Draw(7);
    let l = law();
    for _ in 0..2000 {
        let t = d.range(0.0, 300.0);
        let tau = d.range(-1.5, 1.5) * t;
        let w = d.range(-5.0, 5.0);
        let p = l.dissipation(tau, w, t);
        assert!(p >= 0.0 && p.is_finite(), "{p}");
        // Never more than the friction's own power plus what the elastic energy released.
        let torque = l.torque(tau, w, t);
        assert!(p <= (torque * w).abs() + t * w.abs() * (1.0 + 1e-12), "{p}");
    }
    for &w in &[0.01_f64, -0.01] {
        let t = 67.2;
        let held = w.signum() * t;
        assert_eq!(l.dissipation(held, w, t).to_bits(), (l.torque(held, w, t) * w).abs().to_bits());
        // Elastic range, below the damping's cap: only the damping.
        let c = l.damping_time * t / l.angle;
        assert!((l.dissipation(0.1 * t, w, t) - c * w * w).abs() < 1e-12 * c * w * w);
    }
}

#[test]
fn the_angle_partial_is_the_stiffness_against_the_motion_being_made() {
    let l = law();
    let t = 67.2;
    let k = t / l.angle;
    let bound = bound_jet(t, 0.0, 0.0);
    // Sliding forward at the bound: no stiffness along the motion, elastic against a reversal.
    let j = PreslidingJoint::at_state(l, t, 0.0);
    assert_eq!(j.torque_partials(0.0, 0.5, bound).d[0], 0.0);
    // (at a slow reversal: a fast one saturates the damping at the bound, where no input moves the torque)
    assert!((j.torque_partials(0.0, -0.01, bound).d[0] + k).abs() < 1e-9 * k);
    // At rest with nothing moving: the unloading (elastic) stiffness.
    assert!((j.torque_partials(0.0, 0.0, bound).d[0] + k).abs() < 1e-9 * k);
    let fresh = PreslidingJoint::new(l, 0.0);
    assert!((fresh.torque_partials(0.0, 0.0, bound).d[0] + k).abs() < 1e-9 * k);
    // Committed beyond a bound that has since fallen (faster sliding, lower T): the output is
    // the bound; a reversal unloads elastically from it.
    let above = PreslidingJoint::at_state(l, 1.02 * t, 0.0);
    let j = above.torque_partials(1e-4, -0.01, bound);
    assert_eq!(j.v, above.torque_at(1e-4, -0.01, t));
    assert!((j.d[0] + k).abs() < 1e-9 * k, "{}", j.d[0]);
}

#[test]
fn at_rest_the_velocity_partials_are_the_elastic_ones() {
    let l = law();
    let t = 67.2;
    let k = t / l.angle;
    let bound = Jet::with(t, [0.0, 0.0, 0.0]);
    for &tau in &[0.0, 10.0, -30.0] {
        let (torque, rate) = state_partials(&l, tau, 0.0, bound);
        assert_eq!(torque.v, -tau);
        assert_eq!(rate.v, 0.0);
        assert!((torque.d[1] + l.damping_time * k).abs() < 1e-9 * k, "{}", torque.d[1]);
        assert!((rate.d[1] - k).abs() < 1e-9 * k, "{}", rate.d[1]);
    }
}

#[test]
fn model_exchange_relaxes_an_excess_state_in_either_direction() {
    let l = law();
    let t = 20.16;
    // Beyond the bound behind the motion: the state rises faster than elastic unloading.
    assert!(l.rate(-200.0, 0.05, t) > 0.05 * t / l.angle * 10.0);
    // The torque stays within the bound.
    let torque = l.torque(-200.0, 0.05, t);
    assert!(torque.abs() <= t, "{torque}");
}
