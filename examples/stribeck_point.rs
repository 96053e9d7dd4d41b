//! Using the library directly: the joint of the paper's rig, one operating point, a
//! Stribeck curve at 20 kN, and a joint of your own from a partial parameter file.
//!
//! Run with `cargo run --release -p pinjoint --example stribeck_point`.

use pinjoint::{Joint, Params};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The paper's rig (Tables 1-3, mu_c = 0.12).
    let joint = Joint::new(&Params::default())?;

    // One point: 20 kN at 10 rpm.
    let omega = 10.0 * 2.0 * std::f64::consts::PI / 60.0;
    let op = joint.evaluate(20e3, omega)?;
    println!(
        "20 kN, 10 rpm: mu = {:.4}, torque = {:.2} N.m, h_c = {:.3} um, lambda = {:.2}, fluid share = {:.3} ({})",
        op.friction_coefficient,
        op.torque,
        op.film_thickness * 1e6,
        op.lambda_ratio,
        op.fluid_load_fraction,
        op.regime.as_str()
    );

    // A Stribeck curve, warm-starting each solve from the previous point.
    println!("\n{:>12} {:>12} {:>10} {:>10}", "speed rad/s", "Sommerfeld", "mu", "1/gamma1");
    let mut guess = None;
    for k in 0..=12 {
        let w = 10f64.powf(-2.0 + 0.3 * f64::from(k));
        let p = joint.evaluate_from(20e3, w, guess)?;
        guess = Some(p.logit);
        println!("{:>12.4e} {:>12.4e} {:>10.5} {:>10.4}", w, p.sommerfeld_number, p.friction_coefficient, p.fluid_load_fraction);
    }

    // Your own joint: any subset of the parameter file; the rest keeps the defaults.
    let mine = Params::from_toml_str(
        "[geometry]\npin_radius = 0.035\nbush_radius = 0.03504\n[friction]\nboundary_friction_coefficient = 0.10\n",
    )?;
    let op = Joint::new(&mine)?.evaluate(60e3, 0.5)?;
    println!("\nR = 35 mm, c = 40 um, mu_c = 0.10 at 60 kN, 0.5 rad/s: torque = {:.1} N.m", op.torque);

    // Bad input is an error that names the quantity, its value and its unit.
    if let Err(e) = joint.evaluate(-5.0, 1.0) {
        println!("\nerror example: {e}");
    }
    Ok(())
}
