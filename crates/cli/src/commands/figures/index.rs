//! The captions of `pinjoint figures` and the pages that show the figures: `index.html` and
//! `README.md` in the output directory. Every number in a caption is computed from this run's
//! results; the paper's statements are quoted beside them for comparison.

use crate::common::{lin_space, log_space, readable, RAD_S_PER_RPM, RIG_LOAD_RANGE_N};
use super::claims::{speed_at, Claim};
use crate::numbers::{nm, pct, sig};
use crate::error::Result;
use super::plots::PAPER_LOW_SPEED_MU;
use super::plots::CoreCurves;
use super::rig::{at_frequency, find, RigResult, PAPER_FREQUENCIES};
use pinjoint::paper::LOADS as PAPER_LOADS;
use std::f64::consts::TAU;
use pinjoint::Joint;

/// One figure of the paper as reproduced: its images, data files and caption.
#[derive(Debug, Clone)]
pub struct Entry {
    /// Heading of the figure, e.g. "Figure 3: Stribeck curve".
    pub title: String,
    /// SVG files of the figure, relative to the output directory.
    pub images: Vec<String>,
    /// CSV files with the figure's data, relative to the output directory.
    pub data: Vec<String>,
    /// What the figure shows and how it compares with the paper (HTML-escaped on output).
    pub caption: String,
}

/// How the run was made, for the pages' introduction.
#[derive(Debug, Clone)]
pub struct RunInfo {
    /// Whether the run was `--quick` (coarser grids and rig runs).
    pub quick: bool,
    /// Output samples per rig stroke.
    pub samples_per_cycle: usize,
    /// Relative tolerance of the rig's ODE solver.
    pub rtol: f64,
    /// Absolute tolerance of the rig's ODE solver.
    pub atol: f64,
}

fn r4(x: f64) -> String {
    sig(x, 4)
}

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)))
}

/// Lowest μ and highest λ over loads × speeds (rpm).
fn extremes(joint: &Joint, loads: &[f64], rpm: (f64, f64)) -> Result<(f64, f64)> {
    let speeds = log_space(rpm.0 * RAD_S_PER_RPM, rpm.1 * RAD_S_PER_RPM, 25);
    let (mut mu, mut lambda) = (f64::INFINITY, 0.0f64);
    for &p in loads {
        for &w in &speeds {
            let o = joint.evaluate(p, w)?;
            mu = mu.min(o.friction_coefficient);
            lambda = lambda.max(o.lambda_ratio);
        }
    }
    Ok((mu, lambda))
}

/// The speed (rpm) at which μ(P, ω) falls to `mu` (μ decreases with speed), by bisection in
/// log speed over `rpm`; the range's end if μ does not cross `mu` inside it.
fn speed_where(joint: &Joint, load: f64, mu: f64, rpm: (f64, f64)) -> Result<f64> {
    let f = |n: f64| joint.evaluate(load, n * RAD_S_PER_RPM).map(|o| o.friction_coefficient - mu);
    let (mut a, mut b) = (rpm.0.ln(), rpm.1.ln());
    if f(rpm.0)? <= 0.0 {
        return Ok(rpm.0);
    }
    if f(rpm.1)? > 0.0 {
        return Ok(rpm.1);
    }
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if f(m.exp())? > 0.0 { a = m } else { b = m }
    }
    Ok((0.5 * (a + b)).exp())
}

