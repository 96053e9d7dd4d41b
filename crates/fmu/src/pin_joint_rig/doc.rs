//! `documentation/index.html` of the PinJointRig FMU, generated from the same
//! variable table as the modelDescription, with numbers computed by the library.

use crate::doc_table::{head, rows, Style};
use fmi_layer::core::variables::{Causality, ModelInfo};
use pinjoint::rig::RigParams;
use pinjoint::{Joint, Params};

/// The defaults' reasoning, as written in [`pinjoint::rig::params`] (one item per constant).
const REASONING: &str = r#"<ul>
<li><code>rig.inertia</code> J = 0.05 kg&middot;m&sup2;: the hollow 300M pin (OD 56, ID 42, 200.5 mm, section 4.2) is 1.0e-3 kg&middot;m&sup2;;
the rotor of a 200 N&middot;m rotary vane actuator, its drive shaft, the torque transducer and the spline coupling are taken as
&asymp; 0.05 kg&middot;m&sup2; (an estimate: the paper gives no actuator data).</li>
<li><code>rig.position_gain</code> K<sub>p</sub> = 6000 N&middot;m/rad (105 N&middot;m per degree): the loop must supply the friction torque
&mu;RP (&le; 67 N&middot;m at 20 kN, 202 N&middot;m at 60 kN) from the angle error, so the stroke lags the command by about T/K<sub>p</sub>:
0.64&deg; at 20 kN and 1.9&deg; at 60 kN, 1 Hz (&ldquo;a few degrees&rdquo;).</li>
<li><code>rig.servo_time_constant</code> &tau;<sub>s</sub> = 3 ms: the servo-valve and oil-column response of the torque loop (&asymp; 50 Hz
bandwidth), the limited response the paper blames for the oscillation at 1 Hz (section 5).</li>
<li><code>rig.velocity_gain</code> K<sub>d</sub> = 40 N&middot;m&middot;s/rad = 2.2&middot;&tau;<sub>s</sub>K<sub>p</sub>. The closed loop (no friction) then
has a real pole at 27 Hz and a lightly damped pair at 78 Hz, &zeta; = 0.17. Each reversal (a step of 2&mu;RP in the friction torque)
rings that pair: at 1 Hz the recorded torque oscillates by about &plusmn;10 N&middot;m for &asymp; 60 ms after each reversal at 20 kN
(Figure 13b); at 0.03 Hz the reversal is quasi-static and the torque is clean (Figure 11b). With K<sub>d</sub> = 30 (&zeta; = 0.13) the
ringing at 60 kN, 1 Hz turns into sustained stick&ndash;slip; 40 keeps a margin against the falling (Stribeck) friction, whose slope
RP&middot;d&mu;/d&omega; &asymp; &minus;6 N&middot;m&middot;s/rad at 60 kN acts as negative damping.</li>
<li><code>rig.torque_limit</code> T<sub>max</sub> = 400 N&middot;m: twice the 200 N&middot;m rating, so saturation is available but does not act in the
paper's tests (a 60 kN stroke needs 202 N&middot;m); set 200 to model the rating strictly.</li>
<li><code>rig.breakaway_factor</code> = 1: static = kinetic boundary friction, the paper's model. Raise it (e.g. 1.1) to reproduce the slightly
higher torque the experiments show at stroke ends.</li>
<li><code>rig.regularisation_speed</code> &omega;<sub>reg</sub> = 1e-3 rad/s (regularised formulation only): tanh(&omega;/&omega;<sub>reg</sub>) &gt; 0.99
above 2.6e-3 rad/s, 2 % of the 0.03 Hz peak speed. The creep band is stiff (time constant J&omega;<sub>reg</sub>/(&mu;<sub>c</sub>RP) = 0.75 &micro;s
at 20 kN): explicit integrators take steps of that size while the joint &ldquo;sticks&rdquo;, the price the hybrid formulation avoids.</li>
<li>Integration: Dopri5, <code>rig.rtol</code> = 1e-8, <code>rig.atol</code> = 1e-9 (the state mixes rad, rad/s, N&middot;m and J, all O(0.1&ndash;1e3)),
RK4 step 1e-4 s, events located to 1e-10 s, internal segments of 0.05 s.</li>
</ul>"#;

