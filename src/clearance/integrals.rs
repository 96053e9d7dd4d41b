//! The gap integrals of the clearance torque (see [`super`]): J₁ in closed form, Jₙ by a
//! fixed 12-point Gauss–Legendre rule in the balanced angle χ, and the inline ln it uses.

use std::f64::consts::PI;

/// Largest eccentricity ratio used (the gap is clamped to at least 1e-9·c: ε → 1 at θ_c = 0
/// would make J₁ infinite).
pub const MAX_ECCENTRICITY: f64 = 1.0 - 1e-9;

/// J₁(ε, θ_c) = ∫_{θ_c}^{2π−θ_c} dθ/(1 − ε cos θ) in closed form, ε ∈ [0, 1), θ_c ∈ [0, π].
pub fn newtonian_integral(eps: f64, theta_c: f64) -> f64 {
    let e = eps.clamp(0.0, MAX_ECCENTRICITY);
    let t = theta_c.clamp(0.0, PI);
    let root = ((1.0 - e) * (1.0 + e)).sqrt();
    if t == 0.0 {
        return 2.0 * PI / root;
    }
    newtonian_outside(e, t, root)
}

/// (J₁(ε, 0), J₁(ε, θ_c)): the whole clearance's and the outside's, bit for bit two calls of
/// [`newtonian_integral`] sharing √(1 − ε²).
pub fn newtonian_integral_pair(eps: f64, theta_c: f64) -> (f64, f64) {
    let e = eps.clamp(0.0, MAX_ECCENTRICITY);
    let t = theta_c.clamp(0.0, PI);
    let root = ((1.0 - e) * (1.0 + e)).sqrt();
    let whole = 2.0 * PI / root;
    (whole, if t == 0.0 { whole } else { newtonian_outside(e, t, root) })
}

/// J₁ outside the arc |θ| ≤ t > 0 at the clamped ε `e`, root = √(1 − ε²).
#[inline]
fn newtonian_outside(e: f64, t: f64, root: f64) -> f64 {
    let x = ((1.0 + e) / (1.0 - e)).sqrt() * (0.5 * t).tan();
    // π/2 − atan x = atan2(1, x) for x ≥ 0 (x = +∞ at θ_c = π gives 0).
    4.0 / root * 1.0f64.atan2(x)
}

/// Gauss–Legendre nodes and weights on [−1, 1], 12 points (Abramowitz & Stegun, Table 25.4;
/// the digits by Newton's method on P₁₂, test `gauss12_table_matches_newton`).
pub(super) const GAUSS12: [(f64, f64); 12] = [
    (-0.9815606342467192, 0.047175336386511835),
    (-0.9041172563704748, 0.10693932599531818),
    (-0.7699026741943047, 0.16007832854334633),
    (-0.5873179542866175, 0.20316742672306584),
    (-0.3678314989981802, 0.23349253653835478),
    (-0.1252334085114689, 0.24914704581340288),
    (0.12523340851146894, 0.24914704581340288),
    (0.3678314989981802, 0.23349253653835478),
    (0.5873179542866175, 0.20316742672306584),
    (0.7699026741943047, 0.16007832854334633),
    (0.9041172563704748, 0.10693932599531818),
    (0.9815606342467192, 0.047175336386511835),
];

/// Jₙ(ε, θ_c) = ∫_{θ_c}^{2π−θ_c} (1 − ε cos θ)^−n dθ for 0 < n ≤ 1 by the fixed rule of the
/// module documentation (n = 1: the closed form), ε ∈ [0, 1), θ_c ∈ [0, π].
pub fn power_law_integral(eps: f64, theta_c: f64, n: f64) -> f64 {
    if n == 1.0 {
        return newtonian_integral(eps, theta_c);
    }
    let e = eps.clamp(0.0, MAX_ECCENTRICITY);
    let t = theta_c.clamp(0.0, PI);
    let k = ((1.0 - e) / (1.0 + e)).sqrt().sqrt();
    let k2 = k * k;
    let chi_c = if t == 0.0 { 0.0 } else { 2.0 * ((0.5 * t).tan() / k).atan() };
    let half = 0.5 * (PI - chi_c);
    let (sin_mid, cos_mid) = crate::numerics::fast_math::sin_cos(chi_c + half);
    let (a0, a1) = (1.0 - e, (1.0 + e) * k2);
    let mut sum = 0.0;
    // Nodes in pairs ±x: cos(mid ± half·x) = cos(mid) cos(half·x) ∓ sin(mid) sin(half·x).
    for (x, w) in &GAUSS12[6..] {
        let (s, c) = crate::numerics::fast_math::sin_cos(half * x);
        for cos_chi in [cos_mid * c - sin_mid * s, cos_mid * c + sin_mid * s] {
            let (p, m) = (1.0 + cos_chi, 1.0 - cos_chi);
            let inv_b = 1.0 / (p + k2 * m);
            let h = (a0 * p + a1 * m) * inv_b; // 1 − ε cos θ at the node
            sum += w * crate::numerics::fast_math::exp(-n * ln(h)) * inv_b;
        }
    }
    // Both halves of the arc (symmetric about θ = π): 2 · half · Σ w g, g = 2k(A/B)^−n/B.
    4.0 * k * half * sum
}

/// ln x for a positive normal x (the gap ratio 1 − ε cos θ ≥ 1e-9), to about 1e-15 relative:
/// x = 2^e·m with m ∈ [√½, √2), ln x = e ln 2 + 2 atanh f, f = (m − 1)/(m + 1), |f| ≤ 0.1716,
/// the series to f¹⁹ (remainder below 1e-16). Inlined, without the C library's call: the
/// power-law quadrature takes one per node (measured in `benches/journal.rs`).
#[inline]
pub(super) fn ln(x: f64) -> f64 {
    let bits = x.to_bits();
    let mut e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let mut m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let f = (m - 1.0) / (m + 1.0);
    let f2 = f * f;
    let f4 = f2 * f2;
    let series = (1.0 + f2 * (1.0 / 3.0)) + f4 * ((1.0 / 5.0 + f2 * (1.0 / 7.0)) + f4 * ((1.0 / 9.0 + f2 * (1.0 / 11.0)) + f4 * ((1.0 / 13.0 + f2 * (1.0 / 15.0)) + f4 * (1.0 / 17.0 + f2 * (1.0 / 19.0)))));
    e as f64 * std::f64::consts::LN_2 + 2.0 * f * series
}