fn fig3(joint: &Joint) -> Result<Entry> {
    let p = 20e3;
    let at = |rpm: f64| joint.evaluate(p, rpm * RAD_S_PER_RPM);
    let (a, c) = (at(1.0)?, at(800.0)?);
    let light = joint.evaluate(RIG_LOAD_RANGE_N.0, 800.0 * RAD_S_PER_RPM)?;
    let mu_c = joint.params().friction.boundary_friction_coefficient;
    let half_mu = speed_where(joint, p, 0.5 * mu_c, (1.0, 800.0))?;
    let half_load = speed_at(joint, p, (1.0, 800.0), 0.5, |o| o.fluid_load_fraction)?;
    Ok(Entry {
        title: "Figure 3 — Stribeck curve at 20 kN".into(),
        images: vec!["stribeck.svg".into()],
        data: vec!["stribeck.csv".into()],
        caption: format!(
            "The core model at P_T = 20 kN (mean Hertz pressure {} MPa; paper: 13 MPa): (a) μ, (b) the load \
fractions 1/γ1 (fluid) and 1/γ2 (asperities), (c) λ against the Sommerfeld number (eq. 20). \
Dashed: the paper's simulated range, 1 and 800 rpm, where S runs from {} to {} at 20 kN and up to {} \
at 5 kN (paper: \"0 to 0.15\"). Shaded: the speeds the rig's strokes reach (up to 41.9 rpm at 1 Hz), \
for reference. As S grows the film takes a growing share of the load and μ falls, as the paper \
describes, down to a full-film minimum (past it the film's viscous friction grows with speed). The paper states that over 1–800 rpm at 20 kN \"the dominant mechanism is one of solid \
contact and hydrodynamic film formation plays little part\". This model does not reproduce that: \
the film carries half the load from {} on, μ is half of μ_c from {} rpm, and at 800 rpm the film \
carries {} of the load (μ = {}, λ = {}). See the claims table for why.",
            sig(a.mean_pressure / 1e6, 3),
            sig(a.sommerfeld_number, 3),
            sig(c.sommerfeld_number, 3),
            sig(light.sommerfeld_number, 3),
            half_load.map_or_else(|| "beyond 800 rpm".to_string(), |n| format!("{} rpm", sig(n, 3))),
            sig(half_mu, 3),
            pct(c.fluid_load_fraction),
            sig(c.friction_coefficient, 2),
            sig(c.lambda_ratio, 3),
        ),
    })
}

fn fig4(joint: &Joint) -> Result<Entry> {
    let loads = lin_space(RIG_LOAD_RANGE_N.0, RIG_LOAD_RANGE_N.1, 12);
    let (mu_min, lambda_max) = extremes(joint, &loads, (1.0, 800.0))?;
    let rest: Vec<f64> = [5e3, 20e3, 60e3].iter().map(|&p| joint.evaluate(p, 0.0).map(|o| o.lambda_ratio)).collect::<std::result::Result<_, _>>()?;
    let cross: Vec<f64> = [5e3, 20e3, 60e3].iter().map(|&p| speed_where(joint, p, 0.11, (1.0, 800.0))).collect::<Result<_>>()?;
    Ok(Entry {
        title: "Figure 4 — maps of λ and μ over load and speed".into(),
        images: vec!["map_lambda.svg".into(), "map_friction.svg".into(), "map_curves.svg".into()],
        data: vec!["map.csv".into()],
        caption: format!(
            "(a) λ and (b) μ over 5–60 kN and 1–800 rpm, with contour lines: the whole map is the paper's \
operating region (section 3.2). The third plot shows μ and λ against speed at the paper's five loads. \
The paper: \"friction coefficients do not fall below 0.11 as lambda ratios stay below 2\" in that \
region. This model reproduces neither: μ = 0.11 is crossed at {} / {} / {} rpm at 5 / 20 / 60 kN and \
μ falls to {} in the region; λ (from the central film h_c, as the paper gives no h_min relation) is \
already {} / {} / {} at rest at 5 / 20 / 60 kN and reaches {}. The red box marks the speeds the rig's \
strokes reach (up to 41.9 rpm at 1 Hz) for reference; it is not the paper's operating region.",
            sig(cross[0], 3),
            sig(cross[1], 3),
            sig(cross[2], 3),
            sig(mu_min, 2),
            sig(rest[0], 3),
            sig(rest[1], 3),
            sig(rest[2], 3),
            sig(lambda_max, 3),
        ),
    })
}

fn fig7(results: &[RigResult]) -> Option<Entry> {
    let r = find(results, 1.0, 20e3)?;
    let s = &r.shape;
    let peak = r.run.window().iter().map(|x| x.angular_velocity.abs()).fold(0.0, f64::max);
    Some(Entry {
        title: "Figure 7 — one 1 Hz stroke: angle, speed, torque".into(),
        images: vec!["fig07_cycle_1Hz_20kN.svg".into()],
        data: vec!["fig07_cycle_1Hz_20kN.csv".into()],
        caption: format!(
            "The second stroke of the simulated rig at 1 Hz, ±40°, 20 kN: (a) pin angle and command (a \
smooth sine; the pin lags by at most {}°), (b) speed (peak {} rad/s; the paper derived it from the \
angle record; the flat parts at zero are the stick at each reversal), (c) torque against time and \
(d) against angle. As in the paper's Figure 7, the torque is higher towards the stroke ends where \
the speed is low ({} at 70–80 % of the stroke) and lowest near zero degrees ({} at mid-stroke), \
where the speed peaks and the entrained grease lifts part of the load. The overshoot after each \
breakaway (up to {} from the quasi-static torque) is servo ringing of the rig model, whose gains \
are assumed. The model's torque is higher at the start and stop points only through μ(ω) (μ_c·R·P \
where ω = 0); it has no static-friction peak above that (rig.breakaway_factor = 1), so the \
paper's \"slightly higher\" torque there is only partly reproduced; raising breakaway_factor \
adds a peak.",
            sig(s.tracking_error_deg, 2),
            sig(peak, 3),
            nm(s.outer_torque),
            nm(s.mid_torque),
            nm(s.ringing),
        ),
    })
}

