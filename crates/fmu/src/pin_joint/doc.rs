//! `documentation/index.html` of the PinJoint FMU, generated from the same variable
//! table as the modelDescription, with a table of values computed by the library.

use pinjoint::zero_velocity::band::DEFAULT_SPEED_BAND;
use pinjoint::zero_velocity::Presliding;
use crate::doc_table::{head, rows, Style};
use fmi_layer::core::variables::{Causality, ModelInfo};
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

/// The smallest inertia (kg·m²) for which an explicit host with step `h` (s) holds the joint
/// without sign-alternating decay at breakaway torque `ts` (N·m): (k/J)·h·t_d < 1 and
/// (k/J)·h·(h + t_d) < 2 with k = T_s/φ_s.
pub fn explicit_min_inertia(law: &Presliding, ts: f64, h: f64) -> f64 {
    let k = ts / law.angle;
    (k * h * law.damping_time).max(k * h * (h + law.damping_time) / 2.0)
}

/// The HTML page of `info` (the PinJoint model's description, [`super::INFO`]).
pub fn index_html(info: &ModelInfo) -> String {
    let v = &info.variables;
    let (guid, version, requirements) = (info.guid(), info.version, crate::requirements_html());
    let (platforms, extensions) = (crate::platforms_doc::PLATFORMS_HTML, crate::extensions_doc::EXTENSIONS_HTML);
    let validity = crate::validity::html(false);
    let [inputs, outputs, params] = [Causality::Input, Causality::Output, Causality::Parameter].map(|c| rows(v, c, Style::Plain));
    let header = head(Style::Plain);
    let j = Joint::new(&Params::default()).expect("defaults are valid");
    let law = Presliding::default();
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
<li><code>angle</code>: under Co-Simulation with the presliding model its increments deflect the presliding state (below);
the friction law itself does not depend on position.</li>
</ul>

<h2>Zero velocity: the joint at rest</h2>
<p>The sliding torque T = &mu;(P, |&omega;|)RP<sub>T</sub> has no direction at &omega; = 0. Parameter
<code>zero_velocity.model</code> chooses how the FMU treats the rest point.</p>
<h3>presliding (default)</h3>
<p>A single-state elasto-plastic friction law (Dupont, Hayward, Armstrong, Altpeter, &ldquo;Single state elastoplastic
friction models&rdquo;, IEEE Trans. Automatic Control 47(5), 2002). The state &tau; (<code>presliding_torque</code>, N&middot;m) is the
elastic presliding torque. Along a deflection increment d&Delta; with u = sign(d&Delta;)&middot;&tau;:
du/d&Delta; = k for u &le; &beta;T (purely elastic: no drift under any drive below &beta;T, and every unloading is elastic),
du/d&Delta; = k(T &minus; u)/(T &minus; &beta;T) above (the elasto-plastic transition to sliding), with k = T/&phi;<sub>s</sub>.
In steady sliding &tau; = &plusmn;T and the torque is the model's &minus;sign(&omega;)&mu;RP<sub>T</sub> bit for bit.
The torque is <code>torque</code> = &minus;clamp(clamp(&tau;, &minus;T, T) + c&middot;&zcirc;, &minus;T, T), c = t<sub>d</sub>k, &zcirc; = &omega;&middot;g
the elastic deflection rate: it never exceeds the sliding torque (the damping adds up to Coulomb's limit).
The breakaway torque follows the load at every step: a load change while the joint is held changes the bound, not the
held torque (no jerk); a drop below the held torque lets the joint slide, as it should.</p>
<ul>
<li>Parameters: <code>zero_velocity.presliding_angle</code> &phi;<sub>s</sub> (default {phi} rad = {phi_um:.0} &micro;m at the pin surface:
the elastic deflection at which the presliding torque would reach the sliding torque), <code>zero_velocity.elastic_limit</code>
&beta; (default {beta}), <code>zero_velocity.damping_time</code> t<sub>d</sub> (default {td} s), <code>zero_velocity.host_inertia</code>
J (kg&middot;m&sup2;, default 0 = not given: when given the damping is c = 2&zeta;&radic;(kJ), &zeta; = 0.7, capped under Co-Simulation
at the last step h by c &le; 0.9(J/h)&middot;min(1, 2 &minus; h&sup2;k/J), the explicit host's no-sign-alternation bound: heavy bodies settle
within seconds and a dither near the presliding resonance does not walk).</li>
<li>The host's conventions: the <code>angle</code> is taken modulo 2&pi; (the increment since the reference is the 2&pi;-equivalent
closest to angular_velocity&middot;h of the last step, so a host may wrap its angle into (&minus;&pi;, &pi;]); when no angle is set in
initialization mode, the first angle set afterwards is the reference (no deflection at t = 0); a restored FMU state keeps its
reference.</li>
<li>Co-Simulation: the state is driven by the <code>angle</code> input's increments once the host has set the angle after
initialization: the torque read after setting (angle, angular_velocity) is the one at that angle, the same before and after
fmi2DoStep (which commits it), and &part;torque/&part;angle = &minus;k in stick. A host that never sets the angle drives the
state by angular_velocity&middot;h over each step (the exact solution with the input held). The update is the law's exact
solution over the increment: unconditionally stable and bounded for any step and any angle increment. Feed angle and
angular velocity at each step start. The locals <code>presliding_reference_angle</code> (the angle at which the state
was committed) and <code>presliding_angle_driven</code> (whether the host has set the angle) are this bookkeeping, kept in
the FMU state, with <code>presliding_angle_pending</code> (no angle set yet: the next one is the reference),
<code>presliding_step</code> and <code>presliding_reference_speed</code> (the last step and &omega; there, against which the next
angle is read modulo 2&pi;).</li>
<li>Model Exchange: <code>presliding_torque</code> is the one continuous state (nominal 100 N&middot;m). In stick
(<code>presliding_mode</code> = 0) its derivative is k&omega;&middot;clamp(g, 0, 1): it moves only along &omega;, by at most the
elastic k|&omega;|, so no explicit step can make it oscillate; in slip (&plusmn;1) it is held and the torque is the sliding torque.
The mode changes at step events (fmi2CompletedIntegratorStep asks for event mode when the state reaches the bound along the
motion or a slip's &omega; stops or reverses; fmi2NewDiscreteStates switches it and sets the state). Explicit Euler at 1 ms
and RK4 at 10 ms hold, break away and reverse for J &ge; 20 kg&middot;m&sup2; up to 60 kN; BDF and CVode as before.</li>
<li>Envelope of an explicit host (symplectic Euler, torque held over the step h, body inertia J): in stick the loop is
a spring k = T<sub>s</sub>/&phi;<sub>s</sub> and damper c = t<sub>d</sub>k; it decays without sign-alternation when
(k/J)&middot;h&middot;t<sub>d</sub> &lt; 1 and (k/J)&middot;h&middot;(h + t<sub>d</sub>) &lt; 2, and is stable when
(k/J)&middot;h&middot;(h + 2t<sub>d</sub>) &lt; 4. With the defaults at 60 kN (T<sub>s</sub> = {tb60:.1} N&middot;m,
k = {k60:.3e} N&middot;m/rad) and h = 10 ms this holds for J &ge; {jmin60:.1} kg&middot;m&sup2;; at 20 kN for J &ge; {jmin20:.1} kg&middot;m&sup2;.
A linearly implicit host using the directional derivatives is stable at any step. The presliding ring
(frequency &radic;(k/J), damping ratio (t<sub>d</sub>/2)&radic;(k/J)) decays with time constant 2J/(t<sub>d</sub>k): for heavy bodies
(J in the thousands of kg&middot;m&sup2;) under a sudden drive it rings for tens of seconds: give <code>zero_velocity.host_inertia</code>.</li>
<li><b>Parallel (Jacobi) masters</b> (libcosim/OSP, Ecos) step every FMU and then exchange the values: the body integrates the torque of
the previous communication point, a one-step delay no damping can hold a stiff spring against. Set <code>zero_velocity.host_coupling = 1</code>
(parallel) with <code>zero_velocity.host_inertia = J</code>: the presliding stiffness is then capped at J/(27h&sup2;) (h the communication step),
where the delayed loop's roots are real and positive, and the joint holds, breaks away and comes to rest without chatter. 0 (sequential, the
default) is the law above, bit for bit.</li>
<li><b>Integer mirrors.</b> For masters without Enumeration support (libcosim, Ecos) each Enumeration has an Integer twin with the same value
and codes: <code>fidelity_code</code>, <code>zero_velocity.model_code</code> and the output <code>validity_code</code>.</li>
</ul>
<h3>band</h3>
<p>The stateless law of earlier versions, bit for bit: inside the band |&omega;| &lt; &omega;<sub>b</sub> (parameter
<code>zero_velocity.speed_band</code>, default {band} rad/s) the torque is the band-edge torque scaled linearly,
T(&omega;) = &minus;T(P<sub>T</sub>, &omega;<sub>b</sub>)&middot;&omega;/&omega;<sub>b</sub>; outside the band it is exactly the model's
&minus;sign(&omega;)&mu;RP<sub>T</sub>. Inside the band the friction is a viscous damper k = T(P<sub>T</sub>, &omega;<sub>b</sub>)/&omega;<sub>b</sub>;
an explicit host step h is free of chatter when &omega;<sub>b</sub> &gt; h&middot;&mu;<sub>c</sub>RP<sub>T</sub>/J. A drive torque below the breakaway
torque makes the joint creep at &omega; = T<sub>drive</sub>&omega;<sub>b</sub>/T instead of holding: choose the band only for hosts that
need a stateless map of &omega; (e.g. a torque lookup) and never hold the joint.</p>
<p>The other outputs are the model's values at the actual &omega; (at rest &mu; = &mu;<sub>c</sub>) whatever the zero-velocity model.
<code>power_loss</code> is the power dissipated: |torque&middot;&omega;| in sliding and for the band; under presliding the power
stored in the elastic deflection is not counted.</p>

<h2>Validity</h2>
<ul>
<li>The paper's operating range: loads 5&ndash;60 kN (mean pressure 7&ndash;23 MPa), speeds 1&ndash;800 rpm in its simulations, Sommerfeld numbers 0&ndash;0.15,
oscillation &plusmn;40&deg; at 0.03&ndash;1 Hz in its tests. The model is defined beyond it, but not validated: the <code>validity</code>
output says where (section "Validity envelope").</li>
<li>Hertz theory is applied to a conformal contact (a is not small against R); eq. 11 neglects the tangential pressure
components (under 10 %); the contact is assumed fully flooded (unless the starved-inlet extension is switched on) and isothermal
at the <code>temperature</code> input.</li>
<li>Not modelled: a static friction peak above the sliding torque at reversals (the presliding law breaks away at the sliding
torque), the grease's lower friction at low load seen in the experiments.</li>
<li>Inputs: <code>angle</code> and <code>angular_velocity</code> must be finite; <code>load</code> finite and &ge; 0 N (0 = unloaded: every output
but the energy is 0). Other values are rejected by fmi2SetReal with a message naming the variable, value and unit.
Parameters are checked at fmi2ExitInitializationMode against the ranges below; an invalid one is named in the error message.
A step whose outputs would not be finite, or would leave their declared min/max (a negative film_thickness: with the
default parameters at rest above 5.05e8 N, where the asperity model's mean planes would interpenetrate), fails with
fmi2Error naming the output, instead of returning NaN or an impossible value. tests/fmu_harness/README.md tabulates the
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
<p>With <code>zero_velocity.model = presliding</code> (default) the FMU has <b>one continuous state</b>, <code>presliding_torque</code>,
no event indicators and <b>step events</b> (its stick and slip modes, above); with <code>band</code> the state is not used (its derivative is 0) and the torque is a stateless map
of the inputs. The host's own solver owns &omega; (e.g. <code>J d&omega;/dt = T_drive + torque</code>) and the presliding state;
an implicit solver (BDF) takes the presliding stiffness k = T/&phi;<sub>s</sub> in its stride. Directional derivatives of the
torque and of the state derivative with respect to the state and the inputs are provided for its Jacobian.</p>
<ul>
<li>Band: inside |&omega;| &lt; &omega;<sub>b</sub> the torque is the continuous, odd, Lipschitz ramp (slope
T(P, &omega;<sub>b</sub>)/&omega;<sub>b</sub>, e.g. {tb20:.1} N&middot;m / {band} rad/s at 20 kN); with <code>zero_velocity.speed_band = 0</code>
the torque jumps by 2&mu;<sub>c</sub>RP at &omega; = 0 and variable-step solvers shrink their step at every reversal.</li>
<li><code>dissipated_energy</code> is a Co-Simulation quantity (the sum of power_loss times the step over the steps taken).
Model Exchange takes no steps, so it is not computed there and <b>stays 0</b>; integrate <code>power_loss</code> in the host.</li>
<li>Call <code>fmi2CompletedIntegratorStep</code> after every integrator step and enter event mode when it asks: the event
iteration (one <code>fmi2NewDiscreteStates</code>) switches the presliding mode and may set the state
(<code>valuesOfContinuousStatesChanged</code>); no time events. A host that ignores the step events stays in stick: bounded and
exact in steady sliding, but a reversal after the sliding torque fell unloads from the excess. Parameters can only be set
before exit of initialization.</li>
</ul>

<h2>Directional derivatives</h2>
<p><code>fmi2GetDirectionalDerivative</code> / <code>fmi3GetDirectionalDerivative</code> give the partial derivatives of every output
(and of <code>der(presliding_torque)</code>) with respect to the inputs (and, under Model Exchange, the state), at the current values.
The friction outputs are differentiated exactly through the zero-velocity law; the sliding torque's own partials in &omega; and P
and every other output's come from central differences of the friction model at the instance's fidelity (relative steps 1e-6);
temperature partials from central differences (&plusmn;0.01 K) of the full model. At a kink (the elastic limit, the sliding bound,
&omega; = 0, the band's edge, the envelope of a table level) the derivative is that of the branch the current values are on.
Under Co-Simulation &part;torque/&part;angle is &minus;k in stick and 0 in sliding, so a linearly implicit master can take the
presliding spring implicitly at large steps.</p>

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
        phi = law.angle,
        phi_um = law.angle * j.params().geometry.pin_radius * 1e6,
        beta = law.elastic_limit,
        td = law.damping_time,
        k60 = j.boundary_torque(60e3) / law.angle,
        jmin60 = explicit_min_inertia(&law, j.boundary_torque(60e3), 0.01),
        jmin20 = explicit_min_inertia(&law, j.boundary_torque(20e3), 0.01),
    )
}
