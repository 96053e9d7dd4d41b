//! The instance's index of the variable table ([`crate::core::lookup`]) against a scan of the
//! table: every value reference (present, absent, reordered) and the outputs with their bounds.

use super::linear::{info_for_tests, LINEAR};
use crate::core::lookup::Lookup;
use crate::core::variables::{Causality, ModelInfo};

fn agrees_with_a_scan(info: &ModelInfo) {
    let l = Lookup::new(info);
    let top = info.variables.iter().map(|v| v.value_reference).max().unwrap_or(0);
    for vr in (0..=top.saturating_add(3)).chain([u32::MAX - 1, u32::MAX]) {
        assert_eq!(l.index_of(vr), info.index_of(vr), "vr {vr}");
    }
    let outputs: Vec<usize> = info.variables.iter().enumerate().filter(|(_, v)| v.causality == Causality::Output).map(|(i, _)| i).collect();
    assert_eq!(l.outputs().map(|o| o.index).collect::<Vec<_>>(), outputs);
    for o in l.outputs() {
        assert_eq!((o.min, o.max), (info.variables[o.index].min, info.variables[o.index].max));
    }
    for i in 0..info.variables.len() + 2 {
        assert_eq!(l.output(i).map(|o| o.index), outputs.contains(&i).then_some(i), "index {i}");
    }
}

#[test]
fn finds_what_a_scan_finds() {
    agrees_with_a_scan(&LINEAR);
}

#[test]
fn finds_what_a_scan_finds_in_a_reversed_table_with_gaps() {
    let mut info = info_for_tests();
    info.variables.reverse();
    for (k, v) in info.variables.iter_mut().enumerate() {
        v.value_reference = 7 * (k as u32) + 1000;
    }
    // Sparse: the binary search.
    info.variables[0].min = Some(-1.0);
    info.variables[0].causality = Causality::Output;
    agrees_with_a_scan(&info);
}

#[test]
fn finds_what_a_scan_finds_in_a_compact_reversed_table() {
    // Compact value references in reverse order: the direct index.
    let mut info = info_for_tests();
    let n = info.variables.len() as u32;
    for (k, v) in info.variables.iter_mut().enumerate() {
        v.value_reference = 2 * (n - k as u32);
    }
    agrees_with_a_scan(&info);
}
