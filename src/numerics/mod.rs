//! Numerical helpers of the physics, internal to the crate: the inlined exponential,
//! ln(1 + e) and sin/cos of the solve's inner loops ([`fast_math`]), the inlined logarithm
//! of the table level's cell coordinates ([`fast_ln`]), the bracketed Newton root finder of
//! the load-sharing solve and the GW inverse ([`newton`]), and the process-wide cache of
//! tables built once per parameter value ([`table_cache`]). No physics and no parameters:
//! every other module may use them, they use nothing of the crate.

pub(crate) mod fast_math;
pub(crate) mod fast_ln;
pub(crate) mod newton;
pub(crate) mod table_cache;
