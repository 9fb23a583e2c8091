//! Tests between coplanar sets, decided in an axis projection: the 2D segment and triangle
//! tests, the projection that is one-to-one on a plane, and the exact entry points for callers
//! that know the axis-parallel plane their points lie in (the self-intersection of a mesh keeps
//! it per face).
//!
//! Coplanar sets meet exactly when their images in a projection that is one-to-one on their
//! plane meet; where that projection is not certain, all three are tested (coplanar convex sets
//! meet iff all three projections meet).

use core::cmp::Ordering::{self, Equal, Greater};

use crate::exact::predicates::EdgeSide;
use crate::exact::{ExactKernel, ExactPlane, Kernel, PlaneSide};

type P3 = [f64; 3];
type P2 = [f64; 2];

#[inline]
pub(super) fn orient2d<K: Kernel>(a: &P2, b: &P2, c: &P2) -> Ordering {
    // Coplanar tests meet many exact zeros from equal coordinates (points on axis-parallel
    // lines): both products have a zero factor, decided by comparisons before any filter.
    if (b[0] == a[0] || c[1] == a[1]) && (b[1] == a[1] || c[0] == a[0]) {
        return Equal;
    }
    K::orient2d(a, b, c)
}

/// The two extreme points of collinear points (exact: order along an axis where they differ).
pub(crate) fn extremes<const D: usize>(p: &[[f64; D]]) -> ([f64; D], [f64; D]) {
    for k in 0..D {
        let (mut lo, mut hi) = (0, 0);
        for (i, q) in p.iter().enumerate() {
            if q[k] < p[lo][k] {
                lo = i;
            }
            if q[k] > p[hi][k] {
                hi = i;
            }
        }
        if p[lo][k] < p[hi][k] {
            return (p[lo], p[hi]);
        }
    }
    (p[0], p[0])
}

/// An axis along which all the points have the same coordinate: they lie in one plane
/// perpendicular to it, which the projection dropping that coordinate maps one-to-one, so
/// sets of these points meet exactly when their projections do. Comparisons only.
#[inline]
pub(super) fn common_axis<const N: usize>(p: &[&P3; N]) -> Option<usize> {
    (0..3)
        .rev()
        .find(|&k| p[1..].iter().all(|q| q[k] == p[0][k]))
}

/// Drops coordinate `k`.
#[inline]
pub(super) fn proj(p: &P3, k: usize) -> P2 {
    match k {
        0 => [p[1], p[2]],
        1 => [p[0], p[2]],
        _ => [p[0], p[1]],
    }
}

/// Closed 2D segments (possibly points).
pub(super) fn seg2_seg2<K: Kernel>(a: &P2, b: &P2, c: &P2, d: &P2) -> bool {
    let o1 = orient2d::<K>(a, b, c);
    let o2 = orient2d::<K>(a, b, d);
    if o1 == o2 && o1 != Equal {
        return false;
    }
    let o3 = orient2d::<K>(c, d, a);
    let o4 = orient2d::<K>(c, d, b);
    segments_cross([o1, o2, o3, o4], a, b, c, d)
}

/// Whether the closed 2D segments `ab` and `cd` meet, given `[orient2d(a, b, c),
/// orient2d(a, b, d), orient2d(c, d, a), orient2d(c, d, b)]` (callers that test many edges
/// compute each sign once).
#[inline]
fn segments_cross(o: [Ordering; 4], a: &P2, b: &P2, c: &P2, d: &P2) -> bool {
    if (o[0] == o[1] && o[0] != Equal) || (o[2] == o[3] && o[2] != Equal) {
        return false;
    }
    if o.iter().all(|&s| s == Equal) {
        // All on one line (or points): overlap of the intervals along an axis where they differ.
        let all = [*a, *b, *c, *d];
        let k = if all.iter().all(|p| p[0] == a[0]) {
            1
        } else {
            0
        };
        let (lo1, hi1) = (a[k].min(b[k]), a[k].max(b[k]));
        let (lo2, hi2) = (c[k].min(d[k]), c[k].max(d[k]));
        return lo1 <= hi2 && lo2 <= hi1;
    }
    true
}

/// The sides of `x` against the three edges `t[i] t[i+1]` of a 2D triangle.
#[inline]
fn edge_sides<K: Kernel>(t: &[P2; 3], x: &P2) -> [Ordering; 3] {
    [
        orient2d::<K>(&t[0], &t[1], x),
        orient2d::<K>(&t[1], &t[2], x),
        orient2d::<K>(&t[2], &t[0], x),
    ]
}

