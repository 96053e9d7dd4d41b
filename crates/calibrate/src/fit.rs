//! The quasi-static fit: linear least squares for μ_c, the inertia J (unless given) and the
//! torque offset on the model's own shape, or Levenberg–Marquardt when other parameters are
//! fitted too; then the uncertainty.
//!
//! The recorded torque is T = sign(ω)·R·P·μ_fluid + μ_c·sign(ω)·R·P/γ2 + J·α + T_0: linear in
//! μ_c, J and T_0 (the shape does not depend on any of them), so the three are one linear
//! least-squares problem at the other parameters, and their joint covariance (hence the
//! correlation of J with μ_c) comes out of the same normal matrix. α is the second derivative
//! of the angle by the symmetric Savitzky–Golay cubic ([`crate::derivative`]): a symmetric
//! window has no lag, and its attenuation of a sine's α, (ωh)²/14 for a window of half-length h,
//! is 4e-4 at the default 1/40 of a stroke, far below the 5 % J is asked to.
//! Identifiability: α is largest at the stroke ends and changes sign within each stroke, while
//! the friction's shape keeps its sign through the stroke, so the columns are nearly orthogonal
//! whenever the used samples cover both halves of a stroke; the fit reports J with its interval
//! and the condition number, and J is poorly determined only when J·α is small against the
//! noise (slow strokes): then give it (`inertia`).

use super::across::{dropped, independence, plan, worst, MIN_INDEPENDENCE};
use super::coords::{resolve, Extra, Transform};
use super::error::CalibrationError;
use super::estimates::{check_options, estimate, keys_of, warnings, INERTIA, MIN_POINTS_PER_PARAMETER};
use super::lm::{Adapter, Residuals};
use super::derivative::matched_taps;
use super::model::{shapes, Operating, Shape};
use super::options::{Model, Options};
use super::prepare::{prepare, Prepared, STICK_SLIP_IRREGULARITY};
use super::record::Record;
use super::result::{Calibration, Estimate, Series};
use super::uncertainty::{analyse, widen_two_way};
use levenberg_marquardt::LevenbergMarquardt;
use nalgebra::{DMatrix, DVector};
use pinjoint::Params;
use std::cell::RefCell;
use std::collections::HashMap;

/// One used sample.
#[derive(Debug, Clone, Copy)]
struct Point {
    rec: usize,
    row: usize,
    load: f64,
    omega: f64,
    /// Lubricant temperature (K), when the record gives it.
    temperature: Option<f64>,
    /// α (rad/s²).
    alpha: f64,
    /// T at a used sample; at a fitted point the matched filter's mean of T, less J·α when J
    /// is given (N·m).
    y: f64,
    cluster: usize,
    /// Time since the sample's settling window began (s).
    since: f64,
}

/// The grease's flow index n (dropped from the default fit across temperature when the speeds
/// span less than [`MIN_SPEED_SPAN`]).
pub const FLOW_INDEX: &str = "grease.flow_index";

/// The span of speeds (95th over 5th percentile of |ω| over the used samples) from which the
/// flow index is fitted by default: a decade.
pub const MIN_SPEED_SPAN: f64 = 10.0;

/// 95th over 5th percentile of |ω| over `points`.
fn speed_span(points: &[Point]) -> f64 {
    let mut w: Vec<f64> = points.iter().map(|p| p.omega.abs()).collect();
    if w.is_empty() {
        return 1.0;
    }
    w.sort_by(f64::total_cmp);
    let at = |f: f64| w[((w.len() - 1) as f64 * f).round() as usize];
    at(0.95) / at(0.05)
}

/// Extensions of the settling window at most (each by half the stated settling time).
pub const MAX_SETTLE_EXTENSIONS: usize = 6;

/// Fit `records` with the quasi-static model ([`Model::Core`]) as `options` asks (its `model` is
/// not read). See the crate documentation for the model.
///
/// The settling window is then checked against the data: if the residual just after it (the
/// next half settling time, averaged over every stroke with the sign of the motion) differs
/// from that of the rest of the strokes by more than 3 standard errors, the breakaway or the
/// servo ringing lasts longer than the window, and the window is extended by half the settling
/// time and the fit repeated (at most [`MAX_SETTLE_EXTENSIONS`] times, and only while at least
/// half the samples stay in use). The report says so.
pub fn calibrate_core(records: &[Record], options: &Options) -> Result<Calibration, CalibrationError> {
    calibrate_core_with(records, options, true)
}

