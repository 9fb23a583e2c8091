//! Exact clearance: is the distance between two shapes at most `c`?
//!
//! `query::within_distance_<a>_<b>(&a, &b, c)` decides `dist(a, b) <= c` **exactly** for the
//! real numbers the `f64` inputs denote (closed: a distance of exactly `c` counts, and
//! intersecting shapes are at distance 0). The same tests are methods through
//! [`WithinDistance`] (`a.within_distance(&b, c)`, both argument orders).
//!
//! # How
//! Every decision is the sign of a polynomial in the coordinates, radii and `c`
//! ([`crate::exact::predicates`], certified in `f64`, exact when uncertain):
//! * point within `R` of point / segment / triangle: the closest-feature region (end point,
//!   edge line, face) and a squared distance compared with `R²`, the reach `R` being a sum such
//!   as `r + c` formed inside the exact arithmetic (never rounded);
//! * segment–segment: the four end point–segment tests, then, for non-parallel segments whose
//!   lines' nearest points lie inside both, the line–line distance (a minimiser of the distance
//!   over the parameter square is either on its boundary, an end point, or the lines' common
//!   perpendicular);
//! * segment–triangle and triangle–triangle: the exact intersection test, then the end point /
//!   vertex–triangle tests and the edge–edge tests (if the minimum were attained only at points
//!   interior to both, the shapes would be parallel there and could slide to a boundary);
//! * balls: within `c` of a ball of radius `r` is within `r + c` of its centre;
//! * spheres (surfaces): the distances from the centre to a connected set form an interval
//!   `[m, M]`, and the set is within `c` of the surface iff `m <= r + c` and `M >= r - c`
//!   (`M` is attained at a vertex).
//!
//! # Bad input
//! The shapes are validated by their constructors. `c` is any `f64`: for `c < 0` and NaN the
//! answer is `false` (no distance is at most a negative number), for `c = +∞` it is `true`.
//!
//! ```
//! use cga_collide::nalgebra::Point3;
//! use cga_collide::{query, Segment, Triangle};
//! let p = |x, y, z| Point3::new(x, y, z);
//! let t = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.))?;
//! let s = Segment::new(p(0.25, 0.25, 0.5), p(3., 3., 0.5))?; // 0.5 above the face
//! assert!(query::within_distance_segment_triangle(&s, &t, 0.5)); // exactly 0.5 counts
//! assert!(!query::within_distance_segment_triangle(&s, &t, 0.4999999999999999));
//! # Ok::<(), cga_collide::Error>(())
//! ```

use core::cmp::Ordering::{Equal, Greater, Less};

use crate::exact::predicates::{
    CentreDistance, CrossNorm2, EdgeSide, LineLineParam, LineLineParamRest, LineLineReach,
    LineReach, PlaneReach, ReachSign, SegmentDot,
};
use crate::exact::{ExactKernel, Kernel, PlaneSide};
use crate::query::coplanar::extremes;
use crate::query::Intersects;
use crate::shape::bounded::{coords, corner_coords};
use crate::shape::{Ball, Segment, Sphere, Triangle};

type P3 = [f64; 3];
type K = ExactKernel;

/// A reach `r0 + r1 + r2`, summed exactly inside the predicates (never rounded in `f64`).
pub(crate) type Reach = [f64; 3];

// ---------------------------------------------------------------- points within a reach

/// `|p - q| <= R`.
#[inline]
pub(crate) fn point_point(p: &P3, q: &P3, r: &Reach) -> bool {
    K::sign::<CentreDistance, 9>(&[p[0], p[1], p[2], q[0], q[1], q[2], r[0], r[1], r[2]]) != Greater
}

/// `dist(p, segment ab) <= R`.
pub(crate) fn segment_point(a: &P3, b: &P3, p: &P3, r: &Reach) -> bool {
    let ta = K::sign::<SegmentDot, 9>(&[a[0], a[1], a[2], b[0], b[1], b[2], p[0], p[1], p[2]]);
    if ta != Greater {
        return point_point(a, p, r);
    }
    let tb = K::sign::<SegmentDot, 9>(&[b[0], b[1], b[2], a[0], a[1], a[2], p[0], p[1], p[2]]);
    if tb != Greater {
        return point_point(b, p, r);
    }
    K::sign::<LineReach, 12>(&[
        a[0], a[1], a[2], b[0], b[1], b[2], p[0], p[1], p[2], r[0], r[1], r[2],
    ]) != Greater
}

/// `dist(p, triangle t) <= R`.
pub(crate) fn triangle_point(t: &[P3; 3], p: &P3, r: &Reach) -> bool {
    let pl = K::plane(t);
    if pl.is_degenerate() {
        let (e0, e1) = extremes(t);
        return segment_point(&e0, &e1, p, r);
    }
    let inside = (0..3).all(|i| {
        let (a, b, d) = (&t[i], &t[(i + 1) % 3], &t[(i + 2) % 3]);
        K::sign::<EdgeSide, 12>(&[
            a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2], p[0], p[1], p[2],
        ]) != Less
    });
    if inside {
        // The nearest point is the foot on the plane.
        let [a, b, d] = t;
        return K::sign::<PlaneReach, 15>(&[
            a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2], p[0], p[1], p[2], r[0], r[1],
            r[2],
        ]) != Greater;
    }
    (0..3).any(|i| segment_point(&t[i], &t[(i + 1) % 3], p, r))
}