/// The HTML page of `info` (the PinJointRig model's description, [`super::INFO`]).
pub fn index_html(info: &ModelInfo) -> String {
    let j = Joint::new(&Params::default()).expect("defaults are valid");
    let r = RigParams::default();
    let v = &info.variables;
    let (guid, version, requirements) = (info.guid(), info.version, crate::requirements_html());
    let (platforms, extensions) = (crate::platforms_doc::PLATFORMS_HTML, crate::extensions_doc::EXTENSIONS_HTML);
    let validity = crate::validity::html(true);
    let [inputs, outputs, params] = [Causality::Input, Causality::Output, Causality::Parameter].map(|c| rows(v, c, Style::Typed));
    let header = head(Style::Typed);
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>PinJointRig FMU</title>
<style>body{{font-family:sans-serif;max-width:70em;margin:auto}} table{{border-collapse:collapse}} td,th{{border:1px solid #aaa;padding:2px 6px;font-size:90%}} pre{{background:#f4f4f4;padding:6px}}</style>
</head><body>
<h1>PinJointRig &mdash; the pin joint on its torsion-actuator rig (FMI 2.0 and 3.0 Co-Simulation)</h1>
<p>GUID <code>{guid}</code>, version {version}. Served by the same binary as the PinJoint FMU.</p>

<h2>What it computes</h2>
<p>The paper validates its friction model on a rig (section 4): a servo-hydraulic torsional actuator in angle control, driven by a
function generator, swings the pin through &plusmn;40&deg; sine strokes at 0.03, 0.3 and 1 Hz under 5&ndash;60 kN, and a torque
transducer records the torque (Figures 7, 11&ndash;13). This FMU integrates that rig: the actuator dynamics below, and the friction
torque of the joint from the mixed-lubrication core (the PinJoint FMU's model) at the current load and speed.</p>
<pre>
theta_cmd(t) = A sin(2 pi f (t - t_start))            command (parameters amplitude, frequency), or the command_angle input
T_d   = clamp(K_p (theta_cmd - theta) + K_d (dtheta_cmd/dt - omega), +-T_max)   position loop with a derivative term
tau_s dT_a/dt = T_d - T_a                             first-order torque lag (servo-valve and oil column)
J domega/dt   = T_a + T_f,   dtheta/dt = omega        rotating inertia; T_f the friction torque on the pin
W = integral T_a omega dt,   D = integral -T_f omega dt,   W - D = J omega^2/2 - J omega_0^2/2
</pre>
<p>Without friction the loop's characteristic polynomial is &tau;<sub>s</sub>J s&sup3; + J s&sup2; + K<sub>d</sub> s + K<sub>p</sub>; Routh&ndash;Hurwitz
gives stability iff K<sub>d</sub> &gt; &tau;<sub>s</sub>K<sub>p</sub>, which is checked at fmi2ExitInitializationMode.</p>

<h2>Stick and breakaway at reversal</h2>
<p>Hybrid formulation (<code>rig.formulation</code> = 0, default): while slipping in direction s = &plusmn;1,
T<sub>f</sub> = &minus;s&middot;&mu;(P, |&omega;|)&middot;R&middot;P with the core's &mu; (eqs. 1&ndash;21). When the speed reaches zero (an event located to
<code>rig.event_tolerance</code>), the joint sticks if |T<sub>a</sub>| &le; k<sub>b</sub>&mu;<sub>c</sub>RP (the breakaway torque,
k<sub>b</sub> = <code>rig.breakaway_factor</code>; {tb20:.1} N&middot;m at 20 kN, {tb60:.1} N&middot;m at 60 kN for the defaults) and reverses at
once otherwise. While stuck, &omega; = 0, only the actuator lag evolves and the joint reacts T<sub>f</sub> = &minus;T<sub>a</sub>; it breaks
away when |T<sub>a</sub>| exceeds the breakaway torque. Slip phases are integrated with <code>ode_solvers</code> (Dopri5 or Dop853 with
<code>rig.rtol</code>/<code>rig.atol</code>, or RK4 with <code>rig.rk4_step</code>; <code>rig.method</code> = 3 integrates with Dopri5 the deviation from the
loop's steady response to the sine command and reads the states between steps from its continuous extension). Regularised formulation (<code>rig.formulation</code> = 1):
one smooth ODE with T<sub>f</sub> = &minus;&mu;(P,|&omega;|)RP&middot;tanh(&omega;/&omega;<sub>reg</sub>); <code>stuck</code> is then |&omega;| &le; &omega;<sub>reg</sub>.</p>

<h2>Communication steps</h2>
<ul>
<li>The FMU integrates internally across communication steps. Its own integration nodes are the start, events, multiples of
<code>rig.segment_length</code> (rig time) and the times at which an input changes; the state at a communication point is one
re-integration step from the last node before it. So, with the same inputs, a host stepping at 1e-5 s and one stepping at 1 s
get the same numbers at their shared points (the test suite compares 1 ms and 100 ms hosts through fmpy).</li>
<li>Inputs are held over each step (zero-order hold, as FMI Co-Simulation defines them). A held <code>command_angle</code> has rate 0,
so the derivative term acts on &minus;&omega; only. Setting an input to a <em>different</em> value restarts the integration at the
current time; setting the same value changes nothing. (A host that interpolates a constant signal may pass values
that differ in the last bit, e.g. 19999.999999999996 N: each is a new value and restarts the integration, which
changes the results at the level of the integration tolerance.)</li>
<li>The rig's clock is t &minus; t<sub>start</sub>: the stroke starts at rest on the command at the start time.</li>
<li>Direct feedthrough: <code>friction_torque</code>, <code>friction_coefficient</code>, <code>film_thickness</code>,
<code>fluid_load_fraction</code>, <code>min_film_thickness</code>, <code>min_lambda_ratio</code> and <code>stuck</code> follow a new
<code>load</code> (or <code>temperature</code>) at once; <code>commanded_angle</code> follows
<code>command_angle</code>. The angle, speed, recorded torque and energies are states.</li>
</ul>

<h2>Defaults and why</h2>
<p>The paper gives no actuator data (section 4: a servo-hydraulic torsional actuator rated 200 N&middot;m, in angle control, with an
internal strain-gauge torque transducer). The defaults are chosen so that at 1 Hz the angle tracks the command within a few degrees
and the recorded torque shows the limited-response oscillation the paper describes:</p>
{reasoning}
<p>Stroke: amplitude {amp_deg}&deg; ({amp} rad), frequency {freq} Hz; load input start {load} N. Stroke lag at 20 kN about
&mu;<sub>c</sub>RP/K<sub>p</sub> = {lag:.2}&deg;.</p>

<h2>Zero load, invalid values, errors</h2>
<ul>
<li><code>load</code> = 0: no contact and no friction; the joint moves freely with the actuator. The core's quantities are not
defined there: <code>friction_coefficient</code>, <code>film_thickness</code>, <code>fluid_load_fraction</code>, <code>min_film_thickness</code>
and <code>min_lambda_ratio</code> are reported as 0.</li>
<li>fmi2SetReal rejects a negative or non-finite <code>load</code> and a non-finite <code>command_angle</code> (the message names the
variable, value and unit). Parameters are checked at fmi2ExitInitializationMode (ranges below, K<sub>d</sub> &gt; &tau;<sub>s</sub>K<sub>p</sub>,
R<sub>b</sub> &gt; R); the error message names the parameter, its value and unit.</li>
<li>A step that cannot be computed (integration failure, stick/slip chattering) returns fmi2Error and names the time.</li>
</ul>

<h2>Fidelity</h2>
<ul>
<li><code>fidelity</code> (Enumeration: full, table, boundary, auto) chooses how the friction law is evaluated inside the rig, as in the PinJoint FMU: 0 = full (the
complete solve, warm-started; the default, and the rig exactly as without this parameter), 1 = table (the Stribeck map tabulated
over the envelope at fmi2ExitInitializationMode and interpolated, refined until its error checked against full is below
<code>tolerance</code>), 2 = boundary (&mu; = &mu;<sub>c</sub>), 3 = auto (the cheapest of boundary, table, full whose measured bound
is within <code>tolerance</code>).</li>
<li>The envelope (<code>envelope.load_min</code>..<code>envelope.load_max</code> in N, <code>envelope.speed_min</code>..<code>envelope.speed_max</code>
in rad/s, speed magnitudes) defaults to 1&ndash;100 kN and 1e-3&ndash;10 rad/s: every load and stroke of the defaults and well beyond
(the default stroke peaks at 2&pi;fA = 4.4 rad/s). Outside it, and at speeds below <code>envelope.speed_min</code> that the joint
passes through at every reversal, the full solve answers. A smaller envelope builds a smaller table faster.</li>
<li>The log (category logEvents) says once which level was built (what auto picked) with its measured error bound, and once when a
friction evaluation first fell outside the envelope.</li>
<li>Bad values (a code other than 0&ndash;3, a tolerance not &gt; 0 or, for table and auto, below the full solve's own 1e-10, an envelope
bound not &gt; 0 or a minimum not below its maximum) are refused at fmi2ExitInitializationMode with the parameter's name, value and
unit; a code out of range already by fmi2SetInteger.</li>
<li>The settings are part of the FMU state; a restored state rebuilds the same table (deterministically) and continues bit for bit.</li>
</ul>

{validity}
{extensions}
<h2>Inputs</h2><table>{header}{inputs}</table>
<h2>Outputs</h2><table>{header}{outputs}</table>
<h2>Parameters</h2>
<p>The <code>[rig]</code> section of the parameter file maps to <code>frequency</code>, <code>amplitude</code> (stroke), the <code>load</code>
input, and <code>rig.&lt;key&gt;</code> for every other key (<code>formulation</code> and <code>method</code> as Integer codes); the model's
sections are <code>section.key</code> as in the PinJoint FMU (Tables 1&ndash;3 of the paper). All have variability <em>fixed</em>.</p>
<table>{header}{params}</table>

<h2>FMI notes</h2>
<ul>
<li>Co-Simulation only; variable communication step size; get/set and serialized FMU state (the generic container with
magic, version, length and CRC-32, holding this model's versioned part: every setting, the start time and the simulator's
112-byte state). A restored state continues bit for bit.</li>
<li><code>stuck</code> is a Boolean output (variability discrete), <code>use_command_input</code> a Boolean parameter,
<code>rig.formulation</code>, <code>rig.method</code> and <code>fidelity</code> Enumeration parameters (named choices; the codes of the
former Integer parameters, set through fmi2SetInteger / fmi3SetInt64); everything else is Real (FMI 3.0: Float64).
For masters without Enumeration support (libcosim, Ecos) each Enumeration has an Integer mirror, the same value under another name
(<code>rig.formulation_code</code>, <code>rig.method_code</code>, <code>fidelity_code</code>, the output <code>validity_code</code>):
setting one sets the other, with the same codes.</li>
</ul>
{requirements}

{platforms}</body></html>
"#,
        tb20 = r.breakaway_factor * j.boundary_torque(20e3),
        tb60 = r.breakaway_factor * j.boundary_torque(60e3),
        reasoning = REASONING,
        amp_deg = r.amplitude.to_degrees(),
        amp = r.amplitude,
        freq = r.frequency,
        load = r.load,
        lag = (j.boundary_torque(20e3) / r.position_gain).to_degrees(),
    )
}

#[cfg(test)]
mod tests {
    use fmi_layer::core::variables::Causality;

    #[test]
    fn every_variable_and_output_is_documented() {
        let info = &*crate::pin_joint_rig::INFO;
        let html = super::index_html(info);
        for v in &info.variables {
            assert!(html.contains(&format!("<code>{}</code>", v.name)), "{}", v.name);
        }
        assert_eq!(info.variables.iter().filter(|v| v.causality == Causality::Output).count(), 16);
        assert!(html.contains("Pan &amp; Hamrock") && html.contains("Roelands' temperature relation") && html.contains("Chevalier"));
        // μ_c R P = 67.2 N·m plus the grease's yield torque (0.03 N·m at 20 °C): the library's rest torque.
        let rest = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap().boundary_torque(20e3);
        assert!((rest - 67.2).abs() < 0.05, "{rest}");
        assert!(html.contains("Routh") && html.contains(&format!("{rest:.1} N&middot;m at 20 kN")), "breakaway torque from the library");
    }
}
