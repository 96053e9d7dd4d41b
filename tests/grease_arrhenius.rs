//! The grease's Arrhenius laws at the joint's temperature (docs/cold-day.md, the complete
//! model): an activation temperature whose factor overflows is refused when the joint is built.

use pinjoint::{Joint, Params};

/// An activation temperature whose Arrhenius factor overflows at the joint's temperature
/// (E_y/R = 1.1e6 K at 233.15 K from 293.15 K: exp(966)) is refused when the joint is built
/// or moved to that temperature, naming the key and its value, not met later as an infinite
/// friction coefficient; the same key at 1e5 K (exp(87.8), finite) is accepted.
#[test]
fn an_overflowing_grease_activation_is_refused_by_name() {
    for key in ["yield_activation", "consistency_activation"] {
        let mut p = Params::default();
        match key {
            "yield_activation" => p.grease.yield_activation = 1.1e6,
            _ => p.grease.consistency_activation = 1.1e6,
        }
        // At the reference temperature the factor is 1: no overflow.
        let warm = Joint::new(&p).expect("finite at T_ref");
        let e = warm.at_temperature(233.15).unwrap_err().to_string();
        assert!(e.contains(&format!("grease.{key}")) && e.contains("233.15"), "{e}");
        p.lubricant.temperature = 233.15;
        let e = Joint::new(&p).unwrap_err().to_string();
        assert!(e.contains(&format!("grease.{key}")), "{e}");
        match key {
            "yield_activation" => p.grease.yield_activation = 1e5,
            _ => p.grease.consistency_activation = 1e5,
        }
        assert!(Joint::new(&p).is_ok());
    }
}
