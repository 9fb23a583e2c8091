//! Exact intersection tests between the bounded shapes (closed sets, touching counts).
//!
//! `a.intersects(&b)` ([`Intersects`]) is exact for the real numbers the `f64` inputs denote:
//! every decision is the sign of a polynomial in the input coordinates and radii
//! ([`crate::exact::predicates`]), certified in `f64` and recomputed with exact rationals when the
//! certificate fails ([`ExactKernel`]). The algorithms are generic over the sign
//! [`Kernel`] ([`IntersectsWith`]), so the tests can run them with plain `f64` signs too.
//!
//! The algorithms follow the thesis's IV.1–IV.6 in spirit, made exact:
//! * triangle–triangle: each triangle's plane is computed once and the other's vertices are
//!   classified against it (early exit when all are strictly on one side, as in Möller); in
//!   general position two more `orient3d` signs decide (Guigue–Devillers); with vertices on the
//!   other plane the test falls back to the six edge–triangle tests of the thesis's IV.4;
//!   coplanar triangles are tested in the axis projection that is one-to-one on their plane
//!   (the largest component of the normal, certified nonzero; all three projections when that
//!   is not certain: coplanar convex sets meet iff all three projections meet).
//! * segment–triangle: plane sides of the end points, then the three `orient3d` of the line
//!   against the edges (IV.2).
//! * segment–segment: coplanarity by `orient3d`, then the three projections (IV.1).
//! * segment/triangle vs ball: the exact squared distance comparisons of the closest point
//!   region (end point, edge line, face), as polynomial signs; vs sphere (surface): the closed
//!   connected set meets the surface iff `min distance <= r <= max distance`, the maximum
//!   being at a vertex (IV.3, IV.5, IV.6).
//! * sphere–sphere: the sign of the thesis's `B² = (S1·S2)² - S1² S2²`; ball–ball:
//!   `S1·S2 + 4 r1 r2 >= 0`; ball–sphere: the balls meet and the ball is not strictly inside
//!   the surface (`(r2 - r1)² > |c1 - c2|²` with `r1 < r2`).
//!
//! Degenerate triangles are the segment between their two extreme vertices (exact `f64`
//! comparisons along an axis where they differ), zero-length segments are points, and
//! radius-0 spheres and balls are points.
//!
//! ```
//! use cga_collide::{nalgebra::Point3, Intersects, Triangle, Sphere, Ball};
//! let p = |x, y, z| Point3::new(x, y, z);
//! let t = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
//! // Touching at a single vertex counts.
//! let u = Triangle::new(p(1., 0., 0.), p(2., 0., 1.), p(2., 1., 0.)).unwrap();
//! assert!(t.intersects(&u));
//! // A triangle strictly inside a sphere does not meet the surface, but meets the ball.
//! let s = Sphere::new(p(0.2, 0.2, 0.), 5.0).unwrap();
//! assert!(!t.intersects(&s));
//! assert!(t.intersects(&Ball::from(s)));
//! ```

use core::cmp::Ordering::{self, Equal, Greater, Less};

use nalgebra::Point3;

use crate::exact::predicates::{
    BallBall, EdgeSide, LineDistance, PlaneDistance, PointPower, SegmentDot, SphereSphere,
};
use crate::exact::{ExactKernel, Kernel, PlaneSide};
use crate::query::coplanar::{
    common_axis, coplanar_tri_tri, extremes, proj, projection_axes, seg2_seg2, seg2_tri2,
};
use crate::shape::bounded::{coords, corner_coords};
use crate::shape::{Ball, Segment, Sphere, Triangle};

type P3 = [f64; 3];

/// Exact intersection test between closed sets (touching counts).
pub trait Intersects<Rhs: ?Sized> {
    /// Whether `self` and `rhs` share at least one point (exactly, for the real values of the
    /// `f64` data).
    fn intersects(&self, rhs: &Rhs) -> bool;
}

/// The intersection algorithms with a chosen way of deciding signs: [`ExactKernel`] (what
/// [`Intersects`] uses), or plain `f64` signs in the tests (`testing::FloatKernel`).
pub trait IntersectsWith<Rhs: ?Sized> {
    /// The test with signs decided by `K`.
    fn intersects_with<K: Kernel>(&self, rhs: &Rhs) -> bool;
}

impl<A: IntersectsWith<B>, B: ?Sized> Intersects<B> for A {
    #[inline]
    fn intersects(&self, rhs: &B) -> bool {
        self.intersects_with::<ExactKernel>(rhs)
    }
}

// ---------------------------------------------------------------- sign helpers