/// [`calibrate_core`], with the matched filter for a given J not 0 when `filter_given` (else a
/// given J·α is subtracted sample by sample, as before the filter was used for a given J). The
/// rig fit ([`crate::rig_fit`]) takes its start from the latter: its Levenberg–Marquardt path
/// from that start is the one its tests validate (from the filtered fit's μ_c, 0.36 % away,
/// it ended in another local minimum of k_b on short records).
pub fn calibrate_core_with(records: &[Record], options: &Options, filter_given: bool) -> Result<Calibration, CalibrationError> {
    let plan = plan(records, options, true)?;
    let mut o = options.clone();
    o.fit = plan.keys.clone();
    let mut notes = plan.warnings.clone();
    // The default keys across temperature: fitted, and one the records do not determine
    // dropped and the fit repeated (each round drops one, so this ends).
    let mut screened = plan.screened.clone();
    let mut drop = |o: &mut Options, screened: &mut Vec<String>, key: &str, why: &str| {
        o.fit.retain(|k| k != key);
        screened.retain(|k| k != key);
        notes.push(dropped(key, why));
    };
    let first = loop {
        let once = match calibrate_once(records, &o, filter_given, &screened) {
            Ok(Ok(x)) => x,
            Ok(Err((key, why))) => {
                drop(&mut o, &mut screened, &key, &why);
                continue;
            }
            // The default keys made the fit fail (no convergence, a Jacobian outside the model's
            // domain, a singular problem; a trial step outside it is only a rejected step): fitted without them, each named. An error of the
            // records themselves comes back from the fit without them.
            Err(e) if !screened.is_empty() => {
                let why = format!("the fit with the default keys across temperature failed ({e})");
                for key in screened.clone() {
                    drop(&mut o, &mut screened, &key, &why);
                }
                continue;
            }
            Err(e) => return Err(e),
        };
        for (key, why) in &once.dropped {
            drop(&mut o, &mut screened, key, why);
        }
        match worst(&once.calibration.estimates, &once.independence, &screened) {
            Some((key, why)) => drop(&mut o, &mut screened, &key, &why),
            None => break once,
        }
    };
    let step = 0.5 * options.exclusion.settle_time;
    let first_used = first.calibration.points_used;
    let (mut best, mut deviates) = (first.calibration, first.deviation);
    let mut extended = 0;
    while deviates.is_some() && step > 0.0 && extended < MAX_SETTLE_EXTENSIONS {
        o.exclusion.settle_time += step;
        match calibrate_once(records, &o, filter_given, &[]) {
            Ok(Ok(c)) if 2 * c.calibration.points_used >= first_used => {
                extended += 1;
                (best, deviates) = (c.calibration, c.deviation);
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
    best.temperatures = plan.temperatures;
    notes.append(&mut best.warnings);
    best.warnings = notes;
    Ok(best)
}

/// One fit: the calibration, the settling window's deviation ([`settle_deviation`]), the
/// [`independence`] of each fitted extra at the optimum, and the screened keys dropped before
/// the fit (their Jacobian column at the start nearly collinear with the others', or nearly
/// zero), with why.
struct Once {
    calibration: Calibration,
    deviation: Option<f64>,
    independence: Vec<(String, f64)>,
    dropped: Vec<(String, String)>,
}

/// The mean of sign(ω)·residual over used samples with `since` in [settle, 1.5·settle) against
/// the rest: Some(difference) when it exceeds 3 standard errors of the window's mean.
///
/// `inflation` of each point's record: 1/Σv² of its matched-filter taps v (1 without the
/// filter): filtered white noise has Σv² of the variance per point but the same variance of a
/// long mean, so the points' variance over their count is too small by that factor.
fn settle_deviation(points: &[Point], r: &DVector<f64>, settle: f64, inflation: &[f64]) -> Option<f64> {
    let (mut a, mut b) = (Vec::new(), Vec::new());
    let (mut fa, mut fb) = (0.0, 0.0);
    for (i, p) in points.iter().enumerate() {
        let v = r[i] * p.omega.signum();
        if p.since < 1.5 * settle {
            a.push(v);
            fa += inflation[p.rec];
        } else {
            b.push(v);
            fb += inflation[p.rec];
        }
    }
    if a.len() < 10 || b.len() < 10 {
        return None;
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (ma, mb) = (mean(&a), mean(&b));
    let var = |v: &[f64], m: f64| v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (v.len() - 1) as f64;
    let (fa, fb) = (fa / a.len() as f64, fb / b.len() as f64);
    let se = (var(&a, ma) * fa / a.len() as f64 + var(&b, mb) * fb / b.len() as f64).sqrt();
    ((ma - mb).abs() > 3.0 * se).then_some(ma - mb)
}

fn calibrate_once(records: &[Record], options: &Options, filter_given: bool, screened: &[String]) -> Result<Result<Once, (String, String)>, CalibrationError> {
    if records.is_empty() {
        return Err(CalibrationError::NoRecords);
    }
    options.params.validate()?;
    check_options(options)?;
    let mut extras = resolve(&options.fit, &options.params, &options.rig, false)?;
    let prepared = records.iter().map(|r| prepare(r, &options.params, &options.exclusion, options.half_width)).collect::<Result<Vec<_>, _>>()?;
    // J given: J·α subtracted; J fitted: α is a column of the linear problem.
    let j_given = options.inertia.unwrap_or(0.0);
    let fit_j = options.inertia.is_none();
    // The matched filter whenever J·α enters: fitted, or given and not 0. A given J·α is
    // subtracted at the filtered points, where the filtered torque and the differentiator's α
    // agree to O(Δt⁴); subtracted sample by sample, the differentiator's attenuation of α,
    // (ωh)²/14 = 4e-4 at the default window, left 4e-4·J·α in the residuals, a bias of μ_c of
    // 1.1 standard errors at J = 2 kg·m², 1 Hz and of 3 at 1.5 Hz (95 % intervals covering
    // 8 of 60 fits there).
    let matched = fit_j || (filter_given && j_given > 0.0);
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
                    temperature: p.temperature.as_ref().map(|t| t[row]),
                    alpha: p.alpha[row],
                    y: p.torque[row],
                    cluster,
                    since: p.since[row],
                });
            }
        }
    }
    // The fitted points: with J fitted, the matched filter's centres (whose window lies in one
    // stroke's used samples), the targets filtered; else every used sample.
    let filter = Filter::new(&prepared, &points, matched);
    let support = points;
    let points: Vec<Point> = filter
        .centres
        .iter()
        .map(|&(c, r)| Point { y: filter.apply(r, c, |i| support[i].y) - j_given * support[c].alpha, ..support[c] })
        .collect();
    // μ_c, J (when fitted) and T_0 (when fitted): the linear quantities.
    let nl = 1 + usize::from(fit_j) + usize::from(options.fit_offset);
    let np = nl + extras.len();
    let total: usize = prepared.iter().map(|p| p.time.len()).sum();
    let needed = (MIN_POINTS_PER_PARAMETER * np).max(20);
    if points.len() < needed {
        return Err(CalibrationError::Unidentifiable {
            what: format!(
                "only {} of {total} samples remain after the exclusion rule (|omega| >= {} x peak speed, {} s after each reversal); \
                 at least {needed} are needed for {np} fitted quantities{}: record more strokes or a finer sampling{}",
                points.len(),
                options.exclusion.speed_fraction,
                options.exclusion.settle_time,
                if matched { " (with the inertia fitted or not 0, a sample also needs the differentiator's window, its half-width each side, inside its stroke)" } else { "" },
                if fit_j { ", or give the inertia" } else { "" }
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
    let ident = |i: usize| (prepared[support[i].rec].name.clone(), support[i].row);
    // The friction is evaluated at the smoothed velocity (a raw difference of a quantised angle
    // can be noisier than slow strokes are fast).
    let load_speed: Vec<Operating> = support.iter().map(|p| (p.load, p.omega, p.temperature)).collect();
    let y = DVector::from_iterator(points.len(), points.iter().map(|p| p.y));
    let alpha: Vec<f64> = if fit_j { points.iter().map(|p| p.alpha).collect() } else { Vec::new() };
    let template = Problem {
        load_speed: &load_speed,
        alpha: fit_j.then_some(&alpha[..]),
        filter: &filter,
        y: &y,
        base: options.params,
        extras: &[],
        offset: options.fit_offset,
        ident: &ident,
    };
    // Start: the extras at their start values, μ_c and T_0 by linear least squares.
    let start = |problem: &Problem<'_>| -> Result<DVector<f64>, CalibrationError> {
        let m = problem.extras.len();
        let mut beta = DVector::zeros(nl + m);
        for (k, e) in problem.extras.iter().enumerate() {
            beta[k] = e.transform.forward(e.start).expect("checked by resolve");
        }
        let linear = problem.linear_solve(&beta)?;
        beta.rows_mut(m, beta.len() - m).copy_from(&linear);
        Ok(beta)
    };
    // The screened (default) keys whose column at the start the other columns explain (or
    // that move nothing) are dropped before the fit, one at a time.
    let mut dropped_before = Vec::new();
    // The flow index shows only through the shear rate's spread: over a narrow span of speeds
    // K·γ̇^n is a valley in (K, n), along which the fit crawls without end.
    if let Some(k) = extras.iter().position(|e| screened.contains(&e.key.name()) && e.key.name() == FLOW_INDEX) {
        let span = speed_span(&support);
        if span.is_nan() || span < MIN_SPEED_SPAN {
            dropped_before.push((
                FLOW_INDEX.to_string(),
                format!(
                    "the used samples' speeds span a factor {span:.3} (5th to 95th percentile of |omega|), less than the {MIN_SPEED_SPAN} \
                     needed to tell the flow index from the consistency: record strokes of frequencies a decade apart"
                ),
            ));
            extras.remove(k);
        }
    }
    loop {
        let which: Vec<usize> = (0..extras.len()).filter(|&k| screened.contains(&extras[k].key.name())).collect();
        if which.is_empty() {
            break;
        }
        let trial = Problem { extras: &extras, ..template };
        let (jac, _) = trial.jacobian(&start(&trial)?, false)?;
        let d = independence(&jac, &which);
        let (i, &least) = d.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).expect("not empty");
        if least.is_nan() || least >= MIN_INDEPENDENCE {
            break;
        }
        let key = extras[which[i]].key.name();
        dropped_before.push((
            key,
            format!(
                "at its start value its Jacobian column is nearly collinear with the other fitted quantities' or zero (the part they \
                 do not explain is {least:.2e} of it)"
            ),
        ));
        extras.remove(which[i]);
    }
    let np = nl + extras.len();
    let problem = Problem { extras: &extras, ..template };
    let mut beta = start(&problem)?;
    let mut evaluations = 0;
    if !extras.is_empty() {
        let lm = LmProblem { p: &problem, error: RefCell::new(None), evals: RefCell::new(0), outside: 1e3 * y.amax().max(1.0) };
        let (found, report) = LevenbergMarquardt::new().with_patience(200).minimize(Adapter { fit: &lm, beta: beta.clone() });
        if !report.termination.was_successful() {
            // A model error met on the way is the likelier cause; else LM's own reason.
            // A Jacobian the model refused (at an accepted point) ended LM: that error is the
            // cause. Otherwise LM ran out of patience or tolerance, and an error met on the way
            // was a trial step the model refused, which LM rejected and shortened (its residual
            // 1e3 × the largest |torque|): the fit never stands at such a value, and the report
            // says what ended it, the refused trial step only as a note.
            let met = lm.error.into_inner();
            return Err(match (report.termination, met) {
                (levenberg_marquardt::TerminationReason::User(_), Some(e)) => e,
                (t, met) => CalibrationError::NoConvergence(format!(
                    "{t:?} after {} evaluations{}",
                    report.number_of_evaluations,
                    met.map(|e| format!("; a trial step the model refused on the way was rejected ({e})")).unwrap_or_default()
                )),
            });
        }
        evaluations = report.number_of_evaluations;
        beta = found.beta;
        // μ_c and T_0 exactly at the optimum of the others.
        let linear = problem.linear_solve(&beta)?;
        beta.rows_mut(extras.len(), np - extras.len()).copy_from(&linear);
    }
    let (jac, model) = problem.jacobian(&beta, true)?;
    let r = &y - &model;
    if !(beta.iter().all(|b| b.is_finite()) && r.norm_squared().is_finite()) {
        return Err(CalibrationError::Unidentifiable {
            what: format!("the fit overflows (largest |torque| {:e} N.m): are the torque values in N.m?", y.amax()),
        });
    }
    let cl: Vec<usize> = points.iter().map(|p| p.cluster).collect();
    let Some(mut u) = analyse(&jac, &r, &cl, clusters.len(), options.resamples, options.seed) else {
        // A singular normal matrix at the optimum: a screened (default) key whose column
        // vanished or fell in with the others' on the way (a key the records hardly see drifts
        // along its flat valley to a bound of its range, where its column is 0) is dropped by
        // name and the fit repeated, as [`worst`] drops it after a regular fit; not every
        // default key with it.
        let which: Vec<usize> = (0..extras.len()).filter(|&k| screened.contains(&extras[k].key.name())).collect();
        let d = independence(&jac, &which);
        if let Some((i, &least)) = d.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1))
            && (least.is_nan() || least < MIN_INDEPENDENCE)
        {
            let e = &extras[which[i]];
            return Ok(Err((
                e.key.name(),
                format!(
                    "at the fit's end ({} = {:.6e} {}) its Jacobian column is nearly collinear with the other fitted quantities' or \
                     zero (the part they do not explain is {least:.2e} of it): the records hardly move the torque with it",
                    e.key.name(),
                    e.transform.inverse(beta[which[i]]),
                    e.key.unit()
                ),
            )));
        }
        return Err(CalibrationError::Unidentifiable {
            what: "the fitted quantities cannot be determined from these records (singular normal matrix)".into(),
        });
    };
    // Errors that repeat in every cycle (an encoder's rounding when the sampling is locked to
    // the motion, times J) cancel out of the spread from stroke to stroke: the strokes and the
    // phases of the cycle as two-way clusters see them (tests/coverage.rs).
    widen_two_way(&mut u, &jac, &r, &cl, &phases(&points, &filter));

    // Estimates in the parameters' own units.
    let params = problem.params_at(&beta);
    let keys = keys_of(&extras, fit_j, options.fit_offset);
    let transforms: Vec<(Transform, &'static str, f64)> = extras
        .iter()
        .map(|e| (e.transform, e.key.unit(), e.start))
        .chain(std::iter::once((Transform::Identity, "1", options.params.friction.boundary_friction_coefficient)))
        .chain(fit_j.then_some((Transform::Identity, "kg.m2", 0.0)))
        .chain(options.fit_offset.then_some((Transform::Identity, "N.m", 0.0)))
        .collect();
    let mut estimates: Vec<Estimate> =
        (0..np).map(|k| estimate(&keys[k], transforms[k], beta[k], &u, k)).collect();
    let offset = options.fit_offset.then(|| estimates.pop().expect("offset is last"));
    let inertia_estimate = fit_j.then(|| estimates.pop().expect("J follows mu_c"));
    let mu = estimates.pop().expect("mu_c follows the extras");
    estimates.insert(0, mu);
    let j_used = inertia_estimate.as_ref().map_or(j_given, |e| e.value);

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
    if let Some(e) = &inertia_estimate
        && e.value < 0.0
        && e.ci95.1 < 0.0
    {
        warnings.push(format!(
            "the fitted inertia {INERTIA} = {} kg.m2 is negative (95 % interval up to {} kg.m2): the recorded torque is not \
             T = J*alpha + friction + offset (is the torque's sign the direction of motion?)",
            e.value, e.ci95.1
        ));
    }
    let series = series(&prepared, &params, &beta, j_used, options.fit_offset, np)?;
    // Every used sample enters the fit (as a fitted point or in a window of one).
    let points_used = support.len();
    let inflation: Vec<f64> = filter.taps.iter().map(|v| 1.0 / v.iter().map(|x| x * x).sum::<f64>()).collect();
    let deviation = settle_deviation(&points, &r, options.exclusion.settle_time, &inflation);
    let which: Vec<usize> = (0..extras.len()).collect();
    let independence = independence(&jac, &which).into_iter().zip(&extras).map(|(d, e)| (e.key.name(), d)).collect();
    let calibration = Calibration {
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
        rms_residual: (rss / r.len() as f64).sqrt(),
        points_used,
        points_excluded: total - points_used,
        strokes: clusters.len(),
        dof: u.dof,
        quantile: u.quantile,
        half_widths: prepared.iter().map(|p| p.half_width).collect(),
        exclusions: prepared.into_iter().map(|p| p.exclusion).collect(),
        warnings,
        temperatures: Vec::new(),
        inertia: j_used,
        inertia_estimate,
        samples_read: total,
        block_length: 1,
        evaluations,
        settle_time: options.exclusion.settle_time,
        series,
    };
    Ok(Ok(Once { calibration, deviation, independence, dropped: dropped_before }))
}

