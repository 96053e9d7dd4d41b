//! The fit through the rig simulation ([`crate::Model::Rig`], `--model rig`).
//!
//! The quasi-static model leaves out the reversals; the rig simulation (`pinjoint::rig`, what
//! `pinjoint cycle` runs) describes them: the stick, the breakaway peak k_b·μ_c·R·P, the servo
//! lag τ_s and the ringing after breakaway, and the stick-slip of slow strokes. Here each
//! residual evaluation simulates every record: the rig, started at rest on the command at the
//! record's first sample, driven by the sine command estimated from the record's angle
//! ([`crate::command`]) and the record's load (its load column, interpolated linearly), sampled
//! at the record's times; the residual is the recorded torque minus the simulated actuator
//! torque T_a (plus the offset T_0). J·α is part of the simulation, not subtracted.
//!
//! Fitted: μ_c (no longer linear: the dynamics depend on it), the `--fit` keys (model keys and
//! the rig's physical keys: `rig.breakaway_factor`, `rig.servo_time_constant`, `rig.inertia`,
//! gains, torque limit, regularisation speed; in ln/logit coordinates from the tables' ranges)
//! and T_0, jointly, by Levenberg–Marquardt with forward-difference Jacobians (central ones for
//! the intervals). μ_c starts from the quasi-static fit.
//!
//! Exclusion differs from the quasi-static fit: the low-speed and settling windows are *used*
//! (they are what the rig model describes and where k_b and τ_s show); left out is the start-up,
//! every sample up to the record's first reversal plus the settling time (the simulation starts
//! at rest, a record taken from a running rig does not). Strokes (between reversals) are the
//! clusters of the intervals, as in the quasi-static fit.
//!
//! Bounded work: at most [`Options::max_simulations`] simulations of the record set (the command
//! estimate, every LM evaluation, each Jacobian column and the final Jacobian count), at most
//! [`MAX_RIG_SAMPLES`] samples and [`MAX_RIG_DURATION`] of record time; beyond them the fit is
//! refused, saying which limit and why.

use super::command::{fit_sine, fit_sine_near, Command, COMMAND_TOLERANCE};
use super::coords::{resolve, Extra, Transform};
use super::error::CalibrationError;
use super::exclusion::{Reason, Window};
use super::fit::{check_options, estimate, keys_of, warnings};
use super::prepare::prepare;
use super::record::Record;
use super::result::{Calibration, Estimate, Series};
use super::uncertainty::analyse;
use super::{Model, Options};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};
use pinjoint::rig::{FnExcitation, Inputs, RigConfig, RigSim, Sample};
use std::cell::{Cell, RefCell};
use std::sync::Arc;

/// Default [`Options::max_simulations`].
pub const DEFAULT_MAX_SIMULATIONS: usize = 100;
/// Most samples over all records the rig fit takes.
pub const MAX_RIG_SAMPLES: usize = 200_000;
/// Most record time over all records the rig fit takes (s).
pub const MAX_RIG_DURATION: f64 = 3600.0;
/// Most refinements of the command estimate (each one simulation of the record set).
pub const MAX_COMMAND_ITERATIONS: usize = 4;
/// Finite-difference step in the fit coordinates (μ_c: absolute; ln/logit: relative).
const STEP: f64 = 1e-4;
/// Used samples needed per fitted quantity (as the quasi-static fit).
const MIN_POINTS_PER_PARAMETER: usize = super::fit::MIN_POINTS_PER_PARAMETER;

/// One record as the rig fit sees it.
struct RigRecord {
    name: String,
    /// Time since the record's first sample (s).
    tau: Arc<Vec<f64>>,
    /// Load at each sample (N).
    load: Arc<Vec<f64>>,
    command: Command,
    /// Recorded angle (rad).
    angle: Vec<f64>,
    /// Fitted samples (after the start-up).
    used: Vec<bool>,
}

