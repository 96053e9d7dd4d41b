//! Issue 13's acceptance tests against published numbers: the extensions (h_min, temperature,
//! starved inlet) compared with the values their sources print, each quoted with where it was
//! found. What could not be found is said so here and in docs/extensions.md, and only the identities and limits are tested for it.
//!
//! Sources used (all read through public transcriptions; none of the original papers was at hand):
//! - Pan & Hamrock (1989) line-contact fits, as printed in Hamrock, Schmid & Jacobson,
//!   *Fundamentals of Fluid Film Lubrication* (2nd ed., 2004), eqs. (18.72) and (18.74), with
//!   U of eq. (18.10) on the mean surface velocity ũ = (u_a + u_b)/2. Transcription read:
//!   github.com/VictorLier/Tribology, `Assignment3/A3.py` (2024 course code that cites the
//!   book's equation numbers), which also gives the companion fits (18.70), (18.71), (18.75).
//! - Stachowiak & Batchelor, *Engineering Tribology*, ch. 2 "Physical properties of
//!   lubricants", p. 21: the Roelands viscosity–pressure–temperature equation (refs. [12, 13]
//!   there) and Table 2.3, "Dynamic viscosity and pressure-viscosity coefficients of some
//!   commonly used lubricants (adapted from [12])": η0 at 30, 60 and 100 °C and α at the same
//!   temperatures for 13 mineral oils. Read in two independent text extracts of the book
//!   (123docz.net "Engineering Tribology 2E Episode 2" and tailieunhanh.com), which agree.
//!
//! Searched for and NOT found (2026-11-23; public web pages, documentation, code and issue
//! threads, by title, authors, equation and coefficient strings): Pan & Hamrock's (1989) own
//! check values (their numerical line-contact solutions, or any worked example using eqs.
//! 18.72/18.74 with its numbers), and any published value, table, figure point or worked
//! example of the starvation relation h/h_ff = R/(1 + R^γs)^(1/γs) (Chevalier et al. 1998,
//! Damiens et al. 2004) or of γs for a line contact. So issue 13's "h_min matches its source's
//! check values" and "starvation matches its source's published examples" stay untested here:
//! what is tested is the printed fits, the relation's limits, and the γs sensitivity.

use pinjoint::film::min_film::{ln_min_to_central, pan_hamrock_central, pan_hamrock_min};
use pinjoint::params::{Lubricant, DEFAULT_ROELANDS_TEMPERATURE_INDEX};
use pinjoint::rheology::viscosity::{at_temperature, roelands, roelands_s0_from_two_points};
use pinjoint::{Joint, Params};

// ---------------------------------------------------------------------------------------------
// h_min: Pan & Hamrock (1989)
// ---------------------------------------------------------------------------------------------

/// Hamrock, Schmid & Jacobson (2004) eq. (18.72): H_min = 1.714 W'^−0.128 U^0.694 G^0.568.
fn hsj_18_72(w: f64, u: f64, g: f64) -> f64 {
    1.714 * w.powf(-0.128) * u.powf(0.694) * g.powf(0.568)
}
/// Eq. (18.74): H_c = 2.922 W'^−0.166 U^0.692 G^0.470.
fn hsj_18_74(w: f64, u: f64, g: f64) -> f64 {
    2.922 * w.powf(-0.166) * u.powf(0.692) * g.powf(0.470)
}

/// Heavily loaded steel line contacts of the kind the fits were made for (W' 2e-5–5e-4,
/// U 1e-12–1e-10, G 2500–5000), and this joint's own groups (W' ~ 1e-7, U ~ 1e-16–1e-12).
fn groups() -> Vec<(f64, f64, f64)> {
    let mut v = Vec::new();
    for w in [2e-5, 1e-4, 5e-4, 2e-8, 2e-7] {
        for u in [1e-16, 1e-12, 1e-11, 1e-10] {
            for g in [2500.0, 5000.0, 25.0] {
                v.push((w, u, g));
            }
        }
    }
    v
}

