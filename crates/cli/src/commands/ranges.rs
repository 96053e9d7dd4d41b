//! `pinjoint ranges`: the declared ranges of a joint (the library's `pinjoint::validity`):
//! where the model was checked, where its assumptions end (the validity `outside` beyond) and
//! where it refuses, as a table or one JSON object.

use crate::common::{readable, ParamsArg};
use crate::error::Result;
use crate::output::to_stdout;
use clap::Args;
use pinjoint::params::{MAX_TEMPERATURE, MIN_TEMPERATURE, PAPER_MIN_TEMPERATURE};
use pinjoint::validity::{LOAD_EDGE_SOURCE, RANGES, UPPER_SERVICE_SOURCE};
use pinjoint::Joint;

#[derive(Args, Debug)]
#[command(
    about = "Print the declared ranges: checked, past the model's assumptions, refused",
    long_about = "Print the declared ranges of the joint (the parameter file's, default the paper's): \
the checked envelope (the paper's rig tests: validity checked inside, extrapolation outside), \
the edges of the model's assumptions (the load at which the Hertz half-width of eq. 6 reaches \
the pin radius, the declared load capacity; the grease's upper service temperature, \
grease.upper_service_temperature): past them every answer has the validity outside, and the \
model still answers; and where it refuses (the asperity model's limit, the declared temperatures). \
See docs/validity.md.\n\n\
Examples:\n  \
pinjoint ranges\n  \
pinjoint ranges --params my-joint.toml --json"
)]
/// Arguments of `pinjoint ranges` (its `--help` text is the `#[command]` attribute's).
pub struct RangesCmd {
    /// --params and --temperature.
    #[command(flatten)]
    pub params: ParamsArg,
    /// Print one JSON object (SI units) instead of the table
    #[arg(long)]
    pub json: bool,
}

/// Runs `pinjoint ranges`: prints the ranges of the joint of --params to standard output.
pub fn run(cmd: &RangesCmd) -> Result<()> {
    let p = cmd.params.load()?;
    let joint = Joint::new(&p)?;
    let edges = joint.edges();
    let t_min = if p.model.paper { PAPER_MIN_TEMPERATURE } else { MIN_TEMPERATURE };
    let text = if cmd.json {
        let checked: Vec<serde_json::Value> = RANGES
            .iter()
            .map(|r| serde_json::json!({"quantity": r.quantity, "unit": r.unit, "lo": r.lo, "hi": r.hi, "source": r.source}))
            .collect();
        let v = serde_json::json!({
            "checked": checked,
            "edges": {
                "load": {"value": edges.load, "unit": "N", "basis": LOAD_EDGE_SOURCE},
                "temperature": {"value": edges.temperature, "unit": "K", "basis": UPPER_SERVICE_SOURCE},
            },
            "refused": {
                "load": {"at_or_beyond": joint.capacity(), "unit": "N", "basis": "the asperity model's limit (eq. 19's rest film through zero)"},
                "temperature": {"lo": t_min, "hi": MAX_TEMPERATURE, "unit": "K"},
            },
        });
        format!("{v}\n")
    } else {
        let mut s = String::from("checked (the paper's rig tests): validity checked inside, extrapolation outside\n");
        for r in RANGES {
            let span = format!("{} .. {} {}", readable(r.lo), readable(r.hi), r.unit);
            s.push_str(&format!("  {:<15} {span:<30} {}\n", r.quantity, r.source));
        }
        s.push_str("past the model's assumptions: validity outside (answered, continuous across the edge)\n");
        s.push_str(&format!("  {:<15} above {} N (the declared load capacity): {}\n", "load", readable(edges.load), LOAD_EDGE_SOURCE));
        s.push_str(&format!("  {:<15} above {} K: {}\n", "temperature", readable(edges.temperature), UPPER_SERVICE_SOURCE));
        s.push_str("refused (the model cannot answer)\n");
        s.push_str(&format!("  {:<15} at or beyond {} N: the asperity model's limit (eq. 19's rest film through zero)\n", "load", readable(joint.capacity())));
        s.push_str(&format!("  {:<15} outside {} .. {} K\n", "temperature", readable(t_min), readable(MAX_TEMPERATURE)));
        s
    };
    to_stdout(|w| w.write_all(text.as_bytes()))
}
