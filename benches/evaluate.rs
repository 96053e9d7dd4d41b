//! One full evaluation of the model in each regime, cold (no warm start) and warm
//! (started from the previous point's solution, as a time-stepping host would).
use criterion::{criterion_group, criterion_main, Criterion};
use pinjoint::{Joint, Params};
use std::hint::black_box;

fn evaluate(c: &mut Criterion) {
    let j = Joint::new(&Params::default()).unwrap();
    let cases = [
        ("rest", 20e3, 0.0),
        ("boundary", 20e3, 0.05),
        ("mixed", 20e3, 6.0),
        ("full-film", 20e3, 100.0),
    ];
    let mut g = c.benchmark_group("evaluate_cold");
    for (name, load, omega) in cases {
        g.bench_function(name, |b| b.iter(|| j.evaluate(black_box(load), black_box(omega)).unwrap()));
    }
    g.finish();
    let mut g = c.benchmark_group("evaluate_warm");
    for (name, load, omega) in cases {
        let prev = j.evaluate(load, omega * 0.999).unwrap().logit;
        g.bench_function(name, |b| b.iter(|| j.evaluate_from(black_box(load), black_box(omega), Some(prev)).unwrap()));
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = evaluate
}
criterion_main!(benches);
