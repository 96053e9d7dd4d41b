//! The limits a finite journal bearing tends to, in closed form or by one-dimensional
//! quadrature: independent checks of the two-dimensional Reynolds solution
//! ([`super::reynolds`]) and of the table ([`super::table`]).
//!
//! Same conventions as the table: S = (R/c)² ηN/P, N in rev/s, P = W/(2RL); φ the attitude
//! angle between the load line and the line of centres.

use std::f64::consts::PI;

/// Petroff's friction variable (R/c) f = 2π² S: a concentric journal, Couette shear over
/// the whole clearance, no load-carrying pressure (Petroff, 1883; Raimondi & Boyd's ε → 0
/// limit). A lower bound of the friction of a flooded clearance at any ε (the mean of 1/H
/// over the circumference, 1/√(1 − ε²), is at least 1).
pub fn petroff_friction_variable(sommerfeld: f64) -> f64 {
    2.0 * PI * PI * sommerfeld
}

/// The short (Ocvirk) bearing with the half-Sommerfeld (Gümbel) condition, which the
/// Swift–Stieber condition reduces to as L/D → 0 (Ocvirk, 1952, NACA TN 2808; Hamrock,
/// Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*, 2004, ch. 10):
/// W = ηUL³/(4c²) · ε √(π²(1 − ε²) + 16ε²)/(1 − ε²)², hence
/// S = (D/L)² (1 − ε²)²/(π ε √(π²(1 − ε²) + 16ε²)) and tan φ = π √(1 − ε²)/(4ε).
/// Returns (S, φ) at `eps` ∈ (0, 1) and L/D = `ld`.
pub fn short_bearing(eps: f64, ld: f64) -> (f64, f64) {
    let e2 = eps * eps;
    let s = (1.0 - e2).powi(2) / (PI * eps * (PI * PI * (1.0 - e2) + 16.0 * e2).sqrt()) / (ld * ld);
    (s, (PI * (1.0 - e2).sqrt() / (4.0 * eps)).atan())
}

/// The infinitely long bearing with the Reynolds (Swift–Stieber) condition: the pressure
/// starts at the maximum film (θ = −π from the minimum) and ends at θ₂ where p = dp/dθ = 0.
/// dp̄/dθ = 6 (H − H₂)/H³, H = 1 − ε cos θ, H₂ = H(θ₂); θ₂ solves p̄(θ₂) = 0. The loads
/// follow by parts from dp̄/dθ alone: ∫p̄ cos θ dθ = −∫ p̄' sin θ dθ,
/// ∫p̄ sin θ dθ = ∫ p̄' cos θ dθ (p̄ = 0 at both ends). Quadrature: Gauss–Legendre (8 points)
/// on 400 panels uniform in the angle ψ of tan(θ/2) = k tan(ψ/2) (k = √((1−ε)/(1+ε)));
/// bisection for θ₂. Returns (S, φ, θ₂) at `eps` ∈ (0, 1).
pub fn long_bearing(eps: f64) -> (f64, f64, f64) {
    let k = ((1.0 - eps) / (1.0 + eps)).sqrt();
    let theta_of = |psi: f64| 2.0 * (k * (0.5 * psi).tan()).atan();
    let dtheta = |psi: f64| {
        let t = (0.5 * psi).tan();
        k * (1.0 + t * t) / (1.0 + k * k * t * t)
    };
    let psi_of = |theta: f64| 2.0 * ((0.5 * theta).tan() / k).atan();
    let h = |t: f64| 1.0 - eps * t.cos();
    // ∫_{−π}^{θ2} g(θ) dθ in ψ (ψ from −π to ψ(θ2)).
    let integrate = |theta2: f64, g: &dyn Fn(f64) -> f64| {
        let (a, b) = (-PI, psi_of(theta2));
        let panels = 400;
        let w = (b - a) / panels as f64;
        let mut sum = 0.0;
        for p in 0..panels {
            let mid = a + (p as f64 + 0.5) * w;
            for (x, wt) in GAUSS8 {
                let psi = mid + 0.5 * w * x;
                sum += 0.5 * w * wt * g(theta_of(psi)) * dtheta(psi);
            }
        }
        sum
    };
    let pressure_at_end = |theta2: f64| {
        let h2 = h(theta2);
        integrate(theta2, &|t| (h(t) - h2) / h(t).powi(3))
    };
    // p̄(θ₂) > 0 for θ₂ just past 0 (the converging film's pressure), < 0 for θ₂ → π.
    let (mut lo, mut hi) = (1e-9, PI - 1e-9);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if pressure_at_end(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let theta2 = 0.5 * (lo + hi);
    let h2 = h(theta2);
    let dp = |t: f64| 6.0 * (h(t) - h2) / h(t).powi(3);
    let wr = -integrate(theta2, &|t| dp(t) * t.sin());
    let wt = -integrate(theta2, &|t| dp(t) * t.cos());
    // Over ζ ∈ [−1, 1]: |W̄| = 2 |(wr, wt)|, S = 2/(π |W̄|).
    let s = 1.0 / (PI * wr.hypot(wt));
    (s, wt.atan2(wr), theta2)
}

/// Gauss–Legendre nodes and weights on [−1, 1], 8 points (Abramowitz & Stegun, Table 25.4).
pub(crate) const GAUSS8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss8_integrates_degree_15_exactly() {
        let sum: f64 = GAUSS8.iter().map(|(x, w)| w * x.powi(14)).sum();
        assert!((sum - 2.0 / 15.0).abs() < 1e-14);
        let w: f64 = GAUSS8.iter().map(|(_, w)| w).sum();
        assert!((w - 2.0).abs() < 1e-14);
    }

    #[test]
    fn long_bearing_small_eccentricity_rupture_angle() {
        // ε → 0: p̄ ∝ cos θ₂ (θ + π) − sin θ, zero at θ₂: tan θ₂ = θ₂ + π, θ₂ = 1.351817 rad
        // (Newton on the transcendental equation); the shift at ε = 10⁻⁴ is O(ε).
        let mut root = 1.35f64;
        for _ in 0..30 {
            root -= (root.tan() - root - PI) / (1.0 / root.cos().powi(2) - 1.0);
        }
        assert!((root - 1.351_817).abs() < 1e-6, "{root}");
        let (_, _, t2) = long_bearing(1e-4);
        assert!((t2 - root).abs() < 1e-3, "{t2} vs {root}");
        let (_, _, t2) = long_bearing(1e-6);
        assert!((t2 - root).abs() < 1e-5, "{t2} vs {root}");
    }
}
