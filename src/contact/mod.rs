//! The contact of the pin in its bush and its asperities: the conformal contact's reduced
//! radius, effective modulus and Hertz line-contact quantities (eq. 6; `hertz`, re-exported
//! here), the Greenwood–Williamson statistical function F_{3/2} (eq. 16; [`gw`]) and the
//! asperity side of the load sharing (eqs. 17–19; [`asperity`]).

mod hertz;
pub use hertz::{effective_modulus, hertz, reduced_radius, Hertz};
pub mod gw;
pub mod asperity;
