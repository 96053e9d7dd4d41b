//! Speed against error per evaluation (issue 6): ns per evaluation and the largest relative
//! error in μ (and torque, h_c) against the complete solve, for `full` cold and warm,
//! `table` at several tolerances and `boundary`.
//!
//! Points: a Lissajous path through the envelope in (ln P, ln |ω|) — consecutive points are
//! close, as in a time-stepping host, so the warm start has a previous solution to use —
//! crossing boundary, mixed and (in the wide envelope) full film. Errors are measured on
//! those points and on 20 000 random points of the envelope. Run:
//! `cargo bench -p pinjoint --bench fidelity`; the summary lines (`summary ...`) come from one run.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use pinjoint::fidelity::{Envelope, ErrorReport, Evaluator, Fidelity};
use pinjoint::{Joint, Params};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 1024;

#[path = "../crates/bench/src/eval_path.rs"]
mod eval_path;
use eval_path::path;

/// Largest errors against the complete solve on the path and 20 000 random points.
fn errors(ev: &mut Evaluator, j: &Joint, pts: &[(f64, f64)]) -> ErrorReport {
    eval_path::errors(ev, j, pts, 20_000, 0xbe9c_0001)
}

/// Median over 15 repetitions of the time per evaluation along the path, ns.
fn ns_per_eval(f: impl FnMut(f64, f64) -> f64, pts: &[(f64, f64)]) -> f64 {
    eval_path::ns_per_eval(f, pts, 15)
}

fn fidelity(c: &mut Criterion) {
    let params = Params::default();
    let j = Joint::new(&params).unwrap();
    let envelopes = [
        ("brief", Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap(), &[1e-2, 1e-4, 1e-6][..]),
        ("wide", Envelope::new(5e3, 60e3, 0.01, 100.0).unwrap(), &[1e-2, 1e-4, 1e-5][..]),
    ];
    for (name, env, tols) in envelopes {
        let pts = path(&env, N);
        let mut g = c.benchmark_group(format!("fidelity_{name}"));
        g.throughput(Throughput::Elements(N as u64));
        g.warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
        let mut summary: Vec<(String, f64, ErrorReport, String)> = Vec::new();

        g.bench_function("full_cold", |b| b.iter(|| pts.iter().map(|&(p, w)| j.evaluate(black_box(p), black_box(w)).unwrap().torque).sum::<f64>()));
        summary.push(("full cold".into(), ns_per_eval(|p, w| j.evaluate(p, w).unwrap().torque, &pts), ErrorReport::default(), String::new()));

        let mut full = Evaluator::new(&params, Fidelity::Full, 1e-4, env).unwrap();
        g.bench_function("full_warm", |b| b.iter(|| pts.iter().map(|&(p, w)| full.evaluate(black_box(p), black_box(w)).unwrap().torque).sum::<f64>()));
        let r = errors(&mut full, &j, &pts);
        summary.push(("full warm".into(), ns_per_eval(|p, w| full.evaluate(p, w).unwrap().torque, &pts), r, String::new()));

        for &tol in tols {
            let t0 = Instant::now();
            match Evaluator::new(&params, Fidelity::Table, tol, env) {
                Ok(mut ev) => {
                    let build = t0.elapsed().as_secs_f64();
                    let t = ev.table().unwrap();
                    let info = format!(
                        "{}x{} cells, {:.1} MB, build {:.0} ms, bound {:.2e}",
                        t.stats().load_cells,
                        t.stats().speed_cells,
                        t.size_bytes() as f64 / 1e6,
                        build * 1e3,
                        ev.error_bound()
                    );
                    g.bench_function(format!("table_{tol:.0e}"), |b| {
                        b.iter(|| pts.iter().map(|&(p, w)| ev.evaluate(black_box(p), black_box(w)).unwrap().torque).sum::<f64>());
                    });
                    let r = errors(&mut ev, &j, &pts);
                    summary.push((format!("table {tol:.0e}"), ns_per_eval(|p, w| ev.evaluate(p, w).unwrap().torque, &pts), r, info));
                }
                Err(e) => summary.push((format!("table {tol:.0e}"), f64::NAN, ErrorReport::default(), format!("not built: {e}"))),
            }
        }

        let mut bnd = Evaluator::new(&params, Fidelity::Boundary, 1e-4, env).unwrap();
        g.bench_function("boundary", |b| b.iter(|| pts.iter().map(|&(p, w)| bnd.evaluate(black_box(p), black_box(w)).unwrap().torque).sum::<f64>()));
        let r = errors(&mut bnd, &j, &pts);
        let info = format!("bound {:.2e}", bnd.error_bound());
        summary.push(("boundary".into(), ns_per_eval(|p, w| bnd.evaluate(p, w).unwrap().torque, &pts), r, info));
        g.finish();

        let cold = summary[0].1;
        println!("\nsummary {name}: {env:?}, {N} path points (+20000 random for the errors)");
        println!("summary {:<12} {:>9} {:>8} {:>10} {:>10} {:>10} {:>10}  notes", "level", "ns/eval", "vs cold", "err mu", "err torque", "err h_c", "err share");
        for (lvl, ns, r, info) in &summary {
            println!(
                "summary {:<12} {:>9.1} {:>8.3} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e}  {}",
                lvl,
                ns,
                ns / cold,
                r.friction_coefficient,
                r.torque,
                r.film_thickness,
                r.load_fraction,
                info
            );
        }
    }
}

criterion_group!(benches, fidelity);
criterion_main!(benches);
