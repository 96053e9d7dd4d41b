//! PinJoint's directional derivatives: the partial derivatives of its outputs (and, under
//! Model Exchange, of `der(presliding_torque)`) with respect to its inputs (and the state).
//!
//! - The friction outputs (`torque`, `power_loss`, `der(presliding_torque)`) are
//!   differentiated exactly through the zero-velocity law (forward mode,
//!   [`pinjoint::zero_velocity::jet`]): the presliding stiffness, damping and elasto-plastic
//!   transition, or the band's ramp. The sliding torque T(P, |ω|) enters through its partials
//!   ∂T/∂ω and ∂T/∂P, taken by central differences of the evaluator at the instance's fidelity
//!   ([`pinjoint::zero_velocity::joint::bound_partials`]: relative steps 1e-6).
//! - The other outputs are functions of (P, ω, temperature) alone: central differences of the
//!   evaluator, the same steps.
//! - Temperature: central differences (±0.01 K) of a full-fidelity joint built at the
//!   perturbed temperature, for every output.
//!
//! At a kink of the law (the elastic limit, the sliding bound, ω = 0, the band's edge) the
//! derivative is the one-sided derivative of the branch the current values are on; the
//! angle partial is the presliding tangent stiffness in the direction of motion (that of ω;
//! [`pinjoint::zero_velocity::joint::tangent_held`]): the one a linearly implicit host needs.

use super::evaluate::{operating_point, outputs};
use super::variables::{Values, TABLE};
use fmi_layer::core::model::{ModelError, ModelResult};
use pinjoint::fidelity::Evaluator;
use pinjoint::zero_velocity::jet::{Jet, Scalar};
use pinjoint::zero_velocity::joint::{bound_partials, tangent_held};
use pinjoint::zero_velocity::modes::{self, Mode};
use pinjoint::zero_velocity::{band, ZeroVelocityModel};

/// The knowns a partial can be taken with respect to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Known {
    Angle,
    Omega,
    Load,
    Temperature,
    State,
}

impl Known {
    fn of(name: &str) -> Option<Known> {
        Some(match name {
            "angle" => Known::Angle,
            "angular_velocity" => Known::Omega,
            "load" => Known::Load,
            "temperature" => Known::Temperature,
            "presliding_torque" => Known::State,
            _ => return None,
        })
    }
}

/// The friction outputs as jets over (x0, ω, P), x0 being the angle (Co-Simulation) or the
/// presliding torque (Model Exchange).
struct FrictionJets {
    torque: Jet,
    power: Jet,
    rate: Jet,
}

fn friction_jets(ev: &mut Evaluator, v: &Values, model: ZeroVelocityModel, delta: f64, me: bool) -> ModelResult<FrictionJets> {
    let (load, omega) = (v.load, v.omega);
    let zero = FrictionJets { torque: Jet::c(0.0), power: Jet::c(0.0), rate: Jet::c(0.0) };
    if load == 0.0 {
        return Ok(zero);
    }
    let mut bound = |p: f64, w: f64| -> ModelResult<f64> { if p == 0.0 { Ok(0.0) } else { Ok(operating_point(ev, p, w)?.0.torque) } };
    let w = Jet::var(omega, 1);
    match model {
        ZeroVelocityModel::Presliding => {
            let (t, dw, dp) = bound_partials(&mut bound, load, omega)?;
            let t = Jet::with(t, [0.0, dw, dp]);
            let law = &v.zv.law.at_step(v.step);
            let mode = if me { Mode::from_code(v.mode).unwrap_or_default() } else { Mode::Stick };
            let tau = if me { Jet::var(v.tau, 0) } else { tangent_held(law, v.tau, delta, omega, t) };
            Ok(FrictionJets {
                torque: modes::torque(law, mode, tau, w, t),
                power: modes::dissipation(law, mode, tau, w, t),
                rate: modes::rate(law, mode, tau, w, t),
            })
        }
        ZeroVelocityModel::Band => {
            let width = v.zv.band;
            let torque = if band::inside(omega, width) {
                let (edge, _, dp) = bound_partials(&mut bound, load, width)?;
                -Jet::with(edge, [0.0, 0.0, dp]) * (w / Jet::c(width))
            } else {
                let (t, dw, dp) = bound_partials(&mut bound, load, omega)?;
                let t = Jet::with(t, [0.0, dw, dp]);
                if omega > 0.0 { -t } else if omega < 0.0 { t } else { Jet::c(0.0) }
            };
            let p = torque * w;
            Ok(FrictionJets { torque, power: if p.re() < 0.0 { -p } else { p }, rate: Jet::c(0.0) })
        }
    }
}

