//! Long records in bounded time and memory: block averaging.
//!
//! When the records hold more than [`crate::Options::max_samples`] samples together (default
//! [`crate::options::MAX_FIT_SAMPLES`]), every record is replaced by the means of consecutive
//! blocks of m samples, m = ⌈total / max_samples⌉ ([`block_length`]), the same m for every
//! record; a record's last block holds what is left (1 to m samples). Each column (time, angle,
//! angular velocity, torque, load) is averaged over the block.
//!
//! Why the mean and not every m-th sample: white torque noise of variance σ² averages to σ²/m
//! in a block mean, so the fit loses none of the information the noise leaves (a sub-sampled
//! record would have √m wider intervals), and quantised angles are averaged too. What the mean
//! changes: a smooth signal s(t) averages to s(t̄) + s''·Δ²/24 + … over a block of duration Δ,
//! the same for the torque and for the kinematics it is modelled from, so the fitted model
//! sees a consistent record up to terms of order (ωΔ)²/24: 3e-5 relative at 200 blocks a
//! cycle. The blocks must stay short against a stroke: a record left with fewer than
//! [`MIN_BLOCKS_PER_STROKE`] blocks a stroke is refused with the reason.

use super::derivative::stroke_count;
use super::error::CalibrationError;
use super::record::{Columns, Record};

/// Blocks a stroke at the least after averaging (the differentiator needs a few samples a
/// stroke, the exclusion rule a few more).
pub const MIN_BLOCKS_PER_STROKE: usize = 40;

/// The block length m = ⌈`total` / `max`⌉ (1 when `total` ≤ `max`; `max` = 0 is taken as 1).
pub fn block_length(total: usize, max: usize) -> usize {
    total.div_ceil(max.max(1)).max(1)
}

/// Block means of a stream of samples, pushed one at a time (the CLI reads a CSV this way, so
/// a long file is never held whole).
#[derive(Debug, Clone)]
pub struct BlockMean {
    m: usize,
    count: usize,
    /// Time of the block's first sample (the times are summed relative to it).
    t0: f64,
    sums: [f64; 6],
    out: Record,
}

impl BlockMean {
    /// Averages of blocks of `m` samples (m ≥ 1) for a record named `name`, with or without an
    /// angle and an angular velocity column (and no temperature column: [`BlockMean::with_temperature`]).
    pub fn new(name: &str, m: usize, angle: bool, angular_velocity: bool) -> Self {
        Self {
            m: m.max(1),
            count: 0,
            t0: 0.0,
            sums: [0.0; 6],
            out: Record {
                name: name.to_string(),
                angle: angle.then(Vec::new),
                angular_velocity: angular_velocity.then(Vec::new),
                ..Record::default()
            },
        }
    }

    /// With a temperature column (pass its values as [`BlockMean::push_temperature`]'s).
    pub fn with_temperature(mut self) -> Self {
        self.out.temperature = Some(Vec::new());
        self
    }

    /// Add one sample (an absent column's value is ignored).
    pub fn push(&mut self, time: f64, angle: f64, angular_velocity: f64, torque: f64, load: f64) {
        self.push_temperature(time, angle, angular_velocity, torque, load, 0.0);
    }

    /// [`BlockMean::push`] with the sample's temperature (K; ignored without a temperature column).
    pub fn push_temperature(&mut self, time: f64, angle: f64, angular_velocity: f64, torque: f64, load: f64, temperature: f64) {
        if self.count == 0 {
            self.t0 = time;
        }
        for (s, v) in self.sums.iter_mut().zip([time - self.t0, angle, angular_velocity, torque, load, temperature]) {
            *s += v;
        }
        self.count += 1;
        if self.count == self.m {
            self.flush();
        }
    }

    fn flush(&mut self) {
        if self.count == 0 {
            return;
        }
        let k = self.count as f64;
        let [t, a, w, q, p, temp] = self.sums.map(|s| s / k);
        self.out.time.push(self.t0 + t);
        if let Some(v) = self.out.angle.as_mut() {
            v.push(a);
        }
        if let Some(v) = self.out.angular_velocity.as_mut() {
            v.push(w);
        }
        self.out.torque.push(q);
        self.out.load.push(p);
        if let Some(v) = self.out.temperature.as_mut() {
            v.push(temp);
        }
        self.sums = [0.0; 6];
        self.count = 0;
    }

    /// The averaged record (the last, partial block included).
    pub fn finish(mut self) -> Record {
        self.flush();
        self.out
    }
}

