//! The conformal point.

use ga_core::cga::Vector;
use nalgebra::Point3;

use super::blades::*;
use crate::error::Error;

/// A conformal point `F(x) = 2 up(x)` (grade 1).
///
/// ```
/// use cga_collide::conformal::Point;
/// use cga_collide::nalgebra::Point3;
/// let p = Point::new(Point3::new(1.0, 0.0, 2.0))?;
/// // The thesis's example (II.7): F((1,0,2)) = 2e1 + 4e3 + 5n − n̄.
/// assert_eq!(p.blade().e1, 2.0);
/// assert_eq!(p.blade().e3, 4.0);
/// assert_eq!(p.position(), Some(Point3::new(1.0, 0.0, 2.0)));
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    blade: Vector<f64>,
}

impl Point {
    /// The conformal point of `x`; fails on a non-finite coordinate.
    pub fn new(x: Point3<f64>) -> Result<Self, Error> {
        finite3("conformal::Point::new", ["x.x", "x.y", "x.z"], &x.coords)?;
        Ok(Point {
            blade: embed::<f64>(&x),
        })
    }
    /// A point from any nonzero multiple of a null vector `up(x)`; fails if the weight
    /// `−X·n_inf` is zero (a point at infinity) or a coefficient is not finite.
    /// The vector is not required to be null: `down` of it is taken.
    ///
    /// ```
    /// use cga_collide::conformal::Point;
    /// use cga_collide::ga_core::cga::{up, n_inf};
    /// use cga_collide::nalgebra::Point3;
    /// let p = Point::from_blade(up(&Point3::new(1.0, 2.0, 3.0)) * 5.0)?;
    /// assert_eq!(p.position(), Some(Point3::new(1.0, 2.0, 3.0)));
    /// assert!(Point::from_blade(n_inf()).is_err());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_blade(v: Vector<f64>) -> Result<Self, Error> {
        const C: &str = "conformal::Point::from_blade";
        finite_blade(C, v)?;
        let x = down(&v).ok_or_else(|| degenerate(C, "the weight −X·n_inf is zero"))?;
        Point::new(x)
    }
    /// The blade `F(x)` (or the transformed multiple of it).
    pub fn blade(&self) -> &Vector<f64> {
        &self.blade
    }
    /// The Euclidean position (`None` if it is not finite).
    pub fn position(&self) -> Option<Point3<f64>> {
        down(&self.blade)
    }
}
