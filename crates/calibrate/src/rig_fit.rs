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
//! Only the angle is used (a recorded angular velocity is ignored when there is an angle).
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

use super::across::plan;
use super::command::{fit_sine, fit_sine_near, Command, COMMAND_TOLERANCE};
use super::coords::{resolve, Extra, Transform};
use super::error::CalibrationError;
use super::exclusion::{Reason, Window};
use super::estimates::{check_options, estimate, keys_of, warnings, INERTIA, MIN_POINTS_PER_PARAMETER};
use super::fit::calibrate_core_with;
use super::lm::{Adapter, Residuals};
use super::options::{Model, Options};
use super::prepare::prepare;
use super::record::Record;
use super::result::{Calibration, Estimate};
use super::uncertainty::analyse;
use levenberg_marquardt::LevenbergMarquardt;
use nalgebra::{DMatrix, DVector};
use pinjoint::rig::{FnExcitation, Inputs, RigConfig, RigSim, Sample};
use rayon::prelude::*;
use std::cell::RefCell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

pub use super::options::DEFAULT_MAX_SIMULATIONS;
/// Most samples over all records the rig fit takes.
pub const MAX_RIG_SAMPLES: usize = 200_000;
/// Most record time over all records the rig fit takes (s).
pub const MAX_RIG_DURATION: f64 = 3600.0;
/// Most refinements of the command estimate (each one simulation of the record set).
pub const MAX_COMMAND_ITERATIONS: usize = 4;
/// Most alternations of the command estimate and the fit.
pub const MAX_ROUNDS: usize = 4;
/// Finite-difference step in the fit coordinates (μ_c: absolute; ln/logit: relative).
const STEP: f64 = 1e-4;

/// One record as the rig fit sees it.
#[derive(Clone)]
struct RigRecord {
    name: String,
    /// Time since the record's first sample (s).
    tau: Arc<Vec<f64>>,
    /// Load at each sample (N).
    load: Arc<Vec<f64>>,
    /// Lubricant temperature at each sample (K), when the record gives it.
    temperature: Option<Arc<Vec<f64>>>,
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

/// Simulate one record's stroke with `cfg`, sampled at the record's times. With a temperature
/// column the joint runs at the sample's temperature over the step up to it
/// ([`RigSim::set_temperature`] where it changes: never for a constant one).
fn simulate(cfg: &RigConfig, rec: &RigRecord) -> Result<Vec<Sample>, CalibrationError> {
    let cmd = rec.command;
    let (tau, load) = (rec.tau.clone(), rec.load.clone());
    let exc = FnExcitation { load: move |t: f64| interpolate(&tau, &load, t), command: move |t: f64| cmd.at(t), jumps: Vec::new() };
    let err = |source| CalibrationError::Simulation { record: rec.name.clone(), source };
    let mut cfg = *cfg;
    if let Some(t) = &rec.temperature {
        cfg.model.lubricant.temperature = t[0];
    }
    let mut sim = RigSim::with_excitation(&cfg, Arc::new(exc)).map_err(err)?;
    let hold = Inputs::default();
    rec.tau
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            if let Some(temp) = &rec.temperature {
                sim.set_temperature(temp[i])?;
            }
            sim.advance_to(t, &hold)?;
            sim.sample()
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(err)
}

/// The model over the used samples in the fit coordinates
/// β = [extras…, μ_c, T_0?, (c, a, b, f) of each record's command].
///
/// The residuals are the torque and, for the commands, the angle: K_p·(θ_sim − θ_rec) in N·m
/// (the torque the position loop makes of that angle error), at the used samples.
struct RigProblem<'a> {
    records: &'a [RigRecord],
    base: RigConfig,
    extras: &'a [Extra],
    offset: bool,
    /// [recorded torque; K_p·recorded angle] at the used samples.
    y: DVector<f64>,
    /// Rows of torque (the angle rows follow).
    torque_rows: usize,
    /// Record simulations run so far, and the most allowed now.
    sims: AtomicUsize,
    limit: AtomicUsize,
    total_limit: usize,
}