/// The record of block means of `c` (m = `m`); `c` should have been validated.
pub fn block_mean(c: &Columns<'_>, m: usize) -> Record {
    let mut b = BlockMean::new(c.name, m, c.angle.is_some(), c.angular_velocity.is_some());
    if c.temperature.is_some() {
        b = b.with_temperature();
    }
    for i in 0..c.len() {
        let a = c.angle.map_or(0.0, |a| a[i]);
        let w = c.angular_velocity.map_or(0.0, |w| w[i]);
        let temp = c.temperature.map_or(0.0, |t| t[i]);
        b.push_temperature(c.time[i], a, w, c.torque[i], c.load[i], temp);
    }
    b.finish()
}

/// The records to fit: `records` checked, then block-averaged by [`block_length`] of their
/// total and `max_samples` when they hold more (see the module documentation). Returns the
/// records and m (1: unchanged).
pub fn reduce(records: &[Columns<'_>], max_samples: usize) -> Result<(Vec<Record>, usize), CalibrationError> {
    for r in records {
        r.validate()?;
    }
    let total: usize = records.iter().map(Columns::len).sum();
    let m = block_length(total, max_samples);
    let out: Vec<Record> = records
        .iter()
        .map(|c| {
            if m == 1 {
                Record {
                    name: c.name.to_string(),
                    time: c.time.to_vec(),
                    angle: c.angle.map(<[f64]>::to_vec),
                    angular_velocity: c.angular_velocity.map(<[f64]>::to_vec),
                    torque: c.torque.to_vec(),
                    load: c.load.to_vec(),
                    temperature: c.temperature.map(<[f64]>::to_vec),
                }
            } else {
                block_mean(c, m)
            }
        })
        .collect();
    if m > 1 {
        check_blocks(&out, m)?;
    }
    Ok((out, m))
}

/// Every averaged record keeps at least [`MIN_BLOCKS_PER_STROKE`] blocks a stroke.
pub fn check_blocks(records: &[Record], m: usize) -> Result<(), CalibrationError> {
    for r in records {
        let strokes = match (&r.angle, &r.angular_velocity) {
            (Some(a), _) => stroke_count(a),
            (None, Some(w)) => 1 + w.windows(2).filter(|p| p[0] * p[1] < 0.0).count(),
            (None, None) => 1,
        };
        let per = r.len() / strokes.max(1);
        if per < MIN_BLOCKS_PER_STROKE {
            return Err(CalibrationError::Unidentifiable {
                what: format!(
                    "record {}: the records hold too many samples to fit whole, and averaged in blocks of {m} samples (to the \
                     sample budget) it keeps {per} samples a stroke over {strokes} strokes, fewer than the {MIN_BLOCKS_PER_STROKE} \
                     needed: raise the sample budget (max_samples, --max-samples) or fit fewer or shorter records",
                    r.name
                ),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_means_of_a_line_lie_on_the_line() {
        // A linear signal averages to its value at the block's mean time, partial block included.
        let t: Vec<f64> = (0..10).map(f64::from).collect();
        let y: Vec<f64> = t.iter().map(|x| 2.0 * x + 1.0).collect();
        let c = Columns { name: "r", time: &t, angle: Some(&y), angular_velocity: None, torque: &y, load: &y, temperature: Some(&y) };
        let r = block_mean(&c, 4);
        assert_eq!(r.time, vec![1.5, 5.5, 8.5]);
        assert_eq!(r.angle.as_ref().unwrap(), &vec![4.0, 12.0, 18.0]);
        assert!(r.angular_velocity.is_none());
        assert_eq!(r.temperature.as_ref().unwrap(), &vec![4.0, 12.0, 18.0]);
        assert_eq!(block_length(10, 4), 3);
        assert_eq!(block_length(8, 8), 1);
        assert_eq!(block_length(0, 8), 1);
    }

    #[test]
    fn white_noise_variance_falls_by_the_block_length() {
        let mut rng = crate::uncertainty::SplitMix::new(5);
        let n = 200_000;
        let x: Vec<f64> = (0..n).map(|_| rng.uniform() - 0.5).collect();
        let t: Vec<f64> = (0..n).map(f64::from).collect();
        let c = Columns { name: "r", time: &t, angle: Some(&x), angular_velocity: None, torque: &x, load: &x, temperature: None };
        let r = block_mean(&c, 10);
        let var = r.torque.iter().map(|v| v * v).sum::<f64>() / r.len() as f64;
        // Uniform noise of variance 1/12, averaged over 10: 1/120 (± a few % for 20000 blocks).
        assert!((var * 120.0 - 1.0).abs() < 0.05, "{}", var * 120.0);
    }
}
