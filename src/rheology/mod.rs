//! The lubricants' rheology: the base oil's Roelands pressure–viscosity (eq. 5), the Bair–Winer
//! limiting shear stress (eq. 4) and their temperature dependence ([`viscosity`]); Roelands'
//! temperature relation on plain numbers, shared with the parameter checks
//! (`roelands_temperature`, internal); the grease in the clearance, Herschel–Bulkley with
//! Arrhenius temperature laws, and its defaults with their sources ([`grease`]).
//!
//! [`crate::params`] uses the plain-number parts (the grease's defaults and Arrhenius law,
//! Roelands' temperature factor) to check and default a parameter set; [`viscosity`] takes
//! the parameter set's [`crate::params::Lubricant`].

pub(crate) mod roelands_temperature;
pub mod grease;
pub mod viscosity;
