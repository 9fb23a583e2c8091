//! The closed half-space below a plane.

use nalgebra::{Isometry3, Point3, Vector3};

use crate::error::Error;
use crate::shape::limits::{check_point, check_vector};

/// The closed half-space `{x : (x − point)·normal ≤ 0}`: `normal` points out of the solid.
/// The normal need not be unit length; a zero normal is refused.
///
/// ```
/// use cga_collide::{nalgebra::{Point3, Vector3}, shape::HalfSpace};
/// let ground = HalfSpace::new(Point3::origin(), Vector3::z())?;
/// assert_eq!(ground.normal().z, 1.0);
/// assert!(HalfSpace::new(Point3::origin(), Vector3::zeros()).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfSpace {
    point: Point3<f64>,
    normal: Vector3<f64>,
}

impl HalfSpace {
    /// The half-space through `point` with outward `normal`; fails on non-finite or
    /// out-of-range values and on a zero normal.
    pub fn new(point: Point3<f64>, normal: Vector3<f64>) -> Result<Self, Error> {
        check_point("HalfSpace", "point", &point)?;
        check_vector("HalfSpace", "normal", &normal)?;
        if normal == Vector3::zeros() {
            return Err(Error::Degenerate {
                constructor: "HalfSpace::new",
                reason: "the normal is zero, so there is no boundary plane",
            });
        }
        Ok(HalfSpace { point, normal })
    }

    /// A point of the boundary plane.
    pub fn point(&self) -> &Point3<f64> {
        &self.point
    }

    /// The outward normal (as given, not normalised).
    pub fn normal(&self) -> &Vector3<f64> {
        &self.normal
    }

    /// This half-space moved by `pose`: the point mapped and the normal rotated, each in `f64`
    /// and rounded once. Fails if the rounded normal is zero (it cannot be for a rotation of a
    /// non-zero vector of normal magnitude) or a value leaves the range.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        HalfSpace::new(pose * self.point, pose * self.normal)
    }
}