/// Every output value of the model at `v` (by table index; 0 for non-outputs), from `ev`.
fn output_values(ev: &mut Evaluator, v: &Values, model: ZeroVelocityModel, delta: f64) -> ModelResult<Vec<f64>> {
    let (out, _) = outputs(ev, v, model, delta)?;
    let mut w = *v;
    w.out = out;
    Ok((0..TABLE.rows().len()).map(|i| TABLE.get(&w, i)).collect())
}

/// ∂ output / ∂ temperature for every row, by central differences of a full-fidelity joint.
fn temperature_column(v: &Values, model: ZeroVelocityModel, delta: f64) -> ModelResult<Vec<f64>> {
    let h = 0.01;
    let at = |t: f64| -> ModelResult<Vec<f64>> {
        let mut params = v.params;
        params.lubricant.temperature = t;
        let mut ev = Evaluator::new(&params, pinjoint::fidelity::Fidelity::Full, 1e-4, crate::fidelity::envelope_from_parameters(v.fidelity.envelope)?)
            .map_err(|e| ModelError::failed("temperature partial: ", e))?;
        let mut w = *v;
        w.temperature = t;
        output_values(&mut ev, &w, model, delta)
    };
    let (a, b) = (at(v.temperature + h)?, at(v.temperature - h)?);
    Ok(a.iter().zip(&b).map(|(x, y)| (x - y) / (2.0 * h)).collect())
}

