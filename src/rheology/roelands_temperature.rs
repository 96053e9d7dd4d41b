//! Roelands' temperature–viscosity relation on plain numbers (the relation is documented at
//! [`crate::rheology::viscosity::at_temperature`]): a leaf module, so that the parameter checks
//! ([`crate::params`]) and the rheology ([`crate::rheology::viscosity`]) share one formula without
//! depending on each other.

/// f = [(135 + θ)/(135 + θ_ref)]^−S0, θ and θ_ref the temperature and the reference
/// temperature in °C (`temperature`, `reference` in K; 1 at T = T_ref).
pub fn factor(temperature: f64, reference: f64, s0: f64) -> f64 {
    const ZERO_C: f64 = 273.15;
    ((135.0 + temperature - ZERO_C) / (135.0 + reference - ZERO_C)).powf(-s0)
}

/// η0 at `temperature` (Pa·s) from η0 = `viscosity` at `reference`, Roelands' η∞ = `limit`
/// and S0: ln(η0(T)/η∞) = ln(η0(T_ref)/η∞)·f. At T = T_ref `viscosity` itself, bit for bit.
pub fn viscosity(viscosity: f64, limit: f64, temperature: f64, reference: f64, s0: f64) -> f64 {
    if temperature == reference {
        return viscosity;
    }
    limit * ((viscosity / limit).ln() * factor(temperature, reference, s0)).exp()
}
