//! The exact tests for callers that prepare each triangle once (its plane, the sides of points
//! against it) and test it against many, as the self-intersection of a mesh does: the same
//! algorithms as [`Intersects`](crate::query::Intersects), on raw corners, without recomputing
//! what the caller keeps.

use core::cmp::Ordering;

use crate::exact::{ExactKernel, ExactPlane};
use crate::query::intersects::{seg_seg, seg_tri_plane, seg_tri_sides, tri_tri_planes};

type P3 = [f64; 3];

/// Exact: do the closed triangles of the planes `p` and `q` share a point? What
/// `Triangle::intersects` decides, from planes made once per triangle.
#[inline]
pub(crate) fn triangles_meet(p: &ExactPlane, q: &ExactPlane) -> bool {
    tri_tri_planes::<ExactKernel>(p.corners(), q.corners(), p, || *q)
}
/// Exact: does the closed segment `ab` meet the closed non-degenerate triangle `t` whose plane
/// is `pl`?
#[inline]
pub(crate) fn segment_meets_triangle_plane(a: &P3, b: &P3, t: &[P3; 3], pl: &ExactPlane) -> bool {
    seg_tri_plane::<ExactKernel>(a, b, t, pl)
}
/// Exact: do the closed segments `ab` and `cd` (raw corners, finite) share a point?
#[inline]
pub(crate) fn segments_meet(a: &P3, b: &P3, c: &P3, d: &P3) -> bool {
    seg_seg::<ExactKernel>(a, b, c, d)
}

/// Exact: does the closed segment `ab` meet the closed non-degenerate triangle `t`, whose plane
/// is `pl` and against which `a` and `b` have the sides `sides` (computed once by the caller)?
pub(crate) fn segment_meets_triangle_with_sides(
    a: &P3,
    b: &P3,
    sides: [Ordering; 2],
    t: &[P3; 3],
    pl: &ExactPlane,
) -> bool {
    seg_tri_sides::<ExactKernel>(a, b, sides[0], sides[1], t, pl)
}
