//! A test-only linear system with one continuous state:
//!
//! x' = -a x + b u,   y = c x + d u,
//!
//! with state `x` (local, start 2, nominal 10), input `u` (start 0.5), its derivative `der(x)`
//! (local), output `y` and fixed parameters a = 2, b = 3, c = 5, d = 7. Its Jacobian is the
//! constant matrix [[-a, b], [c, d]] (rows der(x), y; columns x, u), which the tests compare
//! with what the layer's directional-derivative functions return. A state or input beyond
//! ±1e6 is refused, so that a rejected `SetContinuousStates` can be tested; at u = 999 the
//! derivative is NaN and a Co-Simulation step fails, so that the layer's check of the
//! derivatives, and which error a failed step names, can be tested.

use crate::core::model::{Model, ModelError, ModelResult};
use crate::core::variables::{Causality, Initial, Kind, Legal, ModelInfo, Variability, Variable};
use std::sync::LazyLock;

/// Table indices.
pub const X: usize = 0;
pub const U: usize = 1;
pub const DX: usize = 2;
pub const Y: usize = 3;
pub const A: usize = 4;
/// Value references (index + 1).
pub const VR_X: u32 = 1;
pub const VR_U: u32 = 2;
pub const VR_DX: u32 = 3;
pub const VR_Y: u32 = 4;
pub const VR_A: u32 = 5;
/// Parameter values.
pub const PA: f64 = 2.0;
pub const PB: f64 = 3.0;
pub const PC: f64 = 5.0;
pub const PD: f64 = 7.0;
/// Start values of x and u, and the nominal of x.
pub const X0: f64 = 2.0;
pub const U0: f64 = 0.5;
pub const X_NOMINAL: f64 = 10.0;
/// The input at which the test model's derivative is NaN (a model failure to be caught).
pub const SINGULAR_U: f64 = 999.0;

fn var(name: &str, vr: u32, causality: Causality, initial: Initial, start: Option<f64>) -> Variable {
    Variable {
        name: name.into(),
        kind: Kind::Real,
        value_reference: vr,
        causality,
        variability: if causality == Causality::Parameter { Variability::Fixed } else { Variability::Continuous },
        initial,
        unit: None,
        display_unit: None,
        start,
        min: None,
        max: None,
        description: format!("{name} of the linear test system"),
        depends_on: vec![],
        derivative_of: None,
        nominal: None,
    }
}

/// The variable table: x, u, der(x), y, a, b, c, d (value references 1 to 8).
pub fn table() -> Vec<Variable> {
    let mut x = var("x", VR_X, Causality::Local, Initial::Exact, Some(X0));
    x.nominal = Some(X_NOMINAL);
    let mut dx = var("der(x)", VR_DX, Causality::Local, Initial::Calculated, None);
    dx.derivative_of = Some("x");
    dx.depends_on = vec!["x", "u"];
    let mut y = var("y", VR_Y, Causality::Output, Initial::Calculated, None);
    y.depends_on = vec!["x", "u"];
    vec![
        x,
        var("u", VR_U, Causality::Input, Initial::Exact, Some(U0)),
        dx,
        y,
        var("a", VR_A, Causality::Parameter, Initial::Exact, Some(PA)),
        var("b", 6, Causality::Parameter, Initial::Exact, Some(PB)),
        var("c", 7, Causality::Parameter, Initial::Exact, Some(PC)),
        var("d", 8, Causality::Parameter, Initial::Exact, Some(PD)),
    ]
}

/// The model: every value by table index.
#[derive(Debug, Clone)]
pub struct Linear {
    v: [f64; 8],
}

impl Linear {
    /// At its start values.
    pub fn new() -> Self {
        let mut m = Linear { v: [0.0; 8] };
        m.set_start_values();
        m
    }

    /// ∂ variable `i` / ∂ variable `j` for i in {der(x), y}, j in {x, u}.
    fn partial(&self, i: usize, j: usize) -> f64 {
        let [_, _, _, _, a, b, c, d] = self.v;
        match (i, j) {
            (DX, X) => -a,
            (DX, U) => b,
            (Y, X) => c,
            (Y, U) => d,
            _ => f64::NAN,
        }
    }
}

