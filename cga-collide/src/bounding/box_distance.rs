//! Distances between boxes, for the clearance and nearest-pair searches: a lower bound to
//! order and prune by, and a conservative "within distance" test.

use crate::bounding::aabb::Aabb;

/// A lower bound on the squared distance between two boxes, in `f64`, never above the true
/// value by more than a few ulps (only used to order and prune the distance search, whose
/// result is certified separately).
#[inline]
pub(crate) fn box_distance2(a: &Aabb, b: &Aabb) -> f64 {
    let mut s = 0.0;
    for k in 0..3 {
        let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
        s += g * g;
    }
    s
}

/// Conservative: `false` only if the closed boxes are certainly farther apart than `c`
/// (`c >= 0`). Per axis, a rounded gap above `c` proves a true gap above `c` (rounding is
/// monotone and `c` is an `f64`); the Euclidean sum gets a relative margin far above its
/// rounding error.
#[inline]
pub(crate) fn boxes_within(a: &Aabb, b: &Aabb, c: f64) -> bool {
    let mut s = 0.0;
    for k in 0..3 {
        let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
        if g > c {
            return false;
        }
        s += g * g;
    }
    let c2 = c * c;
    !c2.is_finite() || s * (1.0 - 1e-9) <= c2 * (1.0 + 1e-9) + 1e-300
}
