//! What every model of this library shares in its description: the author, copyright and
//! licence ([`LEGAL`]), the requirements section of its documentation page
//! ([`requirements_html`]) and the constructor of its [`ModelInfo`] ([`model_info`]).

use fmi_layer::core::model::Model;
use fmi_layer::core::variables::{Legal, ModelInfo, UnitDef, Variable};

/// Author, copyright and licence of every FMU of this library (the crates it links
/// statically keep their own licences: `documentation/licenses/` in each FMU).
pub const LEGAL: Legal = Legal {
    author: "The pinjoint developers",
    copyright: "Copyright (c) 2026 The pinjoint developers",
    license: "MIT; statically linked Rust crates under their own licences, see documentation/licenses/index.html",
};

/// The "Interfaces, platforms and runtime requirements" section of every FMU's
/// documentation/index.html (both models, both standards).
pub fn requirements_html() -> &'static str {
    r#"<h2>Interfaces, platforms and runtime requirements</h2>
<ul>
<li>Standards: FMI 2.0 (<code>fmiVersion="2.0"</code>) and FMI 3.0 (<code>fmiVersion="3.0"</code>, the FMUs under
<code>fmu/fmi3/</code>), built from one variable table: same names, value references, units, start values, ranges,
fidelity levels, FMU state and error handling. PinJoint is Co-Simulation <em>and</em> Model Exchange in both standards;
PinJointRig is Co-Simulation only (its actuator has continuous states and stick/slip events of its own).</li>
<li>Binaries: the platforms present are the folders under <code>binaries/</code>. The host build
(<code>cargo run --release -p fmu_build</code>) carries <code>linux64</code> (FMI 2.0) / <code>x86_64-linux</code> (FMI 3.0): x86-64
Linux; it needs <code>libc.so.6</code>, <code>libm.so.6</code> and <code>libgcc_s.so.1</code> with the glibc of the build
machine (built on Debian 12: glibc 2.35 or newer; the multi-platform build lowers this, see the project's docs/fmu.md).
Windows and macOS binaries are only present in FMUs built with <code>--platforms all</code>; what was run-tested on which
platform is listed in the project's docs/fmu.md.</li>
<li>No resources, files, network, licence server or environment variables are used; <code>fmuResourceLocation</code> /
<code>resourcePath</code> may be NULL or empty (no message). Nothing is written to disk.</li>
<li>Any number of instances per process (<code>canBeInstantiatedOnlyOncePerProcess = false</code>); instances are
independent, but one instance must not be called from two threads at the same time. Memory: under 1 MB per
instance with fidelity full; a table level builds its map (about 1 s) at exit of initialization.</li>
<li>Licences: this model is MIT; the Rust crates and the Rust standard library linked into the binary keep their own
licences, listed with their notices in <code>documentation/licenses/index.html</code>.</li>
</ul>
"#
}

/// A model of this library (identifier = name, this crate's version, [`LEGAL`]):
/// Co-Simulation only unless the caller sets `model_exchange`, without directional
/// derivatives unless the caller sets `directional_derivatives`.
pub fn model_info(
    name: &'static str,
    description: &'static str,
    (variables, units): (Vec<Variable>, &'static [UnitDef]),
    default_experiment: (f64, f64, f64),
    create: fn() -> Box<dyn Model>,
    documentation: fn() -> String,
) -> ModelInfo {
    ModelInfo {
        model_name: name,
        model_identifier: name,
        description,
        version: env!("CARGO_PKG_VERSION"),
        units,
        variables,
        default_experiment,
        create,
        documentation,
        model_exchange: false,
        directional_derivatives: false,
        step_events: false,
        legal: LEGAL,
    }
}
