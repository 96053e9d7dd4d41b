//! `documentation/index.html` of the PinJoint FMU, generated from the same variable
//! table as the modelDescription, with a table of values computed by the library.

use super::zero_speed::DEFAULT_SPEED_BAND;
use super::INFO;
use crate::doc_table::{head, rows, Style};
use fmi_layer::fmi2::variables::Causality;
use pinjoint::{Joint, Params};
use std::fmt::Write;

fn check_values() -> String {
    let j = Joint::new(&Params::default()).expect("defaults are valid");
    let mut s = String::new();
    for &load in &[5e3, 20e3, 60e3] {
        for &w in &[0.0, 0.21, 6.0, 83.8] {
            let op = j.evaluate(load, w).expect("valid point");
            writeln!(
                s,
                "<tr><td>{}</td><td>{w}</td><td>{:.4}</td><td>{:.2}</td><td>{:.3}</td><td>{:.3}</td><td>{:.3e}</td><td>{:.2}</td></tr>",
                load / 1e3,
                op.friction_coefficient,
                op.torque,
                op.film_thickness * 1e6,
                op.lambda_ratio,
                op.fluid_load_fraction,
                op.mean_pressure / 1e6
            )
            .unwrap();
        }
    }
    s
}

/// The HTML page.
pub fn index_html() -> String {
    let v = &INFO.variables;
    let (guid, version, requirements) = (INFO.guid(), INFO.version, crate::requirements_html());
    let (platforms, extensions) = (crate::platforms_doc::PLATFORMS_HTML, crate::extensions_doc::EXTENSIONS_HTML);
    let validity = crate::validity::html(false);
    let [inputs, outputs, params] = [Causality::Input, Causality::Output, Causality::Parameter].map(|c| rows(v, c, Style::Plain));
    let header = head(Style::Plain);
    let j = Joint::new(&Params::default()).expect("defaults are valid");
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>PinJoint FMU</title>
<style>body{{font-family:sans-serif;max-width:70em;margin:auto}} table{{border-collapse:collapse}} td,th{{border:1px solid #aaa;padding:2px 6px;font-size:90%}}</style>
</head><body>
<h1>PinJoint &mdash; friction torque of a landing-gear pin joint (FMI 2.0 and 3.0, Co-Simulation and Model Exchange)</h1>
<p>GUID <code>{guid}</code>, version {version}.</p>

<h2>What it computes</h2>
<p>At every communication point the FMU evaluates the mixed-lubrication model of the paper
&ldquo;Model and Experiments to Determine Lubricant Film Formation and Frictional Torque in Aircraft
Landing Gear Pin Joints&rdquo; at the held inputs <code>angular_velocity</code> &omega; and <code>load</code> P<sub>T</sub>:</p>
<ul>
<li>Hertz line contact (eq. 6): a = &radic;(8 P<sub>T</sub> R&prime; / (&pi; E&prime; B)), p<sub>m</sub> = P<sub>T</sub>/(2aB),
with 1/R&prime; = 1/R &minus; 1/R<sub>b</sub> (R&prime; = {r_red:.3} m for Table 1: a conformal contact) and
1/E&prime; = &frac12;[(1&minus;&nu;&sup2;)/E + (1&minus;&nu;<sub>b</sub>&sup2;)/E<sub>b</sub>] (E&prime; = {e_eff:.1} GPa; the printed minus sign is an erratum).
Mean pressure 6.61 MPa at 5 kN and 22.89 MPa at 60 kN.</li>
<li>Load sharing (eq. 1, 9): P<sub>T</sub> = P<sub>H</sub> + P<sub>C</sub>, 1/&gamma;<sub>1</sub> + 1/&gamma;<sub>2</sub> = 1, solved with the Moes
central film thickness scaled by &gamma;<sub>1</sub> (eqs. 12&ndash;14, exponents &minus;14/15 and &minus;2/5 from the stated substitution)
and the Greenwood&ndash;Williamson asperity pressure scaled by &gamma;<sub>2</sub> (eqs. 15&ndash;19), sliding speed u = |&omega;|R.</li>
<li>Friction (eqs. 2&ndash;5, 8, 10): Q<sub>H</sub> = &tau;<sub>L</sub>(1 &minus; e<sup>&minus;&eta;u/(&tau;<sub>L</sub>h<sub>c</sub>)</sup>) 2aB with Roelands
&eta;(p<sub>m</sub>) and &tau;<sub>L</sub> = &tau;<sub>L0</sub> + &beta;<sub>0</sub>p<sub>m</sub>; Q<sub>C</sub> = &mu;<sub>c</sub>P<sub>T</sub>/&gamma;<sub>2</sub>;
&mu; = (Q<sub>H</sub> + Q<sub>C</sub>)/P<sub>T</sub>.</li>
<li>Torque (eq. 11): T = &mu; R P<sub>T</sub>, acting against the motion: <code>torque</code> = &minus;sign(&omega;)&middot;T.
At low speed &mu; &rarr; &mu;<sub>c</sub> = 0.12: {tb20:.1} N&middot;m at 20 kN and {tb60:.1} N&middot;m at 60 kN.</li>
<li>Sommerfeld number (eq. 20) with P<sub>L</sub> = P<sub>T</sub>/(2RB) and c = R<sub>b</sub> &minus; R; &lambda; (eq. 21) from the central film h<sub>c</sub>.</li>
<li><code>power_loss</code> = |torque&middot;&omega;|; <code>dissipated_energy</code> = &Sigma; power_loss&middot;h over the steps taken
(the inputs are held over each step, as FMI Co-Simulation defines them, so this is the exact integral of the power the FMU reports).</li>
<li><code>angle</code> is accepted and kept in the FMU state but no output depends on it: the friction law does not depend on position.</li>
</ul>

<h2>Zero velocity</h2>
<p>The torque has no direction at &omega; = 0. Inside the band |&omega;| &lt; &omega;<sub>b</sub> (parameter
<code>zero_velocity.speed_band</code>, default {band} rad/s) the torque is the band-edge torque scaled linearly,
T(&omega;) = &minus;T(P<sub>T</sub>, &omega;<sub>b</sub>)&middot;&omega;/&omega;<sub>b</sub>; outside the band it is exactly the model's
&minus;sign(&omega;)&mu;RP<sub>T</sub>. The other outputs are the model's values at the actual &omega; (at rest &mu; = &mu;<sub>c</sub>).
Inside the band the friction is a viscous damper k = T(P<sub>T</sub>, &omega;<sub>b</sub>)/&omega;<sub>b</sub>; a host integrating
J&middot;d&omega;/dt = T<sub>drive</sub> + torque with an explicit step h is free of chatter when h&middot;k/J &lt; 1, i.e.
&omega;<sub>b</sub> &gt; h&middot;&mu;<sub>c</sub>RP<sub>T</sub>/J. The default satisfies this at h = 1 ms and 60 kN for J &ge; 20.2 kg&middot;m&sup2;;
raise it for lighter inertias or longer steps, or set it to 0 to switch the ramp off. A drive torque below the breakaway
torque then makes the joint creep slowly instead of sticking.</p>

<h2>Validity</h2>
<ul>
<li>The paper's operating range: loads 5&ndash;60 kN (mean pressure 7&ndash;23 MPa), speeds 1&ndash;800 rpm in its simulations, Sommerfeld numbers 0&ndash;0.15,
oscillation &plusmn;40&deg; at 0.03&ndash;1 Hz in its tests. The model is defined beyond it, but not validated: the <code>validity</code>
output says where (section "Validity envelope").</li>
<li>Hertz theory is applied to a conformal contact (a is not small against R); eq. 11 neglects the tangential pressure
components (under 10 %); the contact is assumed fully flooded (unless the starved-inlet extension is switched on) and isothermal
at the <code>temperature</code> input.</li>
<li>Not modelled: the static friction peak at reversals, the grease's lower friction at low load seen in the experiments.</li>
<li>Inputs: <code>angle</code> and <code>angular_velocity</code> must be finite; <code>load</code> finite and &ge; 0 N (0 = unloaded: every output
but the energy is 0). Other values are rejected by fmi2SetReal with a message naming the variable, value and unit.
Parameters are checked at fmi2ExitInitializationMode against the ranges below; an invalid one is named in the error message.
A step whose outputs would not be finite, or would leave their declared min/max (a negative film_thickness: with the
default parameters at rest above 5.05e8 N, where the asperity model's mean planes would interpenetrate), fails with
fmi2Error naming the output, instead of returning NaN or an impossible value. tests/python/README.md tabulates the
defined behaviour of every bad input.</li>
</ul>

{validity}
{extensions}
<h2>Model values (default parameters)</h2>
<table><tr><th>load (kN)</th><th>&omega; (rad/s)</th><th>&mu;</th><th>T (N&middot;m)</th><th>h<sub>c</sub> (&micro;m)</th><th>&lambda;</th><th>1/&gamma;<sub>1</sub></th><th>p<sub>m</sub> (MPa)</th></tr>
{checks}</table>

<h2>Inputs</h2><table>{header}{inputs}</table>
<h2>Outputs</h2><table>{header}{outputs}</table>
<h2>Parameters</h2><p>Named <code>section.key</code> as in the parameter file; defaults from Tables 1&ndash;3 of the paper.
All have variability <em>fixed</em>: set them before fmi2ExitInitializationMode.</p><table>{header}{params}</table>

<h2>Model Exchange</h2>
<p>The friction law is a stateless map of the inputs, so as Model Exchange the FMU has <b>no continuous states</b> (nx = 0) and
<b>no event indicators</b> (nz = 0). The host's own solver owns &omega; (e.g. <code>J d&omega;/dt = T_drive + torque</code>) and
sees the torque as a function of the current &omega; and P at every evaluation (every <code>fmi2GetReal</code>/<code>fmi3GetFloat64</code>
after setting inputs or time), instead of a value held over a communication step; the Co-Simulation stability limit
&omega;<sub>b</sub> &gt; h&middot;&mu;<sub>c</sub>RP/J no longer ties the band to a step size.</p>
<ul>
<li>Zero-speed band: inside |&omega;| &lt; &omega;<sub>b</sub> the torque is the continuous, odd, Lipschitz ramp
&minus;T(P, &omega;<sub>b</sub>)&middot;&omega;/&omega;<sub>b</sub> (slope k = T(P, &omega;<sub>b</sub>)/&omega;<sub>b</sub>, e.g.
{tb20:.1} N&middot;m / {band} rad/s at 20 kN); outside it the library's torque, smooth in &omega;. The torque is continuous
everywhere (a kink, not a jump, at &plusmn;&omega;<sub>b</sub>), so a variable-step solver needs no event: that is why there are no
event indicators. The ramp makes the host's equation stiff near rest (time constant J/k): an implicit solver (CVode BDF) takes it
in its stride; an explicit fixed step h is stable for h &lt; 2J/k and does not oscillate for h &lt; J/k.</li>
<li>With <code>zero_velocity.speed_band = 0</code> the torque jumps by 2&mu;<sub>c</sub>RP at &omega; = 0 and the FMU still
declares no event indicator (&omega; is the host's variable: a host that wants the reversal located must detect the sign change of
its own state); variable-step solvers then shrink their step at every reversal. Keep &omega;<sub>b</sub> &gt; 0 for Model Exchange.</li>
<li><code>dissipated_energy</code> is a Co-Simulation quantity (the sum of power_loss times the step over the steps taken).
Model Exchange takes no steps, so it is not computed there and <b>stays 0</b>; integrate <code>power_loss</code> in the host
(one extra state) for the energy.</li>
<li>Event mode has nothing to iterate (no discrete states, no time events); <code>fmi2CompletedIntegratorStep</code> is not needed
(<code>completedIntegratorStepNotNeeded</code>; FMI 3.0 <code>needsCompletedIntegratorStep = false</code>) but, if called,
checks the outputs at the current inputs. Parameters can only be set before exit of initialization (variability fixed).</li>
</ul>

{requirements}

<h2>FMI notes</h2>
<ul>
<li>Co-Simulation and Model Exchange (above). Variable step size, get/set and serialized FMU state are supported
(a small versioned byte format with magic, version, length and CRC-32; truncated, corrupted or foreign states are rejected).</li>
<li>Log categories: logEvents, logStatusWarning, logStatusDiscard, logStatusError, logStatusFatal, logAll. Errors are reported even with
debug logging off.</li>
<li>fmi2DoStep requires a positive, finite step that continues the previous one.</li>
</ul>

{platforms}</body></html>
"#,
        r_red = j.reduced_radius(),
        e_eff = j.effective_modulus() / 1e9,
        tb20 = j.boundary_torque(20e3),
        tb60 = j.boundary_torque(60e3),
        band = DEFAULT_SPEED_BAND,
        checks = check_values(),
    )
}
