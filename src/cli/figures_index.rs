//! The captions of `pinjoint figures` and the pages that show the figures: `index.html` and
//! `README.md` in the output directory. Every number in a caption is computed from this run's
//! results; the paper's statements are quoted beside them for comparison.

use super::common::{lin_space, log_space, readable, rig_peak_speed, RAD_S_PER_RPM, RIG_LOAD_RANGE_N};
use super::error::Result;
use super::figures_plots::PAPER_LOW_SPEED_MU;
use super::figures_rig::{at_frequency, find, RigResult, PAPER_FREQUENCIES};
use pinjoint::Joint;

/// One figure of the paper as reproduced: its images, data files and caption.
#[derive(Debug, Clone)]
pub struct Entry {
    pub title: String,
    pub images: Vec<String>,
    pub data: Vec<String>,
    pub caption: String,
}

/// How the run was made, for the pages' introduction.
#[derive(Debug, Clone)]
pub struct RunInfo {
    pub quick: bool,
    pub samples_per_cycle: usize,
    pub rtol: f64,
    pub atol: f64,
}

fn pct(x: f64) -> String {
    format!("{} %", readable((x * 1000.0).round() / 10.0))
}

fn r3(x: f64) -> String {
    readable((x * 1000.0).round() / 1000.0)
}

fn r4(x: f64) -> String {
    readable((x * 10000.0).round() / 10000.0)
}

fn nm(x: f64) -> String {
    format!("{} N·m", readable((x * 10.0).round() / 10.0))
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

fn fig3(joint: &Joint) -> Result<Entry> {
    let p = 20e3;
    let at = |rpm: f64| joint.evaluate(p, rpm * RAD_S_PER_RPM);
    let (a, b, c) = (at(1.0)?, at(rig_peak_speed() / RAD_S_PER_RPM)?, at(800.0)?);
    Ok(Entry {
        title: "Figure 3 — Stribeck curve at 20 kN".into(),
        images: vec!["stribeck.svg".into()],
        data: vec!["stribeck.csv".into()],
        caption: format!(
            "The core model at P_T = 20 kN (mean Hertz pressure {} MPa; paper: 13 MPa): (a) μ, (b) the load \
fractions 1/γ1 (fluid) and 1/γ2 (asperities), (c) λ against the Sommerfeld number (eq. 20). \
Shaded: the rig's speeds (up to 41.9 rpm); dashed: the paper's simulated range 1 and 800 rpm. \
Over that range S goes from {} to {} (paper: \"0 to 0.15\"), μ falls from {} (1 rpm) through {} \
(41.9 rpm) to {} (800 rpm), 1/γ1 reaches {} and λ {} at 800 rpm: as the paper says, solid contact \
dominates and the film plays little part, μ decreasing with S as 1/γ1 grows.",
            r3(a.mean_pressure / 1e6),
            readable(a.sommerfeld_number),
            r4(c.sommerfeld_number),
            r4(a.friction_coefficient),
            r4(b.friction_coefficient),
            r4(c.friction_coefficient),
            r3(c.fluid_load_fraction),
            r3(c.lambda_ratio),
        ),
    })
}

fn fig4(joint: &Joint) -> Result<Entry> {
    let loads = lin_space(RIG_LOAD_RANGE_N.0, RIG_LOAD_RANGE_N.1, 12);
    let (mu_rig, lambda_rig) = extremes(joint, &loads, (1.0, rig_peak_speed() / RAD_S_PER_RPM))?;
    let (mu_all, lambda_all) = extremes(joint, &loads, (1.0, 800.0))?;
    Ok(Entry {
        title: "Figure 4 — maps of λ and μ over load and speed".into(),
        images: vec!["map_lambda.svg".into(), "map_friction.svg".into(), "map_curves.svg".into()],
        data: vec!["map.csv".into()],
        caption: format!(
            "(a) λ and (b) μ over 5–60 kN and 1–800 rpm, with contour lines; the red box is the rig \
experiments' region (5–60 kN, up to the 1 Hz stroke's peak speed 41.9 rpm); the third plot shows \
μ and λ against speed at the paper's five loads. In the rig's region μ ≥ {} and λ ≤ {} (paper: \
\"friction coefficients do not fall below 0.11 as lambda ratios stay below 2\"); over the whole \
1–800 rpm map μ reaches down to {} and λ up to {}, at the lightest load and highest speed.",
            r4(mu_rig),
            r3(lambda_rig),
            r4(mu_all),
            r3(lambda_all),
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
angle record), (c) torque against time and (d) against angle. As in the paper's Figure 7, the \
torque is highest at the stroke ends where the speed is zero ({} at 70–80 % of the stroke) and \
lowest near zero degrees ({} at mid-stroke), where the speed peaks and the entrained grease \
lifts part of the load. The model's boundary friction has no static peak (breakaway factor 1); \
raise rig.breakaway_factor to add the paper's slightly higher torque at the start and stop points.",
            r3(s.tracking_error_deg),
            r3(peak),
            nm(s.outer_torque),
            nm(s.mid_torque),
        ),
    })
}