/// The phase of each fitted point: its record, direction and place in its stroke in bins of
/// twice the matched filter's window (at least 8 samples).
fn phases(points: &[Point], filter: &Filter) -> Vec<usize> {
    let mut first: HashMap<usize, usize> = HashMap::new();
    for p in points {
        let e = first.entry(p.cluster).or_insert(p.row);
        *e = (*e).min(p.row);
    }
    let mut ids: HashMap<(usize, bool, usize), usize> = HashMap::new();
    points
        .iter()
        .map(|p| {
            let width = (2 * filter.taps[p.rec].len()).max(8);
            let key = (p.rec, p.omega > 0.0, (p.row - first[&p.cluster]) / width);
            let next = ids.len();
            *ids.entry(key).or_insert(next)
        })
        .collect()
}

/// Every sample of every record, measured and fitted.
fn series(prepared: &[Prepared], params: &Params, beta: &DVector<f64>, inertia: f64, offset: bool, np: usize) -> Result<Vec<Series>, CalibrationError> {
    let off = if offset { beta[np - 1] } else { 0.0 };
    let mu = params.friction.boundary_friction_coefficient;
    prepared
        .iter()
        .map(|p| {
            let pts: Vec<Operating> =
                (0..p.load.len()).map(|i| (p.load[i], p.omega[i], p.temperature.as_ref().map(|t| t[i]))).collect();
            let s = shapes(params, &pts, &|i| (p.name.clone(), i))?;
            let inertia_torque: Vec<f64> = p.alpha.iter().map(|a| inertia * a).collect();
            let fitted = s.iter().zip(&inertia_torque).map(|(s, ja)| ja + s.fluid + mu * s.boundary + off).collect();
            Ok(p.series(inertia_torque, fitted, p.stroke.iter().map(Option::is_some).collect()))
        })
        .collect()
}