/// A point with edge sides `o` is in the closed non-degenerate triangle of orientation `s`.
#[inline]
fn inside(o: &[Ordering; 3], s: Ordering) -> bool {
    o.iter().all(|&x| x == s || x == Equal)
}

/// Points with edge sides `o` all lie strictly outside one edge of a triangle of orientation
/// `s` (the open half-plane beyond that edge's line holds them, the triangle does not meet it).
#[inline]
fn beyond_one_edge<const M: usize>(o: &[[Ordering; 3]; M], s: Ordering) -> bool {
    let outside = s.reverse();
    (0..3).any(|e| o.iter().all(|x| x[e] == outside))
}

pub(super) fn seg2_tri2<K: Kernel>(a: &P2, b: &P2, t: &[P2; 3]) -> bool {
    let s = orient2d::<K>(&t[0], &t[1], &t[2]);
    if s == Equal {
        let (e0, e1) = extremes(t);
        return seg2_seg2::<K>(a, b, &e0, &e1);
    }
    // Every sign once: `a` and `b` against the edges, the corners against the line `ab`; the
    // edge tests below reuse them.
    let oa = edge_sides::<K>(t, a);
    if inside(&oa, s) {
        return true;
    }
    if a == b {
        return false;
    }
    let ob = edge_sides::<K>(t, b);
    if inside(&ob, s) {
        return true;
    }
    if beyond_one_edge(&[oa, ob], s) {
        return false;
    }
    let ot = [
        orient2d::<K>(a, b, &t[0]),
        orient2d::<K>(a, b, &t[1]),
        orient2d::<K>(a, b, &t[2]),
    ];
    (0..3).any(|i| {
        let j = (i + 1) % 3;
        segments_cross([ot[i], ot[j], oa[i], ob[i]], a, b, &t[i], &t[j])
    })
}

fn tri2_tri2<K: Kernel>(t: &[P2; 3], u: &[P2; 3]) -> bool {
    let st = orient2d::<K>(&t[0], &t[1], &t[2]);
    if st == Equal {
        let (e0, e1) = extremes(t);
        return seg2_tri2::<K>(&e0, &e1, u);
    }
    let su = orient2d::<K>(&u[0], &u[1], &u[2]);
    if su == Equal {
        let (e0, e1) = extremes(u);
        return seg2_tri2::<K>(&e0, &e1, t);
    }
    // Every corner against every edge of the other triangle, once (18 signs instead of up to
    // 42 for the nine edge pairs); a corner inside the other, or all corners beyond one edge,
    // decide early.
    // Any corner inside the other closed triangle decides at once (touching neighbours: a
    // corner on the other's edge); the edge tests would find it only after every sign.
    let ut = [0, 1, 2].map(|j| edge_sides::<K>(t, &u[j]));
    if ut.iter().any(|o| inside(o, st)) {
        return true;
    }
    if beyond_one_edge(&ut, st) {
        return false;
    }
    let tu = [0, 1, 2].map(|i| edge_sides::<K>(u, &t[i]));
    if tu.iter().any(|o| inside(o, su)) {
        return true;
    }
    if beyond_one_edge(&tu, su) {
        return false;
    }
    // Edge `t[i] t[i+1]` against edge `u[j] u[j+1]`: `ut[j][i]` is the side of `u[j]` against
    // the first, `tu[i][j]` that of `t[i]` against the second.
    (0..3).any(|i| {
        let i1 = (i + 1) % 3;
        (0..3).any(|j| {
            let j1 = (j + 1) % 3;
            segments_cross(
                [ut[j][i], ut[j1][i], tu[i][j], tu[i1][j]],
                &t[i],
                &t[i1],
                &u[j],
                &u[j1],
            )
        })
    })
}

/// The axes to project coplanar sets along: the plane's one-to-one projection when it is known,
/// otherwise all three (coplanar convex sets meet iff all three projections meet, since one of
/// them is one-to-one on the plane). Testing one projection instead of three also keeps the
/// tests off the projections where the plane collapses to a line, whose signs are all exact
/// zeros.
pub(super) fn projection_axes<K: Kernel>(pl: &K::Plane) -> core::ops::Range<usize> {
    match pl.projection_axis() {
        Some(k) => k..k + 1,
        None => 0..3,
    }
}

/// Coplanar triangles `p` (non-degenerate, plane `pl`) and `q`: they meet exactly when their
/// projections do.
pub(super) fn coplanar_tri_tri<K: Kernel>(p: &[P3; 3], q: &[P3; 3], pl: &K::Plane) -> bool {
    projection_axes::<K>(pl).all(|k| {
        let a = [proj(&p[0], k), proj(&p[1], k), proj(&p[2], k)];
        let b = [proj(&q[0], k), proj(&q[1], k), proj(&q[2], k)];
        tri2_tri2::<K>(&a, &b)
    })
}

