//! The flat point.

use ga_core::cga::{Bivector, Trivector};
use ga_core::prelude::*;
use nalgebra::Point3;

use super::blades::*;
use crate::error::Error;

/// A flat point, OPNS blade `F(x) ∧ n_inf` (grade 2): the meet of a line and a plane.
///
/// ```
/// use cga_collide::conformal::FlatPoint;
/// use cga_collide::nalgebra::Point3;
/// let f = FlatPoint::new(Point3::new(1.0, -2.0, 0.5))?;
/// assert_eq!(f.position(), Some(Point3::new(1.0, -2.0, 0.5)));
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatPoint {
    blade: Bivector<f64>,
}

impl FlatPoint {
    /// The flat point at `x`. Fails on a non-finite coordinate.
    pub fn new(x: Point3<f64>) -> Result<Self, Error> {
        finite3(
            "conformal::FlatPoint::new",
            ["x.x", "x.y", "x.z"],
            &x.coords,
        )?;
        Ok(FlatPoint {
            blade: embed::<f64>(&x).wedge(&n_inf::<f64>()),
        })
    }
    /// The flat point of an OPNS bivector (any nonzero multiple of `F(x) ∧ n_inf`): built
    /// from the `f64` position read from it. Fails on non-finite coefficients and on a flat
    /// point at infinity (zero weight).
    ///
    /// ```
    /// use cga_collide::conformal::FlatPoint;
    /// use cga_collide::nalgebra::Point3;
    /// let f = FlatPoint::new(Point3::new(1.0, 2.0, 3.0))?;
    /// assert_eq!(FlatPoint::from_ipns(f.ipns())?, f);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_blade(blade: Bivector<f64>) -> Result<Self, Error> {
        const C: &str = "conformal::FlatPoint::from_blade";
        finite_blade(C, blade)?;
        let x = flat_point_location(&blade)
            .ok_or_else(|| degenerate(C, "the weight is zero (a flat point at infinity)"))?;
        FlatPoint::new(x)
    }
    /// The flat point of an IPNS trivector (`from_blade(undual(F*))`).
    pub fn from_ipns(t: Trivector<f64>) -> Result<Self, Error> {
        FlatPoint::from_blade(t.undual())
    }
    pub(crate) fn from_blade_unchecked(blade: Bivector<f64>) -> Self {
        FlatPoint { blade }
    }
    /// The OPNS blade.
    pub fn blade(&self) -> &Bivector<f64> {
        &self.blade
    }
    /// The IPNS (dual) form, a trivector.
    pub fn ipns(&self) -> Trivector<f64> {
        self.blade.dual()
    }
    /// The position `(F₁₄, F₂₄, F₃₄) / (−F₄₅)`; `None` for a flat point at infinity.
    pub fn position(&self) -> Option<Point3<f64>> {
        flat_point_location(&self.blade)
    }
}