#[test]
fn pan_hamrock_fits_are_the_printed_equations() {
    for (w, u, g) in groups() {
        let (m, c) = (pan_hamrock_min(w, u, g), pan_hamrock_central(w, u, g));
        assert!((m / hsj_18_72(w, u, g) - 1.0).abs() < 1e-13, "H_min at W'={w}, U={u}, G={g}");
        assert!((c / hsj_18_74(w, u, g) - 1.0).abs() < 1e-13, "H_c at W'={w}, U={u}, G={g}");
        // The ratio the model applies is the quotient of the two printed fits (no γ1 scaling).
        let r = ln_min_to_central(w.ln(), u.ln(), g.ln(), 0.0).exp();
        let printed = (hsj_18_72(w, u, g) / hsj_18_74(w, u, g)).min(1.0);
        assert!((r / printed - 1.0).abs() < 1e-12, "h_min/h_c at W'={w}, U={u}, G={g}: {r} vs {printed}");
    }
}

#[test]
fn the_joint_feeds_the_fits_the_mean_velocity_and_the_fluid_share() {
    // Eq. (18.10) puts the MEAN surface velocity in U; the pin turns in a fixed bush, so
    // ũ = ωR/2 (the paper's eq. 12 uses the sum u = ωR). W' = P/(E'R'B), G = αE', and the
    // fluid's share 1/γ1 enters as eq. 13 does (E' → E'/γ1, P → P/γ1: U → γ1U, G → G/γ1).
    let j = Joint::new(&Params::paper()).unwrap();
    let p = j.params();
    let (e, r) = (j.effective_modulus(), j.reduced_radius());
    let lub = j.lubricant();
    let h_c = 7.5e-6; // any central film: the relation is a ratio
    for load in [5e3, 20e3, 60e3] {
        for omega in [0.2, 4.39, 83.8] {
            for x1 in [1.0, 0.5, 0.1] {
                let w = load / (e * r * p.geometry.bush_length);
                let u = lub.viscosity * (0.5 * omega * p.geometry.pin_radius) / (e * r) / x1;
                let g = lub.pressure_viscosity_coefficient * e * x1;
                let want = (hsj_18_72(w, u, g) / hsj_18_74(w, u, g)).min(1.0) * h_c;
                let got = j.min_film(load, omega, h_c, x1);
                assert!((got / want - 1.0).abs() < 1e-12, "P={load}, ω={omega}, 1/γ1={x1}: {got} vs {want}");
                // With the sum velocity instead (a plausible slip) the answer would differ:
                // the test can tell the two apart (U^0.002 → 2^0.002 = 1.0014).
                let sum_u = (hsj_18_72(w, 2.0 * u, g) / hsj_18_74(w, 2.0 * u, g)).min(1.0) * h_c;
                assert!((got / sum_u - 1.0).abs() > 1e-3);
            }
        }
    }
}

#[test]
fn pan_hamrock_central_film_is_below_moes_for_heavy_loads() {
    // Why the model applies Pan & Hamrock's RATIO to its Moes film rather than their h_min
    // alone: the two published central-film fits differ. For heavily loaded contacts of the
    // kind Pan & Hamrock fitted (W' 2e-5–5e-4, U 1e-12–1e-10, G 2500–5000; their stated range
    // was not found) their H_c (mean-velocity U) is 0.67–0.92 of Moes'
    // (eq. 12 of the paper, sum-velocity U_Σ = 2U), measured; the ratio h_min/h_c of one
    // consistent fit is the transferable part.
    let mut lo = f64::INFINITY;
    let mut hi: f64 = 0.0;
    for w in [2e-5f64, 1e-4, 5e-4] {
        for u in [1e-12f64, 1e-11, 1e-10] {
            for g in [2500.0f64, 5000.0] {
                let us = 2.0 * u;
                let (h, _) = pinjoint::film::moes(w * us.powf(-0.5), g * us.powf(0.25));
                let r = hsj_18_74(w, u, g) / (h * us.sqrt());
                lo = lo.min(r);
                hi = hi.max(r);
            }
        }
    }
    eprintln!("Pan–Hamrock H_c / Moes H_c for heavy loads: {lo:.3}–{hi:.3}");
    assert!(lo > 0.6 && hi < 0.95, "{lo} {hi}");
}

