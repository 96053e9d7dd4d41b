fn main() {
    let j = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap();
    for p in [5e3, 20e3, 60e3] {
        for w in [0.0, 1e-3, 0.01, 0.05, 0.13, 0.5, 1.3, 2.0, 4.4, 6.0, 10.0] {
            let o = j.evaluate(p, w).unwrap();
            print!("{w}:{:.4} ", o.friction_coefficient);
        }
        println!(" P={p}");
    }
}