#[inline]
fn orient3d<K: Kernel>(a: &P3, b: &P3, c: &P3, d: &P3) -> Ordering {
    K::orient3d(a, b, c, d)
}

// ---------------------------------------------------------------- 3D

pub(super) fn seg_seg<K: Kernel>(a: &P3, b: &P3, c: &P3, d: &P3) -> bool {
    if a == b && c != d {
        // A point against a segment: the segment carries the line.
        return seg_seg::<K>(c, d, a, b);
    }
    if let Some(k) = common_axis(&[a, b, c, d]) {
        // In one axis-parallel plane (faces of engineering meshes): one projection, no 3D sign.
        return seg2_seg2::<K>(&proj(a, k), &proj(b, k), &proj(c, k), &proj(d, k));
    }
    if orient3d::<K>(a, b, c, d) != Equal {
        return false;
    }
    if a != b {
        // Coplanar. A known plane through them gives the one projection that is one-to-one on
        // it; four points on the line `ab` reduce to intervals along an axis where `a` and `b`
        // differ (the line is not perpendicular to it). Otherwise all three projections.
        let (abc, abd) = (K::plane(&[*a, *b, *c]), K::plane(&[*a, *b, *d]));
        if let Some(k) = abc.projection_axis().or_else(|| abd.projection_axis()) {
            return seg2_seg2::<K>(&proj(a, k), &proj(b, k), &proj(c, k), &proj(d, k));
        }
        if abc.is_degenerate() && abd.is_degenerate() {
            let k = (0..3).find(|&k| a[k] != b[k]).unwrap_or(0);
            let (lo1, hi1) = (a[k].min(b[k]), a[k].max(b[k]));
            let (lo2, hi2) = (c[k].min(d[k]), c[k].max(d[k]));
            return lo1 <= hi2 && lo2 <= hi1;
        }
    }
    (0..3).all(|k| seg2_seg2::<K>(&proj(a, k), &proj(b, k), &proj(c, k), &proj(d, k)))
}

fn seg_tri<K: Kernel>(a: &P3, b: &P3, t: &[P3; 3]) -> bool {
    if let Some(meet) = seg_tri_axis_plane::<K>(a, b, t) {
        return meet;
    }
    let pl = K::plane(t);
    if pl.is_degenerate() {
        let (e0, e1) = extremes(t);
        return seg_seg::<K>(a, b, &e0, &e1);
    }
    seg_tri_sides::<K>(a, b, pl.side(a), pl.side(b), t, &pl)
}

/// Segment against the non-degenerate triangle `t` whose plane is `pl`.
pub(super) fn seg_tri_plane<K: Kernel>(a: &P3, b: &P3, t: &[P3; 3], pl: &K::Plane) -> bool {
    if let Some(meet) = seg_tri_axis_plane::<K>(a, b, t) {
        return meet;
    }
    seg_tri_sides::<K>(a, b, pl.side(a), pl.side(b), t, pl)
}

/// Segment against triangle (either may be degenerate) when all five points lie in one
/// axis-parallel plane (faces of engineering meshes): one projection decides, with no plane
/// and no 3D sign. `None` otherwise.
#[inline]
fn seg_tri_axis_plane<K: Kernel>(a: &P3, b: &P3, t: &[P3; 3]) -> Option<bool> {
    let k = common_axis(&[a, b, &t[0], &t[1], &t[2]])?;
    let tt = [proj(&t[0], k), proj(&t[1], k), proj(&t[2], k)];
    Some(seg2_tri2::<K>(&proj(a, k), &proj(b, k), &tt))
}

/// [`seg_tri_plane`] with the sides `sa`, `sb` of the end points already known.
pub(super) fn seg_tri_sides<K: Kernel>(
    a: &P3,
    b: &P3,
    sa: Ordering,
    sb: Ordering,
    t: &[P3; 3],
    pl: &K::Plane,
) -> bool {
    if sa == sb && sa != Equal {
        return false;
    }
    if sa == Equal || sb == Equal {
        // A coplanar end point, or the whole segment in the plane: test in the projections.
        let (a, b) = match (sa, sb) {
            (Equal, Equal) => (a, b),
            (Equal, _) => (a, a),
            _ => (b, b),
        };
        return projection_axes::<K>(pl).all(|k| {
            let tt = [proj(&t[0], k), proj(&t[1], k), proj(&t[2], k)];
            seg2_tri2::<K>(&proj(a, k), &proj(b, k), &tt)
        });
    }
    // Proper crossing of the plane: the line meets the closed triangle iff its orientations
    // against the three edges do not take both strict signs.
    let o1 = orient3d::<K>(a, b, &t[0], &t[1]);
    let o2 = orient3d::<K>(a, b, &t[1], &t[2]);
    let o3 = orient3d::<K>(a, b, &t[2], &t[0]);
    let pos = o1 == Greater || o2 == Greater || o3 == Greater;
    let neg = o1 == Less || o2 == Less || o3 == Less;
    !(pos && neg)
}

