//! Issue 37 item 5: the declared ranges end where the model's assumptions end
//! (docs/validity.md, "Past the model's assumptions"). Through the library, on parameter sets
//! drawn around the paper's joint (both models, any upper service temperature):
//!
//! * a load whose Hertz half-width a (eq. 6, computed here from `pinjoint::contact`) exceeds
//!   the pin radius, or a temperature above `grease.upper_service_temperature`, is answered
//!   with the validity `outside` (code 3) or refused by a named error, never `extrapolation`;
//! * just inside both edges the validity is the checked envelope's (computed here from the
//!   paper's ranges, independently of `pinjoint::validity`);
//! * the answer is continuous across each edge (only the flag changes);
//! * every fidelity level reports the same validity as the full solve;
//! * the parameter is a parameter: read from a file, range-checked by name, not re-quoted.

use pinjoint::contact::{effective_modulus, hertz, reduced_radius};
use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};
use pinjoint::params::{MAX_TEMPERATURE, MIN_TEMPERATURE, PAPER_MIN_TEMPERATURE};
use pinjoint::{Joint, ModelError, Params, Validity};
use proptest::prelude::*;
use test_support::strategies::log_uniform;

/// The checked envelope's level of a point (the paper's rig: 5–60 kN, |ω|R up to the 1 Hz
/// ±40° stroke's peak, 15–25 °C; the paper's model below 0 °C known-wrong), written out here.
fn envelope_level(load: f64, sliding_speed: f64, t: f64, paper: bool) -> Validity {
    let u_max = 2.0 * std::f64::consts::PI * 40f64.to_radians() * 0.028;
    if paper && t < 273.15 {
        Validity::KnownWrong
    } else if (5e3..=60e3).contains(&load.abs()) && sliding_speed.abs() <= u_max && (288.15..=298.15).contains(&t) {
        Validity::Checked
    } else {
        Validity::Extrapolation
    }
}

/// The Hertz half-width of eq. 6 at `load` for `p`, from the contact module.
fn half_width(p: &Params, load: f64) -> f64 {
    hertz(load.abs(), reduced_radius(&p.geometry), effective_modulus(&p.materials), p.geometry.bush_length).half_width
}

/// A joint around the paper's: geometry, moduli and clearance within a factor of about 2,
/// either model, an upper service temperature anywhere in its declared range (half the time
/// the default).
fn joint_params() -> impl Strategy<Value = Params> {
    (
        (log_uniform(0.01, 0.06), log_uniform(5e-5, 5e-3), log_uniform(0.02, 0.12)),
        (log_uniform(70e9, 300e9), log_uniform(70e9, 300e9)),
        prop::bool::ANY,
        prop_oneof![Just(None), (MIN_TEMPERATURE..=MAX_TEMPERATURE).prop_map(Some)],
    )
        .prop_map(|((r, clearance_rel, b), (e, eb), paper, t_max)| {
            let mut p = if paper { Params::paper() } else { Params::default() };
            p.geometry.pin_radius = r;
            p.geometry.bush_radius = r * (1.0 + clearance_rel);
            p.geometry.bush_length = b;
            p.materials.pin_elastic_modulus = e;
            p.materials.bush_elastic_modulus = eb;
            if let Some(t) = t_max {
                p.grease.upper_service_temperature = t;
            }
            p
        })
}

/// A temperature the model takes for `p`'s model.
fn temperature_for(p: &Params, x: f64) -> f64 {
    let lo = if p.model.paper { PAPER_MIN_TEMPERATURE } else { MIN_TEMPERATURE };
    lo + x * (MAX_TEMPERATURE - lo)
}

