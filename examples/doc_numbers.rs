//! The library quantities the manual quotes and the command line does not print, as one JSON
//! object (name → number), for the docs checker (`tests/docs/check_docs.py`, which ties each
//! quoted number of docs/journal-bearing.md and docs/cold-day.md to one of these names).
//!
//! ```text
//! cargo run --release -p pinjoint --example doc_numbers
//! ```
//!
//! Every number comes from the library's own functions at the default parameters (the paper's
//! joint): the joint's load capacity, the finite journal bearing's table (Raimondi & Boyd's L/D = 1 comparison), the
//! infinitely long bearing, the grease's rheology (`pinjoint::composite::rheology`, the model's
//! own law) with the base oil of Roelands' temperature relation, the clearance's torque and
//! its quadrature against a high-order reference.

use pinjoint::clearance::{clearance_torque_parts, power_law_integral, PowerLawTable, MAX_ECCENTRICITY};
use pinjoint::journal::limits::long_bearing;
use pinjoint::journal::table::{JournalTable, LD_MAX};
use pinjoint::Params;
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// The default parameters at `celsius` °C (the same kelvin as `pinjoint point --temperature`).
fn at(celsius: f64) -> Params {
    let mut p = Params::default();
    p.lubricant.temperature = (100.0 * celsius + 27315.0) / 100.0;
    p
}

/// η_b(T): the base oil's viscosity at `celsius` (Roelands' temperature relation; not limited to
/// the model's declared temperature range).
fn base_viscosity(celsius: f64) -> f64 {
    pinjoint::rheology::viscosity::at_temperature(&at(celsius).lubricant).viscosity
}

/// The model's clearance rheology (grease and base oil) at `celsius`, with `edit` applied to
/// the parameters first.
fn rheology(celsius: f64, edit: &dyn Fn(&mut Params)) -> pinjoint::rheology::grease::GreaseRheology {
    let mut p = at(celsius);
    edit(&mut p);
    pinjoint::composite::rheology(&p, base_viscosity(celsius))
}

/// Gauss–Legendre nodes and weights (Newton on the Legendre polynomials).
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let (mut xs, mut ws) = (Vec::new(), Vec::new());
    for i in 1..=n {
        let mut x = (PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
            }
            dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        xs.push(x);
        ws.push(2.0 / ((1.0 - x * x) * dp * dp));
    }
    (xs, ws)
}

