//! The fit: linear least squares for μ_c (and the torque offset) on the model's own shape, or
//! Levenberg–Marquardt when other parameters are fitted too; then the uncertainty.

use super::coords::{resolve, Extra, Transform, MU_C};
use super::error::CalibrationError;
use super::model::{shapes, Shape};
use super::prepare::{prepare, Prepared, STICK_SLIP_IRREGULARITY};
use super::record::Record;
use super::result::{Calibration, Estimate, Series};
use super::uncertainty::{analyse, Uncertainty, MIN_BOOTSTRAP_CLUSTERS, MIN_CLUSTERS};
use super::{Model, Options};
use super::lm::{Adapter, Residuals};
use levenberg_marquardt::LevenbergMarquardt;
use nalgebra::{DMatrix, DVector};
use pinjoint::Params;
use std::cell::RefCell;
use std::collections::HashMap;

/// Used samples needed per fitted quantity.
pub const MIN_POINTS_PER_PARAMETER: usize = 10;

/// One used sample.
#[derive(Debug, Clone, Copy)]
struct Point {
    rec: usize,
    row: usize,
    load: f64,
    omega: f64,
    /// T − J·α (N·m).
    y: f64,
    cluster: usize,
    /// Time since the sample's settling window began (s).
    since: f64,
}

/// Extensions of the settling window at most (each by half the stated settling time).
pub const MAX_SETTLE_EXTENSIONS: usize = 6;

/// Fit `records` as `options` asks. See the crate documentation for the model.
///
/// The settling window is then checked against the data: if the residual just after it (the
/// next half settling time, averaged over every stroke with the sign of the motion) differs
/// from that of the rest of the strokes by more than 3 standard errors, the breakaway or the
/// servo ringing lasts longer than the window, and the window is extended by half the settling
/// time and the fit repeated (at most [`MAX_SETTLE_EXTENSIONS`] times, and only while at least
/// half the samples stay in use). The report says so.
pub fn calibrate(records: &[Record], options: &Options) -> Result<Calibration, CalibrationError> {
    if options.model == Model::Rig {
        return super::rig_fit::calibrate_rig(records, options);
    }
    let mut o = options.clone();
    let step = 0.5 * options.exclusion.settle_time;
    let (mut best, mut deviates) = calibrate_once(records, &o)?;
    let first_used = best.points_used;
    let mut extended = 0;
    while deviates.is_some() && step > 0.0 && extended < MAX_SETTLE_EXTENSIONS {
        o.exclusion.settle_time += step;
        match calibrate_once(records, &o) {
            Ok((c, d)) if 2 * c.points_used >= first_used => {
                extended += 1;
                (best, deviates) = (c, d);
            }
            _ => break,
        }
    }
    if extended > 0 {
        best.warnings.push(format!(
            "the settling window was extended from {} s to {} s: just after the shorter one the stroke-averaged residual still \
             differed from the rest of the strokes by more than 3 standard errors (breakaway or servo ringing lasting longer){}",
            options.exclusion.settle_time,
            (o.exclusion.settle_time * 1e6).round() / 1e6,
            match deviates {
                Some(d) => format!("; it still differs by {d:.4} N.m after the last extension"),
                None => String::new(),
            }
        ));
    }
    best.settle_time = o.exclusion.settle_time;
    Ok(best)
}