/// How one frequency's values go with load: "rises from a at 5 kN to b at 60 kN", "falls …",
/// or "goes from a at 5 kN through a maximum of b at 20 kN to c at 60 kN".
fn trend(v: &[(f64, f64)]) -> String {
    let (Some(first), Some(last)) = (v.first(), v.last()) else { return String::new() };
    let at = |p: &(f64, f64)| format!("{} at {} kN", r4(p.1), readable(p.0 / 1e3));
    let rising = v.windows(2).all(|w| w[1].1 > w[0].1);
    let falling = v.windows(2).all(|w| w[1].1 < w[0].1);
    if rising || falling {
        return format!("{} from {} to {}", if rising { "rises" } else { "falls" }, at(first), at(last));
    }
    let max = v.iter().copied().fold(*first, |m, p| if p.1 > m.1 { p } else { m });
    let min = v.iter().copied().fold(*first, |m, p| if p.1 < m.1 { p } else { m });
    let turn = if max != *first && max != *last { ("a maximum", max) } else { ("a minimum", min) };
    format!("goes from {} through {} of {} to {}", at(first), turn.0, at(&turn.1), at(last))
}

fn fig8_10(results: &[RigResult], core: &CoreCurves) -> Result<Vec<Entry>> {
    let at = |f: f64| at_frequency(results, f);
    let amplitude = results.first().map_or(40f64.to_radians(), |r| r.run.config.rig.amplitude);
    let (c_lo, c_hi) = range(core.at_paper.iter().flatten().copied());
    let (slow_lo, slow_hi) = range(core.at_paper[0].iter().copied());
    let (rig_slow_lo, rig_slow_hi) = range(at(0.03).iter().map(|r| r.run.average_friction_coefficient));
    let (stuck_lo, stuck_hi) = range(at(0.03).iter().map(|r| r.shape.stuck_fraction));
    let below = at(0.03).iter().map(|r| 1.0 - r.run.average_friction_coefficient / r.quasi_static_average).fold(0.0, f64::max);
    let factor = 4.0 * amplitude / TAU;
    let method = format!(
        "Lines and dots: the model's friction coefficient the way the paper made its Figures 8–10, eq. 11 \
applied through the stroke: μ(P, |ω(t)|) of the core averaged over a ±{}° sine stroke, which is mean|T| / (R·P) \
of a rig that follows its command exactly. Dots mark the paper's 0.03, 0.3 and 1 Hz; over the 15 test \
conditions the average is {}–{}. Crosses: the rig simulation's eq. 11 average (mean |recorded torque| \
over the second stroke / (R·P)), a second series whose values depend on the servo gains this project \
assumed (the paper gives none). The x axis uses the paper's nominal speed labelling, ω = 2πf (60·f rpm: \
1.8, 18, 60 rpm); at the stroke's mean |ω| = 4Af instead, every x value is {} times as large (the \
CSV has both).",
        readable(amplitude.to_degrees()),
        r4(c_lo),
        r4(c_hi),
        sig(factor, 3),
    );
    let slow = format!(
        "At 0.03 Hz the model's average is {}–{} over the loads (paper: measured {PAPER_LOW_SPEED_MU} at low speed, \
against μ_c = 0.12). The rig simulation gives {}–{}, up to {} below the model, because the joint sticks at \
each reversal for {}–{} of the time while the actuator winds up the reversed torque and the recorded \
torque passes through zero meanwhile; the stick lasts longer at higher load, which reverses the load \
trend of the rig series at 0.03 Hz.",
        r4(slow_lo),
        r4(slow_hi),
        r4(rig_slow_lo),
        r4(rig_slow_hi),
        pct(below),
        pct(stuck_lo),
        pct(stuck_hi),
    );
    let model_trends: Vec<String> = PAPER_FREQUENCIES
        .iter()
        .zip(&core.at_paper)
        .map(|(&f, row)| format!("{} at {} Hz", trend(&PAPER_LOADS.iter().copied().zip(row.iter().copied()).collect::<Vec<_>>()), readable(f)))
        .collect();
    let rig_trends: Vec<String> = PAPER_FREQUENCIES
        .iter()
        .map(|&f| {
            let v: Vec<(f64, f64)> = at(f).iter().map(|r| (r.run.load(), r.run.average_friction_coefficient)).collect();
            format!("{} at {} Hz", trend(&v), readable(f))
        })
        .collect();
    Ok(vec![
        Entry {
            title: "Figure 8 — friction coefficient against Sommerfeld number".into(),
            images: vec!["fig08_mu_sommerfeld.svg".into()],
            data: vec!["core_curves.csv".into(), "rig_averages.csv".into()],
            caption: format!("{method} S (eq. 20) is the core's at the load and the nominal speed. {slow}"),
        },
        Entry {
            title: "Figure 9 — friction coefficient against sliding speed".into(),
            images: vec!["fig09_mu_sliding_speed.svg".into()],
            data: vec!["core_curves.csv".into(), "rig_averages.csv".into()],
            caption: format!(
                "{method} Sliding speed u = R·2πf (R = 28 mm). In the model a heavier load gives a thinner film \
and so a higher μ at the same speed. The paper finds the load effect in its experiments more pronounced \
than in its theory and names grease squeezed out at high load and slow to flow back, which a fully \
flooded model cannot show."
            ),
        },
        Entry {
            title: "Figure 10 — friction coefficient against load".into(),
            images: vec!["fig10_mu_load.svg".into()],
            data: vec!["core_curves.csv".into(), "rig_averages.csv".into()],
            caption: format!(
                "Solid lines and dots: the model's eq. 11 stroke average against load at 0.03, 0.3 and 1 Hz; it {}. \
Dashed with crosses: the rig simulation, which {}. {slow}",
                model_trends.join("; "),
                rig_trends.join("; "),
            ),
        },
    ])
}