/// Index in β of record `j`'s command, given the quantities before the commands.
fn command_index(quantities: usize, j: usize) -> usize {
    quantities + 4 * j
}

impl RigProblem<'_> {
    /// Fitted quantities before the commands: extras, μ_c, T_0?.
    fn quantities(&self) -> usize {
        self.extras.len() + 1 + usize::from(self.offset)
    }

    fn config_at(&self, beta: &DVector<f64>) -> RigConfig {
        let mut c = self.base;
        for (k, e) in self.extras.iter().enumerate() {
            e.key.set(&mut c.model, &mut c.rig, e.transform.inverse(beta[k]));
        }
        c.model.friction.boundary_friction_coefficient = beta[self.extras.len()];
        c
    }

    fn command_at(&self, beta: &DVector<f64>, j: usize) -> Command {
        let i = command_index(self.quantities(), j);
        Command { offset: beta[i], sin: beta[i + 1], cos: beta[i + 2], frequency: beta[i + 3] }
    }

    fn offset_of(&self, beta: &DVector<f64>) -> f64 {
        if self.offset { beta[self.extras.len() + 1] } else { 0.0 }
    }

    /// Count `n` record simulations against the budget.
    fn spend(&self, n: usize) -> Result<(), CalibrationError> {
        let done = self.sims.fetch_add(n, Ordering::SeqCst);
        if done + n > self.limit.load(Ordering::SeqCst) {
            let records = self.records.len();
            let duration: f64 = self.records.iter().map(|r| r.tau.last().copied().unwrap_or(0.0)).sum();
            return Err(CalibrationError::Budget(format!(
                "the rig fit stopped after {} simulations of the {records} records ({duration} s of rig time each time), the limit \
                 (max_simulations = {}, --max-simulations): start closer to the solution (--params), fit fewer keys, \
                 use shorter records or allow more",
                done.div_ceil(records),
                self.total_limit
            )));
        }
        Ok(())
    }

    /// Every record (or only record `only`) simulated at β.
    fn run(&self, beta: &DVector<f64>, only: Option<usize>) -> Result<Vec<Vec<Sample>>, CalibrationError> {
        let cfg = self.config_at(beta);
        let which: Vec<usize> = only.map_or_else(|| (0..self.records.len()).collect(), |j| vec![j]);
        self.spend(which.len())?;
        which
            .par_iter()
            .map(|&j| simulate(&cfg, &RigRecord { command: self.command_at(beta, j), ..self.records[j].clone() }))
            .collect()
    }

    /// [simulated torque + T_0; K_p·simulated angle] at the used samples.
    fn stack(&self, runs: &[Vec<Sample>], beta: &DVector<f64>) -> DVector<f64> {
        let off = self.offset_of(beta);
        let kp = self.base.rig.position_gain;
        let used = || self.records.iter().zip(runs).flat_map(|(r, s)| s.iter().zip(&r.used).filter(|(_, u)| **u).map(|(s, _)| s));
        let v: Vec<f64> = used().map(|s| s.torque + off).chain(used().map(|s| kp * s.angle)).collect();
        DVector::from_vec(v)
    }

    /// The column of β's coordinate `k` at β, with `base` the runs at β: forward differences
    /// (central when `central`; one-sided the other way where a step leaves the parameters'
    /// domain); a command's coordinate simulates only its record.
    fn column(&self, beta: &DVector<f64>, base: &[Vec<Sample>], k: usize, central: bool) -> Result<DVector<f64>, CalibrationError> {
        let (m, q) = (self.extras.len(), self.quantities());
        let mut col = DVector::zeros(self.y.len());
        if self.offset && k == m + 1 {
            col.rows_mut(0, self.torque_rows).fill(1.0);
            return Ok(col);
        }
        let only = (k >= q).then(|| (k - q) / 4);
        let h = if k == m {
            STEP
        } else if k < m {
            STEP * beta[k].abs().max(1.0)
        } else if (k - q) % 4 == 3 {
            1e-7 * beta[k]
        } else {
            1e-6
        };
        let base_model = self.stack(base, beta);
        let shifted = |d: f64| -> Result<DVector<f64>, CalibrationError> {
            let mut b = beta.clone();
            b[k] += d;
            let runs = self.run(&b, only)?;
            let all: Vec<Vec<Sample>> = match only {
                Some(j) => base.iter().enumerate().map(|(i, s)| if i == j { runs[0].clone() } else { s.clone() }).collect(),
                None => runs,
            };
            Ok(self.stack(&all, &b))
        };
        let d = match (shifted(h), central) {
            (Ok(p), true) => match shifted(-h) {
                Ok(q) => (p - q) / (2.0 * h),
                Err(e @ CalibrationError::Budget(_)) => return Err(e),
                Err(_) => (p - &base_model) / h,
            },
            (Ok(p), false) => (p - &base_model) / h,
            (Err(e @ CalibrationError::Budget(_)), _) => return Err(e),
            (Err(_), _) => (&base_model - shifted(-h)?) / h,
        };
        col.copy_from(&d);
        Ok(col)
    }

    /// The Jacobian at β (the columns in parallel).
    fn jacobian(&self, beta: &DVector<f64>, base: &[Vec<Sample>], central: bool) -> Result<DMatrix<f64>, CalibrationError> {
        let cols = (0..beta.len()).into_par_iter().map(|k| self.column(beta, base, k, central)).collect::<Result<Vec<_>, _>>()?;
        Ok(DMatrix::from_columns(&cols))
    }
}

