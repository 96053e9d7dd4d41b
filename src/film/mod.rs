//! The lubricant film in the contact: Moes' central film thickness of a line contact and its
//! load-sharing form (eqs. 12–14; `central.rs`, re-exported here), the minimum film h_min
//! ([`min_film`], an extension), the starved inlet ([`starvation`], an extension) and the
//! grease's oil supply to the inlet ([`cold_supply`], the complete model). Plain numbers and
//! dimensionless groups: no parameter set.

mod central;
pub use central::{
    eq13_closed_form, ln_moes, ln_moes_directional, ln_moes_grad, ln_moes_grad_directional, ln_moes_slope, ln_scaled_moes,
    ln_scaled_moes_grad, ln_scaled_moes_slope, log_add_exp, moes,
};
pub mod min_film;
pub mod starvation;
pub mod cold_supply;