fn fig11_13(joint: &Joint, results: &[RigResult]) -> Result<Vec<Entry>> {
    let spread = range(at_frequency(results, 0.03).iter().map(|r| r.shape.spread)).1;
    let ring_slow = range(at_frequency(results, 0.03).iter().map(|r| r.shape.ringing)).1;
    let dip = |f: f64, p: f64| find(results, f, p).map(|r| r.shape);
    let describe = |f: f64, p: f64| match dip(f, p) {
        Some(s) => format!(
            "by {} ({}) at {} kN (core: {})",
            nm(s.outer_torque - s.mid_torque),
            pct(s.dip()),
            readable(p / 1e3),
            nm(s.outer_core - s.mid_core)
        ),
        None => String::new(),
    };
    let mu_c = joint.params().friction.boundary_friction_coefficient;
    let radius = joint.params().geometry.pin_radius;
    let amplitude = results.first().map_or(40f64.to_radians(), |r| r.run.config.rig.amplitude);
    // The core's dip at 1 Hz measured from the stroke end (ω = 0, T = μ_c·R·P) to mid-stroke (peak speed).
    let from_end = |p: f64| -> Result<String> {
        let end = mu_c * radius * p;
        let mid = joint.evaluate(p, TAU * amplitude)?.torque;
        Ok(format!("{} → {} ({} lower) at {} kN", nm(end), nm(mid), pct(1.0 - mid / end), readable(p / 1e3)))
    };
    let (end20, end60) = (from_end(20e3)?, from_end(60e3)?);
    let r1 = find(results, 1.0, 20e3);
    let (ring, settled) = r1.map_or((f64::NAN, f64::NAN), |r| (r.shape.ringing, r.shape.settled));
    let panels = "(a) the recorded torque over the second stroke at each of the paper's loads; (b) the 20 kN \
run with the core's quasi-static torque μ(P, |ω|)·R·P at each sample's speed (dashed).";
    let names = ["fig11_torque_0.03Hz", "fig12_torque_0.3Hz", "fig13_torque_1Hz"];
    let captions = [
        format!(
            "f = 0.03 Hz (1.8 rpm nominal). {panels} Between the reversals |torque| varies by at most \
{} of its mean over the inner 80 % of the stroke at any load, and deviates from the quasi-static \
core torque by at most {}: the torque remains virtually constant during rotation, as the paper \
observes (hydrodynamic lift negligible), with no servo oscillation. The sloped reversals are the \
stick phases, during which the actuator winds up the reversed torque.",
            pct(spread),
            nm(ring_slow)
        ),
        format!(
            "f = 0.3 Hz (18 rpm nominal). {panels} A shallow dip appears at mid-stroke: |torque| falls \
{}, from 70–80 % of the stroke to mid-stroke. A short ringing follows each breakaway.",
            describe(0.3, 20e3)
        ),
        format!(
            "f = 1 Hz (60 rpm nominal; the stroke peaks at 41.9 rpm). {panels} The torque dips at mid-stroke \
where the speed peaks (paper: \"at the higher speeds there is a reduction in torque as the joint \
articulates at its maximum velocity\"; it gives no number). Measured from the stroke end, where ω = 0 \
and the torque is μ_c·R·P, to mid-stroke, the model's quasi-static torque goes {} and {}. \
Measured from 70–80 % of the stroke instead, |torque| falls {} and {}. After each reversal the recorded torque rings, up to {} away from the \
quasi-static torque at 20 kN, decaying to within {} later in the stroke: the limited response of \
the hydraulic servo that the paper blames for the oscillation in its 1 Hz record.",
            end20,
            end60,
            describe(1.0, 20e3),
            describe(1.0, 60e3),
            nm(ring),
            nm(settled)
        ),
    ];
    Ok(PAPER_FREQUENCIES
        .iter()
        .zip(names)
        .zip(captions)
        .enumerate()
        .map(|(i, ((f, name), caption))| Entry {
            title: format!("Figure {} — frictional torque against time at {} Hz", 11 + i, readable(*f)),
            images: vec![format!("{name}.svg")],
            data: vec![format!("{name}.csv")],
            caption,
        })
        .collect())
}

