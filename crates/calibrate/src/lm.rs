//! The `levenberg-marquardt` crate's view of a fit, shared by the quasi-static fit
//! ([`crate::fit`]) and the rig fit ([`crate::rig_fit`]).

use levenberg_marquardt::LeastSquaresProblem;
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};

/// A least-squares problem in the fit coordinates β: the residuals (model − y) and their
/// Jacobian, None when they cannot be had (the implementor keeps the reason).
pub trait Residuals {
    /// Residuals model − y at β.
    fn residuals_at(&self, beta: &DVector<f64>) -> Option<DVector<f64>>;
    /// Jacobian of the residuals at β.
    fn jacobian_at(&self, beta: &DVector<f64>) -> Option<DMatrix<f64>>;
}

/// A [`Residuals`] with its current β, as `LevenbergMarquardt::minimize` takes it.
pub struct Adapter<'a, R: Residuals> {
    /// The problem.
    pub fit: &'a R,
    /// The current coordinates.
    pub beta: DVector<f64>,
}

impl<R: Residuals> LeastSquaresProblem<f64, Dyn, Dyn> for Adapter<'_, R> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.beta.copy_from(x);
    }
    fn params(&self) -> DVector<f64> {
        self.beta.clone()
    }
    fn residuals(&self) -> Option<DVector<f64>> {
        self.fit.residuals_at(&self.beta)
    }
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        self.fit.jacobian_at(&self.beta)
    }
}
