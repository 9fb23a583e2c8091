//! Minimum distance with witness points: in `f64` with a **certified** error bound, or exactly
//! in rationals.
//!
//! # What is computed
//! The closest points of two segments, a segment and a triangle, two triangles, or two meshes
//! (their surfaces: the nearest pair of triangles, found by branch and bound on the
//! hierarchies). The nearest points are found by one generic routine, written once over
//! [`Real`] and run on `f64` (fast) and on exact rationals: the minimum over the closest-feature
//! candidates (vertex–triangle, edge–edge, and edge crossing the other triangle, which gives 0
//! for intersecting triangles).
//!
//! # The error bound
//! [`CertifiedDistance::distance`] is the `f64` result `d`; [`CertifiedDistance::error_bound`] is an `e` such that
//! the true distance of the inputs (the real numbers the `f64` coordinates denote) lies in
//! `[d - e, d + e]`. It is not an estimate: after the `f64` search, the interval is **proved**
//! with the exact clearance tests of [`crate::query`] (`within_distance(d + e)` is true and
//! `within_distance(d - e)` is false, for meshes over all triangle pairs), starting from
//! `e = 32·2⁻⁵³·(|coordinates| + d)` and widening it eightfold until both proofs succeed. When
//! the `f64` result is 0 and the shapes do meet (exact test), the bound is 0.
//!
//! [`ExactDistance`] gives the squared distance and the witnesses as exact rationals (the
//! distance itself is usually irrational).
//!
//! ```
//! use cga_collide::{nalgebra::Point3, query, Triangle};
//! let p = |x, y, z| Point3::new(x, y, z);
//! let a = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.))?;
//! let b = Triangle::new(p(0.2, 0.2, 0.3), p(1., 1., 2.), p(2., 0., 1.))?;
//! let d = query::distance_triangle_triangle(&a, &b);
//! assert!((d.distance - 0.3).abs() <= d.error_bound);
//! assert_eq!(d.witness_b, p(0.2, 0.2, 0.3));
//! let exact = query::exact_distance_triangle_triangle(&a, &b);
//! // Exactly the square of the f64 nearest to 0.3 (the z of b's first vertex).
//! let z = cga_collide::ga_core::scalar::rational_from_f64(0.3).unwrap();
//! assert_eq!(exact.distance2, &z * &z);
//! # Ok::<(), cga_collide::Error>(())
//! ```

use ga_core::scalar::{rational_from_f64, Rational, Real, Ring};
use nalgebra::Point3;

use crate::exact::vector::{add_scaled, cross, dist2, dot, sub};
use crate::query::closest_points::{
    point_segment, point_triangle, segment_segment, segment_triangle, triangle_triangle, Near, V,
};
use crate::query::within_distance::WithinDistance;
use crate::query::Intersects;
use crate::shape::bounded::{coords, corner_coords};
use crate::shape::{Ball, Segment, Sphere, Triangle};

// ---------------------------------------------------------------- results

/// A minimum distance in `f64` with a certified error bound ([`error_bound`](Self::error_bound)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CertifiedDistance {
    /// The distance computed in `f64`.
    pub distance: f64,
    /// The true distance lies in `[distance - error_bound, distance + error_bound]` (proved
    /// with exact predicates).
    pub error_bound: f64,
    /// The nearest point of the first shape (computed in `f64`: on it up to rounding).
    pub witness_a: Point3<f64>,
    /// The nearest point of the second shape (computed in `f64`).
    pub witness_b: Point3<f64>,
    /// For meshes, the triangles `(i, j)` of the first and the second mesh holding the witnesses.
    pub triangles: Option<(u32, u32)>,
}

/// A minimum distance computed exactly: the squared distance and the witnesses are exact
/// rationals (the true values for the real numbers the `f64` inputs denote).
#[derive(Debug, Clone, PartialEq)]
pub struct ExactDistance {
    /// The squared distance.
    pub distance2: Rational,
    /// The nearest point of the first shape.
    pub witness_a: [Rational; 3],
    /// The nearest point of the second shape.
    pub witness_b: [Rational; 3],
    /// For meshes, the triangles `(i, j)` holding the witnesses.
    pub triangles: Option<(u32, u32)>,
}

impl ExactDistance {
    /// The distance rounded to the nearest `f64` (up to one rounding of the square root).
    pub fn distance_f64(&self) -> f64 {
        Real::to_f64(&self.distance2).sqrt()
    }
}

