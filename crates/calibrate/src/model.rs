//! The fitted torque model and its shape.
//!
//! The recorded actuator torque is T = J·α + sign(ω)·μ(P, |ω|)·R·P + T_0 (the rig's
//! J·ω̇ = T_a + T_f with the friction T_f = −sign(ω)·μRP of eq. 11, and a sensor offset T_0).
//! μ = μ_fluid + μ_c/γ2 (eqs. 3, 8, 10) where the load shares γ1, γ2 and the film h_c come from
//! eqs. 9, 13 and 19, none of which contains μ_c: for fixed other parameters the torque is
//! *linear* in μ_c, with the shape x = sign(ω)·R·P/γ2 and the intercept sign(ω)·R·P·μ_fluid.
//! (`shares_do_not_depend_on_mu_c` in the tests checks this against the library.)

use super::error::CalibrationError;
use pinjoint::{Joint, Params};
use rayon::prelude::*;

/// sign(ω) with sign(0) = 0 (no friction direction at rest).
pub fn sign(w: f64) -> f64 {
    if w > 0.0 {
        1.0
    } else if w < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// The model's shape at one sample: torque = `fluid` + μ_c·`boundary` (+ J·α + offset).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    /// sign(ω)·R·P·μ_fluid (N·m).
    pub fluid: f64,
    /// sign(ω)·R·P/γ2 (N·m per unit μ_c).
    pub boundary: f64,
}

/// One operating point of a record: load (N), angular velocity (rad/s) and the lubricant
/// temperature (K) when the record gives it (None: the parameters' `lubricant.temperature`).
pub type Operating = (f64, f64, Option<f64>);

/// Operating points solved in one sequence (warm-started from each other); the sequences are
/// solved in parallel (rayon). A fixed length, so that the answers do not depend on the number
/// of threads.
pub const CHUNK: usize = 4096;

/// The shape at every operating point, warm-starting each solve from the previous one within
/// a [`CHUNK`] of points, the chunks in parallel. A point with a temperature is evaluated by
/// the joint at that temperature ([`Joint::at_temperature`], a few logarithms), made again
/// only where the temperature changes (once a chunk for a constant one). Each chunk builds its
/// own joint: the joints [`Joint::at_temperature`] makes share the solve's start table, whose
/// rows are solved by whichever joint asks first, so that shared between threads the answers
/// could depend on the threads' timing; a chunk's own table is filled in its own fixed order
/// (one [`Joint::new`] a chunk, about 4 ms).
/// `ident` identifies the sample in an error.
pub fn shapes(params: &Params, points: &[Operating], ident: &(dyn Fn(usize) -> (String, usize) + Sync)) -> Result<Vec<Shape>, CalibrationError> {
    let chunks = points
        .par_chunks(CHUNK)
        .enumerate()
        .map(|(c, pts)| chunk_shapes(&Joint::new(params)?, params, pts, c * CHUNK, ident))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(chunks.into_iter().flatten().collect())
}

/// [`shapes`] of one chunk, its first point the `first`-th.
fn chunk_shapes(
    joint: &Joint,
    params: &Params,
    points: &[Operating],
    first: usize,
    ident: &(dyn Fn(usize) -> (String, usize) + Sync),
) -> Result<Vec<Shape>, CalibrationError> {
    let r = params.geometry.pin_radius;
    let mut guess = None;
    let mut at: Option<(u64, Joint)> = None;
    let mut out = Vec::with_capacity(points.len());
    for (k, &(load, w, temperature)) in points.iter().enumerate() {
        let i = first + k;
        let j = match temperature {
            Some(t) if t.to_bits() != params.lubricant.temperature.to_bits() => {
                if at.as_ref().is_none_or(|(bits, _)| *bits != t.to_bits()) {
                    let made = joint.at_temperature(t).map_err(|e| {
                        let (record, row) = ident(i);
                        CalibrationError::Temperature { record, row, value: t, why: format!("the model refuses it: {e}") }
                    })?;
                    at = Some((t.to_bits(), made));
                    guess = None;
                }
                &at.as_ref().expect("made above").1
            }
            _ => joint,
        };
        let op = j.evaluate_from(load, w, guess).map_err(|source| {
            let (record, row) = ident(i);
            CalibrationError::Model { record, row, source }
        })?;
        guess = op.logit.is_finite().then_some(op.logit);
        let s = sign(w) * r * load;
        out.push(Shape { fluid: s * op.fluid_friction_coefficient, boundary: s * op.asperity_load_fraction });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_do_not_depend_on_mu_c() {
        // Over boundary, mixed and full-film points: every output but the asperity friction is
        // bit-identical when μ_c changes, and μ is exactly μ_fluid + μ_c/γ2.
        let a = Params::default();
        let mut b = a;
        b.friction.boundary_friction_coefficient = 0.05;
        let (ja, jb) = (Joint::new(&a).unwrap(), Joint::new(&b).unwrap());
        for &(p, w) in &[(5e3, 0.0), (5e3, 0.01), (20e3, 1.0), (20e3, 10.0), (60e3, 4.4), (5e3, 80.0)] {
            let (x, y) = (ja.evaluate(p, w).unwrap(), jb.evaluate(p, w).unwrap());
            assert_eq!(x.asperity_load_fraction, y.asperity_load_fraction);
            assert_eq!(x.fluid_load_fraction, y.fluid_load_fraction);
            assert_eq!(x.film_thickness, y.film_thickness);
            assert_eq!(x.fluid_friction_coefficient, y.fluid_friction_coefficient);
            for (op, mu_c) in [(x, 0.12), (y, 0.05)] {
                let mu = op.fluid_friction_coefficient + mu_c * op.asperity_load_fraction;
                assert!((op.friction_coefficient - mu).abs() <= 1e-15, "{p} {w}");
            }
        }
    }

    #[test]
    fn shape_reproduces_the_signed_torque() {
        let p = Params::default();
        let j = Joint::new(&p).unwrap();
        let pts = [(20e3, 2.0, None), (20e3, -2.0, Some(273.15)), (40e3, 0.0, None)];
        let s = shapes(&p, &pts, &|i| ("t".into(), i)).unwrap();
        for (k, &(load, w, temp)) in pts.iter().enumerate() {
            // Recorded torque is the actuator's: minus the friction torque on the pin, at the
            // point's temperature (a joint built at it, not the shared one's `at_temperature`).
            let jt = temp.map(|t| {
                let mut q = p;
                q.lubricant.temperature = t;
                Joint::new(&q).unwrap()
            });
            let t = -jt.as_ref().unwrap_or(&j).evaluate(load, w).unwrap().signed_torque();
            let m = s[k].fluid + 0.12 * s[k].boundary;
            assert!((t - m).abs() <= 1e-12 * t.abs().max(1.0), "{t} {m}");
        }
    }
}