/// Linear interpolation of `v` over `t` at `x`, constant beyond the ends.
fn interpolate(t: &[f64], v: &[f64], x: f64) -> f64 {
    let k = t.partition_point(|&s| s <= x);
    if k == 0 {
        return v[0];
    }
    if k == t.len() {
        return v[k - 1];
    }
    let w = (x - t[k - 1]) / (t[k] - t[k - 1]);
    v[k - 1] + w * (v[k] - v[k - 1])
}

/// Simulate one record's stroke with `cfg`, sampled at the record's times.
fn simulate(cfg: &RigConfig, rec: &RigRecord) -> Result<Vec<Sample>, CalibrationError> {
    let cmd = rec.command;
    let (tau, load) = (rec.tau.clone(), rec.load.clone());
    let exc = FnExcitation { load: move |t: f64| interpolate(&tau, &load, t), command: move |t: f64| cmd.at(t), jumps: Vec::new() };
    let err = |source| CalibrationError::Simulation { record: rec.name.clone(), source };
    let mut sim = RigSim::with_excitation(cfg, Arc::new(exc)).map_err(err)?;
    let hold = Inputs::default();
    rec.tau
        .iter()
        .map(|&t| {
            sim.advance_to(t, &hold)?;
            sim.sample()
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(err)
}

/// The model over the used samples in the fit coordinates β = [extras…, μ_c, T_0?].
struct RigProblem<'a> {
    records: &'a [RigRecord],
    base: RigConfig,
    extras: &'a [Extra],
    offset: bool,
    y: DVector<f64>,
    /// Simulations of the record set run so far, and the most allowed now.
    sims: Cell<usize>,
    limit: Cell<usize>,
    total_limit: usize,
}

impl RigProblem<'_> {
    fn config_at(&self, beta: &DVector<f64>) -> RigConfig {
        let mut c = self.base;
        for (k, e) in self.extras.iter().enumerate() {
            e.key.set(&mut c.model, &mut c.rig, e.transform.inverse(beta[k]));
        }
        c.model.friction.boundary_friction_coefficient = beta[self.extras.len()];
        c
    }

    fn offset_of(&self, beta: &DVector<f64>) -> f64 {
        if self.offset { beta[self.extras.len() + 1] } else { 0.0 }
    }

    /// Every record simulated at β (counts one simulation of the record set).
    fn run(&self, beta: &DVector<f64>) -> Result<Vec<Vec<Sample>>, CalibrationError> {
        if self.sims.get() >= self.limit.get() {
            let duration: f64 = self.records.iter().map(|r| r.tau.last().copied().unwrap_or(0.0)).sum();
            return Err(CalibrationError::Budget(format!(
                "the rig fit stopped after {} simulations of the {} records ({duration} s of rig time each time), the limit \
                 (max_simulations = {}, --max-simulations): start closer to the solution (--params), fit fewer keys, \
                 use shorter records or allow more",
                self.sims.get(),
                self.records.len(),
                self.total_limit
            )));
        }
        self.sims.set(self.sims.get() + 1);
        let cfg = self.config_at(beta);
        self.records.iter().map(|r| simulate(&cfg, r)).collect()
    }

    /// Simulated torque (+ T_0) at the used samples.
    fn stack(&self, runs: &[Vec<Sample>], beta: &DVector<f64>) -> DVector<f64> {
        let off = self.offset_of(beta);
        let v: Vec<f64> = self
            .records
            .iter()
            .zip(runs)
            .flat_map(|(r, s)| s.iter().zip(&r.used).filter(|(_, u)| **u).map(|(s, _)| s.torque + off))
            .collect();
        DVector::from_vec(v)
    }

    fn model(&self, beta: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        Ok(self.stack(&self.run(beta)?, beta))
    }

    /// Jacobian at β with the model `base` there: forward differences (central when
    /// `central`; one-sided the other way where a step leaves the parameters' domain), exact
    /// for T_0.
    fn jacobian(&self, beta: &DVector<f64>, base: &DVector<f64>, central: bool) -> Result<DMatrix<f64>, CalibrationError> {
        let m = self.extras.len();
        let mut j = DMatrix::zeros(base.len(), beta.len());
        for k in 0..=m {
            let h = STEP * if k == m { 1.0 } else { beta[k].abs().max(1.0) };
            let shifted = |d: f64| {
                let mut b = beta.clone();
                b[k] += d;
                self.model(&b)
            };
            let col = match (shifted(h), central) {
                (Ok(p), true) => match shifted(-h) {
                    Ok(q) => (p - q) / (2.0 * h),
                    Err(CalibrationError::Budget(s)) => return Err(CalibrationError::Budget(s)),
                    Err(_) => (p - base) / h,
                },
                (Ok(p), false) => (p - base) / h,
                (Err(CalibrationError::Budget(s)), _) => return Err(CalibrationError::Budget(s)),
                (Err(_), _) => (base - shifted(-h)?) / h,
            };
            j.set_column(k, &col);
        }
        if self.offset {
            j.column_mut(m + 1).fill(1.0);
        }
        Ok(j)
    }
}