fn q(x: f64) -> Rational {
    // Shapes and meshes hold finite coordinates only.
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

fn qv(p: &V<f64>) -> V<Rational> {
    [q(p[0]), q(p[1]), q(p[2])]
}

/// Proves `true distance ∈ [d - e, d + e]` with exact clearance tests and returns
/// `e` (see the module docs). `scale` bounds the magnitude of the coordinates involved.
/// `upper(c)` proves `distance <= c`; `lower(c)` is false only if `distance > c`.
pub(crate) fn certify(
    d: f64,
    scale: f64,
    meets: impl Fn() -> bool,
    upper: impl Fn(f64) -> bool,
    lower: impl Fn(f64) -> bool,
) -> f64 {
    if d == 0.0 && meets() {
        return 0.0;
    }
    let mut e = 32.0 * f64::EPSILON * 0.5 * (scale + d);
    if e.is_nan() || e <= 0.0 {
        e = f64::MIN_POSITIVE;
    }
    loop {
        let hi = (d + e).next_up();
        let lo = (d - e).next_down();
        if upper(hi) && (lo < 0.0 || !lower(lo)) {
            return (hi - d).max(d - lo).next_up();
        }
        if !e.is_finite() {
            return f64::INFINITY; // unreachable for finite inputs
        }
        e *= 8.0;
    }
}

pub(crate) fn scale_of(points: &[&V<f64>]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

fn finish(
    near: Near<f64>,
    scale: f64,
    meets: impl Fn() -> bool,
    within: impl Fn(f64) -> bool,
    triangles: Option<(u32, u32)>,
) -> CertifiedDistance {
    let (d2, x, y) = near;
    let distance = d2.sqrt();
    CertifiedDistance {
        distance,
        error_bound: certify(distance, scale, meets, &within, &within),
        witness_a: Point3::from(x),
        witness_b: Point3::from(y),
        triangles,
    }
}

fn exact(near: Near<Rational>, triangles: Option<(u32, u32)>) -> ExactDistance {
    let (distance2, witness_a, witness_b) = near;
    ExactDistance {
        distance2,
        witness_a,
        witness_b,
        triangles,
    }
}

// ---------------------------------------------------------------- shapes

/// The minimum distance between two closed segments, with witnesses and a certified bound.
pub fn distance_segment_segment(a: &Segment, b: &Segment) -> CertifiedDistance {
    let (p0, p1, q0, q1) = (coords(a.a()), coords(a.b()), coords(b.a()), coords(b.b()));
    finish(
        segment_segment(&p0, &p1, &q0, &q1),
        scale_of(&[&p0, &p1, &q0, &q1]),
        || a.intersects(b),
        |c| a.within_distance(b, c),
        None,
    )
}

/// The minimum distance between a closed segment and a closed triangle.
pub fn distance_segment_triangle(a: &Segment, b: &Triangle) -> CertifiedDistance {
    let (p0, p1, t) = (coords(a.a()), coords(a.b()), corner_coords(b));
    finish(
        segment_triangle(&p0, &p1, &t),
        scale_of(&[&p0, &p1, &t[0], &t[1], &t[2]]),
        || a.intersects(b),
        |c| a.within_distance(b, c),
        None,
    )
}

/// The minimum distance between two closed triangles.
pub fn distance_triangle_triangle(a: &Triangle, b: &Triangle) -> CertifiedDistance {
    let (s, t) = (corner_coords(a), corner_coords(b));
    finish(
        triangle_triangle(&s, &t),
        scale_of(&[&s[0], &s[1], &s[2], &t[0], &t[1], &t[2]]),
        || a.intersects(b),
        |c| a.within_distance(b, c),
        None,
    )
}

/// The exact squared distance and witnesses of two closed segments.
pub fn exact_distance_segment_segment(a: &Segment, b: &Segment) -> ExactDistance {
    let v = |p: &Point3<f64>| qv(&coords(p));
    exact(
        segment_segment(&v(a.a()), &v(a.b()), &v(b.a()), &v(b.b())),
        None,
    )
}

/// The exact squared distance and witnesses of a closed segment and a closed triangle.
pub fn exact_distance_segment_triangle(a: &Segment, b: &Triangle) -> ExactDistance {
    let t = corner_coords(b).map(|p| qv(&p));
    exact(
        segment_triangle(&qv(&coords(a.a())), &qv(&coords(a.b())), &t),
        None,
    )
}

/// The exact squared distance and witnesses of two closed triangles.
pub fn exact_distance_triangle_triangle(a: &Triangle, b: &Triangle) -> ExactDistance {
    let (s, t) = (
        corner_coords(a).map(|p| qv(&p)),
        corner_coords(b).map(|p| qv(&p)),
    );
    exact(triangle_triangle(&s, &t), None)
}

// ---------------------------------------------------------------- balls and spheres

#[inline]
fn norm(v: &V<f64>) -> f64 {
    dot(v, v).sqrt()
}

/// `from + (towards − from)·(len / |towards − from|)`: the point at distance `len` from `from`
/// in the direction of `towards` (any direction if they coincide).
fn step(from: &V<f64>, towards: &V<f64>, len: f64) -> V<f64> {
    let u = sub(towards, from);
    let n = norm(&u);
    if n > 0.0 && n.is_finite() {
        add_scaled(from, &u, &(len / n))
    } else {
        [from[0] + len, from[1], from[2]]
    }
}

/// A point at distance `r` from `c` on the segment `[s, f]`, where `|s − c| <= r <= |f − c|`
/// (`f64`, up to rounding): the root of `|s + t(f − s) − c|² = r²` in `[0, 1]`.
fn crossing(c: &V<f64>, r: f64, s: &V<f64>, f: &V<f64>) -> V<f64> {
    let (u, w) = (sub(f, s), sub(s, c));
    let (aa, bb, cc) = (dot(&u, &u), dot(&u, &w), dot(&w, &w) - r * r);
    if aa.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return *s;
    }
    let t = ((-bb + (bb * bb - aa * cc).max(0.0).sqrt()) / aa).clamp(0.0, 1.0);
    add_scaled(s, &u, &t)
}

/// The nearest points of a closed set `S` and the sphere *surface* (centre `c`, radius `r`),
/// given the point `near` of `S` nearest to `c` and a point `far` of `S` farthest from it
/// (the distances from `c` to `S` fill `[|near − c|, |far − c|]`, `S` being connected).
/// Returns the distance and the witnesses (on `S`, on the surface).
fn set_to_surface(near: V<f64>, far: V<f64>, c: &V<f64>, r: f64) -> (f64, V<f64>, V<f64>) {
    let (m, big) = (norm(&sub(&near, c)), norm(&sub(&far, c)));
    if m > r {
        let y = step(c, &near, r);
        (m - r, near, y)
    } else if big < r {
        let y = step(c, &far, r);
        (r - big, far, y)
    } else {
        let x = crossing(c, r, &near, &far);
        (0.0, x, x)
    }
}

/// The nearest points of a closed set `S` and the ball (centre `c`, radius `r`), given the
/// point `near` of `S` nearest to `c`.
fn set_to_ball(near: V<f64>, c: &V<f64>, r: f64) -> (f64, V<f64>, V<f64>) {
    let m = norm(&sub(&near, c));
    if m > r {
        let y = step(c, &near, r);
        (m - r, near, y)
    } else {
        (0.0, near, near)
    }
}

/// The vertex of `vs` farthest from `c` (in `f64`).
fn farthest(vs: &[V<f64>], c: &V<f64>) -> V<f64> {
    let mut best = (f64::NEG_INFINITY, vs[0]);
    for v in vs {
        let d = dist2(v, c);
        if d > best.0 {
            best = (d, *v);
        }
    }
    best.1
}

/// Wraps an `f64` answer `(distance, witness_a, witness_b)` with its certified bound; `within`
/// is the exact clearance test of the pair, `scale` bounds the coordinates and radii.
fn finish_radial(
    (distance, x, y): (f64, V<f64>, V<f64>),
    scale: f64,
    within: impl Fn(f64) -> bool,
) -> CertifiedDistance {
    CertifiedDistance {
        distance,
        error_bound: certify(distance, scale, || within(0.0), &within, &within),
        witness_a: Point3::from(x),
        witness_b: Point3::from(y),
        triangles: None,
    }
}

fn scale_with(points: &[&V<f64>], radii: &[f64]) -> f64 {
    radii.iter().fold(scale_of(points), |m, r| m.max(r.abs()))
}

/// The minimum distance between two solid balls (0 when they meet), with witnesses and a
/// certified bound ([`CertifiedDistance`]).
///
/// ```
/// use cga_collide::{nalgebra::Point3, query, Ball};
/// let a = Ball::new(Point3::origin(), 1.0)?;
/// let b = Ball::new(Point3::new(3.0, 0.0, 0.0), 0.5)?;
/// let d = query::distance_ball_ball(&a, &b);
/// assert!((d.distance - 1.5).abs() <= d.error_bound);
/// assert_eq!(d.witness_a, Point3::new(1.0, 0.0, 0.0));
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn distance_ball_ball(a: &Ball, b: &Ball) -> CertifiedDistance {
    let (ca, cb, ra, rb) = (
        coords(a.centre()),
        coords(b.centre()),
        a.radius(),
        b.radius(),
    );
    let d = norm(&sub(&cb, &ca));
    let near = if d > ra { step(&ca, &cb, ra) } else { cb };
    finish_radial(
        set_to_ball(near, &cb, rb),
        scale_with(&[&ca, &cb], &[ra, rb]),
        |c| a.within_distance(b, c),
    )
}

/// The minimum distance between a solid ball and a sphere *surface* (a ball deep inside the
/// sphere is at the distance to the surface).
pub fn distance_ball_sphere(a: &Ball, b: &Sphere) -> CertifiedDistance {
    let (ca, cb, ra, rb) = (
        coords(a.centre()),
        coords(b.centre()),
        a.radius(),
        b.radius(),
    );
    let d = norm(&sub(&cb, &ca));
    // The points of the ball nearest to and farthest from the sphere's centre.
    let near = if d > ra { step(&ca, &cb, ra) } else { cb };
    let far = if d > 0.0 {
        step(&ca, &cb, -ra)
    } else {
        [ca[0] + ra, ca[1], ca[2]]
    };
    finish_radial(
        set_to_surface(near, far, &cb, rb),
        scale_with(&[&ca, &cb], &[ra, rb]),
        |c| a.within_distance(b, c),
    )
}

/// The minimum distance between two sphere *surfaces* (nested spheres are at the gap between
/// the surfaces).
pub fn distance_sphere_sphere(a: &Sphere, b: &Sphere) -> CertifiedDistance {
    let (ca, cb, ra, rb) = (
        coords(a.centre()),
        coords(b.centre()),
        a.radius(),
        b.radius(),
    );
    let d = norm(&sub(&cb, &ca));
    // `b`'s surface as a set seen from `a`'s centre: nearest and farthest points.
    let near = if d > 0.0 {
        step(&cb, &ca, rb)
    } else {
        [cb[0] + rb, cb[1], cb[2]]
    };
    let far = if d > 0.0 {
        step(&cb, &ca, -rb)
    } else {
        [cb[0] + rb, cb[1], cb[2]]
    };
    let (dist, mut on_b, mut on_a) = set_to_surface(near, far, &ca, ra);
    if dist == 0.0 {
        // The surfaces meet in a circle (the chord point of `set_to_surface` is not on `b`'s
        // surface): the point of that circle in a plane through the centres.
        let x = circle_point(&ca, ra, &cb, rb);
        (on_a, on_b) = (x, x);
    }
    finish_radial(
        (dist, on_a, on_b),
        scale_with(&[&ca, &cb], &[ra, rb]),
        |c| a.within_distance(b, c),
    )
}

/// A point common to two meeting sphere surfaces (`f64`, up to rounding): on the line of the
/// centres at `t = (d² + ra² − rb²) / 2d` from `ca`, moved by `√(ra² − t²)` across it.
fn circle_point(ca: &V<f64>, ra: f64, cb: &V<f64>, rb: f64) -> V<f64> {
    let u = sub(cb, ca);
    let d = norm(&u);
    if !(d > 0.0 && d.is_finite()) {
        return [ca[0] + ra, ca[1], ca[2]]; // concentric: equal radii, any point
    }
    let t = ((d * d + ra * ra - rb * rb) / (2.0 * d)).clamp(-ra, ra);
    let h = (ra * ra - t * t).max(0.0).sqrt();
    // A unit vector across the line of the centres: `u` crossed with its smallest axis.
    let k = (0..3)
        .min_by(|&i, &j| u[i].abs().total_cmp(&u[j].abs()))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let w = cross(&u, &e);
    let on_axis = add_scaled(ca, &u, &(t / d));
    add_scaled(&on_axis, &w, &(h / norm(&w)))
}

/// The minimum distance between a closed segment and a solid ball.
pub fn distance_segment_ball(a: &Segment, b: &Ball) -> CertifiedDistance {
    let (p0, p1, c) = (coords(a.a()), coords(a.b()), coords(b.centre()));
    finish_radial(
        set_to_ball(point_segment(&p0, &p1, &c), &c, b.radius()),
        scale_with(&[&p0, &p1, &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

/// The minimum distance between a closed segment and a sphere *surface*.
pub fn distance_segment_sphere(a: &Segment, b: &Sphere) -> CertifiedDistance {
    let (p0, p1, c) = (coords(a.a()), coords(a.b()), coords(b.centre()));
    finish_radial(
        set_to_surface(
            point_segment(&p0, &p1, &c),
            farthest(&[p0, p1], &c),
            &c,
            b.radius(),
        ),
        scale_with(&[&p0, &p1, &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

/// The minimum distance between a closed triangle and a solid ball.
pub fn distance_triangle_ball(a: &Triangle, b: &Ball) -> CertifiedDistance {
    let (t, c) = (corner_coords(a), coords(b.centre()));
    finish_radial(
        set_to_ball(point_triangle(&t, &c), &c, b.radius()),
        scale_with(&[&t[0], &t[1], &t[2], &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

/// The minimum distance between a closed triangle and a sphere *surface*.
pub fn distance_triangle_sphere(a: &Triangle, b: &Sphere) -> CertifiedDistance {
    let (t, c) = (corner_coords(a), coords(b.centre()));
    finish_radial(
        set_to_surface(point_triangle(&t, &c), farthest(&t, &c), &c, b.radius()),
        scale_with(&[&t[0], &t[1], &t[2], &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}
