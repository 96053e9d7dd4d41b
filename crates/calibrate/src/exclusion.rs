//! The stated rule that keeps the quasi-static model away from what it does not describe.
//!
//! A sample is excluded when
//! 1. **low speed**: |ω| < `speed_fraction` × the record's peak speed (its 95th percentile of
//!    |ω|, robust to spikes). Around every reversal the joint sticks, the static (breakaway)
//!    peak rises above μ_c·R·P and the rig accelerates hardest; or
//! 2. **settling**: it comes less than `settle_time` after the motion, past a reversal, rose
//!    above the speed threshold in its new direction (or after the start of the record): the
//!    joint breaks away, the static peak decays and the servo rings there (docs/model.md: at 1 Hz the
//!    recorded torque oscillates). Counting from the threshold crossing rather than from the
//!    zero of ω makes the window independent of how long the joint stuck.
//!
//! The samples between two reversals that pass both tests form one *stroke*; strokes are the
//! units of the cluster-robust standard errors and of the bootstrap.

/// Why a sample was left out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reason {
    /// |ω| below the speed threshold.
    LowSpeed,
    /// Within the settling time after a reversal or the record's start.
    Settling,
    /// Rig fit: before the first reversal plus the settling time (the simulation starts at
    /// rest; a record taken from a running rig does not).
    StartUp,
}

impl Reason {
    /// Lower-case name for reports.
    pub fn as_str(&self) -> &'static str {
        match self {
            Reason::LowSpeed => "low speed",
            Reason::Settling => "settling after reversal",
            Reason::StartUp => "start-up (to the first reversal and settling)",
        }
    }
}

/// The exclusion rule's two constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExclusionRule {
    /// Fraction of the record's peak speed below which samples are left out (default 0.3).
    pub speed_fraction: f64,
    /// Time after each reversal (and after the record's start) left out, s (default 0.1 s).
    pub settle_time: f64,
}

impl Default for ExclusionRule {
    fn default() -> Self {
        Self { speed_fraction: 0.3, settle_time: 0.1 }
    }
}

/// A run of consecutive excluded samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// First excluded sample time (s).
    pub start: f64,
    /// Last excluded sample time (s).
    pub end: f64,
    /// Why the samples were excluded.
    pub reason: Reason,
    /// Samples in the window.
    pub samples: usize,
}

/// What the rule did to one record.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordExclusion {
    /// Name of the record.
    pub record: String,
    /// The speed threshold used (rad/s).
    pub speed_threshold: f64,
    /// Reversal times found (s).
    pub reversals: Vec<f64>,
    /// Runs of excluded samples, in time order.
    pub windows: Vec<Window>,
    /// Samples excluded because |ω| was below the speed threshold.
    pub low_speed: usize,
    /// Samples excluded as settling after a reversal or the record's start.
    pub settling: usize,
    /// Rig fit: samples excluded as the start-up (0 for the core model).
    pub start_up: usize,
    /// Samples kept for the fit.
    pub used: usize,
}

/// Per sample: `None` if excluded (with the reason in the second vector), else the stroke index
/// (counting from 0 within the record).
pub struct Classified {
    /// Stroke index of each sample, `None` if excluded.
    pub stroke: Vec<Option<usize>>,
    /// Time since the start of the sample's settling window (the stroke's threshold crossing,
    /// or the record's start), s.
    pub since: Vec<f64>,
    /// Counts, threshold, reversals and windows for the record.
    pub summary: RecordExclusion,
}

