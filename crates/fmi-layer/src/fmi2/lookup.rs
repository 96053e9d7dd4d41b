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

/// The index of a model's variable table by value reference, and its outputs.
#[derive(Debug, Clone, Default)]
pub struct Lookup {
    /// (value reference, table index), sorted by value reference.
    by_vr: Vec<(u32, usize)>,
    /// `dense[vr]` = table index + 1 (0: no such variable), when the largest value reference
    /// is small against the table ([`DENSE_SLACK`]); empty otherwise.
    dense: Vec<u32>,
    /// The outputs in table order.
    outputs: Vec<OutputCheck>,
    /// `output_at[i]`: the position in `outputs` of table index i, if it is an output.
    output_at: Vec<Option<u32>>,
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
        let mut dense = Vec::new();
        if top < DENSE_SLACK * (by_vr.len() + 1) {
            dense = vec![0u32; top + 1];
            for &(vr, i) in &by_vr {
                dense[vr as usize] = u32::try_from(i + 1).unwrap_or(0);
            }
        }
        let outputs: Vec<OutputCheck> = info
            .variables
            .iter()
            .enumerate()
            .filter(|(_, v)| v.causality == Causality::Output)
            .map(|(index, v)| OutputCheck { index, min: v.min, max: v.max })
            .collect();
        let mut output_at = vec![None; info.variables.len()];
        for (k, o) in outputs.iter().enumerate() {
            output_at[o.index] = u32::try_from(k).ok();
        }
        Lookup { by_vr, dense, outputs, output_at }
    }

    /// The table index of the variable with value reference `vr`.
    #[inline]
    pub fn index_of(&self, vr: u32) -> Option<usize> {
        if !self.dense.is_empty() {
            return match self.dense.get(vr as usize) {
                Some(&i) if i > 0 => Some(i as usize - 1),
                _ => None,
            };
        }
        self.by_vr.binary_search_by_key(&vr, |&(r, _)| r).ok().map(|k| self.by_vr[k].1)
    }

    /// The outputs, in table order.
    #[inline]
    pub fn outputs(&self) -> &[OutputCheck] {
        &self.outputs
    }

    /// The output at table index `index`, if it is one.
    #[inline]
    pub fn output(&self, index: usize) -> Option<&OutputCheck> {
        self.output_at.get(index).copied().flatten().map(|k| &self.outputs[k as usize])
    }
}