#[inline]
fn all_zero(s: &[Ordering; 3]) -> bool {
    s[0] == Equal && s[1] == Equal && s[2] == Equal
}

#[inline]
fn strictly_one_side(s: &[Ordering; 3]) -> bool {
    s[0] != Equal && s[0] == s[1] && s[0] == s[2]
}

/// Index of the vertex alone on its side (all three signs nonzero, not all equal).
#[inline]
fn alone(s: &[Ordering; 3]) -> usize {
    if s[1] == s[2] {
        0
    } else if s[0] == s[2] {
        1
    } else {
        2
    }
}

fn tri_tri<K: Kernel>(p: &[P3; 3], q: &[P3; 3]) -> bool {
    let pl1 = K::plane(p);
    tri_tri_planes::<K>(p, q, &pl1, || K::plane(q))
}

/// [`tri_tri`] with the plane of `p` given and that of `q` made on demand (callers that keep
/// the planes of a whole mesh pass them in).
pub(super) fn tri_tri_planes<K: Kernel>(
    p: &[P3; 3],
    q: &[P3; 3],
    pl1: &K::Plane,
    plane_q: impl FnOnce() -> K::Plane,
) -> bool {
    // Each plane (normal and filter data) is computed once; its degeneracy is checked only when
    // no side came out nonzero: a certified nonzero side proves the triangle non-degenerate (a
    // collinear triangle has exact side 0 everywhere), so in general position the filter costs
    // the six plane evaluations and nothing more.
    let dq = pl1.sides_of(q);
    // (A degenerate first triangle gives exact zeros here, so this exit is sound before the
    // degeneracy check.)
    if strictly_one_side(&dq) {
        return false;
    }
    if all_zero(&dq) {
        if pl1.is_degenerate() {
            let (e0, e1) = extremes(p);
            return seg_tri::<K>(&e0, &e1, q);
        }
        // `q` lies in the plane of the non-degenerate `p`: coplanar, whatever `q`'s own
        // plane says (no need to classify `p` against it).
        return coplanar_tri_tri::<K>(p, q, pl1);
    }
    let pl2 = plane_q();
    let dp = pl2.sides(pl1);
    if strictly_one_side(&dp) {
        return false;
    }
    if all_zero(&dp) && pl2.is_degenerate() {
        let (e0, e1) = extremes(q);
        return seg_tri_plane::<K>(&e0, &e1, p, pl1);
    }
    if all_zero(&dp) {
        // `p` in the plane of the non-degenerate `q` (`dq` not all zero: not reached for exact
        // signs, kept for kernels that round).
        return coplanar_tri_tri::<K>(q, p, &pl2);
    }
    if dq.iter().all(|&s| s != Equal) && dp.iter().all(|&s| s != Equal) {
        // General position (Guigue–Devillers): put the lonely vertices first, orient both so
        // that they lie on the positive sides, then two orientations compare the intervals
        // cut on the common line.
        let i = alone(&dp);
        let j = alone(&dq);
        let mut a = [p[i], p[(i + 1) % 3], p[(i + 2) % 3]];
        let mut b = [q[j], q[(j + 1) % 3], q[(j + 2) % 3]];
        if dp[i] == Less {
            b.swap(1, 2);
        }
        if dq[j] == Less {
            a.swap(1, 2);
        }
        return orient3d::<K>(&a[0], &a[1], &b[0], &b[1]) != Greater
            && orient3d::<K>(&a[0], &a[2], &b[2], &b[0]) != Greater;
    }
    // A vertex on the other plane. Where one triangle meets the other's plane only in a vertex
    // or an edge, that set against the other triangle decides.
    if let Some(meet) = plane_contact::<K>(p, &dp, q, &pl2) {
        return meet;
    }
    if let Some(meet) = plane_contact::<K>(q, &dq, p, pl1) {
        return meet;
    }
    // Otherwise an edge of one meets the other (thesis IV.4), with the known sides reused.
    (0..3).any(|i| {
        let j = (i + 1) % 3;
        seg_tri_sides::<K>(&p[i], &p[j], dp[i], dp[j], q, &pl2)
    }) || (0..3).any(|i| {
        let j = (i + 1) % 3;
        seg_tri_sides::<K>(&q[i], &q[j], dq[i], dq[j], p, pl1)
    })
}