// ---------------------------------------------------------------- polytopes within c

/// `dist(segment ab, segment cd) <= c`.
pub(crate) fn segment_segment(a: &P3, b: &P3, c: &P3, d: &P3, reach: f64) -> bool {
    let r = [reach, 0.0, 0.0];
    if segment_point(a, b, c, &r)
        || segment_point(a, b, d, &r)
        || segment_point(c, d, a, &r)
        || segment_point(c, d, b, &r)
    {
        return true;
    }
    // The minimum is not at an end point: it is at the lines' common perpendicular, if that
    // meets both segments.
    let x = [
        a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2],
    ];
    if K::sign::<CrossNorm2, 12>(&x) == Equal {
        return false;
    }
    let y = [
        c[0], c[1], c[2], d[0], d[1], d[2], a[0], a[1], a[2], b[0], b[1], b[2],
    ];
    K::sign::<LineLineParam, 12>(&x) != Less
        && K::sign::<LineLineParamRest, 12>(&x) != Less
        && K::sign::<LineLineParam, 12>(&y) != Less
        && K::sign::<LineLineParamRest, 12>(&y) != Less
        && K::sign::<LineLineReach, 13>(&[
            a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2], reach,
        ]) != Greater
}

/// `dist(segment ab, triangle t) <= c` (without the intersection test).
fn segment_triangle_apart(a: &P3, b: &P3, t: &[P3; 3], c: f64) -> bool {
    let r = [c, 0.0, 0.0];
    triangle_point(t, a, &r)
        || triangle_point(t, b, &r)
        || (0..3).any(|i| segment_segment(a, b, &t[i], &t[(i + 1) % 3], c))
}

/// `dist(triangle p, triangle q) <= c` (without the intersection test).
fn triangle_triangle_apart(p: &[P3; 3], q: &[P3; 3], c: f64) -> bool {
    let r = [c, 0.0, 0.0];
    p.iter().any(|v| triangle_point(q, v, &r))
        || q.iter().any(|v| triangle_point(p, v, &r))
        || (0..3).any(|i| {
            (0..3).any(|j| segment_segment(&p[i], &p[(i + 1) % 3], &q[j], &q[(j + 1) % 3], c))
        })
}

/// `None` when `c` alone decides (`c < 0`, NaN: `false`; `+∞`: `true`).
#[inline]
pub(crate) fn trivial(c: f64) -> Option<bool> {
    if (0.0..f64::INFINITY).contains(&c) {
        None
    } else {
        Some(c == f64::INFINITY)
    }
}

/// Exact: `dist(triangle p, triangle q) <= c`, on raw coordinates (the mesh queries' test).
pub(crate) fn triangles_within(p: &[P3; 3], q: &[P3; 3], c: f64) -> bool {
    if let Some(answer) = trivial(c) {
        return answer;
    }
    triangle_triangle_apart(p, q, c) || {
        let to = |t: &[P3; 3]| {
            Triangle::new(t[0].into(), t[1].into(), t[2].into())
                .unwrap_or_else(|_| unreachable!("finite mesh coordinates"))
        };
        to(p).intersects(&to(q))
    }
}

// ---------------------------------------------------------------- spheres

/// Whether a point set with the given vertices (its farthest point from `centre` is a vertex)
/// has a point at distance `>= r - c` from `centre`.
fn reaches_out(vertices: &[P3], centre: &P3, r: f64, c: f64) -> bool {
    if K::sign::<ReachSign, 3>(&[r, -c, 0.0]) != Greater {
        return true;
    }
    vertices.iter().any(|v| {
        K::sign::<CentreDistance, 9>(&[
            v[0], v[1], v[2], centre[0], centre[1], centre[2], r, -c, 0.0,
        ]) != Less
    })
}

/// `|c1 - c2| >= big - small - c` (true when the right side is not positive).
fn centres_apart(c1: &P3, c2: &P3, big: f64, small: f64, c: f64) -> bool {
    if K::sign::<ReachSign, 3>(&[big, -small, -c]) != Greater {
        return true;
    }
    K::sign::<CentreDistance, 9>(&[c1[0], c1[1], c1[2], c2[0], c2[1], c2[2], big, -small, -c])
        != Less
}

// ---------------------------------------------------------------- the trait

/// Exact clearance test: is the distance between the closed sets at most `c`?
pub trait WithinDistance<Rhs: ?Sized> {
    /// Whether `dist(self, rhs) <= c`, exactly (see `query::within_distance_segment_segment` for `c` outside
    /// `[0, ∞)`).
    fn within_distance(&self, rhs: &Rhs, c: f64) -> bool;
}

impl WithinDistance<Segment> for Segment {
    fn within_distance(&self, rhs: &Segment, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        segment_segment(
            &coords(self.a()),
            &coords(self.b()),
            &coords(rhs.a()),
            &coords(rhs.b()),
            c,
        )
    }
}

