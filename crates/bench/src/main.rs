//! `pinjoint-bench`: the developer's benchmark tool (speed against error, measured in one
//! run). It is not part of the user's `pinjoint` binary: it shells out to Python (fmpy) for
//! the FMU section. Run it with `cargo run --release -p pinjoint-bench -- --output .`.

// In dependency order: each module uses only those above it (tests/module_graph.py).
mod alloc_count;
mod rng;
mod bench_error;
mod bench_output;
mod bench_rig;
mod bench_throughput;
mod bench_calibrate;
mod bench_batch;
mod eval_path;
mod bench_eval;
mod bench_report;
mod bench;

use clap::Parser;

/// Counts heap bytes for the batch section's memory figure ([`alloc_count`]).
#[global_allocator]
static ALLOC: alloc_count::Counting = alloc_count::Counting;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cmd = bench::BenchCmd::parse();
    match bench::run(&cmd) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
