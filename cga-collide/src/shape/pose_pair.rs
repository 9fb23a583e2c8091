//! [`PosePair`]: the poses of the two objects of one query of a batch.

use nalgebra::Isometry3;

/// The poses of the two objects of one query: two meshes
/// ([`Collider::collides_batch`](crate::collider::Collider::collides_batch) and the rest) or
/// two shapes ([`query::intersects_batch`](crate::query::intersects_batch) and the rest).
/// Also reachable as `cga_collide::collider::PosePair`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PosePair {
    /// Pose of the first object (`self` of a collider query, `a` of a shape query).
    pub a: Isometry3<f64>,
    /// Pose of the second object.
    pub b: Isometry3<f64>,
}

impl PosePair {
    /// The pair of poses.
    pub fn new(a: Isometry3<f64>, b: Isometry3<f64>) -> PosePair {
        PosePair { a, b }
    }
}