/// The mean of sign(ω)·residual over used samples with `since` in [settle, 1.5·settle) against
/// the rest: Some(difference) when it exceeds 3 standard errors of the window's mean.
fn settle_deviation(points: &[Point], r: &DVector<f64>, settle: f64) -> Option<f64> {
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for (i, p) in points.iter().enumerate() {
        let v = r[i] * p.omega.signum();
        if p.since < 1.5 * settle { a.push(v) } else { b.push(v) }
    }
    if a.len() < 10 || b.len() < 10 {
        return None;
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (ma, mb) = (mean(&a), mean(&b));
    let var = |v: &[f64], m: f64| v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (v.len() - 1) as f64;
    let se = (var(&a, ma) / a.len() as f64 + var(&b, mb) / b.len() as f64).sqrt();
    ((ma - mb).abs() > 3.0 * se).then_some(ma - mb)
}

fn calibrate_once(records: &[Record], options: &Options) -> Result<(Calibration, Option<f64>), CalibrationError> {
    if records.is_empty() {
        return Err(CalibrationError::NoRecords);
    }
    options.params.validate()?;
    check_options(options)?;
    let extras = resolve(&options.fit, &options.params, &options.rig, false)?;
    let prepared = records.iter().map(|r| prepare(r, &options.exclusion, options.half_width)).collect::<Result<Vec<_>, _>>()?;
    let j_inertia = options.inertia;
    let mut clusters: HashMap<(usize, usize), usize> = HashMap::new();
    let mut points = Vec::new();
    for (ri, p) in prepared.iter().enumerate() {
        for (row, s) in p.stroke.iter().enumerate() {
            if let Some(s) = s {
                let next = clusters.len();
                let cluster = *clusters.entry((ri, *s)).or_insert(next);
                points.push(Point {
                    rec: ri,
                    row,
                    load: p.load[row],
                    omega: p.omega[row],
                    y: p.torque[row] - j_inertia * p.alpha[row],
                    cluster,
                    since: p.since[row],
                });
            }
        }
    }
    let np = 1 + usize::from(options.fit_offset) + extras.len();
    let total: usize = prepared.iter().map(|p| p.time.len()).sum();
    let needed = (MIN_POINTS_PER_PARAMETER * np).max(20);
    if points.len() < needed {
        return Err(CalibrationError::Unidentifiable {
            what: format!(
                "only {} of {total} samples remain after the exclusion rule (|omega| >= {} x peak speed, {} s after each reversal); \
                 at least {needed} are needed for {np} fitted quantities: record more strokes or a finer sampling",
                points.len(),
                options.exclusion.speed_fraction,
                options.exclusion.settle_time
            ),
        });
    }
    let (pos, neg) = (points.iter().filter(|p| p.omega > 0.0).count(), points.iter().filter(|p| p.omega < 0.0).count());
    if options.fit_offset && (pos == 0 || neg == 0) {
        let dir = if pos == 0 { "negative" } else { "positive" };
        return Err(CalibrationError::Unidentifiable {
            what: format!(
                "every used sample moves in one direction (angular velocity {dir}): a torque offset and mu_c cannot be told apart; \
                 record both directions of motion (or do not fit the offset)"
            ),
        });
    }
    let ident = |i: usize| (prepared[points[i].rec].name.clone(), points[i].row);
    let load_speed: Vec<(f64, f64)> = points.iter().map(|p| (p.load, p.omega)).collect();
    let y = DVector::from_iterator(points.len(), points.iter().map(|p| p.y));
    let problem = Problem { load_speed: &load_speed, y: &y, base: options.params, extras: &extras, offset: options.fit_offset, ident: &ident };

    // Start: the extras at their start values, μ_c and T_0 by linear least squares.
    let mut beta = DVector::zeros(np);
    for (k, e) in extras.iter().enumerate() {
        beta[k] = e.transform.forward(e.start).expect("checked by resolve");
    }
    let linear = problem.linear_solve(&beta)?;
    beta.rows_mut(extras.len(), np - extras.len()).copy_from(&linear);
    let mut evaluations = 0;
    if !extras.is_empty() {
        let lm = LmProblem { p: &problem, error: RefCell::new(None), evals: RefCell::new(0) };
        let (found, report) = LevenbergMarquardt::new().with_patience(200).minimize(Adapter { fit: &lm, beta: beta.clone() });
        if !report.termination.was_successful() {
            // A model error met on the way is the likelier cause; else LM's own reason.
            return Err(lm.error.into_inner().unwrap_or_else(|| {
                CalibrationError::NoConvergence(format!("{:?} after {} evaluations", report.termination, report.number_of_evaluations))
            }));
        }
        evaluations = report.number_of_evaluations;
        beta = found.beta;
        // μ_c and T_0 exactly at the optimum of the others.
        let linear = problem.linear_solve(&beta)?;
        beta.rows_mut(extras.len(), np - extras.len()).copy_from(&linear);
    }
    let (jac, model) = problem.jacobian(&beta)?;
    let r = &y - &model;
    if !(beta.iter().all(|b| b.is_finite()) && r.norm_squared().is_finite()) {
        return Err(CalibrationError::Unidentifiable {
            what: format!("the fit overflows (largest |torque| {:e} N.m): are the torque values in N.m?", y.amax()),
        });
    }
    let cl: Vec<usize> = points.iter().map(|p| p.cluster).collect();
    let u = analyse(&jac, &r, &cl, clusters.len(), options.resamples, options.seed).ok_or_else(|| CalibrationError::Unidentifiable {
        what: "the fitted quantities cannot be determined from these records (singular normal matrix)".into(),
    })?;

    // Estimates in the parameters' own units.
    let params = problem.params_at(&beta);
    let keys = keys_of(&extras, options.fit_offset);
    let transforms: Vec<(Transform, &'static str, f64)> = extras
        .iter()
        .map(|e| (e.transform, e.key.unit(), e.start))
        .chain(std::iter::once((Transform::Identity, "1", options.params.friction.boundary_friction_coefficient)))
        .chain(options.fit_offset.then_some((Transform::Identity, "N.m", 0.0)))
        .collect();
    let mut estimates: Vec<Estimate> =
        (0..np).map(|k| estimate(&keys[k], transforms[k], beta[k], &u, k)).collect();
    let offset = options.fit_offset.then(|| estimates.pop().expect("offset is last"));
    let mu = estimates.pop().expect("mu_c follows the extras");
    estimates.insert(0, mu);

    let mut warnings = warnings(&extras, &jac, &model, &u, &estimates, &keys, clusters.len(), options);
    let mean_abs = y.iter().map(|v| v.abs()).sum::<f64>() / y.len() as f64;
    let rms = (r.norm_squared() / y.len() as f64).sqrt();
    if rms > 0.1 * mean_abs {
        warnings.push(format!(
            "the fit is poor: rms residual {rms:.4} N.m is {:.0} % of the mean |torque| {mean_abs:.4} N.m; check each record's load (N) and units",
            100.0 * rms / mean_abs
        ));
    }
    for p in &prepared {
        if let Some(x) = p.irregularity.filter(|x| *x > STICK_SLIP_IRREGULARITY) {
            warnings.push(format!(
                "record {}: the motion is irregular (sample-to-sample speed deviates from the smoothed speed by {:.0} % rms): \
                 stick-slip? The quasi-static model does not describe it and the fitted mu_c will be biased (high)",
                p.name,
                100.0 * x
            ));
        }
    }
    let rss = r.norm_squared();
    let series = series(&prepared, &params, &beta, options, np)?;
    let points_used = points.len();
    let deviation = settle_deviation(&points, &r, options.exclusion.settle_time);
    Ok((Calibration {
        model: Model::Core,
        rig: None,
        simulations: 0,
        commands: Vec::new(),
        params,
        estimates,
        offset,
        correlation_keys: keys,
        correlation: u.correlation.clone(),
        condition: u.condition,
        rms_residual: (rss / points_used as f64).sqrt(),
        points_used,
        points_excluded: total - points_used,
        strokes: clusters.len(),
        dof: u.dof,
        quantile: u.quantile,
        half_widths: prepared.iter().map(|p| p.half_width).collect(),
        exclusions: prepared.into_iter().map(|p| p.exclusion).collect(),
        warnings,
        inertia: j_inertia,
        evaluations,
        settle_time: options.exclusion.settle_time,
        series,
    }, deviation))
}

pub(crate) fn check_options(o: &Options) -> Result<(), CalibrationError> {
    let bad = |what: String| Err(CalibrationError::Option(what));
    if !(o.inertia.is_finite() && o.inertia >= 0.0) {
        return bad(format!("inertia = {} kg.m2 is invalid: it must be a finite number >= 0", o.inertia));
    }
    let f = o.exclusion.speed_fraction;
    if !(0.0..1.0).contains(&f) {
        return bad(format!("exclusion speed fraction = {f} is invalid: it must be in [0, 1)"));
    }
    let s = o.exclusion.settle_time;
    if !(s.is_finite() && s >= 0.0) {
        return bad(format!("exclusion settle time = {s} s is invalid: it must be a finite number >= 0 s"));
    }
    if o.half_width == Some(0) {
        return bad("differentiator half-width = 0 samples is invalid: it must be >= 1".into());
    }
    Ok(())
}

pub(crate) fn keys_of(extras: &[Extra], offset: bool) -> Vec<String> {
    extras.iter().map(|e| e.key.name()).chain(std::iter::once(MU_C.to_string())).chain(offset.then(|| "torque_offset".to_string())).collect()
}

pub(crate) fn estimate(key: &str, (t, unit, initial): (Transform, &'static str, f64), b: f64, u: &Uncertainty, k: usize) -> Estimate {
    let slope = t.slope(b);
    let (lo, hi) = u.ci95[k];
    Estimate {
        key: key.to_string(),
        unit,
        value: t.inverse(b),
        initial,
        standard_error: slope * u.standard_error[k],
        standard_error_iid: slope * u.standard_error_iid[k],
        standard_error_cluster: u.standard_error_cluster.as_ref().map(|s| slope * s[k]),
        ci95: (t.inverse(b + lo), t.inverse(b + hi)),
        bootstrap_ci95: u.bootstrap_ci95.as_ref().map(|c| (t.inverse(b + c[k].0), t.inverse(b + c[k].1))),
    }
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn warnings(
    extras: &[Extra],
    jac: &DMatrix<f64>,
    model: &DVector<f64>,
    u: &Uncertainty,
    estimates: &[Estimate],
    keys: &[String],
    clusters: usize,
    o: &Options,
) -> Vec<String> {
    let mut w = Vec::new();
    let scale = model.norm().max(f64::MIN_POSITIVE);
    for (k, e) in extras.iter().enumerate() {
        // ∂T/∂β for a log coordinate is the torque change per unit relative change.
        let rel = jac.column(k).norm() / scale;
        if rel < 1e-3 {
            w.push(format!(
                "{} is not identifiable from these records: a 1 % change of it moves the fitted torque by {:.2e} % (rms); \
                 its interval means nothing (e.g. viscosity from records that never leave the boundary regime)",
                e.key.name(),
                rel
            ));
        }
    }
    for e in estimates {
        if e.value != 0.0 && (e.standard_error / e.value.abs()) > 0.5 {
            w.push(format!("{} is poorly determined: its standard error is {:.0} % of its value", e.key, 100.0 * e.standard_error / e.value.abs()));
        }
    }
    if u.condition > 1e6 {
        let p = keys.len();
        let (mut best, mut pair) = (0.0, (0, 0));
        for a in 0..p {
            for b in a + 1..p {
                if u.correlation[a][b].abs() > best {
                    best = u.correlation[a][b].abs();
                    pair = (a, b);
                }
            }
        }
        w.push(format!(
            "the fitted quantities are nearly collinear (condition number {:.3e}); the strongest correlation is {} with {} ({:.4})",
            u.condition, keys[pair.0], keys[pair.1], u.correlation[pair.0][pair.1]
        ));
    }
    if clusters < MIN_CLUSTERS {
        w.push(format!(
            "only {clusters} strokes: the intervals assume independent residuals and are likely too narrow (cluster-robust errors need {MIN_CLUSTERS})"
        ));
    } else if clusters < MIN_BOOTSTRAP_CLUSTERS && o.resamples > 0 {
        w.push(format!("only {clusters} strokes: no bootstrap (it needs {MIN_BOOTSTRAP_CLUSTERS}); intervals from the cluster-robust errors"));
    }
    let mu = estimates[0].value;
    if mu < 0.0 {
        w.push(format!("fitted {MU_C} = {mu} is negative: the records are not described by this model"));
    }
    w
}

/// Every sample of every record, measured and fitted.
fn series(prepared: &[Prepared], params: &Params, beta: &DVector<f64>, o: &Options, np: usize) -> Result<Vec<Series>, CalibrationError> {
    let off = if o.fit_offset { beta[np - 1] } else { 0.0 };
    let mu = params.friction.boundary_friction_coefficient;
    prepared
        .iter()
        .map(|p| {
            let pts: Vec<(f64, f64)> = p.load.iter().copied().zip(p.omega.iter().copied()).collect();
            let s = shapes(params, &pts, &|i| (p.name.clone(), i))?;
            let inertia_torque: Vec<f64> = p.alpha.iter().map(|a| o.inertia * a).collect();
            let fitted = s.iter().zip(&inertia_torque).map(|(s, ja)| ja + s.fluid + mu * s.boundary + off).collect();
            Ok(p.series(inertia_torque, fitted, p.stroke.iter().map(Option::is_some).collect()))
        })
        .collect()
}

/// The model over the used samples, in the fit coordinates β = [extras…, μ_c, T_0?].
struct Problem<'a> {
    load_speed: &'a [(f64, f64)],
    y: &'a DVector<f64>,
    base: Params,
    extras: &'a [Extra],
    offset: bool,
    ident: &'a dyn Fn(usize) -> (String, usize),
}

impl Problem<'_> {
    fn params_at(&self, beta: &DVector<f64>) -> Params {
        let (mut p, mut rig) = (self.base, pinjoint::rig::RigParams::default());
        for (k, e) in self.extras.iter().enumerate() {
            e.key.set(&mut p, &mut rig, e.transform.inverse(beta[k]));
        }
        p.friction.boundary_friction_coefficient = beta[self.extras.len()];
        p
    }

    fn shapes(&self, beta: &DVector<f64>) -> Result<Vec<Shape>, CalibrationError> {
        let mut p = self.params_at(beta);
        // μ_c does not enter the shape; keep the shape's evaluation valid if a step makes it < 0.
        p.friction.boundary_friction_coefficient = 0.0;
        shapes(&p, self.load_speed, self.ident)
    }

    fn model(&self, beta: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        let s = self.shapes(beta)?;
        let (mu, off) = self.linear_of(beta);
        Ok(DVector::from_iterator(s.len(), s.iter().map(|s| s.fluid + mu * s.boundary + off)))
    }

    fn linear_of(&self, beta: &DVector<f64>) -> (f64, f64) {
        let m = self.extras.len();
        (beta[m], if self.offset { beta[m + 1] } else { 0.0 })
    }

    /// μ_c and T_0 by linear least squares at the extras of `beta` (QR of the shape columns).
    fn linear_solve(&self, beta: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        let s = self.shapes(beta)?;
        let cols = 1 + usize::from(self.offset);
        let a = DMatrix::from_fn(s.len(), cols, |i, c| if c == 0 { s[i].boundary } else { 1.0 });
        let rhs = DVector::from_iterator(s.len(), s.iter().zip(self.y.iter()).map(|(s, y)| y - s.fluid));
        let qr = a.qr();
        let r = qr.r();
        if (0..cols).any(|k| r[(k, k)].abs() <= 1e-12 * r[(0, 0)].abs().max(f64::MIN_POSITIVE)) {
            return Err(CalibrationError::Unidentifiable { what: "the boundary shape and the offset are collinear in these records".into() });
        }
        let qty = qr.q().transpose() * rhs;
        r.solve_upper_triangular(&qty)
            .ok_or_else(|| CalibrationError::Unidentifiable { what: "singular least-squares problem for mu_c".into() })
    }

    /// Jacobian of the model with respect to β (central differences for the extras, exact for
    /// μ_c and T_0), and the model.
    fn jacobian(&self, beta: &DVector<f64>) -> Result<(DMatrix<f64>, DVector<f64>), CalibrationError> {
        let s = self.shapes(beta)?;
        let n = s.len();
        let (mu, off) = self.linear_of(beta);
        let model = DVector::from_iterator(n, s.iter().map(|s| s.fluid + mu * s.boundary + off));
        let m = self.extras.len();
        let mut j = DMatrix::zeros(n, beta.len());
        for k in 0..m {
            let h = 1e-5 * beta[k].abs().max(1.0);
            let (mut bp, mut bm) = (beta.clone(), beta.clone());
            bp[k] += h;
            bm[k] -= h;
            let d = (self.model(&bp)? - self.model(&bm)?) / (2.0 * h);
            j.set_column(k, &d);
        }
        for i in 0..n {
            j[(i, m)] = s[i].boundary;
            if self.offset {
                j[(i, m + 1)] = 1.0;
            }
        }
        Ok((j, model))
    }
}

/// The quasi-static problem for LM ([`Adapter`]): residuals model − y over β.
struct LmProblem<'a, 'b> {
    p: &'a Problem<'b>,
    error: RefCell<Option<CalibrationError>>,
    evals: RefCell<usize>,
}

impl Residuals for LmProblem<'_, '_> {
    fn residuals_at(&self, beta: &DVector<f64>) -> Option<DVector<f64>> {
        *self.evals.borrow_mut() += 1;
        match self.p.model(beta) {
            Ok(m) => Some(m - self.p.y),
            Err(e) => {
                // A step outside the model's domain ends LM; keep the first error to report.
                self.error.borrow_mut().get_or_insert(e);
                None
            }
        }
    }
    fn jacobian_at(&self, beta: &DVector<f64>) -> Option<DMatrix<f64>> {
        match self.p.jacobian(beta) {
            Ok((j, _)) => Some(j),
            Err(e) => {
                self.error.borrow_mut().get_or_insert(e);
                None
            }
        }
    }
}
