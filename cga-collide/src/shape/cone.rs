//! The solid cone with its base disc.

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::shape::limits::{check_point, check_radius};

/// The closed solid cone: the convex hull of the `apex` and the base disc of centre `base`
/// and radius `radius`, perpendicular to `base - apex`.
///
/// `apex == base` is refused (the base plane would be undefined); radius `0` gives the
/// segment `[apex, base]`.
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::Cone};
/// let c = Cone::new(Point3::new(0.0, 0.0, 1.0), Point3::origin(), 0.5)?;
/// assert_eq!(c.apex().z, 1.0);
/// assert!(Cone::new(Point3::origin(), Point3::origin(), 0.5).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cone {
    apex: Point3<f64>,
    base: Point3<f64>,
    radius: f64,
}

impl Cone {
    /// The cone of the given apex, base centre and base radius; fails on non-finite or
    /// out-of-range values, a negative radius, or `apex == base`.
    pub fn new(apex: Point3<f64>, base: Point3<f64>, radius: f64) -> Result<Self, Error> {
        check_point("Cone", "apex", &apex)?;
        check_point("Cone", "base", &base)?;
        check_radius("Cone", radius)?;
        if apex == base {
            return Err(Error::Degenerate {
                constructor: "Cone::new",
                reason: "the apex and the base centre coincide, so the base has no plane",
            });
        }
        Ok(Cone { apex, base, radius })
    }

    /// The apex.
    pub fn apex(&self) -> &Point3<f64> {
        &self.apex
    }

    /// The centre of the base disc.
    pub fn base(&self) -> &Point3<f64> {
        &self.base
    }

    /// The radius of the base disc.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// This cone moved by `pose`: apex and base centre mapped in `f64` and rounded once, the
    /// radius unchanged. Fails if the rounded points coincide or leave the range.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        Cone::new(pose * self.apex, pose * self.base, self.radius)
    }
}
