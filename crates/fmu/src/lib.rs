//! # pinjoint-fmu
//!
//! The FMU shared library: the models PinJoint and PinJointRig (and the PassThrough
//! benchmark baseline, `pinjoint-bench`), each plugged into the generic
//! [`fmi_layer::fmi2`] layer. The registry below is passed to that layer from this
//! root with [`fmi_layer::export_fmi2!`]; `fmi2Instantiate` finds a model in it by GUID.

pub mod pass_through;
pub mod pin_joint;
pub mod pin_joint_rig;
pub mod platforms_doc;

use fmi_layer::fmi2::variables::{Legal, ModelInfo};

fmi_layer::export_fmi2!(crate::registry);
fmi_layer::export_fmi3!(crate::registry);

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
machine (built on Debian 12: glibc 2.35 or newer; the multi-platform build lowers this, see the project README).
Windows and macOS binaries are only present in FMUs built with <code>--platforms all</code>; what was run-tested on which
platform is listed in the project README.</li>
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

/// Every model the shared library serves.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*pin_joint::INFO, &*pin_joint_rig::INFO, &*pass_through::INFO]
}

/// The envelope parameters of both FMUs (`envelope.*`), with their units.
pub const ENVELOPE_NAMES: [(&str, &str); 4] =
    [("envelope.load_min", "N"), ("envelope.load_max", "N"), ("envelope.speed_min", "rad/s"), ("envelope.speed_max", "rad/s")];

/// The envelope from the four `envelope.*` parameter values; an error names the parameter,
/// its value and unit.
pub fn envelope_from_parameters(values: [f64; 4]) -> Result<pinjoint::fidelity::Envelope, String> {
    use fmi_layer::fmi2::logging::show;
    for (k, (name, unit)) in ENVELOPE_NAMES.iter().enumerate() {
        let x = values[k];
        if !(x.is_finite() && x > 0.0) {
            return Err(format!("parameter {name} = {} {unit} is invalid: it must be a finite number > 0 {unit}", show(x)));
        }
    }
    for k in [0, 2] {
        let ((lo_name, unit), (hi_name, _)) = (ENVELOPE_NAMES[k], ENVELOPE_NAMES[k + 1]);
        let (lo, hi) = (values[k], values[k + 1]);
        if lo >= hi {
            return Err(format!("parameter {lo_name} = {} {unit} is invalid: it must be below {hi_name} = {} {unit}", show(lo), show(hi)));
        }
    }
    let [a, b, c, d] = values;
    pinjoint::fidelity::Envelope::new(a, b, c, d).map_err(|e| format!("parameter {e}"))
}
