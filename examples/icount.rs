//! Instruction-count probe for callgrind: `valgrind --tool=callgrind target/release/examples/icount MODE N`.
use pinjoint::{Joint, Params};
use std::hint::black_box;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let mode = a.get(1).map(String::as_str).unwrap_or("warm");
    let n: usize = a.get(2).and_then(|s| s.parse().ok()).unwrap_or(100000);
    let j = Joint::new(&Params::default()).unwrap();
    let mut acc = 0.0;
    let mut guess = None;
    for i in 0..n {
        let w = 6.0 * (1.0 + 1e-3 * ((i % 100) as f64));
        let op = match mode {
            "cold" => j.evaluate(black_box(20e3), black_box(w)).unwrap(),
            "none" => { acc += w; continue; }
            _ => j.evaluate_from(black_box(20e3), black_box(w), guess).unwrap(),
        };
        guess = Some(op.logit);
        acc += op.friction_coefficient;
    }
    println!("{acc}");
}