/// Every figure, in the paper's order.
pub fn entries(joint: &Joint, results: &[RigResult], core: &CoreCurves) -> Result<Vec<Entry>> {
    let mut out = vec![fig3(joint)?, fig4(joint)?];
    out.extend(fig7(results));
    out.extend(fig8_10(results, core)?);
    out.extend(fig11_13(joint, results)?);
    out.push(starvation());
    out.push(at_rest());
    Ok(out)
}

/// Friction at rest: the zero-velocity models ([`super::at_rest`]).
fn at_rest() -> Entry {
    Entry {
        title: "Friction at rest: band against presliding".into(),
        images: vec!["at_rest_hold.svg".into(), "at_rest_loop.svg".into()],
        data: vec!["at_rest_hold.csv".into(), "at_rest_loop.csv".into()],
        caption: "Not in the paper: what the FMU does when a system simulation holds the joint. A body (J = 50 kg·m²) on the pin \
at 20 kN under a drive of half the breakaway torque, integrated by an explicit host at 1 ms: with the stateless band the joint \
creeps at ω = T_drive·ω_b/T, with the presliding state (the FMU's default) it holds at its elastic deflection. Below: torque \
against angle over a 0.5 Hz sine of the angle, amplitudes 0.5 and 2 presliding angles: presliding is elastic below breakaway and \
an elasto-plastic loop beyond it; the band, a function of ω alone, gives a loop through zero torque at rest."
            .into(),
    }
}

/// The starved-inlet extension (off by default; [`super::starvation`]).
fn starvation() -> Entry {
    Entry {
        title: "Extension: a starved inlet (off by default)".into(),
        images: vec!["starvation_stribeck.svg".into(), "starvation_cycle_1Hz.svg".into()],
        data: vec!["starvation_stribeck.csv".into(), "starvation_cycle_1Hz.csv".into(), "starvation_summary.csv".into()],
        caption: "μ and the asperities' load share 1/γ2 against speed at 20 kN, and the core's torque along the 1 Hz ±40° \
stroke at 20 kN (no servo dynamics), for inlet oil layers h_oil = ∞ (the paper's fully flooded model), 10, 4 and 3.4 µm: \
Chevalier et al.'s starvation relation h^−γs = h_flooded^−γs + h_oil^−γs (γs = 2.8) inside the load-sharing solve \
(`[starvation] inlet_layer_inverse` = 1/h_oil); not checked against the 1998 paper (not available here): the form was \
found only in a secondary summary of Lugt (2013, eq. 9.73; γ about 3 for circular, up to 15 for wide elliptical contacts), \
γs = 2.8 is from memory and may be low for this line contact, and only the relation's limits and its γs sensitivity are tested. A thin layer keeps the joint boundary-dominated to higher speeds, as \
the paper's experiments suggest, but a constant layer makes the lightest load the most boundary, the opposite of the \
measured load trend; the per-layer numbers (μ = 0.11 crossings, half-load speed, μ at 800 rpm, the 1 Hz dip) are in \
starvation_summary.csv and the project's docs/extensions.md."
            .into(),
    }
}

