//! The capsule: every point within a radius of a segment.

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::shape::limits::{check_point, check_radius};

/// The closed set of points within distance `radius` of the segment `[a, b]` (a cylinder with
/// round caps). `a == b` gives a ball, radius `0` the segment itself; both are valid.
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::Capsule};
/// let c = Capsule::new(Point3::origin(), Point3::new(0.0, 0.0, 2.0), 0.5)?;
/// assert_eq!(c.radius(), 0.5);
/// assert!(Capsule::new(Point3::origin(), Point3::origin(), -1.0).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capsule {
    a: Point3<f64>,
    b: Point3<f64>,
    radius: f64,
}

impl Capsule {
    /// The capsule around `[a, b]`; fails on non-finite or out-of-range values and on a
    /// negative radius.
    pub fn new(a: Point3<f64>, b: Point3<f64>, radius: f64) -> Result<Self, Error> {
        check_point("Capsule", "a", &a)?;
        check_point("Capsule", "b", &b)?;
        check_radius("Capsule", radius)?;
        Ok(Capsule { a, b, radius })
    }

    /// The first end of the axis segment.
    pub fn a(&self) -> &Point3<f64> {
        &self.a
    }

    /// The second end of the axis segment.
    pub fn b(&self) -> &Point3<f64> {
        &self.b
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// This capsule moved by `pose`: both ends mapped in `f64` and rounded once, the radius
    /// unchanged.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        Capsule::new(pose * self.a, pose * self.b, self.radius)
    }
}