// ---------------------------------------------------------------------------------------------
// Temperature: Roelands' relation against Stachowiak & Batchelor
// ---------------------------------------------------------------------------------------------

/// Stachowiak & Batchelor's form of Roelands' viscosity–pressure–temperature equation,
/// written from the book independently of `src/rheology/viscosity.rs`:
/// `η = η0 exp{(ln η0 + 9.67)[−1 + (1 + 5.1e-9 p)^Z ((θ − 138)/(θ0 − 138))^−S0]}`,
/// η0 in Pa·s at θ0, θ in K, p in Pa. `k0` is the temperature pole (138 K printed; Roelands'
/// "1 + t/135" with t in °C puts it at 138.15 K).
fn stachowiak_roelands(eta0: f64, theta0: f64, theta: f64, p: f64, z: f64, s0: f64, k0: f64) -> f64 {
    let f = ((theta - k0) / (theta0 - k0)).powf(-s0);
    eta0 * ((eta0.ln() + 9.67) * (-1.0 + (1.0 + 5.1e-9 * p).powf(z) * f)).exp()
}

#[test]
fn roelands_temperature_and_pressure_form_is_the_books() {
    // With the book's rounded constants in the parameter set (η∞ = e^−9.67 Pa·s,
    // c_p = 1/5.1e-9 Pa) the code and the book's equation are the same function, η(T, p): the
    // temperature factor multiplies ln(η0/η∞), and the pressure term multiplies it again with
    // a temperature-independent Z. Agreement to rounding.
    let base = Lubricant {
        roelands_viscosity_limit: (-9.67f64).exp(),
        roelands_pressure_constant: 1.0 / 5.1e-9,
        reference_temperature: 303.15,
        ..Lubricant::default()
    };
    for (eta0, z, s0) in [(0.153, 0.63, 1.27), (12.45e-3, 0.63, DEFAULT_ROELANDS_TEMPERATURE_INDEX), (2.0, 0.5, 1.57)] {
        for t in [218.15, 253.15, 303.15, 333.15, 373.15] {
            let l = at_temperature(&Lubricant { viscosity: eta0, roelands_index: z, roelands_temperature_index: s0, temperature: t, ..base });
            for p in [0.0, 13.22e6, 1e8, 5e8] {
                let code = roelands(&l, p);
                let book = stachowiak_roelands(eta0, 303.15, t, p, z, s0, 273.15 - 135.0);
                assert!((code / book - 1.0).abs() < 1e-11, "η0={eta0}, T={t}, p={p}: {code} vs {book}");
            }
            // α follows Roelands' initial slope d ln η/dp at p = 0, which scales with the same
            // factor: α(T)/α(T_ref) = [d ln η/dp](T)/[d ln η/dp](T_ref), by the book's equation.
            let slope = |t: f64| {
                let dp = 1e3;
                (stachowiak_roelands(eta0, 303.15, t, dp, z, s0, 138.15).ln() - stachowiak_roelands(eta0, 303.15, t, -dp, z, s0, 138.15).ln()) / (2.0 * dp)
            };
            let want = slope(t) / slope(303.15);
            let got = l.pressure_viscosity_coefficient / base.pressure_viscosity_coefficient;
            assert!((got / want - 1.0).abs() < 1e-6, "α ratio at T={t}: {got} vs {want}");
        }
    }
}