/// When `t` (sides `d` against the plane `pl` of the non-degenerate triangle `u`, not all zero,
/// not all one strict side) meets that plane only in one vertex or one edge, whether that
/// vertex or edge meets `u`; `None` when `t` crosses the plane.
fn plane_contact<K: Kernel>(
    t: &[P3; 3],
    d: &[Ordering; 3],
    u: &[P3; 3],
    pl: &K::Plane,
) -> Option<bool> {
    let zeros = d.iter().filter(|&&s| s == Equal).count();
    let (a, b) = match zeros {
        // An edge in the plane, the third vertex off it.
        2 => {
            let off = d.iter().position(|&s| s != Equal)?;
            (&t[(off + 1) % 3], &t[(off + 2) % 3])
        }
        // One vertex in the plane, the other two strictly on one side.
        1 => {
            let on = d.iter().position(|&s| s == Equal)?;
            if d[(on + 1) % 3] != d[(on + 2) % 3] {
                return None;
            }
            (&t[on], &t[on])
        }
        _ => return None,
    };
    Some(seg_tri_sides::<K>(a, b, Equal, Equal, u, pl))
}

// ---------------------------------------------------------------- spheres and balls

#[inline]
fn point_power<K: Kernel>(x: &P3, c: &P3, r: f64) -> Ordering {
    K::sign::<PointPower, 7>(&[x[0], x[1], x[2], c[0], c[1], c[2], r])
}

/// Closed segment against closed ball.
fn seg_ball<K: Kernel>(a: &P3, b: &P3, c: &P3, r: f64) -> bool {
    let ta = K::sign::<SegmentDot, 9>(&[a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]]);
    if ta != Greater {
        return point_power::<K>(a, c, r) != Greater;
    }
    let tb = K::sign::<SegmentDot, 9>(&[b[0], b[1], b[2], a[0], a[1], a[2], c[0], c[1], c[2]]);
    if tb != Greater {
        return point_power::<K>(b, c, r) != Greater;
    }
    K::sign::<LineDistance, 10>(&[a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], r])
        != Greater
}

fn tri_ball<K: Kernel>(t: &[P3; 3], c: &P3, r: f64) -> bool {
    let pl = K::plane(t);
    if pl.is_degenerate() {
        let (e0, e1) = extremes(t);
        return seg_ball::<K>(&e0, &e1, c, r);
    }
    let inside = (0..3).all(|i| {
        let (a, b, d) = (&t[i], &t[(i + 1) % 3], &t[(i + 2) % 3]);
        let x = [
            a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2], c[0], c[1], c[2],
        ];
        K::sign::<EdgeSide, 12>(&x) != Less
    });
    if inside {
        // The closest point is the foot on the plane.
        let [a, b, d] = t;
        let x = [
            a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2], c[0], c[1], c[2], r,
        ];
        return K::sign::<PlaneDistance, 13>(&x) != Greater;
    }
    (0..3).any(|i| seg_ball::<K>(&t[i], &t[(i + 1) % 3], c, r))
}

impl IntersectsWith<Segment> for Segment {
    fn intersects_with<K: Kernel>(&self, rhs: &Segment) -> bool {
        seg_seg::<K>(
            &coords(self.a()),
            &coords(self.b()),
            &coords(rhs.a()),
            &coords(rhs.b()),
        )
    }
}

impl IntersectsWith<Triangle> for Segment {
    fn intersects_with<K: Kernel>(&self, rhs: &Triangle) -> bool {
        seg_tri::<K>(&coords(self.a()), &coords(self.b()), &corner_coords(rhs))
    }
}

