//! The models of a batch, one per (parameter set, temperature) in use, shared by every joint
//! at that key: joints with one parameter set and one temperature share one [`Model`] (one
//! table at the table level). A temperature that changes builds the model at the new one
//! ([`Joint::at_temperature`]: a few logarithms at full, the level built and measured again
//! otherwise, the cost of the scalar `Evaluator::set_temperature`). A model no joint uses any
//! more is kept among the [`RETAINED`] most recently released (a host whose joints share a
//! parameter set and alternate between two temperatures, or call `torque` with a temperature
//! and `commit` without, does not rebuild a table each call); older ones are dropped at the
//! end of the call, so at most one model per joint plus [`RETAINED`] are held. Per-joint
//! parameter sets have a model per joint: when more than [`RETAINED`] joints leave a
//! temperature in one call and come back to it in the next, their models are built again
//! (measured in `tests/batch_independent.rs`: allocation-free with a shared set).
//!
//! Tables are bounded: at the table and auto levels, in each call the joints of the first
//! [`LEVELS_MAX`] distinct (parameter set, temperature) keys, in the order of the lowest joint
//! index asking, are the level's; the joints of any further key are answered by the complete
//! solve, exactly as at `full` (their key carries [`FULL_BIT`]: a model without a table, a few
//! logarithms to build). A boundary level holds no table and is not limited. So at most
//! [`LEVELS_MAX`] tables are in use, and with the retired ones at most [`LEVELS_MAX`] held
//! after a call (the oldest retired tables go first), whatever the number of parameter sets
//! and temperatures (before: 40 joints at 40 temperatures held 40 tables, 1 GB, and took 6 s a
//! step; a table of the default envelope is ~13 MiB and ~0.2 s to build). Which joints are the
//! table's depends on the call's keys alone, not on earlier calls.

use super::error::BatchError;
use super::model::{Model, Settings};
use crate::joint::Joint;
use rayon::prelude::*;
use std::collections::HashMap;

/// Models no joint uses that are kept for reuse.
pub const RETAINED: usize = 4;

/// The most (parameter set, temperature) keys whose joints a table answers in one call, and
/// the most tables held after it (module doc).
pub const LEVELS_MAX: usize = 4;

/// The bit of a key's parameter-set index marking a key beyond [`LEVELS_MAX`] in its call:
/// its model has no table (the complete solve answers).
pub const FULL_BIT: u32 = 1 << 31;

/// (parameter set, temperature's bits).
pub type Key = (u32, u64);

/// The models in use and which key each holds.
#[derive(Debug, Clone)]
pub struct Models {
    /// Each parameter set's joint at its own temperature, the origin of every model.
    bases: Vec<Joint>,
    settings: Settings,
    slots: Vec<Option<(Key, Model)>>,
    users: Vec<u32>,
    index: HashMap<Key, u32>,
    free: Vec<u32>,
    /// Keys to build in this call and the first joint that asked for each (reused buffer).
    pending: Vec<(Key, usize)>,
    /// Slots whose last user left in this call (reused buffer).
    released: Vec<u32>,
    /// Slots holding a model no joint uses, oldest first (at most [`RETAINED`]).
    retired: std::collections::VecDeque<u32>,
}

impl Models {
    /// The models of `bases` (one joint per parameter set) at `settings`, none built yet.
    pub fn new(bases: Vec<Joint>, settings: Settings) -> Self {
        Models { bases, settings, slots: Vec::new(), users: Vec::new(), index: HashMap::new(), free: Vec::new(), pending: Vec::new(), released: Vec::new(), retired: std::collections::VecDeque::new() }
    }

    /// The fidelity settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The parameter sets' joints at their own temperatures.
    pub fn bases(&self) -> &[Joint] {
        &self.bases
    }

    /// The model in `slot`.
    #[inline]
    pub fn get(&self, slot: u32) -> &Model {
        &self.slots[slot as usize].as_ref().expect("a slot in use holds its model").1
    }

    /// The key of the model in `slot`.
    #[inline]
    pub fn key(&self, slot: u32) -> Key {
        self.slots[slot as usize].as_ref().expect("a slot in use holds its model").0
    }

    /// Models held now (those in use and the retained ones).
    pub fn held(&self) -> usize {
        self.slots.iter().filter(|s| s.is_some()).count()
    }

    /// Models held now with a table (at most [`LEVELS_MAX`] after a call).
    pub fn tables_held(&self) -> usize {
        self.slots.iter().flatten().filter(|(_, m)| m.has_table()).count()
    }

    /// The key of parameter set `set` at temperature `t` (K; None: the set's own).
    #[inline]
    pub fn key_of(&self, set: u32, t: Option<f64>) -> Key {
        let t = t.unwrap_or(self.bases[set as usize].params().lubricant.temperature);
        (set, t.to_bits())
    }