#[test]
fn the_books_rounded_constants_change_the_viscosity_by_under_half_a_percent_above_0_c() {
    // The code keeps Table 3's η∞ = 6.31e-5 Pa·s, c_p = 1.96e8 Pa (eq. 5) and Roelands'
    // 135 °C pole; the book prints 9.67 (−ln 6.31e-5 = 9.6707), 5.1e-9 (1/1.96e8 = 5.102e-9)
    // and 138 K. Between 0 and 100 °C and up to 100 MPa (this joint's pressures are 7–23 MPa)
    // the two differ by less than 0.5 % (measured 0.26 % at most); at −55 to −20 °C by under
    // 3.5 % (measured 2.1 %), the pole's 0.15 K mattering near it.
    let base = Lubricant { reference_temperature: 293.15, ..Lubricant::default() };
    let mut worst_warm: f64 = 0.0;
    let mut worst_cold: f64 = 0.0;
    for t in [218.15, 233.15, 253.15, 273.15, 293.15, 333.15, 373.15] {
        let l = at_temperature(&Lubricant { temperature: t, ..base });
        for p in [0.0, 7e6, 23e6, 1e8] {
            let code = roelands(&l, p);
            let book = stachowiak_roelands(base.viscosity, 293.15, t, p, base.roelands_index, base.roelands_temperature_index, 138.0);
            let d = (code / book - 1.0).abs();
            if t >= 273.15 { worst_warm = worst_warm.max(d) } else { worst_cold = worst_cold.max(d) }
        }
    }
    eprintln!("book's rounded constants vs the code: {worst_warm:.4} (0–100 °C), {worst_cold:.4} (−55 to −20 °C)");
    assert!(worst_warm < 0.005, "{worst_warm}");
    assert!(worst_cold < 0.035, "{worst_cold}");
}

/// Stachowiak & Batchelor, Table 2.3: η0 (mPa·s) at 30, 60, 100 °C and α (1e-9 m²/N) at the
/// same temperatures (NaN: not given), as printed. Groups as in the book: high-, medium- and
/// low-VI mineral oils.
const TABLE_2_3: [(&str, [f64; 3], [f64; 3]); 13] = [
    ("HVI light machine oil", [38.0, 12.1, 5.3], [f64::NAN, 18.4, 13.4]),
    ("HVI heavy machine oil", [153.0, 34.0, 9.1], [23.7, 20.5, 15.8]),
    ("HVI heavy machine oil", [250.0, 50.5, 12.6], [25.0, 21.3, 17.6]),
    ("HVI cylinder oil", [810.0, 135.0, 26.8], [34.0, 28.0, 22.0]),
    ("MVI spindle oil", [18.6, 6.3, 2.4], [20.0, 16.0, 13.0]),
    ("MVI light machine oil", [45.0, 12.0, 3.9], [28.0, 20.0, 16.0]),
    ("MVI medicinal white oil", [107.0, 23.3, 6.4], [29.6, 22.8, 17.8]),
    ("MVI heavy machine oil", [122.0, 26.3, 7.3], [27.0, 21.6, 17.5]),
    ("MVI heavy machine oil", [171.0, 31.0, 7.5], [28.0, 23.0, 18.0]),
    ("LVI spindle oil", [30.7, 8.6, 3.1], [25.7, 20.3, 15.4]),
    ("LVI heavy machine oil", [165.0, 30.0, 6.8], [33.0, 23.8, 16.0]),
    ("LVI heavy machine oil", [310.0, 44.2, 9.4], [34.6, 26.3, 19.5]),
    ("LVI cylinder oil", [2000.0, 180.0, 24.0], [41.5, 29.4, 25.0]),
];
const TABLE_T: [f64; 3] = [303.15, 333.15, 373.15];

/// S0 through the 30 and 100 °C viscosities of a row, and the lubricant at 30 °C.
fn fitted(row: &(&str, [f64; 3], [f64; 3])) -> (f64, Lubricant) {
    let eta_inf = Lubricant::default().roelands_viscosity_limit;
    let s0 = roelands_s0_from_two_points(30.0, row.1[0] * 1e-3, 100.0, row.1[2] * 1e-3, eta_inf);
    let alpha = if row.2[0].is_nan() { 1.0 } else { row.2[0] * 1e-9 };
    let l = Lubricant {
        viscosity: row.1[0] * 1e-3,
        pressure_viscosity_coefficient: alpha,
        reference_temperature: TABLE_T[0],
        temperature: TABLE_T[0],
        roelands_temperature_index: s0,
        ..Lubricant::default()
    };
    (s0, l)
}