impl IntersectsWith<Segment> for Triangle {
    fn intersects_with<K: Kernel>(&self, rhs: &Segment) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

impl IntersectsWith<Triangle> for Triangle {
    #[inline]
    fn intersects_with<K: Kernel>(&self, rhs: &Triangle) -> bool {
        tri_tri::<K>(&corner_coords(self), &corner_coords(rhs))
    }
}

impl IntersectsWith<Ball> for Segment {
    fn intersects_with<K: Kernel>(&self, rhs: &Ball) -> bool {
        seg_ball::<K>(
            &coords(self.a()),
            &coords(self.b()),
            &coords(rhs.centre()),
            rhs.radius(),
        )
    }
}

impl IntersectsWith<Segment> for Ball {
    fn intersects_with<K: Kernel>(&self, rhs: &Segment) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

impl IntersectsWith<Sphere> for Segment {
    fn intersects_with<K: Kernel>(&self, rhs: &Sphere) -> bool {
        let (a, b, c, r) = (
            coords(self.a()),
            coords(self.b()),
            coords(rhs.centre()),
            rhs.radius(),
        );
        // min distance <= r <= max distance (the maximum is at an end point).
        (point_power::<K>(&a, &c, r) != Less || point_power::<K>(&b, &c, r) != Less)
            && seg_ball::<K>(&a, &b, &c, r)
    }
}

impl IntersectsWith<Segment> for Sphere {
    fn intersects_with<K: Kernel>(&self, rhs: &Segment) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

impl IntersectsWith<Ball> for Triangle {
    fn intersects_with<K: Kernel>(&self, rhs: &Ball) -> bool {
        tri_ball::<K>(&corner_coords(self), &coords(rhs.centre()), rhs.radius())
    }
}

impl IntersectsWith<Triangle> for Ball {
    fn intersects_with<K: Kernel>(&self, rhs: &Triangle) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

impl IntersectsWith<Sphere> for Triangle {
    fn intersects_with<K: Kernel>(&self, rhs: &Sphere) -> bool {
        let (t, c, r) = (corner_coords(self), coords(rhs.centre()), rhs.radius());
        t.iter().any(|v| point_power::<K>(v, &c, r) != Less) && tri_ball::<K>(&t, &c, r)
    }
}

impl IntersectsWith<Triangle> for Sphere {
    fn intersects_with<K: Kernel>(&self, rhs: &Triangle) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

fn spheres(a: &Point3<f64>, ra: f64, b: &Point3<f64>, rb: f64) -> [f64; 8] {
    [a.x, a.y, a.z, ra, b.x, b.y, b.z, rb]
}

impl IntersectsWith<Sphere> for Sphere {
    fn intersects_with<K: Kernel>(&self, rhs: &Sphere) -> bool {
        K::sign::<SphereSphere, 8>(&spheres(
            self.centre(),
            self.radius(),
            rhs.centre(),
            rhs.radius(),
        )) != Greater
    }
}

impl IntersectsWith<Ball> for Ball {
    fn intersects_with<K: Kernel>(&self, rhs: &Ball) -> bool {
        K::sign::<BallBall, 8>(&spheres(
            self.centre(),
            self.radius(),
            rhs.centre(),
            rhs.radius(),
        )) != Less
    }
}

impl IntersectsWith<Sphere> for Ball {
    fn intersects_with<K: Kernel>(&self, rhs: &Sphere) -> bool {
        let x = spheres(self.centre(), self.radius(), rhs.centre(), rhs.radius());
        // The surface meets the solid ball unless the balls are apart or the ball lies strictly
        // inside the surface: `|c1 - c2| + r1 < r2`, i.e. `r1 < r2` and `(r2 - r1)² > |c1 - c2|²`.
        let strictly_inside = self.radius() < rhs.radius()
            && K::sign::<crate::exact::predicates::BallInBall, 8>(&x) == Greater;
        K::sign::<BallBall, 8>(&x) != Less && !strictly_inside
    }
}

impl IntersectsWith<Ball> for Sphere {
    fn intersects_with<K: Kernel>(&self, rhs: &Ball) -> bool {
        rhs.intersects_with::<K>(self)
    }
}

/// Declares `query::intersects_<a>_<b>`, the exact test of one pair under its findable name.
macro_rules! named_tests {
    ($($(#[$doc:meta])* $name:ident($a:ty, $b:ty);)*) => {$(
        $(#[$doc])*
        #[inline]
        pub fn $name(a: &$a, b: &$b) -> bool {
            a.intersects(b)
        }
    )*};
}

named_tests! {
    /// Exact: do two closed segments share a point?
    intersects_segment_segment(Segment, Segment);
    /// Exact: does the closed segment meet the closed triangle?
    intersects_segment_triangle(Segment, Triangle);
    /// Exact: do two closed triangles share a point?
    intersects_triangle_triangle(Triangle, Triangle);
    /// Exact: does the closed segment meet the solid ball?
    intersects_segment_ball(Segment, Ball);
    /// Exact: does the closed segment meet the spherical surface?
    intersects_segment_sphere(Segment, Sphere);
    /// Exact: does the closed triangle meet the solid ball?
    intersects_triangle_ball(Triangle, Ball);
    /// Exact: does the closed triangle meet the spherical surface?
    intersects_triangle_sphere(Triangle, Sphere);
    /// Exact: do two spherical surfaces share a point?
    intersects_sphere_sphere(Sphere, Sphere);
    /// Exact: do two solid balls share a point?
    intersects_ball_ball(Ball, Ball);
    /// Exact: does the solid ball meet the spherical surface? A ball strictly inside the
    /// surface does not; touching it (from outside or from inside) counts.
    intersects_ball_sphere(Ball, Sphere);
}
