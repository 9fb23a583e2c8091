//! Poses as the queries take them: a rigid motion `nalgebra::Isometry3<f64>` per mesh, a
//! [`PosePair`] per query of a batch, and [`pose_from_degrees`], the convention of the command
//! line (`--rotate ax,ay,az --translate tx,ty,tz`) as a function, so that a pose written for one
//! is the same pose in the other.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

/// The poses of the two meshes of one query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PosePair {
    /// Pose of the first mesh (`self` of the query).
    pub a: Isometry3<f64>,
    /// Pose of the second mesh.
    pub b: Isometry3<f64>,
}

impl PosePair {
    /// The pair of poses.
    pub fn new(a: Isometry3<f64>, b: Isometry3<f64>) -> PosePair {
        PosePair { a, b }
    }
}

/// The rigid motion that rotates by `degrees[0]` about the x axis, then by `degrees[1]` about
/// the y axis, then by `degrees[2]` about the z axis (fixed axes, right-handed, counter-clockwise
/// looking down the axis), then translates by `translation`: `x ↦ Rz Ry Rx x + t`. This is the
/// convention of the `cga` command line's `--rotate` and `--translate`.
///
/// ```
/// use cga_collide::collider::pose_from_degrees;
/// use cga_collide::nalgebra::Point3;
/// let pose = pose_from_degrees([0.0, 0.0, 90.0], [1.0, 0.0, 0.0]);
/// let p = pose * Point3::new(1.0, 0.0, 0.0); // turned onto +y, then moved along +x
/// assert!((p - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-15);
/// ```
pub fn pose_from_degrees(degrees: [f64; 3], translation: [f64; 3]) -> Isometry3<f64> {
    let [ax, ay, az] = degrees.map(f64::to_radians);
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), az)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), ay)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), ax);
    let [tx, ty, tz] = translation;
    Isometry3::from_parts(Translation3::new(tx, ty, tz), rotation)
}