/// Samples of every record's simulation.
type Runs = Vec<Vec<Sample>>;

/// The rig problem for LM ([`Adapter`]): residuals model − y.
struct Lm<'a, 'b> {
    p: &'a RigProblem<'b>,
    /// The last runs evaluated and their β (the Jacobian's base point).
    last: RefCell<Option<(DVector<f64>, Runs)>>,
    error: RefCell<Option<CalibrationError>>,
    /// Residual given to a step outside the rig's domain (LM then shortens the step).
    outside: f64,
}

impl Residuals for Lm<'_, '_> {
    fn residuals_at(&self, beta: &DVector<f64>) -> Option<DVector<f64>> {
        match self.p.run(beta, None) {
            Ok(runs) => {
                let r = self.p.stack(&runs, beta) - &self.p.y;
                *self.last.borrow_mut() = Some((beta.clone(), runs));
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
    fn jacobian_at(&self, beta: &DVector<f64>) -> Option<DMatrix<f64>> {
        let cached = self.last.borrow().as_ref().filter(|(b, _)| b == beta).map(|(_, r)| r.clone());
        let base = match cached {
            Some(r) => r,
            None => match self.p.run(beta, None) {
                Ok(r) => r,
                Err(e) => {
                    *self.error.borrow_mut() = Some(e);
                    return None;
                }
            },
        };
        match self.p.jacobian(beta, &base, false) {
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
    // The rig fit uses the angle only: a recorded angular velocity is dropped (when there is an
    // angle), so that a stick-slipping record, whose sampled velocity disagrees with the angle's
    // smoothed derivative, is not refused as inconsistent.
    let stripped: Vec<Record> =
        records.iter().map(|r| if r.angle.is_some() { Record { angular_velocity: None, ..r.clone() } } else { r.clone() }).collect();
    let records = &stripped[..];
    // Start: μ_c (and J when it is not given) from the quasi-static fit; the given μ_c and the
    // rig's J if that fails.
    let core = Options { model: Model::Core, fit: Vec::new(), across_temperature: Vec::new(), resamples: 0, ..options.clone() };
    let core_fit = calibrate_core_with(records, &core, false).ok();
    let mu0 = core_fit.as_ref().map_or(options.params.friction.boundary_friction_coefficient, |c| c.estimates[0].value);
    let (lo_j, hi_j) = match pinjoint::rig::RIG_PARAMS.iter().find(|s| s.key == "inertia").map(|s| s.range) {
        Some(pinjoint::params::Range::HalfOpen(lo, hi)) => (lo, hi),
        _ => (0.0, f64::INFINITY),
    };
    let mut base = RigConfig { model: options.params, rig: options.rig };
    let j_from_core = options.inertia.is_none().then(|| core_fit.as_ref().and_then(|c| c.inertia_estimate.clone())).flatten();
    base.rig.inertia = match (options.inertia, &j_from_core) {
        (Some(j), _) => j,
        // The simulation needs J in the rig's range: the fitted J is clamped into it.
        (None, Some(e)) => e.value.clamp(lo_j, hi_j * (1.0 - 1e-9)),
        (None, None) => options.rig.inertia,
    };
    base.validate()?;
    let plan = plan(records, options, false)?;
    let extras = resolve(&plan.keys, &options.params, &base.rig, true)?;
    let inertia_estimate = j_from_core.filter(|_| !extras.iter().any(|e| e.key.name() == INERTIA));
    let prepared = records.iter().map(|r| prepare(r, &options.params, &options.exclusion, options.half_width)).collect::<Result<Vec<_>, _>>()?;
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
    // (a command's Jacobian column simulates its record only: 4 columns, one record-set's worth)
    let reserve = 2 * (fd + 4) + 1;
    let least = MAX_COMMAND_ITERATIONS + BREAKAWAY_SCAN.len() + 2 + (fd + 4) + reserve;
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
        recs.push(RigRecord {
            name: r.name.clone(),
            tau: Arc::new(tau),
            load: Arc::new(r.load.clone()),
            temperature: r.temperature.clone().map(Arc::new),
            command,
            angle: angle.clone(),
            used,
        });
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

    // The keys at their start values.
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
    let (mut sims, _) = refine_commands(&mut recs, &start)?;
    let records_n = recs.len();
    let torque_rows = y.len();
    let kp = base.rig.position_gain;
    let angle_rows = recs.iter().flat_map(|r| r.angle.iter().zip(&r.used).filter(|(_, u)| **u).map(|(a, _)| kp * a));
    let y_all = DVector::from_iterator(torque_rows + torque_rows, y.iter().copied().chain(angle_rows));
    let make = |recs: &[RigRecord], sims: usize, beta: &DVector<f64>| -> (DVector<f64>, AtomicUsize) {
        let mut full = DVector::zeros(np + 4 * records_n);
        full.rows_mut(0, np).copy_from(beta);
        for (j, r) in recs.iter().enumerate() {
            let c = r.command;
            full.rows_mut(command_index(np, j), 4).copy_from(&DVector::from_vec(vec![c.offset, c.sin, c.cos, c.frequency]));
        }
        (full, AtomicUsize::new(sims * records_n))
    };
    // The breakaway factor given on its bound: scan it, then estimate the command again there.
    for (k, e) in extras.iter().enumerate() {
        if e.key.name() == "rig.breakaway_factor" && e.start != e.key.get(&options.params, &base.rig) {
            let (full, count) = make(&recs, sims, &beta);
            let problem = RigProblem {
                records: &recs,
                base,
                extras: &extras,
                offset: options.fit_offset,
                y: y_all.clone(),
                torque_rows,
                sims: count,
                limit: AtomicUsize::new(usize::MAX),
                total_limit: options.max_simulations,
            };
            beta[k] = breakaway_scan(&problem, &full, k, e.transform)?;
            sims = problem.sims.load(Ordering::SeqCst).div_ceil(records_n);
            e.key.set(&mut start.model, &mut start.rig, e.transform.inverse(beta[k]));
            sims += refine_commands(&mut recs, &start)?.0;
        }
    }
    let (mut full, count) = make(&recs, sims, &beta);
    let problem = RigProblem {
        records: &recs,
        base,
        extras: &extras,
        offset: options.fit_offset,
        y: y_all,
        torque_rows,
        sims: count,
        // The final central Jacobian is kept out of LM's share.
        limit: AtomicUsize::new((options.max_simulations - reserve) * records_n),
        total_limit: options.max_simulations,
    };
    if options.fit_offset {
        let m = problem.stack(&problem.run(&full, None)?, &full);
        full[np - 1] = (problem.y.rows(0, torque_rows) - m.rows(0, torque_rows)).mean();
    }
    let start_beta = full.clone();
    let mut evaluations = 0;
    full = lm_fit(&problem, &full, options.max_simulations, &mut evaluations)?;
    problem.limit.store(options.max_simulations * records_n, Ordering::SeqCst);
    let runs = problem.run(&full, None)?;
    let model_all = problem.stack(&runs, &full);
    let jac = problem.jacobian(&full, &runs, true)?;
    let r_all = &problem.y - &model_all;
    let cl_all: Vec<usize> = clusters.iter().chain(clusters.iter()).copied().collect();
    let u = analyse(&jac, &r_all, &cl_all, ncl, options.resamples, options.seed).ok_or_else(|| CalibrationError::Unidentifiable {
        what: "the fitted quantities cannot be determined from these records (singular normal matrix)".into(),
    })?;
    let u = super::uncertainty::Uncertainty {
        correlation: u.correlation.iter().take(np).map(|row| row[..np].to_vec()).collect(),
        ..u
    };
    let commands: Vec<Command> = (0..records_n).map(|j| problem.command_at(&full, j)).collect();
    let beta = full.rows(0, np).into_owned();
    let model = model_all.rows(0, torque_rows).into_owned();
    let r = problem.y.rows(0, torque_rows) - &model;
    let jac_t = jac.view((0, 0), (torque_rows, np)).into_owned();
    let cfg = problem.config_at(&beta);
    let keys = keys_of(&extras, false, options.fit_offset);
    let transforms: Vec<(Transform, &'static str, f64)> = extras
        .iter()
        .enumerate()
        .map(|(k, e)| (e.transform, e.key.unit(), e.transform.inverse(start_beta[k])))
        .chain(std::iter::once((Transform::Identity, "1", mu0)))
        .chain(options.fit_offset.then_some((Transform::Identity, "N.m", 0.0)))
        .collect();
    let mut estimates: Vec<Estimate> = (0..np).map(|k| estimate(&keys[k], transforms[k], beta[k], &u, k)).collect();
    let offset = options.fit_offset.then(|| estimates.pop().expect("offset is last"));
    let mu = estimates.pop().expect("mu_c follows the extras");
    estimates.insert(0, mu);
    let strokes = clusters.iter().collect::<std::collections::HashSet<_>>().len();
    let mut warn = plan.warnings.clone();
    warn.extend(warnings(&extras, &jac_t, &model, &u, &estimates, &keys, strokes, options));
    for (k, e) in extras.iter().enumerate() {
        let v = e.key.get(&cfg.model, &cfg.rig);
        if e.start != e.key.get(&options.params, &base.rig) {
            warn.push(format!(
                "{} started at {}{} (the best of a scan: its given start value lies on the bound of its range {})",
                e.key.name(),
                e.transform.inverse(start_beta[k]),
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
    let mean_abs = model.iter().map(|v| v.abs()).sum::<f64>() / model.len() as f64;
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
        .map(|((p, s), x)| {
            p.series(s.iter().map(|s| s.torque + s.friction_torque).collect(), s.iter().map(|s| s.torque + off).collect(), x.used.clone())
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
        temperatures: plan.temperatures,
        inertia: cfg.rig.inertia,
        inertia_estimate,
        samples_read: samples,
        block_length: 1,
        settle_time: options.exclusion.settle_time,
        evaluations,
        simulations: problem.sims.load(Ordering::SeqCst).div_ceil(records_n),
        commands,
        series,
    })
}

/// Breakaway factors tried for the start when the given one is on its bound (the default 1).
pub const BREAKAWAY_SCAN: [f64; 7] = [1.05, 1.1, 1.2, 1.3, 1.45, 1.65, 2.0];

/// The scanned breakaway factor whose simulation (other quantities at their start, the offset
/// at its least-squares value) has the least residual: the records' stick-slip makes the
/// residual multimodal in k_b, so LM starts from the best of a coarse scan.
fn breakaway_scan(p: &RigProblem<'_>, beta: &DVector<f64>, k: usize, t: Transform) -> Result<f64, CalibrationError> {
    let (mut best, mut at) = (f64::INFINITY, beta[k]);
    for v in BREAKAWAY_SCAN {
        let mut b = beta.clone();
        b[k] = t.forward(v).expect("inside the range");
        let r = p.y.rows(0, p.torque_rows) - p.stack(&p.run(&b, None)?, &b).rows(0, p.torque_rows);
        let rss = if p.offset { r.add_scalar(-r.mean()).norm_squared() } else { r.norm_squared() };
        if rss < best {
            (best, at) = (rss, b[k]);
        }
    }
    Ok(at)
}

/// Levenberg–Marquardt from `beta`; adds its evaluations to `evaluations`.
fn lm_fit(problem: &RigProblem<'_>, beta: &DVector<f64>, patience: usize, evaluations: &mut usize) -> Result<DVector<f64>, CalibrationError> {
    let scale = problem.y.amax().max(1.0);
    let lm = Lm { p: problem, last: RefCell::new(None), error: RefCell::new(None), outside: 1e3 * scale };
    let (found, report) = LevenbergMarquardt::new().with_xtol(1e-8).with_patience(patience).minimize(Adapter { fit: &lm, beta: beta.clone() });
    *evaluations += report.number_of_evaluations;
    if !report.termination.was_successful() {
        let stored = lm.error.into_inner();
        return Err(match stored {
            Some(e @ CalibrationError::Budget(_)) => e,
            Some(e) if matches!(report.termination, levenberg_marquardt::TerminationReason::User(_)) => e,
            _ => CalibrationError::NoConvergence(format!("{:?} after {} evaluations", report.termination, report.number_of_evaluations)),
        });
    }
    Ok(found.beta)
}

/// Step 2 of [`crate::command`]: move each command by the difference between the recorded and
/// the simulated angle's sine (over the used samples), at the start parameters `cfg`, until no
/// command moves by more than [`COMMAND_TOLERANCE`] (at most [`MAX_COMMAND_ITERATIONS`]
/// simulations of the record set). Returns the simulations run and the first move (rad).
fn refine_commands(recs: &mut [RigRecord], cfg: &RigConfig) -> Result<(usize, f64), CalibrationError> {
    let singular = |name: &str| CalibrationError::Unidentifiable { what: format!("record {name}: no sine fits the angle after the start-up") };
    let sine = |r: &RigRecord, angle: &[f64]| fit_sine_near(&r.tau, angle, &r.used, r.command.frequency, 0.01).ok_or_else(|| singular(&r.name));
    let targets: Vec<Command> = recs.iter().map(|r| sine(r, &r.angle)).collect::<Result<_, _>>()?;
    let mut first = 0.0;
    for k in 1..=MAX_COMMAND_ITERATIONS {
        let mut moved = 0.0f64;
        let sims = recs.par_iter().map(|r| simulate(cfg, r)).collect::<Result<Vec<_>, _>>()?;
        for ((r, t), sim) in recs.iter_mut().zip(&targets).zip(sims) {
            let angle: Vec<f64> = sim.iter().map(|s| s.angle).collect();
            let s = sine(r, &angle)?;
            let span = r.tau.last().copied().unwrap_or(0.0);
            let d = [t.offset - s.offset, t.sin - s.sin, t.cos - s.cos, t.frequency - s.frequency];
            r.command.offset += d[0];
            r.command.sin += d[1];
            r.command.cos += d[2];
            r.command.frequency += d[3];
            moved = [d[0], d[1], d[2], d[3] * span].iter().fold(moved, |m, x| m.max(x.abs()));
        }
        if k == 1 {
            first = moved;
        }
        if moved < COMMAND_TOLERANCE {
            return Ok((k, first));
        }
    }
    Ok((MAX_COMMAND_ITERATIONS, first))
}

/// " unit", or nothing for a dimensionless quantity.
fn unit_suffix(unit: &str) -> String {
    if unit == "1" { String::new() } else { format!(" {unit}") }
}
