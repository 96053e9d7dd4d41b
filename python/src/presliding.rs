//! `_Presliding`: the presliding joint of `pinjoint::zero_velocity` as a stateful Python
//! object, stepped exactly as the PinJoint FMU steps it (the same library code), so a Python
//! simulation uses the law the FMU uses, bit for bit at fidelity full.

use crate::messages::model_error;
use crate::params::PyParams;
use pinjoint::zero_velocity::joint::{bound_jet, bound_partials};
use pinjoint::zero_velocity::{modes, Presliding, PreslidingJoint};
use pinjoint::Joint;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The presliding joint (native half of `pinjoint.Presliding`).
#[pyclass(name = "_Presliding", module = "pinjoint._native")]
pub struct NativePresliding {
    joint: Joint,
    state: PreslidingJoint,
}

/// A finite number, or a ValueError naming the quantity, its value and unit.
fn finite(name: &str, x: f64, unit: &str) -> PyResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(PyValueError::new_err(format!("{name} = {} {unit} is not a finite number", crate::messages::short(x))))
    }
}

/// A step that is a finite number ≥ 0 (s), or a ValueError naming it.
fn check_step(step: f64) -> PyResult<()> {
    if step.is_finite() && step >= 0.0 {
        Ok(())
    } else {
        Err(PyValueError::new_err(format!("step = {} s is invalid: it must be a finite number >= 0", crate::messages::short(step))))
    }
}

impl NativePresliding {
    /// The sliding torque T(P, |ω|) (N·m; 0 unloaded), the FMU's cold full solve.
    fn bound(&self, load: f64, omega: f64) -> PyResult<f64> {
        let load = finite("load", load, "N")?;
        let omega = finite("angular_velocity", omega, "rad/s")?;
        if load.abs() >= self.joint.capacity() {
            return Err(PyValueError::new_err(format!(
                "load = {} N is beyond the asperity model's capacity of {} N for these parameters",
                crate::messages::short(load),
                crate::messages::short(self.joint.capacity())
            )));
        }
        if load == 0.0 {
            return Ok(0.0);
        }
        self.joint.evaluate(load, omega).map(|op| op.torque).map_err(|e| PyValueError::new_err(model_error(&e)))
    }
}

#[pymethods]
impl NativePresliding {
    /// `angle` None: no reference yet, the first angle given is it.
    #[new]
    #[pyo3(signature = (params, presliding_angle, elastic_limit, damping_time, angle, host_inertia=0.0))]
    fn new(params: &PyParams, presliding_angle: f64, elastic_limit: f64, damping_time: f64, angle: Option<f64>, host_inertia: f64) -> PyResult<Self> {
        let joint = Joint::new(&params.inner).map_err(crate::params::param_err)?;
        let law = Presliding::new(presliding_angle, elastic_limit, damping_time)
            .and_then(|l| l.with_host_inertia(host_inertia))
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        let state = match angle {
            Some(a) => PreslidingJoint::new(law, finite("angle", a, "rad")?),
            None => PreslidingJoint::unreferenced(law),
        };
        Ok(Self { joint, state })
    }

    /// The friction torque on the pin (N·m) at (angle, angular_velocity, load), the state unchanged.
    fn torque(&self, angle: f64, angular_velocity: f64, load: f64) -> PyResult<f64> {
        let t = self.bound(load, angular_velocity)?;
        Ok(self.state.torque_at(finite("angle", angle, "rad")?, angular_velocity, t))
    }

    /// Commit the state at `angle` (the FMU's fmi2DoStep when the host sets the angle); `step`
    /// (s, None: not known) is the host's step: the next angle is read against
    /// angular_velocity·step, and the host-inertia damping capped at it.
    #[pyo3(signature = (angle, angular_velocity, load, step=None))]
    fn commit(&mut self, angle: f64, angular_velocity: f64, load: f64, step: Option<f64>) -> PyResult<()> {
        let t = self.bound(load, angular_velocity)?;
        let angle = finite("angle", angle, "rad")?;
        match step {
            Some(h) => {
                check_step(h)?;
                self.state.commit_step(angle, angular_velocity, t, h);
            }
            None => self.state.commit(angle, t),
        }
        Ok(())
    }

    /// Drive the state by angular_velocity·step (the FMU's step when the host does not set the angle).
    fn advance(&mut self, angular_velocity: f64, load: f64, step: f64) -> PyResult<()> {
        let t = self.bound(load, angular_velocity)?;
        check_step(step)?;
        self.state.advance(angular_velocity, step, t);
        let reference = self.state.reference_angle() + angular_velocity * step;
        self.state.set_state(self.state.presliding_torque(), reference);
        self.state.set_last_step(step, angular_velocity, false);
        Ok(())
    }

    /// dτ/dt (N·m/s) at the committed state (the Model Exchange derivative).
    fn rate(&self, angular_velocity: f64, load: f64) -> PyResult<f64> {
        let t = self.bound(load, angular_velocity)?;
        Ok(modes::rate(self.state.law(), modes::Mode::Stick, self.state.presliding_torque(), angular_velocity, t))
    }

    /// Partial derivatives of the torque at (angle, angular_velocity, load) with respect to each.
    fn partials<'py>(&self, py: Python<'py>, angle: f64, angular_velocity: f64, load: f64) -> PyResult<Bound<'py, PyDict>> {
        let angle = finite("angle", angle, "rad")?;
        let (t, dw, dp) = bound_partials(|p, w| self.bound(p, w), load, angular_velocity)?;
        let j = self.state.torque_partials(angle, angular_velocity, bound_jet(t, dw, dp));
        let d = PyDict::new(py);
        d.set_item("torque", j.v)?;
        d.set_item("angle", j.d[0])?;
        d.set_item("angular_velocity", j.d[1])?;
        d.set_item("load", j.d[2])?;
        Ok(d)
    }

    /// (presliding torque τ in N·m, reference angle in rad).
    #[getter]
    fn state(&self) -> (f64, f64) {
        (self.state.presliding_torque(), self.state.reference_angle())
    }

    /// Replace the state: presliding torque (N·m) and reference angle (rad).
    fn set_state(&mut self, torque: f64, angle: f64) -> PyResult<()> {
        self.state.set_state(finite("presliding_torque", torque, "N.m")?, finite("angle", angle, "rad")?);
        Ok(())
    }

    /// (presliding_angle rad, elastic_limit, damping_time s).
    #[getter]
    fn law(&self) -> (f64, f64, f64) {
        let l = self.state.law();
        (l.angle, l.elastic_limit, l.damping_time)
    }

    /// The host's inertia (kg·m², 0 = not given).
    #[getter]
    fn host_inertia(&self) -> f64 {
        self.state.law().host_inertia
    }

    /// Everything the state holds, for pickling: (τ N·m, reference angle rad, last step s,
    /// ω at the last commit rad/s, unreferenced).
    #[getter]
    fn full_state(&self) -> (f64, f64, f64, f64, bool) {
        let (step, omega) = self.state.last_step();
        (self.state.presliding_torque(), self.state.reference_angle(), step, omega, self.state.is_unreferenced())
    }

    /// Restore [`NativePresliding::full_state`].
    fn set_full_state(&mut self, torque: f64, angle: f64, step: f64, omega: f64, unreferenced: bool) -> PyResult<()> {
        self.set_state(torque, angle)?;
        check_step(step)?;
        self.state.set_last_step(step, finite("angular_velocity", omega, "rad/s")?, unreferenced);
        Ok(())
    }
}