impl Model for Linear {
    fn set_start_values(&mut self) {
        self.v = [X0, U0, 0.0, 0.0, PA, PB, PC, PD];
    }
    fn get_real(&self, index: usize) -> f64 {
        self.v[index]
    }
    fn check_real(&self, index: usize, value: f64) -> ModelResult<()> {
        if !(value.is_finite() && value.abs() <= 1e6) {
            return Err(ModelError::invalid("", table()[index].name.clone(), value, "", "is out of range: it must be a finite number within ±1e6"));
        }
        Ok(())
    }
    fn set_real(&mut self, index: usize, value: f64) {
        self.v[index] = value;
    }
    fn exit_initialization(&mut self, _start_time: f64) -> ModelResult<()> {
        Ok(())
    }
    fn compute_outputs(&mut self) -> ModelResult<()> {
        let [x, u, _, _, a, b, c, d] = self.v;
        // u = 999 stands for an input at which a model fails: the derivative is not a number.
        self.v[DX] = if u == SINGULAR_U { f64::NAN } else { -a * x + b * u };
        self.v[Y] = c * x + d * u;
        Ok(())
    }
    fn do_step(&mut self, _time: f64, step: f64) -> ModelResult<()> {
        // Exact solution over the step with u held; at u = 999 the step fails too (a model
        // whose outputs were already out of range at the step's start).
        let [x, u, _, _, a, b, ..] = self.v;
        if u == SINGULAR_U {
            return Err(ModelError::NotFinite("the step cannot be taken at u = 999".into()));
        }
        let e = (-a * step).exp();
        self.v[X] = x * e + b * u / a * (1.0 - e);
        self.compute_outputs()
    }
    fn jacobian(&mut self, unknowns: &[usize], knowns: &[usize], out: &mut [f64]) -> ModelResult<()> {
        for (r, &i) in unknowns.iter().enumerate() {
            for (k, &j) in knowns.iter().enumerate() {
                out[r * knowns.len() + k] = self.partial(i, j);
            }
        }
        Ok(())
    }
    fn serialize(&self, out: &mut Vec<u8>) {
        for x in self.v {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        if bytes.len() != 64 {
            return Err(ModelError::RejectedState(format!("{} bytes, expected 64", bytes.len())));
        }
        for (k, chunk) in bytes.chunks_exact(8).enumerate() {
            self.v[k] = f64::from_le_bytes(chunk.try_into().expect("8 bytes"));
        }
        Ok(())
    }
}

/// The same model without [`Model::jacobian`] (the trait's default refuses).
pub struct NoJacobian(Linear);

impl Model for NoJacobian {
    fn set_start_values(&mut self) {
        self.0.set_start_values();
    }
    fn get_real(&self, index: usize) -> f64 {
        self.0.get_real(index)
    }
    fn check_real(&self, index: usize, value: f64) -> ModelResult<()> {
        self.0.check_real(index, value)
    }
    fn set_real(&mut self, index: usize, value: f64) {
        self.0.set_real(index, value);
    }
    fn exit_initialization(&mut self, start_time: f64) -> ModelResult<()> {
        self.0.exit_initialization(start_time)
    }
    fn compute_outputs(&mut self) -> ModelResult<()> {
        self.0.compute_outputs()
    }
    fn do_step(&mut self, time: f64, step: f64) -> ModelResult<()> {
        self.0.do_step(time, step)
    }
    fn serialize(&self, out: &mut Vec<u8>) {
        self.0.serialize(out);
    }
    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        self.0.deserialize(bytes)
    }
}

/// The linear model's description without directional derivatives, for table edits.
pub fn info_for_tests() -> ModelInfo {
    info("LinearEdited", false, || Box::new(Linear::new()))
}

fn info(name: &'static str, directional_derivatives: bool, create: fn() -> Box<dyn Model>) -> ModelInfo {
    ModelInfo {
        model_name: name,
        model_identifier: name,
        description: "x' = -a x + b u, y = c x + d u (test model)",
        version: "1",
        units: &[],
        variables: table(),
        default_experiment: (0.0, 1.0, 0.01),
        create,
        documentation: String::new,
        model_exchange: true,
        directional_derivatives,
        step_events: false,
        legal: Legal { author: "test", copyright: "test", license: "test" },
    }
}

/// The linear system with directional derivatives.
pub static LINEAR: LazyLock<ModelInfo> = LazyLock::new(|| info("Linear", true, || Box::new(Linear::new())));
/// The same without the capability (`directional_derivatives: false`).
pub static LINEAR_NO_DD: LazyLock<ModelInfo> = LazyLock::new(|| info("LinearNoDD", false, || Box::new(Linear::new())));
/// Declares the capability but keeps the trait's default `jacobian`.
pub static LINEAR_DEFAULT_JACOBIAN: LazyLock<ModelInfo> =
    LazyLock::new(|| info("LinearDefaultJacobian", true, || Box::new(NoJacobian(Linear::new()))));

/// The output y declared at most [`Y_MAX`]: reading it beyond is refused.
pub static LINEAR_BOUNDED: LazyLock<ModelInfo> = LazyLock::new(|| {
    let mut info = info("LinearBounded", true, || Box::new(Linear::new()));
    info.variables[Y].max = Some(Y_MAX);
    info
});
/// The declared maximum of y in [`LINEAR_BOUNDED`].
pub const Y_MAX: f64 = 100.0;

/// Every model of this file, as a registry.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*LINEAR, &*LINEAR_NO_DD, &*LINEAR_DEFAULT_JACOBIAN, &*LINEAR_BOUNDED]
}

/// The Jacobian expected from the parameters alone: rows (der(x), y), columns (x, u).
pub fn expected(i: usize, j: usize) -> f64 {
    match (i, j) {
        (DX, X) => -PA,
        (DX, U) => PB,
        (Y, X) => PC,
        (Y, U) => PD,
        _ => unreachable!("no such pair"),
    }
}
