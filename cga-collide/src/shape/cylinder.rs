//! The solid cylinder with flat caps.

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::shape::limits::{check_point, check_radius};

/// The closed solid cylinder of axis segment `[a, b]` and radius `radius`: the points whose
/// projection on the line `ab` falls in `[a, b]` and whose distance to that line is at most
/// `radius`. The caps are the flat discs at `a` and `b`, perpendicular to `b - a`.
///
/// `a == b` is refused (the caps' plane would be undefined); radius `0` gives the segment.
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::Cylinder, Error};
/// let c = Cylinder::new(Point3::origin(), Point3::new(0.0, 0.0, 1.0), 0.25)?;
/// assert_eq!(c.b().z, 1.0);
/// let flat = Cylinder::new(Point3::origin(), Point3::origin(), 1.0);
/// assert!(matches!(flat, Err(Error::Degenerate { .. })));
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    a: Point3<f64>,
    b: Point3<f64>,
    radius: f64,
}

impl Cylinder {
    /// The cylinder of axis `[a, b]`; fails on non-finite or out-of-range values, a negative
    /// radius, or `a == b`.
    pub fn new(a: Point3<f64>, b: Point3<f64>, radius: f64) -> Result<Self, Error> {
        check_point("Cylinder", "a", &a)?;
        check_point("Cylinder", "b", &b)?;
        check_radius("Cylinder", radius)?;
        if a == b {
            return Err(Error::Degenerate {
                constructor: "Cylinder::new",
                reason: "the axis ends a and b coincide, so the caps have no plane",
            });
        }
        Ok(Cylinder { a, b, radius })
    }

    /// The centre of the first cap.
    pub fn a(&self) -> &Point3<f64> {
        &self.a
    }

    /// The centre of the second cap.
    pub fn b(&self) -> &Point3<f64> {
        &self.b
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// This cylinder moved by `pose`: both ends mapped in `f64` and rounded once, the radius
    /// unchanged. Fails if the rounded ends coincide or leave the range.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        Cylinder::new(pose * self.a, pose * self.b, self.radius)
    }
}
