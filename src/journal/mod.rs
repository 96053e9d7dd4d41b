//! The joint as a hydrodynamic journal bearing (issue 28, item 1): once the film is not small
//! against the radial clearance c, the pin turning in its bush is a plain 360° journal
//! bearing, whose eccentricity ratio ε follows from the Sommerfeld number
//! S = (R/c)² ηN/P (N in rev/s, P the load over the projected area 2RB).
//!
//! - [`reynolds`]: the finite-volume solution of the Reynolds equation of the finite bearing
//!   with the Swift–Stieber (Reynolds) cavitation condition at one ε (a linear complementarity
//!   problem, solved by a primal–dual active-set method with a banded Cholesky factorisation).
//! - [`limits`]: the limits it tends to (Petroff's concentric journal, Ocvirk's short bearing,
//!   the infinitely long bearing with the Reynolds condition by 1-D quadrature).
//! - [`interp`]: the monotone C¹ interpolation of the table.
//! - [`table`]: S(ε), φ(ε), the friction variable (R/c) f(ε), tabulated once per L/D
//!   (a process-wide cache), and the inverse ε(S) with dε/d ln S: [`JournalTable`].
//!
//! Checked against Raimondi & Boyd (1958), "A solution for the finite journal bearing and its
//! application to analysis and design", ASLE Trans. 1, parts I–III, the table for L/D = 1 as
//! reproduced in Shigley's *Mechanical Engineering Design* (the chapter on lubrication and
//! journal bearings): see the tests of [`table`] for the values and the measured agreement.
//!
//! Assumptions (as Raimondi & Boyd): rigid surfaces, isoviscous Newtonian lubricant, no
//! misalignment, steady load, laminar flow, the clearance flooded (the ends at ambient
//! pressure, no supply groove).

pub mod reynolds;
pub mod limits;
pub mod interp;
pub mod table;

pub use table::JournalTable;

/// Errors of the journal-bearing table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JournalError {
    /// The length-to-diameter ratio is not a positive finite number.
    #[error("journal bearing: the length-to-diameter ratio L/D = B/(2R) = {value} (dimensionless) must be positive and finite")]
    LengthToDiameter {
        /// L/D given.
        value: f64,
    },
    /// A Reynolds solve failed (not reachable for a valid L/D; a guard).
    #[error(transparent)]
    Solve(#[from] reynolds::SolveError),
    /// The solved S(ε) was not strictly decreasing (not reachable; a guard of the table).
    #[error("journal bearing: the solved Sommerfeld numbers are not strictly decreasing in the eccentricity ratio at L/D = {length_to_diameter}")]
    NotMonotone {
        /// L/D of the table.
        length_to_diameter: f64,
    },
}
