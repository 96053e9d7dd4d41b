fn main() {
    let j = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap();
    for &(p, w) in &[(20e3, 0.0), (20e3, 1e-12), (20e3, 0.0057), (20e3, 0.2), (20e3, 6.28), (20e3, 83.8), (5e3, 83.8), (1e3, 1000.0), (1.0, 1e4), (1e6, 1.0), (20e3, 1e5)] {
        let o = j.evaluate(p, w).unwrap();
        println!("P={p:8} w={w:8} mu={:.6} h={:.4e} x1={:.4e} x2={:.4e} lam={:.3} S={:.3e} {:?} mufl={:.3e}", o.friction_coefficient, o.film_thickness, o.fluid_load_fraction, o.asperity_load_fraction, o.lambda_ratio, o.sommerfeld_number, o.regime, o.fluid_friction_coefficient);
    }
}