#[test]
fn roelands_temperature_relation_reproduces_table_2_3_viscosities() {
    // Fitted through each oil's 30 and 100 °C values, the relation predicts its 60 °C value.
    // Measured: RMS error 4.9 % over the 13 oils, median 2.5 %, largest +13.1 % (the HVI light
    // machine oil, 38 / 12.1 / 5.3 mPa·s, the only row beyond 7 %). The table prints 2–3
    // significant figures (±0.4–4 %), so most of the spread is the two-parameter relation's; it
    // overestimates at mid-range (mean +3.2 %, 11 of the 13 rows above the table).
    let mut sq = 0.0;
    let mut worst: f64 = 0.0;
    let mut beyond_7 = 0;
    for row in &TABLE_2_3 {
        let (_, l) = fitted(row);
        // The fit carries 30 °C exactly onto 100 °C ...
        let at100 = at_temperature(&Lubricant { temperature: TABLE_T[2], ..l }).viscosity;
        assert!((at100 / (row.1[2] * 1e-3) - 1.0).abs() < 1e-12, "{}", row.0);
        // ... and is checked at 60 °C, which it was not fitted to.
        let at60 = at_temperature(&Lubricant { temperature: TABLE_T[1], ..l }).viscosity;
        let e = at60 / (row.1[1] * 1e-3) - 1.0;
        assert!(e.abs() < 0.15, "{}: {at60} Pa·s vs {} mPa·s ({e:+.3})", row.0, row.1[1]);
        sq += e * e;
        worst = worst.max(e.abs());
        beyond_7 += usize::from(e.abs() > 0.07);
    }
    let rms = (sq / TABLE_2_3.len() as f64).sqrt();
    eprintln!("η(60 °C): RMS {rms:.4}, largest {worst:.4}");
    assert!(rms < 0.06, "RMS {rms}");
    assert_eq!(beyond_7, 1, "only the HVI light machine oil row is beyond 7 % (largest {worst})");
}

#[test]
fn pressure_viscosity_coefficient_follows_table_2_3_within_its_scatter() {
    // The code scales α with ln(η0/η∞) (Roelands' Z independent of temperature). From each
    // oil's α at 30 °C it predicts α at 60 and 100 °C. Measured against the 12 rows that give
    // α at 30 °C: RMS 7.2 %, mean +1.5 %, largest +22.7 % (LVI heavy machine oil, 165 mPa·s,
    // at 100 °C); 22 of the 24 values within 10 %. The printed α have 2–3 figures (±2–4 %).
    let mut errs = Vec::new();
    for row in TABLE_2_3.iter().filter(|r| !r.2[0].is_nan()) {
        let (_, l) = fitted(row);
        for (t, alpha) in TABLE_T.iter().zip(row.2).skip(1) {
            let a = at_temperature(&Lubricant { temperature: *t, ..l }).pressure_viscosity_coefficient;
            errs.push(a / (alpha * 1e-9) - 1.0);
        }
    }
    assert_eq!(errs.len(), 24);
    let rms = (errs.iter().map(|e| e * e).sum::<f64>() / 24.0).sqrt();
    let mean = errs.iter().sum::<f64>() / 24.0;
    let within_10 = errs.iter().filter(|e| e.abs() <= 0.10).count();
    eprintln!("α(60, 100 °C): RMS {rms:.4}, mean {mean:+.4}, {within_10}/24 within 10 %, {errs:.3?}");
    assert!(rms < 0.08, "RMS {rms}");
    assert!(mean.abs() < 0.02, "mean {mean}");
    assert!(within_10 >= 20, "{within_10} of 24 within 10 %: {errs:?}");
    assert!(errs.iter().all(|e| e.abs() < 0.25), "{errs:?}");
    // The alternative "α independent of temperature" is far worse against the same table:
    let flat: f64 = TABLE_2_3.iter().filter(|r| !r.2[0].is_nan()).flat_map(|r| [r.2[0] / r.2[1] - 1.0, r.2[0] / r.2[2] - 1.0]).map(|e| e * e).sum::<f64>();
    assert!((flat / 24.0).sqrt() > 3.0 * rms);
}