fn intro(info: &RunInfo) -> Vec<String> {
    vec![
        "The paper's figures reproduced by `pinjoint figures` on the built-in parameters (Tables 1–3, \
μ_c = 0.12, and the rig defaults of src/rig/params.rs). Figures 3 and 4 are the friction core alone; \
Figures 7–13 come from 15 simulations of the torsion rig (loads 5, 10, 20, 40, 60 kN × 0.03, 0.3, \
1 Hz, ±40° sine strokes, hybrid stick/slip formulation), each two strokes from rest, of which the \
first (start-up) is left out."
            .into(),
        format!(
            "Rig integration: Dopri5, rtol {:e}, atol {:e}, {} samples per stroke{}.",
            info.rtol,
            info.atol,
            info.samples_per_cycle,
            if info.quick { " (--quick: coarser core sweeps and samples, looser tolerances; for a look, not for the record)" } else { "" }
        ),
        "Only the simulated side of Figures 8–13 can be reproduced: the paper's measurements are not \
available as data. Every number in the claims table and the captions below is computed from this run."
            .into(),
    ]
}

/// The lines around the claims table in the figures' README.md, and in docs/paper-comparison.md
/// (where `crates/cli/tests/figures_claims.rs` checks that the two tables are the same).
pub const CLAIMS_BEGIN: &str = "<!-- claims table: generated by `pinjoint figures`, do not edit -->";
/// The line after the claims table (see [`CLAIMS_BEGIN`]).
pub const CLAIMS_END: &str = "<!-- end of claims table -->";

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// `index.html`: every figure with its caption and data files.
pub fn html(entries: &[Entry], claims: &[Claim], info: &RunInfo) -> String {
    let mut out = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pinjoint: the paper's figures</title>\n\
<style>body{font-family:sans-serif;max-width:1050px;margin:2em auto;padding:0 1em;line-height:1.45}\
figure{margin:2.5em 0}img{max-width:100%;border:1px solid #ddd}figcaption{margin-top:.6em}\
.data{color:#555;font-size:.9em}table.claims{border-collapse:collapse;font-size:.85em}\
.claims td,.claims th{border:1px solid #ccc;padding:.3em .4em;vertical-align:top;text-align:left}\
.claims .yes{background:#e3f4e3}.claims .no{background:#f8dede}.claims .other{background:#f2f2f2}</style>\n</head>\n<body>\n<h1>Pin joint friction: the paper's figures</h1>\n",
    );
    for p in intro(info) {
        out.push_str(&format!("<p>{}</p>\n", html_escape(&p)));
    }
    out.push_str("<h2>The paper's statements against this model</h2>\n");
    out.push_str(&super::claims::html(claims, html_escape));
    for e in entries {
        out.push_str(&format!("<figure>\n<h2>{}</h2>\n", html_escape(&e.title)));
        for img in &e.images {
            out.push_str(&format!("<img src=\"{img}\" alt=\"{}\">\n", html_escape(&e.title)));
        }
        out.push_str(&format!("<figcaption>{}</figcaption>\n", html_escape(&e.caption)));
        let links: Vec<String> = e.data.iter().map(|d| format!("<a href=\"{d}\">{d}</a>")).collect();
        out.push_str(&format!("<p class=\"data\">Data: {}</p>\n</figure>\n", links.join(", ")));
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// `README.md`: the same as Markdown.
pub fn markdown(entries: &[Entry], claims: &[Claim], info: &RunInfo) -> String {
    let mut out = String::from("# Pin joint friction: the paper's figures\n\n");
    for p in intro(info) {
        out.push_str(&p);
        out.push_str("\n\n");
    }
    out.push_str("## The paper's statements against this model\n\n");
    out.push_str(CLAIMS_BEGIN);
    out.push('\n');
    out.push_str(&super::claims::markdown(claims));
    out.push_str(CLAIMS_END);
    out.push_str("\n\n");
    for e in entries {
        out.push_str(&format!("## {}\n\n", e.title));
        for img in &e.images {
            out.push_str(&format!("![{}]({img})\n\n", e.title));
        }
        out.push_str(&e.caption);
        out.push_str("\n\n");
        let links: Vec<String> = e.data.iter().map(|d| format!("[{d}]({d})")).collect();
        out.push_str(&format!("Data: {}\n\n", links.join(", ")));
    }
    out
}