/// The partials of `unknowns` with respect to `knowns` (table indices) at the values `v`,
/// row-major into `out` (see [`fmi_layer::core::model::Model::jacobian`]). `delta` is the angle
/// increment the Co-Simulation outputs deflect the state by; `me`: Model Exchange.
pub fn jacobian(
    ev: &mut Evaluator,
    v: &Values,
    model: ZeroVelocityModel,
    delta: f64,
    me: bool,
    (unknowns, knowns): (&[usize], &[usize]),
    out: &mut [f64],
) -> ModelResult<()> {
    let rows = TABLE.rows();
    let known: Vec<Option<Known>> = knowns.iter().map(|&k| Known::of(&rows[k].var.name)).collect();
    let jets = friction_jets(ev, v, model, delta, me)?;
    // Finite differences of every output in ω and P (only if some unknown needs them).
    let names: Vec<&str> = unknowns.iter().map(|&u| rows[u].var.name.as_str()).collect();
    let needs_fd = names.iter().any(|n| !matches!(*n, "torque" | "power_loss" | "der(presliding_torque)" | "dissipated_energy"));
    let fd = if needs_fd && v.load != 0.0 {
        let hw = (1e-6 * v.omega.abs()).max(1e-9);
        let hp = (1e-6 * v.load.abs()).max(1e-3);
        let mut at = |p: f64, w: f64| {
            let mut x = *v;
            (x.load, x.omega) = (p, w);
            output_values(ev, &x, model, delta)
        };
        let (wp, wm) = (at(v.load, v.omega + hw)?, at(v.load, v.omega - hw)?);
        let (pp, pm) = (at(v.load + hp, v.omega)?, at(v.load - hp, v.omega)?);
        let col = |a: &[f64], b: &[f64], h: f64| a.iter().zip(b).map(|(x, y)| (x - y) / (2.0 * h)).collect::<Vec<f64>>();
        Some((col(&wp, &wm, hw), col(&pp, &pm, hp)))
    } else {
        None
    };
    let temperature = if known.contains(&Some(Known::Temperature)) { Some(temperature_column(v, model, delta)?) } else { None };
    let n = knowns.len();
    for (i, (&u, name)) in unknowns.iter().zip(&names).enumerate() {
        let jet = match *name {
            "torque" => Some(jets.torque),
            "power_loss" => Some(jets.power),
            "der(presliding_torque)" => Some(jets.rate),
            _ => None,
        };
        for (j, k) in known.iter().enumerate() {
            let d = match (k, jet) {
                (None, _) | (Some(Known::Angle), None) | (Some(Known::State), None) => 0.0,
                (Some(Known::Temperature), _) => temperature.as_ref().map_or(0.0, |t| t[u]),
                (Some(Known::Angle), Some(j)) => if me { 0.0 } else { j.d[0] },
                (Some(Known::State), Some(j)) => if me { j.d[0] } else { 0.0 },
                (Some(Known::Omega), Some(j)) => j.d[1],
                (Some(Known::Load), Some(j)) => j.d[2],
                (Some(Known::Omega), None) => fd.as_ref().map_or(0.0, |f| f.0[u]),
                (Some(Known::Load), None) => fd.as_ref().map_or(0.0, |f| f.1[u]),
            };
            out[i * n + j] = d;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pin_joint::variables::DEFAULT_FIDELITY;
    use crate::pin_joint::zero_velocity::ZeroVelocitySettings;

    fn values(model: ZeroVelocityModel, load: f64, omega: f64, tau: f64) -> Values {
        let mut v = Values { load, omega, tau, ..Values::default() };
        v.zv = ZeroVelocitySettings { code: model.code() as f64, ..ZeroVelocitySettings::default() };
        v
    }

    /// Every known's partial of every output against central differences of the model's own
    /// outputs, in stick, transition and slip (presliding) and inside/outside the band, at
    /// every fidelity level.
    #[test]
    fn partials_match_central_differences() {
        let names = ["torque", "power_loss", "der(presliding_torque)", "friction_coefficient", "film_thickness"];
        let knowns = ["angle", "angular_velocity", "load", "temperature", "presliding_torque"];
        let unknowns: Vec<usize> = names.iter().map(|n| TABLE.index(n).unwrap()).collect();
        let known_idx: Vec<usize> = knowns.iter().map(|n| TABLE.index(n).unwrap()).collect();
        for code in [0.0, 1.0, 2.0, 3.0] {
            let settings = crate::fidelity::FidelitySettings { code, ..DEFAULT_FIDELITY };
            let mut ev = settings.build(&pinjoint::Params::default()).unwrap();
            // (model, load, omega, committed tau, angle increment, model exchange, ME mode)
            let cases = [
                (ZeroVelocityModel::Presliding, 20e3, 1e-3, 10.0, 2e-4, false, 0.0),
                (ZeroVelocityModel::Presliding, 20e3, 0.3, 60.0, 1e-4, false, 0.0),
                (ZeroVelocityModel::Presliding, 55e3, -0.5, -150.0, -3e-3, false, 0.0),
                (ZeroVelocityModel::Presliding, 20e3, 0.2, 30.0, 0.0, true, 0.0),
                (ZeroVelocityModel::Presliding, 20e3, 0.2, 66.0, 0.0, true, 0.0),
                (ZeroVelocityModel::Presliding, 20e3, 0.2, 66.0, 0.0, true, 1.0),
                (ZeroVelocityModel::Presliding, 40e3, -0.2, 100.0, 0.0, true, 1.0),
                (ZeroVelocityModel::Band, 20e3, 0.004, 0.0, 0.0, false, 0.0),
                (ZeroVelocityModel::Band, 55e3, -0.7, 0.0, 0.0, false, 0.0),
            ];
            for (model, load, omega, tau, delta, me, mode) in cases {
                let v = Values { mode, ..values(model, load, omega, tau) };
                let mut jac = vec![0.0; unknowns.len() * knowns.len()];
                jacobian(&mut ev, &v, model, delta, me, (&unknowns, &known_idx), &mut jac).unwrap();
                let f = |ev: &mut Evaluator, x: &Values, delta: f64| output_values(ev, x, model, delta).unwrap();
                for (j, k) in knowns.iter().enumerate() {
                    let (plus, minus, h) = match *k {
                        "angle" if !me => (f(&mut ev, &v, delta + 1e-9), f(&mut ev, &v, delta - 1e-9), 1e-9),
                        "angular_velocity" => {
                            let h = 1e-7 * omega.abs().max(1e-3);
                            (f(&mut ev, &Values { omega: omega + h, ..v }, delta), f(&mut ev, &Values { omega: omega - h, ..v }, delta), h)
                        }
                        "load" => (f(&mut ev, &Values { load: load + 10.0, ..v }, delta), f(&mut ev, &Values { load: load - 10.0, ..v }, delta), 10.0),
                        "presliding_torque" if me => (f(&mut ev, &Values { tau: tau + 1e-4, ..v }, delta), f(&mut ev, &Values { tau: tau - 1e-4, ..v }, delta), 1e-4),
                        _ => continue,
                    };
                    for (i, &u) in unknowns.iter().enumerate() {
                        let fd = (plus[u] - minus[u]) / (2.0 * h);
                        let got = jac[i * knowns.len() + j];
                        // The differences' rounding: the table level interpolates to ~1e-12 relative.
                        let noise = 1e-11 * (1.0 + plus[u].abs()) / h;
                        assert!((got - fd).abs() <= 1e-4 * got.abs().max(fd.abs()) + noise,
                            "fidelity {code} {model:?} load {load} omega {omega} tau {tau} me {me}: d {}/d {k} = {got} vs {fd}", names[i]);
                    }
                }
            }
        }
    }
}