    /// The model of `key`, built from its base: without a table for a key with [`FULL_BIT`].
    fn build(&self, key: Key) -> Result<Model, BatchError> {
        let base = &self.bases[(key.0 & !FULL_BIT) as usize];
        let t = f64::from_bits(key.1);
        let joint = if key.1 == base.params().lubricant.temperature.to_bits() { base.clone() } else { base.at_temperature(t).map_err(|source| BatchError::Temperature { index: 0, source })? };
        if key.0 & FULL_BIT != 0 {
            return Ok(Model::full(joint));
        }
        Model::build(joint, &self.settings).map_err(|source| BatchError::Level { index: 0, source })
    }

    /// Mark with [`FULL_BIT`] the keys of `keys` (one per joint) beyond the first [`LEVELS_MAX`]
    /// distinct ones in joint order, at the table and auto levels (module doc). No allocation.
    pub fn budget(&self, keys: &mut [Key]) {
        if !matches!(self.settings.fidelity, crate::fidelity::Fidelity::Table | crate::fidelity::Fidelity::Auto) {
            return;
        }
        let mut top = [(0u32, 0u64); LEVELS_MAX];
        let mut len = 0;
        for k in keys.iter_mut() {
            if top[..len].contains(k) {
                continue;
            }
            if len < LEVELS_MAX {
                top[len] = *k;
                len += 1;
            } else {
                k.0 |= FULL_BIT;
            }
        }
    }

    /// Make every joint's slot hold the model of its key: `wanted(i)` is joint i's key,
    /// `slot[i]` its current slot (u32::MAX: none yet). Builds the missing models first, in
    /// parallel on rayon's threads when `parallel` (else on the calling thread); on an error
    /// (a temperature the model cannot take) nothing is changed and the error names the lowest
    /// joint index asking for it.
    pub fn assign(&mut self, slots: &mut [u32], wanted: impl Fn(usize) -> Key, parallel: bool) -> Result<(), BatchError> {
        self.pending.clear();
        let mut changed = false;
        for (i, &s) in slots.iter().enumerate() {
            let k = wanted(i);
            if s != u32::MAX && self.key(s) == k {
                continue;
            }
            changed = true;
            // A key being built is in the index as u32::MAX until its slot is known.
            let pending = &mut self.pending;
            self.index.entry(k).or_insert_with(|| {
                pending.push((k, i));
                u32::MAX
            });
        }
        if !changed {
            return Ok(());
        }
        if !self.pending.is_empty() {
            let built: Vec<Result<Model, BatchError>> =
                if parallel { self.pending.par_iter().map(|&(k, _)| self.build(k)).collect() } else { self.pending.iter().map(|&(k, _)| self.build(k)).collect() };
            // Every build first, so that an error leaves the batch as it was.
            if let Some((pos, e)) = built.iter().enumerate().filter_map(|(p, r)| r.as_ref().err().map(|e| (p, e))).min_by_key(|(p, _)| self.pending[*p].1) {
                let index = self.pending[pos].1;
                for (k, _) in &self.pending {
                    self.index.remove(k);
                }
                return Err(match e.clone() {
                    BatchError::Temperature { source, .. } => BatchError::Temperature { index, source },
                    BatchError::Level { source, .. } => BatchError::Level { index, source },
                    other => other,
                });
            }
            let pending = std::mem::take(&mut self.pending);
            for (&(k, _), m) in pending.iter().zip(built) {
                let m = m.expect("checked above");
                let slot = match self.free.pop() {
                    Some(s) => {
                        self.slots[s as usize] = Some((k, m));
                        s
                    }
                    None => {
                        self.slots.push(Some((k, m)));
                        self.users.push(0);
                        (self.slots.len() - 1) as u32
                    }
                };
                self.index.insert(k, slot);
            }
            self.pending = pending;
        }
        self.released.clear();
        for (i, s) in slots.iter_mut().enumerate() {
            let k = wanted(i);
            if *s != u32::MAX && self.key(*s) == k {
                continue;
            }
            if *s != u32::MAX {
                self.users[*s as usize] -= 1;
                if self.users[*s as usize] == 0 {
                    self.released.push(*s);
                }
            }
            let new = self.index[&k];
            if self.users[new as usize] == 0 {
                // A retired model back in use.
                self.retired.retain(|&r| r != new);
            }
            self.users[new as usize] += 1;
            *s = new;
        }
        for i in 0..self.released.len() {
            let s = self.released[i];
            if self.users[s as usize] == 0 && !self.retired.contains(&s) {
                self.retired.push_back(s);
            }
        }
        // The oldest retired models go: beyond RETAINED, and while more than LEVELS_MAX tables
        // are held (those in use are at most LEVELS_MAX by `budget`).
        let mut levels = self.tables_held();
        while self.retired.len() > RETAINED || (levels > LEVELS_MAX && self.retired.iter().any(|&s| self.get(s).has_table())) {
            let pos = if self.retired.len() > RETAINED { 0 } else { self.retired.iter().position(|&s| self.get(s).has_table()).expect("checked above") };
            let s = self.retired.remove(pos).expect("a retired slot");
            if let Some((k, m)) = self.slots[s as usize].take() {
                levels -= usize::from(m.has_table());
                self.index.remove(&k);
            }
            self.free.push(s);
        }
        Ok(())
    }
}