/// The `levenberg-marquardt` crate's view: residuals model − y.
struct Lm<'a, 'b> {
    p: &'a RigProblem<'b>,
    beta: DVector<f64>,
    /// The last model evaluated and its β (the Jacobian's base point).
    last: RefCell<Option<(DVector<f64>, DVector<f64>)>>,
    error: RefCell<Option<CalibrationError>>,
    /// Residual given to a step outside the rig's domain (LM then shortens the step).
    outside: f64,
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Lm<'_, '_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.beta.copy_from(x);
    }
    fn params(&self) -> DVector<f64> {
        self.beta.clone()
    }
    fn residuals(&self) -> Option<DVector<f64>> {
        match self.p.model(&self.beta) {
            Ok(m) => {
                let r = &m - &self.p.y;
                *self.last.borrow_mut() = Some((self.beta.clone(), m));
                Some(r)
            }
            Err(e @ CalibrationError::Budget(_)) => {
                *self.error.borrow_mut() = Some(e);
                None
            }
            Err(e) => {
                self.error.borrow_mut().get_or_insert(e);
                Some(DVector::from_element(self.p.y.len(), self.outside))
            }
        }
    }
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        let cached = self.last.borrow().as_ref().filter(|(b, _)| *b == self.beta).map(|(_, m)| m.clone());
        let base = match cached {
            Some(m) => m,
            None => match self.p.model(&self.beta) {
                Ok(m) => m,
                Err(e) => {
                    *self.error.borrow_mut() = Some(e);
                    return None;
                }
            },
        };
        match self.p.jacobian(&self.beta, &base, false) {
            Ok(j) => Some(j),
            Err(e) => {
                *self.error.borrow_mut() = Some(e);
                None
            }
        }
    }
}

