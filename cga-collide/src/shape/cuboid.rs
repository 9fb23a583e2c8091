//! The solid box: a centre and three half axes (any parallelepiped, flat ones included).

use nalgebra::{Isometry3, Point3, Vector3};

use crate::error::Error;
use crate::shape::limits::{check_point, check_vector};

/// The closed solid `centre + s₁·U + s₂·V + s₃·W` with `|sᵢ| ≤ 1`, for half axes `U, V, W`.
///
/// The half axes are usually orthogonal (a box), but any three vectors are allowed and the
/// set is exactly the parallelepiped they span, with the exact real values of the `f64`s
/// given: its corners `centre ± U ± V ± W` are exact sums, never rounded. Dependent half axes
/// give the flat parallelogram, segment or point they span, which is a valid shape.
///
/// ```
/// use cga_collide::{nalgebra::{Point3, Vector3}, shape::Cuboid};
/// let unit = Cuboid::axis_aligned(Point3::origin(), Vector3::new(0.5, 0.5, 0.5))?;
/// assert_eq!(unit.half_axes()[2], Vector3::new(0.0, 0.0, 0.5));
/// assert!(Cuboid::axis_aligned(Point3::origin(), Vector3::new(-1.0, 1.0, 1.0)).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cuboid {
    centre: Point3<f64>,
    half_axes: [Vector3<f64>; 3],
}

impl Cuboid {
    /// The parallelepiped of the given centre and half axes; fails on non-finite or
    /// out-of-range values ([`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE)).
    pub fn new(centre: Point3<f64>, half_axes: [Vector3<f64>; 3]) -> Result<Self, Error> {
        check_point("Cuboid", "centre", &centre)?;
        for (axis, argument) in
            half_axes
                .iter()
                .zip(["half_axes[0]", "half_axes[1]", "half_axes[2]"])
        {
            check_vector("Cuboid", argument, axis)?;
        }
        Ok(Cuboid { centre, half_axes })
    }

    /// The axis-aligned box `centre ± half_extents`; every half extent must be `>= 0`.
    pub fn axis_aligned(centre: Point3<f64>, half_extents: Vector3<f64>) -> Result<Self, Error> {
        if half_extents.iter().any(|h| *h < 0.0) {
            return Err(Error::Degenerate {
                constructor: "Cuboid::axis_aligned",
                reason: "a half extent is negative",
            });
        }
        Cuboid::new(
            centre,
            [
                Vector3::new(half_extents.x, 0.0, 0.0),
                Vector3::new(0.0, half_extents.y, 0.0),
                Vector3::new(0.0, 0.0, half_extents.z),
            ],
        )
    }

    /// The centre.
    pub fn centre(&self) -> &Point3<f64> {
        &self.centre
    }

    /// The three half axes.
    pub fn half_axes(&self) -> &[Vector3<f64>; 3] {
        &self.half_axes
    }

    /// This box moved by `pose`: the centre is mapped and each half axis rotated, each in `f64`
    /// and rounded once (the crate's placement rule); fails if a value leaves the range.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        Cuboid::new(pose * self.centre, self.half_axes.map(|h| pose * h))
    }
}
