//! `pinjoint-bench --quick`: the report and its plots are written (timings are not asserted).

use std::process::Command;

#[test]
fn bench_quick_writes_the_report_and_plots() {
    let dir = tempfile::tempdir().unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_pinjoint-bench"))
        .args(["--quick", "--no-fmu", "--output"])
        .arg(dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let md = std::fs::read_to_string(dir.path().join("BENCHMARKS.md")).unwrap();
    for needle in [
        "## Targets",
        "`full` warm-started < 1 µs",
        "`table` < 50 ns",
        "within 1.1 × the pass-through",
        "10 strokes of the 1 Hz rig",
        "## Per evaluation",
        "| full, warm |",
        "| table 1e-3 |",
        "| boundary |",
        "## Per cycle simulation",
        "Dopri5 + table",
        "RK4, 100 samples/cycle, h = 1e-3 s",
        "Not measured in this run: skipped (--no-fmu)",
        "## Calibration of long records",
        "`pinjoint calibrate` on 100000 rows",
        "## Scenes at scale",
        "2000 scenes × 200 steps at table fidelity ≤ 60 s on 2 cores",
        "table fidelity costs ≤ 0.1 × full, per joint-step",
        "memory of a batch of 2000 joints ≤ 64 MiB beyond the outputs",
        "--quick",
    ] {
        assert!(md.contains(needle), "BENCHMARKS.md lacks {needle:?}:\n{md}");
    }
    // Measured numbers, not placeholders: the boundary level's μ error over the rig envelope is
    // large (the envelope reaches mixed lubrication) and the table's is within its tolerance.
    // Both models: the complete one (the default) and the paper's (the earlier targets').
    for model in ["complete", "model.paper"] {
        let row = md.lines().find(|l| l.contains(&format!("| {model} | rig: 5-60 kN, 0.01-10 rad/s | table 1e-3 |"))).expect("table row");
        let mu: f64 = row.split('|').nth(5).unwrap().trim().parse().unwrap();
        assert!(mu > 0.0 && mu <= 1e-3, "{row}");
    }
    // The pictures go to benches/results/ under DIR (the repository's root stays clean), and
    // BENCHMARKS.md links them there; nothing but BENCHMARKS.md and that folder is written to DIR.
    for svg in ["bench_evaluation.svg", "bench_rig.svg"] {
        let s = std::fs::read_to_string(dir.path().join("benches/results").join(svg)).unwrap();
        assert!(s.starts_with("<svg") && s.contains("</svg>") && s.len() > 2000, "{svg}");
        assert!(!dir.path().join(svg).exists(), "{svg} written at the top of DIR");
    }
    assert!(md.contains("(benches/results/bench_evaluation.svg)") && md.contains("(benches/results/bench_rig.svg)"));
}

#[test]
fn bench_without_python_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_pinjoint-bench"))
        .args(["--quick", "--python", "/nonexistent/python", "--output"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(dir.path().join("BENCHMARKS.md")).unwrap();
    // Either the FMUs are not built in this tree, or Python is missing: the report names it.
    assert!(md.contains("Not measured in this run:") && (md.contains("/nonexistent/python") || md.contains("fmu_build")), "{md}");
}

/// `--only-batch` replaces the batch section of an existing BENCHMARKS.md in place and leaves
/// the rest of the file as it was.
#[test]
fn only_batch_replaces_its_section_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("BENCHMARKS.md");
    std::fs::write(&path, "# Benchmarks\n\nthe rest of the file\n").unwrap();
    for _ in 0..2 {
        let o = Command::new(env!("CARGO_BIN_EXE_pinjoint-bench"))
            .args(["--quick", "--only-batch", "--package-python", "/nonexistent/python", "--output"])
            .arg(dir.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let md = std::fs::read_to_string(&path).unwrap();
    assert!(md.starts_with("# Benchmarks\n\nthe rest of the file\n"), "{md}");
    assert_eq!(md.matches("## Scenes at scale").count(), 1, "{md}");
    assert!(md.contains("not measured (no Python at /nonexistent/python"), "{md}");
    // Measured numbers: the memory row gives a peak in MiB.
    let row = md.lines().find(|l| l.starts_with("| memory of a batch")).expect("memory row");
    assert!(row.contains("peak ") && row.contains(" MiB at table fidelity"), "{row}");
}