fn fig8_10(results: &[RigResult]) -> Vec<Entry> {
    let at = |f: f64| at_frequency(results, f);
    let (lo_slow, hi_slow) = range(at(0.03).iter().map(|r| r.run.average_friction_coefficient));
    let (qlo, qhi) = range(at(0.03).iter().map(|r| r.quasi_static_average));
    let (lo_fast, hi_fast) = range(at(1.0).iter().map(|r| r.run.average_friction_coefficient));
    let light = find(results, 1.0, 5e3).map_or(f64::NAN, |r| r.run.average_friction_coefficient);
    let heavy = find(results, 1.0, 60e3).map_or(f64::NAN, |r| r.run.average_friction_coefficient);
    let below = at(0.03).iter().map(|r| 1.0 - r.run.average_friction_coefficient / r.quasi_static_average).fold(0.0, f64::max);
    let speeds = |f: f64| range(at(f).iter().map(|r| r.run.mean_speed));
    let (s03, s1) = (speeds(0.03), speeds(1.0));
    let common = format!(
        "Each dot is one rig run (5, 10, 20, 40, 60 kN × 0.03, 0.3, 1 Hz, ±40°): the paper's eq. 11 \
average, mean |recorded torque| over the second stroke divided by R·P. Its x value is the stroke's \
characteristic speed, the time-mean of |ω| over that stroke (≈ 4·A·f: {}–{} rad/s at 0.03 Hz, \
{}–{} rad/s at 1 Hz); the paper labels its runs by 60·f rpm (1.8, 18, 60 rpm) instead. Lines are \
the core's steady μ(P, ω) at the same loads.",
        r4(s03.0),
        r4(s03.1),
        r3(s1.0),
        r3(s1.1)
    );
    let slow = format!(
        "At 0.03 Hz the rig averages are {}–{} over the loads (paper: measured {PAPER_LOW_SPEED_MU} \
at low speed against the assumed μ_c = 0.12). They sit up to {} below the core's own stroke average \
({}–{}) because the recorded torque passes through zero while the joint sticks at each reversal \
(the actuator must wind its angle error through 2·μ_c·R·P/K_p), which lowers the mean |torque| just \
as it would on the real rig. At 1 Hz the averages fall to {}–{}.",
        r4(lo_slow),
        r4(hi_slow),
        pct(below),
        r4(qlo),
        r4(qhi),
        r4(lo_fast),
        r4(hi_fast)
    );
    vec![
        Entry {
            title: "Figure 8 — friction coefficient against Sommerfeld number".into(),
            images: vec!["fig08_mu_sommerfeld.svg".into()],
            data: vec!["rig_averages.csv".into(), "core_curves.csv".into()],
            caption: format!(
                "{common} S (eq. 20) is the core's at the run's load and mean |ω|. {slow} As in the \
paper's Figure 8, the joint works in the boundary regime at every test condition: μ stays \
within a few per cent of μ_c."
            ),
        },
        Entry {
            title: "Figure 9 — friction coefficient against sliding speed".into(),
            images: vec!["fig09_mu_sliding_speed.svg".into()],
            data: vec!["rig_averages.csv".into(), "core_curves.csv".into()],
            caption: format!(
                "{common} Sliding speed u = R·mean|ω| (R = 28 mm). The model's load effect is \
mild: at the same speed a heavier load gives a thinner film and a higher μ. The paper finds the \
load effect in its experiments more pronounced than the theory (grease squeezed out at high load, \
starved inlet), which a fully flooded model cannot show."
            ),
        },
        Entry {
            title: "Figure 10 — friction coefficient against load".into(),
            images: vec!["fig10_mu_load.svg".into()],
            data: vec!["rig_averages.csv".into(), "core_curves.csv".into()],
            caption: format!(
                "Solid: the rig's eq. 11 averages at 0.03, 0.3 and 1 Hz against load; dashed: the \
core's μ(P, |θ̇_cmd|) averaged over the same sine stroke (a rig that follows its command and \
never sticks). μ rises with load at every frequency (at 1 Hz from {} at 5 kN to {} at 60 kN) and \
falls with frequency; the paper's higher loads agree closely with its model while its low-load \
measurements lie below it.",
                r4(light),
                r4(heavy)
            ),
        },
    ]
}