/// The matched filter ([`crate::derivative::matched_taps`]) from the used samples (the support)
/// to the fitted points. With J fitted, or given and not 0, a used sample is a fitted point (a
/// centre) when the filter's whole window, ±k samples of its record's differentiator
/// half-width k, lies in the same stroke's used samples on a uniform time step; its target and
/// the model's other terms are the taps' mean over the window, its α the differentiator's.
/// Records whose α is not the angle's second derivative (a velocity column) or whose sampling
/// is uneven get the taps [1] (no filter; J is then as good as that record's α). With J given
/// as 0, every used sample is a centre with the taps [1].
struct Filter {
    /// (index in the support, record) of each fitted point.
    centres: Vec<(usize, usize)>,
    /// The taps of each record.
    taps: Vec<Vec<f64>>,
}

/// Relative deviation of a time step from the record's typical step still taken as uniform.
const UNIFORM_STEP: f64 = 1e-3;

impl Filter {
    fn new(prepared: &[Prepared], support: &[Point], matched: bool) -> Self {
        let mut uniform: Vec<Vec<bool>> = Vec::new();
        let taps: Vec<Vec<f64>> = prepared
            .iter()
            .map(|p| {
                let n = p.time.len();
                let dt = (p.time[n - 1] - p.time[0]) / (n - 1) as f64;
                let steps: Vec<bool> = p.time.windows(2).map(|w| ((w[1] - w[0]) / dt - 1.0).abs() <= UNIFORM_STEP).collect();
                let mostly = 2 * steps.iter().filter(|u| **u).count() >= steps.len();
                uniform.push(steps);
                if matched && p.alpha_from_angle && mostly { matched_taps(p.half_width) } else { vec![1.0] }
            })
            .collect();
        // Prefix counts of uneven steps per record, to test a window in O(1).
        let uneven: Vec<Vec<usize>> = uniform
            .iter()
            .map(|u| std::iter::once(0).chain(u.iter().scan(0, |c, ok| { *c += usize::from(!ok); Some(*c) })).collect())
            .collect();
        let mut centres = Vec::with_capacity(support.len());
        for (c, p) in support.iter().enumerate() {
            let h = taps[p.rec].len() / 2;
            if h == 0 {
                centres.push((c, p.rec));
                continue;
            }
            let (Some(lo), Some(hi)) = (c.checked_sub(h).map(|i| &support[i]), support.get(c + h)) else { continue };
            let inside = |q: &Point, row: usize| q.rec == p.rec && q.cluster == p.cluster && q.row == row;
            // Rows increase within the support, so matching ends mean the window is contiguous.
            let ok = p.row >= h && inside(lo, p.row - h) && inside(hi, p.row + h);
            if ok && uneven[p.rec][p.row + h] == uneven[p.rec][p.row - h] {
                centres.push((c, p.rec));
            }
        }
        Filter { centres, taps }
    }

