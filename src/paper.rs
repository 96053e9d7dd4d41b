//! The paper's test conditions, in one place (SI units unless the name says otherwise): the
//! loads and frequencies of the rig experiments (section 4, Figures 8–13), the speed range of
//! its simulations (Figures 3 and 4), and what it measured. The model's parameters (Tables
//! 1–3) are [`crate::Params::default`].

/// The rig's test loads (N): 5, 10, 20, 40 and 60 kN (section 4, Figures 8–13).
pub const LOADS: [f64; 5] = [5e3, 10e3, 20e3, 40e3, 60e3];

/// The rig's stroke frequencies (Hz): 0.03, 0.3 and 1 Hz (Figures 11–13).
pub const FREQUENCIES: [f64; 3] = [0.03, 0.3, 1.0];

/// The stroke amplitude of the experiments: ±40° (rad).
pub const STROKE_AMPLITUDE: f64 = 40.0 * std::f64::consts::PI / 180.0;

/// The speed range (rpm) of the paper's simulations, Figures 3 and 4: 1–800 rpm.
pub const SPEED_RANGE_RPM: (f64, f64) = (1.0, 800.0);

/// The friction coefficient the paper measured at low speed (section 5), against the assumed
/// μ_c = 0.12 of Table 3.
pub const MEASURED_LOW_SPEED_MU: f64 = 0.117;

#[cfg(test)]
mod tests {
    #[test]
    fn amplitude_is_forty_degrees() {
        assert!((super::STROKE_AMPLITUDE.to_degrees() - 40.0).abs() < 1e-12);
    }
}
