//! `PassThrough`: a trivial co-simulation FMU for benchmarks only. Outputs `y1`, `y2` equal
//! inputs `u1`, `u2`. `pinjoint-bench` drives it with the same fmpy loop as PinJoint (set two
//! inputs, `doStep`, get two outputs), so the ratio of the two step costs shows what the
//! friction model adds to the host's own per-step overhead.

use fmi_layer::core::bytes::{ByteReader, ByteWriter};
use fmi_layer::core::model::{Model, ModelResult};
use fmi_layer::core::variables::{Causality, Initial, Kind, ModelInfo, Variability, Variable};
use std::sync::LazyLock;

fn var(name: &str, vr: u32, causality: Causality, d: &str) -> Variable {
    let input = causality == Causality::Input;
    Variable {
        name: name.into(),
        value_reference: vr,
        causality,
        variability: Variability::Continuous,
        initial: if input { Initial::Exact } else { Initial::Calculated },
        unit: None,
        display_unit: None,
        start: input.then_some(0.0),
        min: None,
        max: None,
        description: d.into(),
        depends_on: if input { vec![] } else if vr == 11 { vec!["u1"] } else { vec!["u2"] },
        kind: Kind::Real,
        derivative_of: None,
        nominal: None,
    }
}

/// The PassThrough model's description for the registry: four Real variables (`u1`, `u2`
/// inputs, `y1`, `y2` outputs), Co-Simulation only.
pub static INFO: LazyLock<ModelInfo> = LazyLock::new(|| ModelInfo {
    model_name: "PassThrough",
    model_identifier: "PassThrough",
    description: "Benchmark baseline: y1 = u1, y2 = u2 (no model); see pinjoint-bench",
    version: env!("CARGO_PKG_VERSION"),
    units: &[],
    variables: vec![
        var("u1", 1, Causality::Input, "First input"),
        var("u2", 2, Causality::Input, "Second input"),
        var("y1", 11, Causality::Output, "y1 = u1"),
        var("y2", 12, Causality::Output, "y2 = u2"),
    ],
    default_experiment: (0.0, 1.0, 1e-3),
    create: || Box::new(PassThrough::default()),
    documentation: || {
        "<html><body><h1>PassThrough</h1><p>y1 = u1, y2 = u2. A benchmark baseline for the host's per-step cost \
         (pinjoint-bench).</p></body></html>"
            .into()
    },
    model_exchange: false,
    directional_derivatives: false,
    step_events: false,
    legal: crate::LEGAL,
});

/// The PassThrough instance: it holds the two inputs, which are also its outputs.
#[derive(Debug, Clone, Default)]
pub struct PassThrough {
    u: [f64; 2],
}

impl Model for PassThrough {
    fn set_start_values(&mut self) {
        self.u = [0.0; 2];
    }
    fn get_real(&self, i: usize) -> f64 {
        self.u[i % 2]
    }
    fn check_real(&self, i: usize, v: f64) -> ModelResult<()> {
        if v.is_finite() { Ok(()) } else { Err(fmi_layer::core::model::ModelError::invalid("input", format!("u{}", i + 1), v, "", "is not a finite number")) }
    }
    fn set_real(&mut self, i: usize, v: f64) {
        self.u[i] = v;
    }
    fn exit_initialization(&mut self, _start_time: f64) -> ModelResult<()> {
        Ok(())
    }
    fn compute_outputs(&mut self) -> ModelResult<()> {
        Ok(())
    }
    fn do_step(&mut self, _time: f64, _step: f64) -> ModelResult<()> {
        Ok(())
    }
    fn serialize(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter::default();
        w.f64(self.u[0]);
        w.f64(self.u[1]);
        out.extend_from_slice(&w.buf);
    }
    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let mut r = ByteReader::new(bytes);
        let u = [r.f64("u1").map_err(crate::table::rejected)?, r.f64("u2").map_err(crate::table::rejected)?];
        r.finish().map_err(crate::table::rejected)?;
        self.u = u;
        Ok(())
    }
}