#[test]
fn default_s0_lies_among_the_s0_of_table_2_3_mineral_oils() {
    // The default S0 = 1.262 (an ISO VG 100 mineral oil, see viscosity::DEFAULT_S0_SOURCE) is
    // inside the range fitted to the 13 oils of Table 2.3, 1.04–1.57 (medium-VI oils:
    // 1.26–1.42; the MVI spindle oil gives 1.262 itself).
    let s: Vec<f64> = TABLE_2_3.iter().map(|r| fitted(r).0).collect();
    let (lo, hi) = s.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    assert!((lo - 1.04).abs() < 0.01 && (hi - 1.57).abs() < 0.01, "{lo} {hi}");
    assert!(DEFAULT_ROELANDS_TEMPERATURE_INDEX > lo && DEFAULT_ROELANDS_TEMPERATURE_INDEX < hi);
    let mvi: Vec<f64> = s[4..9].to_vec();
    assert!(mvi.iter().any(|x| (x - DEFAULT_ROELANDS_TEMPERATURE_INDEX).abs() < 0.002), "{mvi:?}");
    // What that spread means for a cold soak: Table 3's η0 at 20 °C carried to −55 °C with the
    // lowest and highest S0 of the table, against the default's 12.25 Pa·s.
    let cold = |s0: f64| at_temperature(&Lubricant { temperature: 218.15, roelands_temperature_index: s0, ..Lubricant::default() }).viscosity;
    let (a, b, d) = (cold(lo), cold(hi), cold(DEFAULT_ROELANDS_TEMPERATURE_INDEX));
    eprintln!("η0 at −55 °C: {a:.3} Pa·s (S0 = {lo:.3}) … {b:.1} Pa·s (S0 = {hi:.3}); default {d:.2} Pa·s");
    assert!(a > 2.0 && a < 2.6 && b > 150.0 && b < 250.0 && (d / 12.25 - 1.0).abs() < 0.01, "{a} {b} {d}");
}

// ---------------------------------------------------------------------------------------------
// Starved inlet: no published values were found (see docs/extensions.md and src/film/starvation.rs); the
// limits of the relation, and how much the unverified exponent γs matters.
// ---------------------------------------------------------------------------------------------

#[test]
fn starvation_relation_limits_and_monotonicity() {
    use pinjoint::film::starvation::starved_ratio;
    // h^−γ = h_ff^−γ + h_oil^−γ: flooded for R → ∞, the layer itself for R → 0, 2^(−1/γ) at R = 1,
    // increasing in R, and thinner than both the flooded film and the layer.
    for g in [2.0, 2.8, 3.5] {
        assert!((starved_ratio(1e8, g) - 1.0).abs() < 1e-14);
        assert!((starved_ratio(1e-8, g) / 1e-8 - 1.0).abs() < 1e-12);
        assert!((starved_ratio(1.0, g) - 2f64.powf(-1.0 / g)).abs() < 1e-15);
        let mut prev = 0.0;
        for k in -30..=30 {
            let r = 10f64.powf(f64::from(k) / 10.0);
            let v = starved_ratio(r, g);
            assert!(v > prev && v < 1.0 && v < r, "γ={g}, R={r}");
            assert!((v.powf(-g) - (1.0 + r.powf(-g))).abs() < 1e-9 * v.powf(-g));
            prev = v;
        }
    }
    // A larger γs makes the transition sharper: closer to min(1, R) everywhere.
    for r in [0.3, 1.0, 3.0] {
        assert!(starved_ratio(r, 3.5) > starved_ratio(r, 2.8) && starved_ratio(r, 2.8) > starved_ratio(r, 2.0));
    }
}

/// The lowest speed (rpm) in 1–800 rpm where μ falls below `level` at `load` (log grid, then
/// bisection; the same search as the starvation figure's summary). `None`: it stays above.
fn mu_crossing_rpm(joint: &Joint, load: f64, level: f64) -> Option<f64> {
    let rad = std::f64::consts::PI / 30.0;
    let mu = |rpm: f64| joint.evaluate(load, rpm * rad).unwrap().friction_coefficient;
    let n = 200;
    let mut prev = 1.0f64;
    for k in 0..=n {
        let w = 800f64.powf(f64::from(k) / f64::from(n));
        if mu(w) < level {
            let (mut a, mut b) = (prev, w);
            for _ in 0..60 {
                let m = (a * b).sqrt();
                if mu(m) < level { b = m } else { a = m }
            }
            return Some((a * b).sqrt());
        }
        prev = w;
    }
    None
}