/// An answer past an edge: `outside`, or a refusal that names the quantity.
fn outside_or_named(r: &Result<pinjoint::OperatingPoint, ModelError>) -> Result<(), TestCaseError> {
    match r {
        Ok(op) => prop_assert_eq!(op.validity, Validity::Outside, "{:?}", op),
        Err(e) => prop_assert!(e.to_string().contains(" = "), "unnamed refusal: {}", e),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Past either edge: `outside` or a named refusal, never `extrapolation`; inside both:
    /// the envelope's level, exactly as before the edges existed.
    #[test]
    fn past_an_edge_is_outside_and_inside_is_the_envelopes_level(
        p in joint_params(),
        x in 0.0f64..=1.0,
        near_t_max in prop_oneof![1 => Just(None), 2 => (-2.0f64..2.0).prop_map(Some)],
        load_exp in prop_oneof![-2.0f64..8.0, -0.3f64..0.3],
        w in prop_oneof![Just(0.0), log_uniform(1e-3, 100.0), log_uniform(1e-3, 100.0).prop_map(|w| -w)],
        sign in prop::sample::select(vec![1.0, -1.0]),
    ) {
        let mut p = p;
        p.lubricant.temperature = temperature_for(&p, x);
        if let Some(dt) = near_t_max {
            let lo = if p.model.paper { PAPER_MIN_TEMPERATURE } else { MIN_TEMPERATURE };
            p.lubricant.temperature = (p.grease.upper_service_temperature + dt).clamp(lo, MAX_TEMPERATURE);
        }
        let joint = match Joint::new(&p) {
            Ok(j) => j,
            // Roelands' relation with these parameters (eta_0(T) beyond a glass) names the key.
            Err(e) => {
                prop_assert!(e.to_string().contains("lubricant.temperature"), "{}", e);
                return Ok(());
            }
        };
        let r = p.geometry.pin_radius;
        let load = sign * 10f64.powf(load_exp) * joint.load_edge();
        let t = p.lubricant.temperature;
        let a = half_width(&p, load);
        // Away from the edge by more than rounding, the half-width decides by itself.
        let beyond_load = a > r * (1.0 + 1e-9);
        let inside_load = a < r * (1.0 - 1e-9);
        let beyond_t = t > p.grease.upper_service_temperature;
        let answer = joint.evaluate(load, w);
        let v = joint.validity(load, w);
        if let Ok(op) = &answer {
            prop_assert_eq!(op.validity, v);
        }
        if beyond_load || beyond_t {
            prop_assert_eq!(v, Validity::Outside, "a/R = {}, T = {} K, T_max = {} K", a / r, t, p.grease.upper_service_temperature);
            outside_or_named(&answer)?;
            let x = joint.excursion(load, w).unwrap();
            prop_assert!(x.to_string().contains("beyond the model's assumptions"), "{}", x);
        } else if inside_load {
            prop_assert_eq!(v, envelope_level(load, w * r, t, p.model.paper), "a/R = {}, T = {} K", a / r, t);
        }
        // Beyond the asperity limit the refusal names it.
        if load.abs() >= joint.capacity() {
            prop_assert!(matches!(answer, Err(ModelError::BeyondCapacity { .. })), "{:?}", answer);
        }
    }

    /// The answer is continuous across the load edge and across the upper service
    /// temperature: 1e-9 either side of the edge, μ, torque and film within 1e-6 relative.
    #[test]
    fn the_answer_is_continuous_across_each_edge(
        p in joint_params(),
        x in 0.0f64..=1.0,
        w in log_uniform(1e-3, 100.0),
    ) {
        let mut p = p;
        p.lubricant.temperature = temperature_for(&p, x);
        let Ok(joint) = Joint::new(&p) else { return Ok(()) };
        let edge = joint.load_edge();
        let close = |a: &pinjoint::OperatingPoint, b: &pinjoint::OperatingPoint| -> Result<(), TestCaseError> {
            for (name, x, y) in [("mu", a.friction_coefficient, b.friction_coefficient), ("torque", a.torque, b.torque), ("film", a.film_thickness, b.film_thickness)] {
                prop_assert!((x - y).abs() <= 1e-6 * x.abs().max(y.abs()), "{}: {} against {}", name, x, y);
            }
            Ok(())
        };
        if edge < joint.capacity() * 0.5
            && let (Ok(a), Ok(b)) = (joint.evaluate(edge * (1.0 - 1e-9), w), joint.evaluate(edge * (1.0 + 1e-9), w))
        {
            // Inside the temperature edge only the load decides.
            if p.lubricant.temperature <= p.grease.upper_service_temperature {
                prop_assert_ne!(a.validity, Validity::Outside);
            }
            prop_assert_eq!(b.validity, Validity::Outside);
            close(&a, &b)?;
        }
        let t_max = p.grease.upper_service_temperature;
        let lo = if p.model.paper { PAPER_MIN_TEMPERATURE } else { MIN_TEMPERATURE };
        if t_max - 1e-6 >= lo && t_max + 1e-6 <= MAX_TEMPERATURE {
            let (Ok(below), Ok(above)) = (joint.at_temperature(t_max - 1e-6), joint.at_temperature(t_max + 1e-6)) else { return Ok(()) };
            let load = 20e3f64.min(edge * 0.5);
            if let (Ok(a), Ok(b)) = (below.evaluate(load, w), above.evaluate(load, w)) {
                prop_assert_ne!(a.validity, Validity::Outside);
                prop_assert_eq!(b.validity, Validity::Outside);
                // 2e-6 K on a temperature: the properties move by ~1e-8 relative per K.
                for (x, y) in [(a.friction_coefficient, b.friction_coefficient), (a.torque, b.torque), (a.film_thickness, b.film_thickness)] {
                    prop_assert!((x - y).abs() <= 1e-5 * x.abs().max(y.abs()), "{} against {}", x, y);
                }
            }
        }
    }
}

/// The paper's joint: the edge is where a = R (96.7 kN), the answers past it are the
/// equations' (no refusal up to the asperity limit), 400 °C is `outside`, not the
/// `extrapolation` of 26 °C; every fidelity level says the same.
#[test]
fn the_papers_joint_at_the_issues_points() {
    for p in [Params::default(), Params::paper()] {
        let j = Joint::new(&p).unwrap();
        let edge = j.load_edge();
        assert!((half_width(&p, edge) / 0.028 - 1.0).abs() < 1e-12);
        assert!((96.6e3..96.7e3).contains(&edge), "{edge}");
        assert!(j.capacity() > 1e3 * edge);
        assert_eq!(j.evaluate(edge, 1.0).unwrap().validity, Validity::Extrapolation);
        for load in [edge.next_up(), 97e3, 2e5, 1e6, 1e8] {
            assert_eq!(j.evaluate(load, 1.0).unwrap().validity, Validity::Outside, "{load} N");
            assert_eq!(j.evaluate(-load, 1.0).unwrap().validity, Validity::Outside, "{load} N");
        }
        assert_eq!(j.at_temperature(299.15).unwrap().evaluate(20e3, 1.0).unwrap().validity, Validity::Extrapolation);
        assert_eq!(j.at_temperature(394.15).unwrap().evaluate(20e3, 1.0).unwrap().validity, Validity::Extrapolation);
        for t in [394.15f64.next_up(), 394.16, 450.15, 673.15] {
            assert_eq!(j.at_temperature(t).unwrap().evaluate(20e3, 1.0).unwrap().validity, Validity::Outside, "{t} K");
        }
        // Every fidelity level answers with the full solve's validity, in and out of its envelope.
        let env = Envelope::new(5e3, 200e3, 0.01, 10.0).unwrap();
        for fidelity in [Fidelity::Full, Fidelity::Table, Fidelity::Boundary, Fidelity::Auto] {
            for t in [293.15, 400.0] {
                let mut q = p;
                q.lubricant.temperature = t;
                let mut ev = Evaluator::new(&q, fidelity, 1e-3, env).unwrap();
                for (load, w) in [(20e3, 1.0), (96e3, 0.5), (150e3, 0.5), (1e6, 0.5)] {
                    let (op, _, _) = ev.evaluate_complete(load, w).unwrap();
                    let expect = Joint::new(&q).unwrap().validity(load, w);
                    assert_eq!(op.validity, expect, "{fidelity:?} at {load} N, {w} rad/s, {t} K");
                    assert_eq!(expect == Validity::Outside, load > edge || t > 394.15);
                }
            }
        }
    }
}

/// `grease.upper_service_temperature` is a parameter: the file's key, range-checked by name,
/// absolute (re-quoting the lubricant at another reference temperature leaves it alone), and
/// 673.15 K (the declared maximum) turns the temperature edge off.
#[test]
fn the_upper_service_temperature_is_a_parameter() {
    let p = Params::from_toml_str("[grease]\nupper_service_temperature = 450.15\n").unwrap();
    assert_eq!(p.grease.upper_service_temperature, 450.15);
    assert!(Params::default().to_toml_string().contains("upper_service_temperature = 394.15"));
    for bad in ["100.0", "700.0", "nan", "-1.0"] {
        let e = Params::from_toml_str(&format!("[grease]\nupper_service_temperature = {bad}\n")).unwrap_err().to_string();
        assert!(e.contains("grease.upper_service_temperature") && e.contains(" K"), "{e}");
    }
    let j = Joint::new(&p).unwrap();
    assert_eq!(j.at_temperature(450.15).unwrap().validity(20e3, 1.0), Validity::Extrapolation);
    assert_eq!(j.at_temperature(451.0).unwrap().validity(20e3, 1.0), Validity::Outside);
    // Off: the declared maximum.
    let mut off = Params::default();
    off.grease.upper_service_temperature = MAX_TEMPERATURE;
    off.lubricant.temperature = MAX_TEMPERATURE;
    assert_eq!(Joint::new(&off).unwrap().validity(20e3, 1.0), Validity::Extrapolation);
    // The same grease quoted at 40 C: the edge does not move.
    let mut quoted = Params::default();
    quoted.lubricant.reference_temperature = 313.15;
    assert_eq!(pinjoint::validity::Edges::new(&quoted).temperature, 394.15);
    // A lower limit moves the edge below the checked box: 20 C is then outside.
    let mut low = Params::default();
    low.grease.upper_service_temperature = 290.0;
    assert_eq!(Joint::new(&low).unwrap().validity(20e3, 1.0), Validity::Outside);
    assert_eq!(Joint::new(&low).unwrap().at_temperature(289.0).unwrap().validity(20e3, 1.0), Validity::Checked);
}