/// Fit `records` through the rig simulation (see the module documentation).
pub fn calibrate_rig(records: &[Record], options: &Options) -> Result<Calibration, CalibrationError> {
    if records.is_empty() {
        return Err(CalibrationError::NoRecords);
    }
    options.params.validate()?;
    check_options(options)?;
    let mut base = RigConfig { model: options.params, rig: options.rig };
    base.rig.inertia = options.inertia;
    base.validate()?;
    let extras = resolve(&options.fit, &options.params, &base.rig, true)?;
    let prepared = records.iter().map(|r| prepare(r, &options.exclusion, options.half_width)).collect::<Result<Vec<_>, _>>()?;
    let samples: usize = records.iter().map(Record::len).sum();
    let duration: f64 = records.iter().map(|r| r.time[r.len() - 1] - r.time[0]).sum();
    if samples > MAX_RIG_SAMPLES || duration > MAX_RIG_DURATION {
        return Err(CalibrationError::Budget(format!(
            "the rig fit takes at most {MAX_RIG_SAMPLES} samples and {MAX_RIG_DURATION} s of records (each evaluation simulates \
             them all); these records have {samples} samples over {duration} s: fit fewer or shorter records"
        )));
    }
    let np = 1 + usize::from(options.fit_offset) + extras.len();
    let fd = np - usize::from(options.fit_offset);
    // Command estimate, one LM iteration and the final central Jacobian, at the least.
    let least = MAX_COMMAND_ITERATIONS + 2 + fd + 2 * fd;
    if options.max_simulations < least {
        return Err(CalibrationError::Budget(format!(
            "max_simulations = {} is too small: the rig fit of {np} quantities needs at least {least} simulations of the record set",
            options.max_simulations
        )));
    }

    // Records: the command from the angle, the start-up left out, strokes as clusters.
    let mut recs = Vec::new();
    let mut clusters = Vec::new();
    let mut exclusions = Vec::new();
    let mut ncl = 0;
    for (r, p) in records.iter().zip(&prepared) {
        let angle = r.angle.as_ref().ok_or_else(|| CalibrationError::Unidentifiable {
            what: format!("record {}: the rig fit needs the angle column (rad): the command that drove the rig is estimated from it", r.name),
        })?;
        let t0 = r.time[0];
        let tau: Vec<f64> = r.time.iter().map(|t| t - t0).collect();
        let span = tau[tau.len() - 1];
        let command = fit_sine(&tau, angle).ok_or_else(|| CalibrationError::TooShort {
            record: r.name.clone(),
            samples: r.len(),
            needed: r.len() + 1,
            why: "the rig fit needs the angle over at least one full cycle (three crossings of its mid-range) to estimate the command",
        })?;
        let first = p.exclusion.reversals.first().copied().filter(|_| p.exclusion.reversals.len() >= 2).ok_or_else(|| {
            CalibrationError::Unidentifiable {
                what: format!(
                    "record {}: {span} s holds fewer than two reversals: the rig fit leaves out the start-up (up to the first reversal plus \
                     the settling time) and needs a whole stroke after it",
                    r.name
                ),
            }
        })?;
        let start_end = first + options.exclusion.settle_time;
        let used: Vec<bool> = r.time.iter().map(|&t| t > start_end).collect();
        let n_start = used.iter().filter(|u| !**u).count();
        for &t in r.time.iter().filter(|&&t| t > start_end) {
            clusters.push(ncl + p.exclusion.reversals.iter().filter(|&&x| x < t).count() - 1);
        }
        ncl += p.exclusion.reversals.len();
        let mut x = p.exclusion.clone();
        x.windows = vec![Window { start: r.time[0], end: r.time[n_start.max(1) - 1], reason: Reason::StartUp, samples: n_start }];
        (x.low_speed, x.settling, x.start_up, x.used) = (0, 0, n_start, r.len() - n_start);
        exclusions.push(x);
        recs.push(RigRecord { name: r.name.clone(), tau: Arc::new(tau), load: Arc::new(r.load.clone()), command, angle: angle.clone(), used });
    }
    let y = DVector::from_iterator(
        clusters.len(),
        records.iter().zip(&recs).flat_map(|(r, x)| r.torque.iter().zip(&x.used).filter(|(_, u)| **u).map(|(t, _)| *t)),
    );
    let needed = (MIN_POINTS_PER_PARAMETER * np).max(20);
    if y.len() < needed {
        return Err(CalibrationError::Unidentifiable {
            what: format!("only {} samples remain after the start-up; at least {needed} are needed for {np} fitted quantities", y.len()),
        });
    }

    // Start: μ_c from the quasi-static fit (the given one if that fails), the keys at theirs.
    let core = Options { model: Model::Core, fit: Vec::new(), resamples: 0, ..options.clone() };
    let mu0 = super::fit::calibrate(records, &core).map_or(options.params.friction.boundary_friction_coefficient, |c| c.estimates[0].value);
    let mut beta = DVector::zeros(np);
    for (k, e) in extras.iter().enumerate() {
        beta[k] = e.transform.forward(e.start).expect("checked by resolve");
    }
    beta[extras.len()] = mu0;
    let mut start = base;
    for e in &extras {
        e.key.set(&mut start.model, &mut start.rig, e.start);
    }
    start.model.friction.boundary_friction_coefficient = mu0;
    let refinements = refine_commands(&mut recs, &start)?;
    let commands: Vec<Command> = recs.iter().map(|r| r.command).collect();
    let problem = RigProblem {
        records: &recs,
        base,
        extras: &extras,
        offset: options.fit_offset,
        y,
        sims: Cell::new(refinements),
        limit: Cell::new(options.max_simulations - 2 * fd),
        total_limit: options.max_simulations,
    };
    if options.fit_offset {
        let m = problem.model(&beta)?;
        beta[np - 1] = (&problem.y - m).mean();
    }

    let scale = problem.y.amax().max(1.0);
    let lm = Lm { p: &problem, beta: beta.clone(), last: RefCell::new(None), error: RefCell::new(None), outside: 1e3 * scale };
    let (lm, report) = LevenbergMarquardt::new().with_xtol(1e-8).with_patience(options.max_simulations).minimize(lm);
    let evaluations = report.number_of_evaluations;
    if !report.termination.was_successful() {
        let stored = lm.error.into_inner();
        return Err(match stored {
            Some(e @ CalibrationError::Budget(_)) => e,
            Some(e) if matches!(report.termination, levenberg_marquardt::TerminationReason::User(_)) => e,
            _ => CalibrationError::NoConvergence(format!("{:?} after {evaluations} evaluations", report.termination)),
        });
    }
    beta = lm.beta;
    problem.limit.set(options.max_simulations);
    let runs = problem.run(&beta)?;
    let model = problem.stack(&runs, &beta);
    let jac = problem.jacobian(&beta, &model, true)?;
    let r = &problem.y - &model;
    let u = analyse(&jac, &r, &clusters, ncl, options.resamples, options.seed).ok_or_else(|| CalibrationError::Unidentifiable {
        what: "the fitted quantities cannot be determined from these records (singular normal matrix)".into(),
    })?;

    let cfg = problem.config_at(&beta);
    let keys = keys_of(&extras, options.fit_offset);
    let transforms: Vec<(Transform, &'static str, f64)> = extras
        .iter()
        .map(|e| (e.transform, e.key.unit(), e.start))
        .chain(std::iter::once((Transform::Identity, "1", mu0)))
        .chain(options.fit_offset.then_some((Transform::Identity, "N.m", 0.0)))
        .collect();
    let mut estimates: Vec<Estimate> = (0..np).map(|k| estimate(&keys[k], transforms[k], beta[k], &u, k)).collect();
    let offset = options.fit_offset.then(|| estimates.pop().expect("offset is last"));
    let mu = estimates.pop().expect("mu_c follows the extras");
    estimates.insert(0, mu);
    let strokes = clusters.iter().collect::<std::collections::HashSet<_>>().len();
    let mut warn = warnings(&extras, &jac, &model, &u, &estimates, &keys, strokes, options);
    for e in &extras {
        let v = e.key.get(&cfg.model, &cfg.rig);
        if e.start != e.key.get(&options.params, &base.rig) {
            warn.push(format!(
                "{} started at {}{} (its given start value lies on the bound of its range {})",
                e.key.name(),
                e.start,
                unit_suffix(e.key.unit()),
                e.key.range().describe()
            ));
        }
        if let Transform::Logit(lo, hi) = e.transform
            && ((v - lo) < 1e-6 * (hi - lo) || (hi - v) < 1e-6 * (hi - lo))
        {
            warn.push(format!("{} = {v}{} is at the bound of its range: the records ask for a value outside it", e.key.name(), unit_suffix(e.key.unit())));
        }
    }
    let mean_abs = problem.y.iter().map(|v| v.abs()).sum::<f64>() / problem.y.len() as f64;
    let rms = (r.norm_squared() / r.len() as f64).sqrt();
    if rms > 0.1 * mean_abs {
        warn.push(format!(
            "the fit is poor: rms residual {rms:.4} N.m is {:.0} % of the mean |torque| {mean_abs:.4} N.m; check each record's load (N), units \
             and the rig's parameters (--params [rig])",
            100.0 * rms / mean_abs
        ));
    }
    let off = problem.offset_of(&beta);
    let series = prepared
        .iter()
        .zip(&runs)
        .zip(&recs)
        .map(|((p, s), x)| Series {
            record: p.name.clone(),
            time: p.time.clone(),
            angle: p.angle.clone(),
            angular_velocity: p.omega.clone(),
            load: p.load.clone(),
            measured: p.torque.clone(),
            inertia_torque: s.iter().map(|s| s.torque + s.friction_torque).collect(),
            fitted: s.iter().map(|s| s.torque + off).collect(),
            used: x.used.clone(),
        })
        .collect();
    let points_used = r.len();
    Ok(Calibration {
        params: cfg.model,
        rig: Some(cfg.rig),
        model: Model::Rig,
        estimates,
        offset,
        correlation_keys: keys,
        correlation: u.correlation.clone(),
        condition: u.condition,
        rms_residual: rms,
        points_used,
        points_excluded: samples - points_used,
        strokes,
        dof: u.dof,
        quantile: u.quantile,
        half_widths: prepared.iter().map(|p| p.half_width).collect(),
        exclusions,
        warnings: warn,
        inertia: cfg.rig.inertia,
        settle_time: options.exclusion.settle_time,
        evaluations,
        simulations: problem.sims.get(),
        commands,
        series,
    })
}

/// Step 2 of [`crate::command`]: move each command by the difference between the recorded and
/// the simulated angle's sine (over the used samples), at the start parameters `cfg`, until no
/// command moves by more than [`COMMAND_TOLERANCE`] (at most [`MAX_COMMAND_ITERATIONS`]
/// simulations of the record set). Returns the simulations run.
fn refine_commands(recs: &mut [RigRecord], cfg: &RigConfig) -> Result<usize, CalibrationError> {
    let singular = |name: &str| CalibrationError::Unidentifiable { what: format!("record {name}: no sine fits the angle after the start-up") };
    let sine = |r: &RigRecord, angle: &[f64]| fit_sine_near(&r.tau, angle, &r.used, r.command.frequency, 0.01).ok_or_else(|| singular(&r.name));
    let targets: Vec<Command> = recs.iter().map(|r| sine(r, &r.angle)).collect::<Result<_, _>>()?;
    for k in 1..=MAX_COMMAND_ITERATIONS {
        let mut moved = 0.0f64;
        for (r, t) in recs.iter_mut().zip(&targets) {
            let angle: Vec<f64> = simulate(cfg, r)?.iter().map(|s| s.angle).collect();
            let s = sine(r, &angle)?;
            let span = r.tau.last().copied().unwrap_or(0.0);
            let d = [t.offset - s.offset, t.sin - s.sin, t.cos - s.cos, t.frequency - s.frequency];
            r.command.offset += d[0];
            r.command.sin += d[1];
            r.command.cos += d[2];
            r.command.frequency += d[3];
            moved = [d[0], d[1], d[2], d[3] * span].iter().fold(moved, |m, x| m.max(x.abs()));
        }
        if moved < COMMAND_TOLERANCE {
            return Ok(k);
        }
    }
    Ok(MAX_COMMAND_ITERATIONS)
}

/// " unit", or nothing for a dimensionless quantity.
fn unit_suffix(unit: &str) -> String {
    if unit == "1" { String::new() } else { format!(" {unit}") }
}