/// Jₙ(ε, θ_c) by composite 20-point Gauss–Legendre on 600 panels in the balanced angle
/// (tan(θ/2) = ((1−ε)/(1+ε))^¼ tan(ψ/2)): the reference of the clearance module's tests.
fn reference_integral(eps: f64, theta_c: f64, n: f64, rule: &(Vec<f64>, Vec<f64>)) -> f64 {
    let k = ((1.0 - eps) / (1.0 + eps)).powf(0.25);
    let psi_c = 2.0 * ((0.5 * theta_c).tan() / k).atan();
    let panels = 600u32;
    let width = (PI - psi_c) / f64::from(panels);
    let mut sum = 0.0;
    for p in 0..panels {
        let mid = psi_c + (f64::from(p) + 0.5) * width;
        for (x, w) in rule.0.iter().zip(&rule.1) {
            let psi = mid + 0.5 * width * x;
            let t = (0.5 * psi).tan();
            let theta = 2.0 * (k * t).atan();
            let dtheta = k * (1.0 + t * t) / (1.0 + k * k * t * t);
            let dtheta = if dtheta.is_finite() { dtheta } else { 1.0 / k };
            sum += 0.5 * width * w * (1.0 - eps * theta.cos()).powf(-n) * dtheta;
        }
    }
    2.0 * sum
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut out = BTreeMap::<String, f64>::new();
    let defaults = Params::default();

    // The asperity model's limit: the load at which eq. 19's rest film reaches zero.
    out.insert("joint.capacity".into(), pinjoint::Joint::new(&defaults)?.capacity());

    // The finite journal bearing at L/D = 1 against Raimondi & Boyd's rows.
    let ld1 = JournalTable::build(1.0)?;
    for eps in [0.1, 0.2, 0.4, 0.6, 0.8, 0.9, 0.97] {
        out.insert(format!("journal.ld1.S.{eps}"), ld1.sommerfeld(eps));
        out.insert(format!("journal.ld1.phi_deg.{eps}"), ld1.attitude_angle(eps).to_degrees());
        out.insert(format!("journal.ld1.f.{eps}"), ld1.friction_variable(eps));
    }
    for (name, ld) in [("ld_half", 0.5), ("ld_quarter", 0.25)] {
        let t = JournalTable::build(ld)?;
        for eps in [0.1, 0.2, 0.4, 0.6, 0.8, 0.9] {
            out.insert(format!("journal.{name}.S.{eps}"), t.sommerfeld(eps));
            out.insert(format!("journal.{name}.phi_deg.{eps}"), t.attitude_angle(eps).to_degrees());
            out.insert(format!("journal.{name}.f.{eps}"), t.friction_variable(eps));
        }
    }
    let (s_long, phi_long, _) = long_bearing(0.1);
    out.insert("journal.long.S.0.1".into(), s_long);
    out.insert("journal.long.phi_deg.0.1".into(), phi_long.to_degrees());
    out.insert("journal.ld_max.S.0.1".into(), JournalTable::build(LD_MAX)?.sommerfeld(0.1));

    // The base oil (Roelands' temperature relation with the default lubricant).
    for c in [20.0, 25.0, 40.0, 100.0, -54.0, -55.0, -73.0] {
        out.insert(format!("base_oil.viscosity.{c}"), base_viscosity(c));
    }

    // The grease's rheology (the model's law) at the default parameters.
    let keep = |_: &mut Params| {};
    for c in [20.0, 25.0, -54.0] {
        out.insert(format!("grease.apparent_viscosity.25.{c}"), rheology(c, &keep).apparent_viscosity(25.0));
    }
    out.insert("grease.yield_stress_ratio.-54".into(), rheology(-54.0, &keep).yield_stress / rheology(20.0, &keep).yield_stress);
    out.insert("grease.yield_stress.-54".into(), rheology(-54.0, &keep).yield_stress);
    out.insert("grease.consistency.-54".into(), rheology(-54.0, &keep).consistency);
    // A thickener that keeps its share of the stress: the activation that moves K (and τ_y) by
    // the base oil's own ratio η_b(−54 °C)/η_b(20 °C) (the reference temperature's default).
    let oil_activation = (base_viscosity(-54.0) / base_viscosity(20.0)).ln() / (1.0 / at(-54.0).lubricant.temperature - 1.0 / at(20.0).lubricant.temperature);
    out.insert("grease.oil_activation.-54".into(), oil_activation);
    out.insert(
        "grease.apparent_viscosity.25.-54.k_with_oil".into(),
        rheology(-54.0, &|p: &mut Params| p.grease.consistency_activation = oil_activation).apparent_viscosity(25.0),
    );
    out.insert(
        "grease.apparent_viscosity.25.-54.both_with_oil".into(),
        rheology(-54.0, &|p: &mut Params| {
            p.grease.consistency_activation = oil_activation;
            p.grease.yield_activation = oil_activation;
        })
        .apparent_viscosity(25.0),
    );
    // ASTM D1478 translated: the stress at 0.2 and 2 s⁻¹ on the 6204 bearing's pitch radius
    // r = 16.75 mm and width w = 14 mm, T = τ·2π r² w.
    let (r, w) = (16.75e-3, 14e-3);
    for c in [-54.0, -73.0] {
        for rate in [0.2, 2.0] {
            out.insert(format!("grease.d1478_torque.{c}/{rate}"), rheology(c, &keep).stress(rate) * 2.0 * PI * r * r * w);
        }
    }

    // The clearance's torque parts at U = 0.1 m/s, ε_g = 0.98, θ_c = 0.1 rad on the paper's pin.
    let g = &defaults.geometry;
    let clearance = g.bush_radius - g.pin_radius;
    let parts = |c: f64, edit: &dyn Fn(&mut Params)| {
        clearance_torque_parts(&rheology(c, edit), 0.1, g.pin_radius, g.bush_length, clearance, 0.98, 0.1)
    };
    // The activations at their defaults and 1000 K either side.
    for d in [-1000.0, 0.0, 1000.0] {
        let e = defaults.grease.yield_activation + d;
        out.insert(format!("clearance.yield.-54.Ey.{e}"), parts(-54.0, &|p: &mut Params| p.grease.yield_activation = e).yield_part);
        let e = defaults.grease.consistency_activation + d;
        out.insert(format!("clearance.power.-54.EK.{e}"), parts(-54.0, &|p: &mut Params| p.grease.consistency_activation = e).power_law_part);
    }
    out.insert("clearance.base.-54".into(), parts(-54.0, &keep).newtonian_part);
    let warm = parts(20.0, &keep);
    out.insert("clearance.yield.20".into(), warm.yield_part);
    out.insert("clearance.power.20".into(), warm.power_law_part);
    out.insert("clearance.base.20".into(), warm.newtonian_part);

    // The 12-point rule for Jₙ against the 600-panel reference: the worst relative error over
    // flow indices and contact arcs, at each ε.
    let rule = gauss_legendre(20);
    for eps in [0.3, 0.9, 0.99, 0.999, 0.9999] {
        let mut worst = 0.0f64;
        for n in [0.05, 0.2, 0.4, 0.7, 0.95] {
            for t in [0.0, 0.005, 0.05, 0.3, 1.0, 2.5] {
                worst = worst.max((power_law_integral(eps, t, n) / reference_integral(eps, t, n, &rule) - 1.0).abs());
            }
        }
        out.insert(format!("clearance.rule_error.{eps}"), worst);
    }
    // The power-law table against the same reference, by region.
    let mut worst = [0.0f64; 3];
    for n in [0.05, 0.2, 0.4, 0.7, 0.95] {
        let t = PowerLawTable::build(n)?;
        for le in [-6.0f64, -3.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 6.9, 8.0, 9.2, 10.5, 12.0, 14.0, 16.0, 20.7] {
            let eps: f64 = (1.0 / (1.0 + (-le).exp())).min(MAX_ECCENTRICITY);
            for th in [0.0, 0.001, 0.01, 0.03, 0.1, 0.2, 0.35, 0.5, 0.78, 1.0, 1.5, 2.0, 2.5, 3.0, 3.13] {
                let err = (t.integral(eps, th) / reference_integral(eps, th, n, &rule) - 1.0).abs();
                let region = if eps <= 0.999 && th <= 1.0 { 0 } else if eps <= 0.99999 { 1 } else { 2 };
                worst[region] = worst[region].max(err);
            }
        }
    }
    out.insert("clearance.table_error.near".into(), worst[0]);
    out.insert("clearance.table_error.to_0.99999".into(), worst[1]);
    out.insert("clearance.table_error.beyond".into(), worst[2]);

    let body: Vec<String> = out.iter().map(|(k, v)| format!("  {k:?}: {v:e}")).collect();
    println!("{{\n{}\n}}", body.join(",\n"));
    Ok(())
}
