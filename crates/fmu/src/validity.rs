//! The `validity` output both FMUs share and its log: whether the inputs are inside the
//! conditions the model was checked against ([`pinjoint::validity`], one definition for every
//! front end), and one log message per excursion ([`pinjoint::validity::Tracker`]).

use crate::declare::declare;
use crate::table::Row;
use fmi_layer::core::variables::{Causality, EnumType, Kind};
use pinjoint::validity::{Excursion, Tracker, Validity};

/// The `validity` output's choices: the codes of [`Validity::code`].
pub static VALIDITY_TYPE: EnumType = EnumType {
    name: "Validity",
    description: "Whether the answer is inside the conditions the model was checked against (the paper's rig tests)",
    items: &[
        ("checked", 0, "Load 5-60 kN, sliding speed up to the 1 Hz +-40 deg stroke's peak, 15-25 C (and for the rig 0.03-1 Hz, 40 deg): checked against the paper's measurements"),
        ("extrapolation", 1, "Some input outside the checked ranges: the model's equations, unconfirmed there"),
        ("known_wrong", 2, "Below 0 C (cold soak): base-oil film only, no grease yield stress: friction coefficient and torque too LOW"),
        ("outside", 3, "Beyond the model's assumptions: load above the one at which the Hertz half-width of eq. 6 reaches the pin radius (96.7 kN with the default parameters), or temperature above grease.upper_service_temperature (121 C by default); answered, not a model of the joint there"),
    ],
};

/// The `validity` output (Enumeration) at value reference `vr`, depending directly on the
/// inputs `depends`, read by `get` (the code as f64).
pub fn output<S: 'static>(vr: u32, depends: &[&'static str], description: &str, get: impl Fn(&S) -> f64 + Send + Sync + 'static) -> Row<S> {
    let mut v = declare("validity", vr, Kind::Enumeration(&VALIDITY_TYPE), Causality::Output, None, None, description);
    v.depends_on = depends.to_vec();
    Row::output(v, get)
}

/// The log message for an excursion that starts now (`tracker` says whether it does),
/// `context` naming the model and time; appended to `message` if one is pending.
pub fn note(tracker: &mut Tracker, validity: Validity, excursion: impl FnOnce() -> Option<Excursion>, context: &str, message: &mut Option<String>) {
    if !tracker.update(validity) {
        return;
    }
    let why = excursion().map_or_else(|| validity.meaning().to_string(), |e| e.to_string());
    let text = format!("validity {} ({}){context}: {why}. Said once per excursion: logged again only after the inputs came back inside and left again", validity.code(), validity);
    *message = Some(match message.take() {
        Some(m) => format!("{m}\n{text}"),
        None => text,
    });
}

/// The documentation page's section on the `validity` output: the envelope's table (from
/// [`pinjoint::validity::RANGES`]), what the codes mean, the log, and the cost of a
/// temperature change. `rig`: include the stroke's rows.
pub fn html(rig: bool) -> String {
    use pinjoint::validity::{FREQUENCY, LOAD, SLIDING_SPEED, STROKE_AMPLITUDE, TEMPERATURE};
    let mut ranges = vec![LOAD, SLIDING_SPEED, TEMPERATURE];
    if rig {
        ranges.extend([FREQUENCY, STROKE_AMPLITUDE]);
    }
    let rows: String = ranges
        .iter()
        .map(|r| format!("<tr><td><code>{}</code></td><td>{} &ndash; {} {}</td><td>{}</td></tr>\n", r.quantity, r.lo, r.hi, r.unit, r.source))
        .collect();
    let edges = pinjoint::validity::Edges::paper();
    let (edge_load, edge_t) = (pinjoint::fmt::Num((edges.load / 10.0).round() * 10.0), pinjoint::fmt::Num(edges.temperature));
    let codes: String = VALIDITY_TYPE.items.iter().map(|(name, code, what)| format!("<li>{code} = <code>{name}</code>: {what}</li>\n")).collect();
    format!(
        r#"<h2>Validity envelope (the <code>validity</code> output)</h2>
<p>The output <code>validity</code> (Enumeration, discrete) says whether the current answer lies inside the conditions the model
was checked against in the paper (its rig tests, sections 4.3&ndash;5, Figures 8&ndash;13), one definition shared with the
library, the command line and the Python package:</p>
<table><tr><th>quantity</th><th>checked range</th><th>source in the paper</th></tr>
{rows}</table>
<ul>
{codes}</ul>
<p>Outside the checked ranges the equations still hold as written but nothing measured confirms them; the paper itself saw the measured
friction fall below the model's at its lower loads. Below 0 &deg;C the direction of the error is known: the model has the base oil's
film only, which Roelands' temperature relation thickens without bound as it cools, so &mu; falls (0.021 at &minus;40 &deg;C, 12&deg;/s,
20 kN, against 0.119 at 20 &deg;C), while a cold-soaked grease's thickener gains a yield stress the model lacks and the real joint turns
stiffer: torque and &mu; there are too <b>low</b>. The log (category logEvents) says once per excursion which quantity left which
range: when the inputs leave the envelope, and again only after they came back and left again. <code>validity</code> is not part of the
FMU state.</p>
<p>Past the model's own assumptions the output is 3 (<code>outside</code>), never a plain extrapolation: a load |P| above
&pi; E' B R<sup>2</sup>/(8 R'), where the Hertz half-width a of eq. 6 reaches the pin's radius R ({edge_load} N with the default
parameters: a flat strip wider than the pin has no reading on this geometry), or a temperature above the parameter
<code>grease.upper_service_temperature</code> (default {edge_t} K, +121 &deg;C: MIL-PRF-23827 Type I, the default grease's class).
The outputs are still computed there, continuous across the edge; the FMU refuses only loads at the asperity model's limit
and temperatures outside the declared range of the <code>temperature</code> input.</p>
<p>Temperature: a change of the <code>temperature</code> input costs a few logarithms at fidelity full (the start table of the solve
is the same at every temperature, read at the speed shifted by ln(&eta;<sub>0</sub>(T)/&eta;<sub>0</sub>(T<sub>ref</sub>))), and
the outputs are bit for bit those of an instance started at that temperature; at table, boundary and auto the level is built and its
bound measured again at the new temperature (the cost of an initialization: about 4 ms for a table at tolerance 1e-4 over
5&ndash;60 kN, 0.01&ndash;10 rad/s, 0.5 ms for boundary). For a temperature that changes at every step use fidelity full.</p>
"#
    )
}
