//! The "Extensions beyond the paper" section of both FMUs' documentation pages.

/// The extensions beyond the paper (h_min, temperature, starved inlet), shared by both FMUs'
/// documentation pages.
pub const EXTENSIONS_HTML: &str = r#"<h2>Extensions beyond the paper (neutral or off by default)</h2>
<ul>
<li><b>Minimum film</b> (outputs <code>min_film_thickness</code>, <code>min_lambda_ratio</code>): eq. 21 names h<sub>min</sub> but the paper gives
no relation for it; <code>film_thickness</code> and <code>lambda_ratio</code> stay the central film h<sub>c</sub>. h<sub>min</sub> = h<sub>c</sub>&middot;r with
Pan &amp; Hamrock's (1989, ASME J. Tribol. 111, 246&ndash;251) line-contact ratio
r = (1.714/2.922) W&prime;<sup>0.038</sup> U<sup>0.002</sup> G<sup>0.098</sup> (U on the mean velocity u/2), with eq. 13's substitution
E&prime;&rarr;E&prime;/&gamma;<sub>1</sub>, P<sub>T</sub>&rarr;P<sub>T</sub>/&gamma;<sub>1</sub> (U&rarr;&gamma;<sub>1</sub>U, G&rarr;G/&gamma;<sub>1</sub>), capped at 1.
Validity: the fits are for heavily loaded elastic&ndash;piezoviscous contacts (W&prime; of order 1e-5); this joint has W&prime; &asymp; 2e-8&ndash;2e-7,
so h<sub>min</sub> is an extrapolation, and as the fluid share goes to 0 (speed &rarr; 0) r goes to 0: 0 at rest. The coefficients and exponents
are the printed fits (tested); Pan &amp; Hamrock's own check values and stated validity range were not available, so the range above is from memory.</li>
<li><b>Temperature</b> (input <code>temperature</code>, K, display degC; parameters <code>lubricant.reference_temperature</code>,
<code>lubricant.roelands_temperature_index</code>): &eta;<sub>0</sub> and &alpha; of Table 3 hold at the reference temperature (default 293.15 K,
the paper's room temperature, assumed). Roelands' temperature relation ln(&eta;<sub>0</sub>(T)/&eta;<sub>&infin;</sub>) = ln(&eta;<sub>0</sub>(T<sub>ref</sub>)/&eta;<sub>&infin;</sub>)&middot;f,
f = [(135 + &theta;)/(135 + &theta;<sub>ref</sub>)]<sup>&minus;S<sub>0</sub></sup> (&theta; in &deg;C, &eta;<sub>&infin;</sub> = 6.31e-5 Pa&middot;s of eq. 5), and at fixed Roelands Z
&alpha;(T) = &alpha;(T<sub>ref</sub>)&middot;f. Default S<sub>0</sub> = 1.262: Roelands' relation through an ISO VG 100 mineral oil
(100 mm&sup2;/s at 40 &deg;C, 11.1 mm&sup2;/s at 100 &deg;C): a class-typical base oil, not the paper's grease. At T = T<sub>ref</sub> the outputs are
exactly the paper model's. With the defaults &eta;<sub>0</sub> is 12.25 Pa&middot;s at &minus;55 &deg;C and 2.59 mPa&middot;s at +70 &deg;C (12.45 mPa&middot;s at 20 &deg;C).
Below about 0 &deg;C this is an extrapolation of the relation; &tau;<sub>L0</sub>, &beta;<sub>0</sub> and &mu;<sub>c</sub> do not change with temperature here.
The parameter <code>lubricant.temperature</code> exists because every parameter-file key is a parameter; in the FMU the input sets the temperature.</li>
<li><b>Starved inlet</b> (parameters <code>starvation.inlet_layer_inverse</code> = 1/h<sub>oil</sub> in 1/m, default 0 = fully flooded, the paper's model;
<code>starvation.exponent</code> &gamma;<sub>s</sub>, default 2.8): the film of eq. 13 is replaced by h<sup>&minus;&gamma;<sub>s</sub></sup> = h<sub>13</sub><sup>&minus;&gamma;<sub>s</sub></sup> + h<sub>oil</sub><sup>&minus;&gamma;<sub>s</sub></sup>,
Chevalier et al.'s (1998, ASME J. Tribol. 120, 126&ndash;133) starvation relation h/h<sub>ff</sub> = R/(1 + R<sup>&gamma;<sub>s</sub></sup>)<sup>1/&gamma;<sub>s</sub></sup>, R = h<sub>oil</sub>/h<sub>ff</sub>,
inside the load-sharing solve. <b>Not verified against the source</b>: neither Chevalier et al. nor Damiens et al. (2004) was available, and
no published example of the relation was found; the form was found only in a secondary summary of Lugt (2013, eq. 9.73; &gamma; about 3 for circular,
up to 15 for wide elliptical contacts), &gamma;<sub>s</sub> = 2.8 is written from memory and may be low for this line contact, and only the relation's limits
(flooded as h<sub>oil</sub> &rarr; &infin;, h &rarr; h<sub>oil</sub> for a thin layer) and its &gamma;<sub>s</sub> sensitivity are tested. A phenomenological stand-in for the grease the stroke squeezes out (the paper, section 5); fit it to
measurements (<code>pinjoint calibrate</code> can fit <code>starvation.inlet_layer_inverse</code>).</li>
</ul>
"#;