fn fig11_13(results: &[RigResult]) -> Vec<Entry> {
    let spread = range(at_frequency(results, 0.03).iter().map(|r| r.shape.spread)).1;
    let ring_slow = range(at_frequency(results, 0.03).iter().map(|r| r.shape.ringing)).1;
    let dip = |f: f64, p: f64| find(results, f, p).map(|r| (r.shape.outer_torque - r.shape.mid_torque, r.shape.dip()));
    let (d03, d03p) = dip(0.3, 20e3).unwrap_or((f64::NAN, f64::NAN));
    let (d1, d1p) = dip(1.0, 20e3).unwrap_or((f64::NAN, f64::NAN));
    let (d60, d60p) = dip(1.0, 60e3).unwrap_or((f64::NAN, f64::NAN));
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
observes (hydrodynamic lift negligible), and there is no servo oscillation.",
            pct(spread),
            nm(ring_slow)
        ),
        format!(
            "f = 0.3 Hz (18 rpm nominal). {panels} A shallow dip appears at mid-stroke: at 20 kN the \
|torque| there is {} ({}) below its value at 70–80 % of the stroke.",
            nm(d03),
            pct(d03p)
        ),
        format!(
            "f = 1 Hz (60 rpm nominal). {panels} The torque dips at mid-stroke where the speed peaks: \
by {} ({}) at 20 kN and {} ({}) at 60 kN, the amount the core predicts at that speed (paper: \"at \
the higher speeds there is a reduction in torque as the joint articulates at its maximum velocity\"). \
After each reversal the recorded torque rings (up to {} from the quasi-static torque at 20 kN, \
decaying to {} later in the stroke): the limited response of the hydraulic servo the paper blames \
for the oscillation in its 1 Hz record.",
            nm(d1),
            pct(d1p),
            nm(d60),
            pct(d60p),
            nm(ring),
            nm(settled)
        ),
    ];
    PAPER_FREQUENCIES
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
        .collect()
}

/// Every figure, in the paper's order.
pub fn entries(joint: &Joint, results: &[RigResult]) -> Result<Vec<Entry>> {
    let mut out = vec![fig3(joint)?, fig4(joint)?];
    out.extend(fig7(results));
    out.extend(fig8_10(results));
    out.extend(fig11_13(results));
    Ok(out)
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
            "Rig integration: Dopri5, rtol {}, atol {}, {} samples per stroke{}.",
            info.rtol,
            info.atol,
            info.samples_per_cycle,
            if info.quick { " (--quick: coarser core sweeps and samples, looser tolerances; for a look, not for the record)" } else { "" }
        ),
        "Only the simulated side of Figures 8–13 can be reproduced: the paper's measurements are not \
available as data. Every number in the captions below is computed from this run."
            .into(),
    ]
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// `index.html`: every figure with its caption and data files.
pub fn html(entries: &[Entry], info: &RunInfo) -> String {
    let mut out = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pinjoint: the paper's figures</title>\n\
<style>body{font-family:sans-serif;max-width:1050px;margin:2em auto;padding:0 1em;line-height:1.45}\
figure{margin:2.5em 0}img{max-width:100%;border:1px solid #ddd}figcaption{margin-top:.6em}\
.data{color:#555;font-size:.9em}</style>\n</head>\n<body>\n<h1>Pin joint friction: the paper's figures</h1>\n",
    );
    for p in intro(info) {
        out.push_str(&format!("<p>{}</p>\n", html_escape(&p)));
    }
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
pub fn markdown(entries: &[Entry], info: &RunInfo) -> String {
    let mut out = String::from("# Pin joint friction: the paper's figures\n\n");
    for p in intro(info) {
        out.push_str(&p);
        out.push_str("\n\n");
    }
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
