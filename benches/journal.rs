//! The journal bearing's table build (once per L/D, cached) and the per-evaluation costs of
//! issue 28's new physics: the eccentricity lookup ε(S) and the clearance torque, with and
//! without grease; beside them one warm model evaluation (mixed regime), for the ratio.
use criterion::{criterion_group, criterion_main, Criterion};
use pinjoint::clearance::clearance_torque;
use pinjoint::rheology::grease::{GreaseReference, GreaseRheology};
use pinjoint::journal::JournalTable;
use pinjoint::{Joint, Params};
use std::hint::black_box;

fn journal(c: &mut Criterion) {
    let mut g = c.benchmark_group("journal");
    // The paper's bush: L/D = 59.4/56.
    g.bench_function("table_build", |b| b.iter(|| JournalTable::build(black_box(59.4 / 56.0)).unwrap()));
    let t = JournalTable::shared(59.4 / 56.0).unwrap();
    g.bench_function("eccentricity", |b| b.iter(|| t.eccentricity(black_box(-2.3))));
    g.bench_function("power_law_table_build", |b| b.iter(|| pinjoint::clearance::PowerLawTable::build(black_box(0.4)).unwrap()));
    g.finish();

    let (r, bl, cl) = (0.028, 0.0594, 25e-6);
    let oil = GreaseRheology::newtonian(0.01245);
    let grease = GreaseReference::DEFAULT.at(253.15, 293.15, 0.2);
    let mut g = c.benchmark_group("clearance_torque");
    g.bench_function("newtonian", |b| b.iter(|| clearance_torque(&oil, black_box(0.05), r, bl, cl, black_box(0.98), black_box(0.2))));
    g.bench_function("grease_theta_c_0", |b| b.iter(|| clearance_torque(&grease, black_box(0.05), r, bl, cl, black_box(0.98), black_box(0.0))));
    g.bench_function("grease_theta_c_0.2", |b| b.iter(|| clearance_torque(&grease, black_box(0.05), r, bl, cl, black_box(0.98), black_box(0.2))));
    let table = pinjoint::clearance::PowerLawTable::shared(grease.flow_index).unwrap();
    let geo = pinjoint::clearance::ClearanceGeometry { radius: r, length: bl, clearance: cl };
    g.bench_function("grease_tabulated_theta_c_0.2", |b| b.iter(|| pinjoint::clearance::clearance_torque_tabulated(&table, &grease, &geo, black_box(0.05), black_box(0.98), black_box(0.2))));
    g.bench_function("power_law_table_only", |b| b.iter(|| table.integral(black_box(0.98), black_box(0.2))));
    g.bench_function("power_law_integral_only", |b| b.iter(|| pinjoint::clearance::power_law_integral(black_box(0.98), black_box(0.2), black_box(0.4))));
    g.bench_function("newtonian_integral_only", |b| b.iter(|| pinjoint::clearance::newtonian_integral(black_box(0.98), black_box(0.2))));
    g.finish();

    let j = Joint::new(&Params::default()).unwrap();
    let prev = j.evaluate(20e3, 6.0 * 0.999).unwrap().logit;
    let mut g = c.benchmark_group("reference");
    g.bench_function("evaluate_warm_mixed", |b| b.iter(|| j.evaluate_from(black_box(20e3), black_box(6.0), Some(prev)).unwrap()));
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(2));
    targets = journal
}
criterion_main!(benches);