    /// The taps' mean of `f` over the window of support index `c` (record `r`).
    fn apply(&self, r: usize, c: usize, f: impl Fn(usize) -> f64) -> f64 {
        let v = &self.taps[r];
        let h = v.len() / 2;
        v.iter().enumerate().map(|(m, w)| w * f(c + m - h)).sum()
    }
}

/// The model over the used samples, in the fit coordinates β = [extras…, μ_c, J?, T_0?].
#[derive(Clone, Copy)]
struct Problem<'a> {
    /// Load, speed and temperature at the support (every used sample).
    load_speed: &'a [Operating],
    /// From the support to the fitted points.
    filter: &'a Filter,
    /// α at the used samples when J is fitted.
    alpha: Option<&'a [f64]>,
    y: &'a DVector<f64>,
    base: Params,
    extras: &'a [Extra],
    offset: bool,
    ident: &'a (dyn Fn(usize) -> (String, usize) + Sync),
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

    /// The shapes at the fitted points (the matched filter's means of the support's shapes).
    fn shapes(&self, beta: &DVector<f64>) -> Result<Vec<Shape>, CalibrationError> {
        let mut p = self.params_at(beta);
        // μ_c does not enter the shape; keep the shape's evaluation valid if a step makes it < 0.
        p.friction.boundary_friction_coefficient = 0.0;
        let raw = shapes(&p, self.load_speed, self.ident)?;
        let f = self.filter;
        Ok(f.centres
            .iter()
            .map(|&(c, r)| Shape { fluid: f.apply(r, c, |i| raw[i].fluid), boundary: f.apply(r, c, |i| raw[i].boundary) })
            .collect())
    }

    fn model(&self, beta: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        let s = self.shapes(beta)?;
        Ok(self.model_of(&s, beta))
    }

    /// fluid + μ_c·boundary + J·α + T_0 at every used sample.
    fn model_of(&self, s: &[Shape], beta: &DVector<f64>) -> DVector<f64> {
        let (mu, j, off) = self.linear_of(beta);
        let alpha = |i: usize| self.alpha.map_or(0.0, |a| a[i]);
        DVector::from_iterator(s.len(), s.iter().enumerate().map(|(i, s)| s.fluid + mu * s.boundary + j * alpha(i) + off))
    }

    /// (μ_c, J, T_0) of β (J and T_0 are 0 when not fitted).
    fn linear_of(&self, beta: &DVector<f64>) -> (f64, f64, f64) {
        let m = self.extras.len();
        let j = usize::from(self.alpha.is_some());
        (beta[m], if j == 1 { beta[m + 1] } else { 0.0 }, if self.offset { beta[m + 1 + j] } else { 0.0 })
    }

    /// The linear columns at sample i: boundary shape, α (J fitted), 1 (offset fitted).
    fn linear_column(&self, s: &[Shape], i: usize, c: usize) -> f64 {
        match (c, self.alpha) {
            (0, _) => s[i].boundary,
            (1, Some(a)) => a[i],
            _ => 1.0,
        }
    }

    /// μ_c, J (when fitted) and T_0 (when fitted) by linear least squares at the extras of
    /// `beta` (QR of the shape columns).
    fn linear_solve(&self, beta: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        let s = self.shapes(beta)?;
        let cols = 1 + usize::from(self.alpha.is_some()) + usize::from(self.offset);
        let a = DMatrix::from_fn(s.len(), cols, |i, c| self.linear_column(&s, i, c));
        let rhs = DVector::from_iterator(s.len(), s.iter().zip(self.y.iter()).map(|(s, y)| y - s.fluid));
        let norms: Vec<f64> = (0..cols).map(|k| a.column(k).norm()).collect();
        let qr = a.qr();
        let r = qr.r();
        // Each column's R diagonal against that column's own norm: the part of it the columns
        // before it do not explain.
        let collinear = (0..cols).any(|k| r[(k, k)].abs() <= 1e-12 * norms[k].max(f64::MIN_POSITIVE));
        if collinear {
            let what = if self.alpha.is_some() {
                "the boundary shape, the angular acceleration (for the inertia J) and the offset are collinear in these records: \
                 give the inertia (--inertia) or record both directions of motion"
            } else {
                "the boundary shape and the offset are collinear in these records"
            };
            return Err(CalibrationError::Unidentifiable { what: what.into() });
        }
        let qty = qr.q().transpose() * rhs;
        r.solve_upper_triangular(&qty)
            .ok_or_else(|| CalibrationError::Unidentifiable { what: "singular least-squares problem for mu_c".into() })
    }

    /// Jacobian of the model with respect to β (central differences for the extras when
    /// `central`, else forward ones; exact for μ_c, J and T_0), and the model. LM's steps take
    /// the forward one (half the model evaluations), the intervals the central one.
    fn jacobian(&self, beta: &DVector<f64>, central: bool) -> Result<(DMatrix<f64>, DVector<f64>), CalibrationError> {
        let s = self.shapes(beta)?;
        let n = s.len();
        let model = self.model_of(&s, beta);
        let m = self.extras.len();
        let mut j = DMatrix::zeros(n, beta.len());
        for k in 0..m {
            let h = 1e-5 * beta[k].abs().max(1.0);
            let (mut bp, mut bm) = (beta.clone(), beta.clone());
            bp[k] += h;
            bm[k] -= h;
            let d = if central { (self.model(&bp)? - self.model(&bm)?) / (2.0 * h) } else { (self.model(&bp)? - &model) / h };
            j.set_column(k, &d);
        }
        for c in 0..beta.len() - m {
            for i in 0..n {
                j[(i, m + c)] = self.linear_column(&s, i, c);
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
    /// Residual given to a trial step outside the model's domain (1e3 × the largest |torque|,
    /// as the rig fit's).
    outside: f64,
}

impl Residuals for LmProblem<'_, '_> {
    fn residuals_at(&self, beta: &DVector<f64>) -> Option<DVector<f64>> {
        *self.evals.borrow_mut() += 1;
        match self.p.model(beta) {
            Ok(m) => Some(m - self.p.y),
            Err(e) => {
                // A trial step outside the model's domain (a wild step in ln or logit
                // coordinates: exp overflow, a film past the clearance) is a rejected step, not
                // a failed fit: a residual far above any the model gives makes LM shorten the
                // step. The first such error is kept, reported if the fit still fails.
                self.error.borrow_mut().get_or_insert(e);
                Some(DVector::from_element(self.p.y.len(), self.outside))
            }
        }
    }
    fn jacobian_at(&self, beta: &DVector<f64>) -> Option<DMatrix<f64>> {
        match self.p.jacobian(beta, false) {
            Ok((j, _)) => Some(j),
            Err(e) => {
                // This ends LM (an accepted point's neighbourhood): its error is the one to report.
                *self.error.borrow_mut() = Some(e);
                None
            }
        }
    }
}