/// Exact: do the closed triangles `p` and `q` (either may be degenerate), all of whose corners
/// have the same coordinate `k`, share a point? In the projection dropping `k`, one-to-one on
/// their plane.
pub(crate) fn coplanar_triangles_meet(p: &[P3; 3], q: &[P3; 3], k: usize) -> bool {
    let a = [proj(&p[0], k), proj(&p[1], k), proj(&p[2], k)];
    let b = [proj(&q[0], k), proj(&q[1], k), proj(&q[2], k)];
    tri2_tri2::<ExactKernel>(&a, &b)
}

/// Exact, for points with the same coordinate `k` (in the projection dropping it): the
/// orientation of the corner `x1 v x2`, nonzero for a triangle's corner.
pub(crate) fn coplanar_orientation(v: &P3, x1: &P3, x2: &P3, k: usize) -> Ordering {
    orient2d::<ExactKernel>(&proj(v, k), &proj(x1, k), &proj(x2, k))
}

/// Exact, for points with the same coordinate `k`: does the ray from `v` through `e` (`e ≠ v`)
/// lie in the closed corner at `v` spanned by the rays through `x1` and `x2`, of orientation
/// `s` (nonzero, see [`coplanar_orientation`])? Writing `e - v = α (x1 - v) + β (x2 - v)`, the
/// two signs are those of `β s` and `α s`.
pub(crate) fn coplanar_ray_in_corner(
    v: &P3,
    x1: &P3,
    x2: &P3,
    s: Ordering,
    e: &P3,
    k: usize,
) -> bool {
    let (v, e) = (proj(v, k), proj(e, k));
    let first = orient2d::<ExactKernel>(&v, &proj(x1, k), &e);
    (first == s || first == Equal) && {
        let second = orient2d::<ExactKernel>(&v, &e, &proj(x2, k));
        second == s || second == Equal
    }
}

/// Exact, for points with the same coordinate `k`: are the rays from `v` through `e1` and
/// through `e2` (both `≠ v`) one ray?
pub(crate) fn coplanar_same_ray(v: &P3, e1: &P3, e2: &P3, k: usize) -> bool {
    let (v2, e1_2, e2_2) = (proj(v, k), proj(e1, k), proj(e2, k));
    if orient2d::<ExactKernel>(&v2, &e1_2, &e2_2) != Equal {
        return false;
    }
    // On one line through `v`: the same ray when they leave `v` the same way along an axis
    // where `e1` differs from `v` (where `e2` differs too, the line not being perpendicular).
    let j = (0..3).find(|&j| e1[j] != v[j]).unwrap_or(0);
    (e1[j] > v[j]) == (e2[j] > v[j])
}

/// Exact: [`coplanar_triangles_meet`] for a segment `ab` and a triangle `t`.
pub(crate) fn coplanar_segment_meets_triangle(a: &P3, b: &P3, t: &[P3; 3], k: usize) -> bool {
    let tt = [proj(&t[0], k), proj(&t[1], k), proj(&t[2], k)];
    seg2_tri2::<ExactKernel>(&proj(a, k), &proj(b, k), &tt)
}

/// Exact: [`coplanar_triangles_meet`] for two segments `ab` and `cd`.
pub(crate) fn coplanar_segments_meet(a: &P3, b: &P3, c: &P3, d: &P3, k: usize) -> bool {
    seg2_seg2::<ExactKernel>(&proj(a, k), &proj(b, k), &proj(c, k), &proj(d, k))
}
/// Exact: do `a` and `b`, in the plane `pl` of a non-degenerate triangle and off the line
/// `uv` in it, lie on the same side of that line? In the projection that is one-to-one on the
/// plane when it is certified (two 2D orientations), otherwise from the 3D predicate.
pub(crate) fn same_side_in_plane(pl: &ExactPlane, u: &P3, v: &P3, a: &P3, b: &P3) -> bool {
    match pl.projection_axis() {
        Some(k) => {
            let (u, v) = (proj(u, k), proj(v, k));
            let side_a = orient2d::<ExactKernel>(&u, &v, &proj(a, k));
            side_a != Equal && side_a == orient2d::<ExactKernel>(&u, &v, &proj(b, k))
        }
        None => {
            ExactKernel::sign::<EdgeSide, 12>(&[
                u[0], u[1], u[2], v[0], v[1], v[2], a[0], a[1], a[2], b[0], b[1], b[2],
            ]) == Greater
        }
    }
}
