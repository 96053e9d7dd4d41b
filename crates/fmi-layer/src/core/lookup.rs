//! What an instance looks up on every call, computed once from the model's variable table
//! at instantiation: the variable of a value reference (a direct index when the value
//! references are compact, as they are in this project's models, else sorted pairs and a
//! binary search; instead of a scan of the table) and the bounds of each output (checked as
//! the host reads it).
//!
//! Measured (callgrind, the PinJoint FMU at boundary fidelity, set 2 inputs, `fmi2DoStep`,
//! get 2 outputs): the scans cost ~3 400 instructions a step of ~9 000 before this index.

use super::variables::{Causality, ModelInfo};

/// The direct index is used when the largest value reference is below this many times the
/// number of variables (its memory then stays within a few words per variable).
pub const DENSE_SLACK: usize = 8;

/// An output's table index and bounds, as its [`super::variables::Variable`] declares them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutputCheck {
    /// Index in the model's variable table.
    pub index: usize,
    /// Smallest allowed value (`min`), if any.
    pub min: Option<f64>,
    /// Largest allowed value (`max`), if any.
    pub max: Option<f64>,
}

/// How value references map to table indices.
#[derive(Debug, Clone)]
enum Index {
    /// `dense[vr]` = table index + 1 (0: no such variable): the largest value reference is
    /// small against the table ([`DENSE_SLACK`]).
    Dense(Vec<u32>),
    /// (value reference, table index), sorted by value reference.
    Sorted(Vec<(u32, usize)>),
}

/// The index of a model's variable table by value reference, and its outputs.
#[derive(Debug, Clone)]
pub struct Lookup {
    index: Index,
    /// By table index: the output's check, `None` for a variable that is not an output.
    outputs: Vec<Option<OutputCheck>>,
}

impl Lookup {
    /// The index of `info`'s table.
    pub fn new(info: &ModelInfo) -> Self {
        let mut by_vr: Vec<(u32, usize)> = info.variables.iter().enumerate().map(|(i, v)| (v.value_reference, i)).collect();
        // Value references are unique per model (the table is checked when the XML is
        // written); a stable sort keeps the first of equal ones, as a scan would find it.
        by_vr.sort_by_key(|&(vr, _)| vr);
        by_vr.dedup_by_key(|&mut (vr, _)| vr);
        let top = by_vr.last().map_or(0, |&(vr, _)| vr as usize);
        let index = if top < DENSE_SLACK * (by_vr.len() + 1) {
            let mut dense = vec![0u32; top + 1];
            for &(vr, i) in &by_vr {
                dense[vr as usize] = u32::try_from(i + 1).unwrap_or(0);
            }
            Index::Dense(dense)
        } else {
            Index::Sorted(by_vr)
        };
        let outputs = info
            .variables
            .iter()
            .enumerate()
            .map(|(index, v)| (v.causality == Causality::Output).then_some(OutputCheck { index, min: v.min, max: v.max }))
            .collect();
        Lookup { index, outputs }
    }

    /// The table index of the variable with value reference `vr`.
    #[inline]
    pub fn index_of(&self, vr: u32) -> Option<usize> {
        match &self.index {
            Index::Dense(dense) => match dense.get(vr as usize) {
                Some(&i) if i > 0 => Some(i as usize - 1),
                _ => None,
            },
            Index::Sorted(by_vr) => by_vr.binary_search_by_key(&vr, |&(r, _)| r).ok().map(|k| by_vr[k].1),
        }
    }

    /// The outputs, in table order.
    pub fn outputs(&self) -> impl Iterator<Item = &OutputCheck> {
        self.outputs.iter().flatten()
    }

    /// The output at table index `index`, if it is one.
    #[inline]
    pub fn output(&self, index: usize) -> Option<&OutputCheck> {
        self.outputs.get(index).and_then(Option::as_ref)
    }
}