impl WithinDistance<Triangle> for Segment {
    fn within_distance(&self, rhs: &Triangle, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        segment_triangle_apart(&coords(self.a()), &coords(self.b()), &corner_coords(rhs), c)
            || self.intersects(rhs)
    }
}

impl WithinDistance<Triangle> for Triangle {
    fn within_distance(&self, rhs: &Triangle, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        triangle_triangle_apart(&corner_coords(self), &corner_coords(rhs), c)
            || self.intersects(rhs)
    }
}

impl WithinDistance<Ball> for Segment {
    fn within_distance(&self, rhs: &Ball, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        let r = [rhs.radius(), c, 0.0];
        segment_point(
            &coords(self.a()),
            &coords(self.b()),
            &coords(rhs.centre()),
            &r,
        )
    }
}

impl WithinDistance<Ball> for Triangle {
    fn within_distance(&self, rhs: &Ball, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        triangle_point(
            &corner_coords(self),
            &coords(rhs.centre()),
            &[rhs.radius(), c, 0.0],
        )
    }
}

impl WithinDistance<Sphere> for Segment {
    fn within_distance(&self, rhs: &Sphere, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        let (a, b, o, r) = (
            coords(self.a()),
            coords(self.b()),
            coords(rhs.centre()),
            rhs.radius(),
        );
        reaches_out(&[a, b], &o, r, c) && segment_point(&a, &b, &o, &[r, c, 0.0])
    }
}

impl WithinDistance<Sphere> for Triangle {
    fn within_distance(&self, rhs: &Sphere, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        let (t, o, r) = (corner_coords(self), coords(rhs.centre()), rhs.radius());
        reaches_out(&t, &o, r, c) && triangle_point(&t, &o, &[r, c, 0.0])
    }
}

impl WithinDistance<Ball> for Ball {
    fn within_distance(&self, rhs: &Ball, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        point_point(
            &coords(self.centre()),
            &coords(rhs.centre()),
            &[self.radius(), rhs.radius(), c],
        )
    }
}

impl WithinDistance<Sphere> for Sphere {
    fn within_distance(&self, rhs: &Sphere, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        let (c1, c2) = (coords(self.centre()), coords(rhs.centre()));
        let (r1, r2) = (self.radius(), rhs.radius());
        let (big, small) = if r1 >= r2 { (r1, r2) } else { (r2, r1) };
        point_point(&c1, &c2, &[r1, r2, c]) && centres_apart(&c1, &c2, big, small, c)
    }
}

impl WithinDistance<Sphere> for Ball {
    fn within_distance(&self, rhs: &Sphere, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        let (c1, c2) = (coords(self.centre()), coords(rhs.centre()));
        // Apart from outside (`d <= r1 + r2 + c`) and from inside (`d >= r2 - r1 - c`).
        point_point(&c1, &c2, &[self.radius(), rhs.radius(), c])
            && centres_apart(&c1, &c2, rhs.radius(), self.radius(), c)
    }
}

macro_rules! swapped {
    ($($a:ty => $b:ty),*) => {$(
        impl WithinDistance<$b> for $a {
            #[inline]
            fn within_distance(&self, rhs: &$b, c: f64) -> bool {
                rhs.within_distance(self, c)
            }
        }
    )*};
}
swapped!(Triangle => Segment, Ball => Segment, Ball => Triangle, Sphere => Segment,
    Sphere => Triangle, Sphere => Ball);

/// Declares `query::within_distance_<a>_<b>`, the exact clearance test of one pair.
macro_rules! named_tests {
    ($($(#[$doc:meta])* $name:ident($a:ty, $b:ty);)*) => {$(
        $(#[$doc])*
        #[inline]
        pub fn $name(a: &$a, b: &$b, c: f64) -> bool {
            a.within_distance(b, c)
        }
    )*};
}

named_tests! {
    /// Exact: are two closed segments within distance `c`?
    within_distance_segment_segment(Segment, Segment);
    /// Exact: are the closed segment and the closed triangle within distance `c`?
    within_distance_segment_triangle(Segment, Triangle);
    /// Exact: are two closed triangles within distance `c`?
    within_distance_triangle_triangle(Triangle, Triangle);
    /// Exact: are the closed segment and the solid ball within distance `c`?
    within_distance_segment_ball(Segment, Ball);
    /// Exact: are the closed segment and the spherical surface within distance `c`?
    within_distance_segment_sphere(Segment, Sphere);
    /// Exact: are the closed triangle and the solid ball within distance `c`?
    within_distance_triangle_ball(Triangle, Ball);
    /// Exact: are the closed triangle and the spherical surface within distance `c`?
    within_distance_triangle_sphere(Triangle, Sphere);
    /// Exact: are two spherical surfaces within distance `c`?
    within_distance_sphere_sphere(Sphere, Sphere);
    /// Exact: are two solid balls within distance `c`?
    within_distance_ball_ball(Ball, Ball);
    /// Exact: are the solid ball and the spherical surface within distance `c`?
    within_distance_ball_sphere(Ball, Sphere);
}