#[test]
fn starvation_exponent_sensitivity_over_the_quoted_range() {
    // No published value of γs for a line contact was found (see `src/film/starvation.rs` and
    // docs/extensions.md). A secondary source, an AI-assisted Korean summary (public GitHub notes, dated
    // 2026-03-10) of Lugt, *Grease Lubrication in Rolling Bearings* (Wiley, 2013), ch. 9,
    // gives eq. (9.73) in the same form, h_c/h_cff = r/(1 + r^γ)^(1/γ), and says γ is about 3
    // for circular contacts and up to about 15 for wide elliptical ones (towards a line
    // contact, like this joint). Not verified at the source, so the default stays 2.8; this
    // measures what 2.8 → 15 does to the starvation figure's numbers at 20 kN.
    let with = |h_oil: Option<f64>, g: f64| {
        let mut p = Params::paper();
        p.starvation.inlet_layer_inverse = h_oil.map_or(0.0, |h| 1.0 / h);
        p.starvation.exponent = g;
        Joint::new(&p).unwrap()
    };
    let rad = std::f64::consts::PI / 30.0;
    let flooded = mu_crossing_rpm(&with(None, 2.8), 20e3, 0.11).unwrap();
    // The flooded model: μ = 0.11 at 17.0 rpm at 20 kN (docs/model.md, the claims table of docs/paper-comparison.md).
    assert!((flooded / 17.0 - 1.0).abs() < 0.01, "{flooded}");
    // Measured (rpm where μ = 0.11 at 20 kN; μ at 800 rpm):
    //   h_oil = 10 µm:  17.4 / 17.3 / 17.0 rpm for γs = 2.8 / 3 / 15;  μ(800) 0.0003 for all
    //   h_oil = 4 µm:   26.5 / 25.2 / 17.1 rpm;  μ(800) 0.0224 / 0.0215 / 0.0187
    //   h_oil = 3.4 µm: 69.2 / 61.7 / 19.5 rpm;  μ(800) 0.0965 / 0.0964 / 0.0963
    // So with γs = 15 the thin layers barely move the μ = 0.11 crossing off the flooded 17 rpm
    // (the starvation figure's 26.5 and 69 rpm are γs = 2.8 numbers); μ at 800 rpm, where the
    // film is nearly the layer itself (R ≪ 1), moves by at most 17 % (4 µm).
    let want = [(10e-6, [17.43, 17.32, 17.03]), (4e-6, [26.54, 25.20, 17.14]), (3.4e-6, [69.19, 61.74, 19.54])];
    for (h_oil, rpm) in want {
        let mut line = format!("h_oil = {:.1} µm:", h_oil * 1e6);
        let mut prev_cross = f64::INFINITY;
        for (g, r) in [2.8, 3.0, 15.0].into_iter().zip(rpm) {
            let j = with(Some(h_oil), g);
            let c = mu_crossing_rpm(&j, 20e3, 0.11).unwrap();
            let mu800 = j.evaluate(20e3, 800.0 * rad).unwrap().friction_coefficient;
            line += &format!("  γs = {g}: μ = 0.11 at {c:.2} rpm, μ(800 rpm) = {mu800:.4};");
            assert!((c / r - 1.0).abs() < 0.002, "h_oil = {h_oil}, γs = {g}: {c} rpm, measured {r}");
            // A larger γs is a sharper blend (min(h_ff, h_oil) in the limit): a thicker film, so
            // μ falls below 0.11 no later, and never earlier than in the flooded model.
            assert!(c <= prev_cross * (1.0 + 1e-9) && c >= flooded * (1.0 - 1e-9), "h_oil = {h_oil}, γs = {g}: {c} after {prev_cross}");
            prev_cross = c;
        }
        eprintln!("{line}");
    }
}
