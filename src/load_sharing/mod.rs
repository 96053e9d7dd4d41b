//! The load-sharing solve: eqs. 9, 13 and 19 in the fluid share γ1, the asperity share γ2 and
//! the central film h_c ([`solve`]: one strictly increasing residual in the logit of the
//! shares, Newton's method in a bracket), and its deterministic start, a table of the root
//! over (ln P_T, ln u) ([`start`]).

pub mod solve;
pub mod start;