/// Apply the rule to one record's time and velocity.
pub fn classify(record: &str, time: &[f64], omega: &[f64], rule: &ExclusionRule) -> Classified {
    let n = time.len();
    let mut speeds: Vec<f64> = omega.iter().map(|w| w.abs()).collect();
    speeds.sort_by(f64::total_cmp);
    let peak = if n == 0 { 0.0 } else { speeds[((n - 1) as f64 * 0.95).round() as usize] };
    let threshold = rule.speed_fraction * peak;
    let mut stroke = vec![None; n];
    let mut since = vec![0.0; n];
    let mut reasons: Vec<Option<Reason>> = vec![None; n];
    let mut reversals = Vec::new();
    let (mut sign, mut t_settle, mut index) = (0.0f64, time.first().copied().unwrap_or(0.0), 0usize);
    // The last sample with ω ≤ 0 and the last with ω ≥ 0: where a reversal to + / to − began.
    let (mut last_nonpos, mut last_nonneg) = (0usize, 0usize);
    for i in 0..n {
        let w = omega[i];
        if w.abs() >= threshold && w != 0.0 {
            let s = w.signum();
            if s != sign {
                if sign != 0.0 {
                    index += 1;
                    // The reversal: the last sample before this one not moving in the new direction.
                    let j = if s > 0.0 { last_nonpos } else { last_nonneg };
                    reversals.push(time[j]);
                    // Settling is counted from the motion's return above the threshold: the
                    // stick at the reversal may last any time, and the breakaway ends it.
                    t_settle = time[i];
                }
                sign = s;
            }
            since[i] = time[i] - t_settle;
            if time[i] - t_settle < rule.settle_time {
                reasons[i] = Some(Reason::Settling);
            } else {
                stroke[i] = Some(index);
            }
        } else {
            reasons[i] = Some(Reason::LowSpeed);
        }
        if w <= 0.0 {
            last_nonpos = i;
        }
        if w >= 0.0 {
            last_nonneg = i;
        }
    }
    let mut windows: Vec<Window> = Vec::new();
    for i in 0..n {
        if let Some(r) = reasons[i] {
            match windows.last_mut() {
                Some(w) if w.reason == r && i > 0 && reasons[i - 1] == Some(r) => {
                    w.end = time[i];
                    w.samples += 1;
                }
                _ => windows.push(Window { start: time[i], end: time[i], reason: r, samples: 1 }),
            }
        }
    }
    let count = |r| reasons.iter().filter(|x| **x == Some(r)).count();
    let (low_speed, settling) = (count(Reason::LowSpeed), count(Reason::Settling));
    let summary = RecordExclusion {
        record: record.to_string(),
        speed_threshold: threshold,
        reversals,
        windows,
        low_speed,
        settling,
        start_up: 0,
        used: n - low_speed - settling,
    };
    Classified { stroke, since, summary }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sine_strokes_and_counts() {
        let n = 4000;
        let t: Vec<f64> = (0..n).map(|i| f64::from(i) * 1e-3).collect();
        let w: Vec<f64> = t.iter().map(|&x| (std::f64::consts::TAU * x).cos()).collect();
        let c = classify("r", &t, &w, &ExclusionRule { speed_fraction: 0.3, settle_time: 0.1 });
        // Reversals at 0.25, 0.75, ... (the last sample before the new sign).
        assert_eq!(c.summary.reversals.len(), 8);
        for (k, r) in c.summary.reversals.iter().enumerate() {
            assert!((r - (0.25 + 0.5 * k as f64)).abs() < 1.5e-3, "{r}");
        }
        // Low speed: |cos| < 0.3 is a fraction 2·asin(0.3)/π of the time.
        let f = c.summary.low_speed as f64 / f64::from(n);
        assert!((f - 2.0 * 0.3f64.asin() / std::f64::consts::PI).abs() < 2e-3, "{f}");
        // Settling: 0.1 s after each threshold crossing and at the start.
        let expected = 9.0 * 0.1 * 1000.0;
        assert!((c.summary.settling as f64 - expected).abs() < 10.0, "{} vs {expected}", c.summary.settling);
        assert_eq!(c.stroke.iter().flatten().max(), Some(&8));
        assert_eq!(c.summary.used, c.stroke.iter().filter(|s| s.is_some()).count());
    }
}
