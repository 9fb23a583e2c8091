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
//! [`Distance::distance`] is the `f64` result `d`; [`Distance::error_bound`] is an `e` such that
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
//! # Ok::<(), cga_collide::GeometryError>(())
//! ```

use ga_core::scalar::{rational_from_f64, Rational, Real, Ring};
use nalgebra::Point3;

use crate::query::clearance::{mesh_tri, triangles_within, WithinDistance};
use crate::query::proximity::nearest_pair;
use crate::query::{Collider, Intersects};
use crate::shape::{Ball, Segment, Sphere, Triangle};

type V<F> = [F; 3];

#[inline(always)]
fn sub<F: Real>(a: &V<F>, b: &V<F>) -> V<F> {
    [
        a[0].clone() - b[0].clone(),
        a[1].clone() - b[1].clone(),
        a[2].clone() - b[2].clone(),
    ]
}

#[inline(always)]
fn add_scaled<F: Real>(a: &V<F>, u: &V<F>, s: &F) -> V<F> {
    [
        a[0].clone() + u[0].clone() * s.clone(),
        a[1].clone() + u[1].clone() * s.clone(),
        a[2].clone() + u[2].clone() * s.clone(),
    ]
}

#[inline(always)]
fn dot<F: Real>(a: &V<F>, b: &V<F>) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

#[inline(always)]
fn cross<F: Real>(u: &V<F>, v: &V<F>) -> V<F> {
    [
        u[1].clone() * v[2].clone() - u[2].clone() * v[1].clone(),
        u[2].clone() * v[0].clone() - u[0].clone() * v[2].clone(),
        u[0].clone() * v[1].clone() - u[1].clone() * v[0].clone(),
    ]
}

#[inline(always)]
fn dist2<F: Real>(a: &V<F>, b: &V<F>) -> F {
    let d = sub(a, b);
    dot(&d, &d)
}

/// A candidate nearest pair: squared distance and the two points.
type Near<F> = (F, V<F>, V<F>);

#[inline(always)]
fn keep<F: Real>(best: &mut Option<Near<F>>, c: Near<F>) {
    if best.as_ref().is_none_or(|b| c.0 < b.0) {
        *best = Some(c);
    }
}

/// The point of segment `ab` nearest to `p`.
fn point_segment<F: Real>(a: &V<F>, b: &V<F>, p: &V<F>) -> V<F> {
    let u = sub(b, a);
    let t = dot(&sub(p, a), &u);
    if t <= F::zero() {
        return a.clone();
    }
    let den = dot(&u, &u);
    if t >= den {
        return b.clone();
    }
    add_scaled(a, &u, &(t / den))
}

/// The point of triangle `t` nearest to `p`.
fn point_triangle<F: Real>(t: &[V<F>; 3], p: &V<F>) -> V<F> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let nn = dot(&n, &n);
    let inside = !nn.is_zero()
        && (0..3).all(|i| {
            let e = sub(&t[(i + 1) % 3], &t[i]);
            dot(&cross(&e, &sub(p, &t[i])), &n) >= F::zero()
        });
    if inside {
        let h = dot(&n, &sub(p, &t[0])) / nn;
        return add_scaled(p, &n, &-h);
    }
    let mut best: Option<Near<F>> = None;
    for i in 0..3 {
        let q = point_segment(&t[i], &t[(i + 1) % 3], p);
        keep(&mut best, (dist2(&q, p), q, p.clone()));
    }
    best.map(|b| b.1).unwrap_or_else(|| t[0].clone())
}

/// The nearest points of segments `ab` and `cd`.
fn segment_segment<F: Real>(a: &V<F>, b: &V<F>, c: &V<F>, d: &V<F>) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for (p, s0, s1, first) in [
        (a, c, d, true),
        (b, c, d, true),
        (c, a, b, false),
        (d, a, b, false),
    ] {
        let q = point_segment(s0, s1, p);
        let d2 = dist2(p, &q);
        keep(
            &mut best,
            if first {
                (d2, p.clone(), q)
            } else {
                (d2, q, p.clone())
            },
        );
    }
    if let Some(near) = common_perpendicular(a, b, c, d) {
        keep(&mut best, near);
    }
    best.unwrap_or_else(|| unreachable!("four candidates"))
}

/// The points where the common perpendicular of lines `ab` and `cd` meets them, if it meets
/// both segments (the interior candidate of the nearest points of two segments).
fn common_perpendicular<F: Real>(a: &V<F>, b: &V<F>, c: &V<F>, d: &V<F>) -> Option<Near<F>> {
    let (u, v, w) = (sub(b, a), sub(d, c), sub(c, a));
    let n = cross(&u, &v);
    let nn = dot(&n, &n);
    if !nn.is_zero() {
        let s = dot(&cross(&w, &v), &n);
        let t = dot(&cross(&w, &u), &n);
        let zero = F::zero();
        if s >= zero && s <= nn && t >= zero && t <= nn {
            let p = add_scaled(a, &u, &(s / nn.clone()));
            let q = add_scaled(c, &v, &(t / nn));
            return Some((dist2(&p, &q), p, q));
        }
    }
    None
}

/// Where segment `ab` crosses the plane of the triangle `t` strictly (its end points strictly
/// on opposite sides), if it does.
fn plane_crossing<F: Real>(a: &V<F>, b: &V<F>, t: &[V<F>; 3]) -> Option<V<F>> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let da = dot(&n, &sub(a, &t[0]));
    let db = dot(&n, &sub(b, &t[0]));
    let zero = F::zero();
    let crosses = (da > zero && db < zero) || (da < zero && db > zero);
    crosses.then(|| add_scaled(a, &sub(b, a), &(da.clone() / (da - db))))
}

/// The nearest points of segment `ab` and triangle `t`.
fn segment_triangle<F: Real>(a: &V<F>, b: &V<F>, t: &[V<F>; 3]) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for p in [a, b] {
        let q = point_triangle(t, p);
        keep(&mut best, (dist2(p, &q), p.clone(), q));
    }
    for i in 0..3 {
        keep(&mut best, segment_segment(a, b, &t[i], &t[(i + 1) % 3]));
    }
    if let Some(x) = plane_crossing(a, b, t) {
        let q = point_triangle(t, &x);
        keep(&mut best, (dist2(&x, &q), x, q));
    }
    best.unwrap_or_else(|| unreachable!("candidates"))
}

/// The nearest points of triangles `p` and `q`.
fn triangle_triangle<F: Real>(p: &[V<F>; 3], q: &[V<F>; 3]) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for v in p {
        let y = point_triangle(q, v);
        keep(&mut best, (dist2(v, &y), v.clone(), y));
    }
    for v in q {
        let x = point_triangle(p, v);
        keep(&mut best, (dist2(&x, v), x, v.clone()));
    }
    // Edge pairs: only their interiors, since a vertex's distance to an edge is never below
    // its distance to that edge's triangle (a candidate above).
    for i in 0..3 {
        for j in 0..3 {
            if let Some(near) = common_perpendicular(&p[i], &p[(i + 1) % 3], &q[j], &q[(j + 1) % 3])
            {
                keep(&mut best, near);
            }
        }
    }
    // Intersecting triangles: an edge of one crosses the other.
    for i in 0..3 {
        if let Some(x) = plane_crossing(&p[i], &p[(i + 1) % 3], q) {
            let y = point_triangle(q, &x);
            keep(&mut best, (dist2(&x, &y), x, y));
        }
        if let Some(y) = plane_crossing(&q[i], &q[(i + 1) % 3], p) {
            let x = point_triangle(p, &y);
            keep(&mut best, (dist2(&x, &y), x, y));
        }
    }
    best.unwrap_or_else(|| unreachable!("candidates"))
}

// ---------------------------------------------------------------- results

/// A minimum distance in `f64` with a certified error bound (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Distance {
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

#[inline]
fn pt(p: &Point3<f64>) -> V<f64> {
    [p.x, p.y, p.z]
}

fn q(x: f64) -> Rational {
    // Shapes and meshes hold finite coordinates only.
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

fn qv(p: &V<f64>) -> V<Rational> {
    [q(p[0]), q(p[1]), q(p[2])]
}

fn tri(t: &Triangle) -> [V<f64>; 3] {
    let [a, b, c] = t.vertices();
    [pt(a), pt(b), pt(c)]
}

/// Proves `true distance ∈ [d - e, d + e]` with exact clearance tests and returns
/// `e` (see the module docs). `scale` bounds the magnitude of the coordinates involved.
/// `upper(c)` proves `distance <= c`; `lower(c)` is false only if `distance > c`.
fn certify(
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

fn scale_of(points: &[&V<f64>]) -> f64 {
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
) -> Distance {
    let (d2, x, y) = near;
    let distance = d2.sqrt();
    Distance {
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
pub fn distance_segment_segment(a: &Segment, b: &Segment) -> Distance {
    let (p0, p1, q0, q1) = (pt(a.a()), pt(a.b()), pt(b.a()), pt(b.b()));
    finish(
        segment_segment(&p0, &p1, &q0, &q1),
        scale_of(&[&p0, &p1, &q0, &q1]),
        || a.intersects(b),
        |c| a.within_distance(b, c),
        None,
    )
}

/// The minimum distance between a closed segment and a closed triangle.
pub fn distance_segment_triangle(a: &Segment, b: &Triangle) -> Distance {
    let (p0, p1, t) = (pt(a.a()), pt(a.b()), tri(b));
    finish(
        segment_triangle(&p0, &p1, &t),
        scale_of(&[&p0, &p1, &t[0], &t[1], &t[2]]),
        || a.intersects(b),
        |c| a.within_distance(b, c),
        None,
    )
}

/// The minimum distance between two closed triangles.
pub fn distance_triangle_triangle(a: &Triangle, b: &Triangle) -> Distance {
    let (s, t) = (tri(a), tri(b));
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
    let v = |p: &Point3<f64>| qv(&pt(p));
    exact(
        segment_segment(&v(a.a()), &v(a.b()), &v(b.a()), &v(b.b())),
        None,
    )
}

/// The exact squared distance and witnesses of a closed segment and a closed triangle.
pub fn exact_distance_segment_triangle(a: &Segment, b: &Triangle) -> ExactDistance {
    let t = tri(b).map(|p| qv(&p));
    exact(segment_triangle(&qv(&pt(a.a())), &qv(&pt(a.b())), &t), None)
}

/// The exact squared distance and witnesses of two closed triangles.
pub fn exact_distance_triangle_triangle(a: &Triangle, b: &Triangle) -> ExactDistance {
    let (s, t) = (tri(a).map(|p| qv(&p)), tri(b).map(|p| qv(&p)));
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
) -> Distance {
    Distance {
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
/// certified bound (see the [module docs](self)).
///
/// ```
/// use cga_collide::{nalgebra::Point3, query, Ball};
/// let a = Ball::new(Point3::origin(), 1.0)?;
/// let b = Ball::new(Point3::new(3.0, 0.0, 0.0), 0.5)?;
/// let d = query::distance_ball_ball(&a, &b);
/// assert!((d.distance - 1.5).abs() <= d.error_bound);
/// assert_eq!(d.witness_a, Point3::new(1.0, 0.0, 0.0));
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
pub fn distance_ball_ball(a: &Ball, b: &Ball) -> Distance {
    let (ca, cb, ra, rb) = (pt(a.centre()), pt(b.centre()), a.radius(), b.radius());
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
pub fn distance_ball_sphere(a: &Ball, b: &Sphere) -> Distance {
    let (ca, cb, ra, rb) = (pt(a.centre()), pt(b.centre()), a.radius(), b.radius());
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
pub fn distance_sphere_sphere(a: &Sphere, b: &Sphere) -> Distance {
    let (ca, cb, ra, rb) = (pt(a.centre()), pt(b.centre()), a.radius(), b.radius());
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
pub fn distance_segment_ball(a: &Segment, b: &Ball) -> Distance {
    let (p0, p1, c) = (pt(a.a()), pt(a.b()), pt(b.centre()));
    finish_radial(
        set_to_ball(point_segment(&p0, &p1, &c), &c, b.radius()),
        scale_with(&[&p0, &p1, &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

/// The minimum distance between a closed segment and a sphere *surface*.
pub fn distance_segment_sphere(a: &Segment, b: &Sphere) -> Distance {
    let (p0, p1, c) = (pt(a.a()), pt(a.b()), pt(b.centre()));
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
pub fn distance_triangle_ball(a: &Triangle, b: &Ball) -> Distance {
    let (t, c) = (tri(a), pt(b.centre()));
    finish_radial(
        set_to_ball(point_triangle(&t, &c), &c, b.radius()),
        scale_with(&[&t[0], &t[1], &t[2], &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

/// The minimum distance between a closed triangle and a sphere *surface*.
pub fn distance_triangle_sphere(a: &Triangle, b: &Sphere) -> Distance {
    let (t, c) = (tri(a), pt(b.centre()));
    finish_radial(
        set_to_surface(point_triangle(&t, &c), farthest(&t, &c), &c, b.radius()),
        scale_with(&[&t[0], &t[1], &t[2], &c], &[b.radius()]),
        |r| a.within_distance(b, r),
    )
}

// ---------------------------------------------------------------- meshes

/// `2⁻⁵³`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;
/// Absolute allowance for underflow in a few products (far above `2⁻¹⁰⁷⁴` each).
const TINY: f64 = 9.332636185032189e-302; // 2^-1000
/// Below this squared length a direction is too small for a relative error analysis.
const SMALL2: f64 = 1.0e-280;
/// Results below this are treated as no information: far above the subnormal range, where
/// rounding errors are absolute rather than relative.
const NORMAL: f64 = 1.0e-290;

/// The separation of triangles `p` and `q` along a direction `n` (any vector), as a pair
/// `(g, nn)`: the distance is **proved** (for the real numbers the `f64` coordinates denote)
/// to be at least `g / √nn`, from the gap between the projections of the triangles on `n`
/// (projection on a line is 1-Lipschitz, so that gap divided by `|n|` never exceeds the
/// distance).
///
/// Roundings: each dot product `fl(n·v)` is within `γ₃ Σ|nᵢ||vᵢ| < 3.01u·m` of `n·v` (`m` the
/// largest such magnitude sum over the six vertices, itself computed within `γ₃`), and the
/// gap's subtraction adds at most `u·2m`; so `g = fl(gap − (12u·m + TINY))` is at most the true
/// gap times `1 + u` (`TINY` pays for underflowing products). `nn = fl(n·n)` is within `γ₃` of
/// `|n|²`. `None` when the projections overlap, or anything is out of range (non-finite, or `n`
/// so short that `nn` could underflow).
#[inline]
fn separation(n: &V<f64>, p: &[V<f64>; 3], q: &[V<f64>; 3]) -> Option<(f64, f64)> {
    let nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if !(nn >= SMALL2 && nn.is_finite()) {
        return None;
    }
    let proj = |v: &V<f64>| n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    let mag = |v: &V<f64>| (n[0] * v[0]).abs() + (n[1] * v[1]).abs() + (n[2] * v[2]).abs();
    let (mut pmin, mut pmax, mut qmin, mut qmax) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    let mut m = 0.0f64;
    for v in p {
        let s = proj(v);
        pmin = pmin.min(s);
        pmax = pmax.max(s);
        m = m.max(mag(v));
    }
    for v in q {
        let s = proj(v);
        qmin = qmin.min(s);
        qmax = qmax.max(s);
        m = m.max(mag(v));
    }
    let g = (qmin - pmax).max(pmin - qmax) - (12.0 * U * m + TINY);
    (g > 0.0 && g.is_finite()).then_some((g, nn))
}

/// Whether a separation `(g, nn)` proves the distance squared above `best`: `g² > best·nn`
/// with a relative margin `16u` that pays for `g` (`1 + u`), `nn` (`γ₃`) and the two products.
/// `g²` must be far from the subnormal range (where rounding is absolute, not relative); then
/// a subnormal `best·nn` is below it anyway.
#[inline]
fn separated_beyond((g, nn): (f64, f64), best: f64) -> bool {
    let g2 = g * g;
    g2 >= NORMAL && g2 * (1.0 - 16.0 * U) > best * nn
}

/// The proved lower bound `g / √nn` of a separation, rounded down (the square root, the
/// division and `nn` cost under `4u` relative, paid by the factor `1 − 8u`).
#[inline]
fn separation_bound((g, nn): (f64, f64)) -> f64 {
    let b = g / nn.sqrt() * (1.0 - 8.0 * U);
    // A quotient near the subnormal range could be rounded up by an absolute amount.
    if b >= NORMAL {
        b
    } else {
        0.0
    }
}

/// The normal `(b − a) × (c − a)` of a triangle, in `f64` (a test direction for
/// [`separation`]).
#[cfg(test)]
fn normal(t: &[V<f64>; 3]) -> V<f64> {
    cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]))
}

/// Three times the centroid of a triangle, in `f64` (a direction for [`separation`]).
#[inline]
fn centroid3(t: &[V<f64>; 3]) -> V<f64> {
    [
        t[0][0] + t[1][0] + t[2][0],
        t[0][1] + t[1][1] + t[2][1],
        t[0][2] + t[1][2] + t[2][2],
    ]
}

/// The open pairs of a mesh search: `(proved lower bound, i, j)` for every examined pair whose
/// proved bounds did not exceed the best squared distance at the time (see [`examine_pair`]).
pub(crate) type Open = Vec<(f64, u32, u32)>;

/// One examined pair of the `f64` nearest-pair search (triangles `x` of A and `y` of B with
/// corners `p` and `q`; `best` the best squared distance so far): its `f64` squared distance,
/// or `+∞` when it is proved farther than `best`. First a proved lower bound from the
/// separation along the line of the centroids (for small triangles far apart, nearly their
/// distance; the normals were tried too and cost more than they saved); only when that does not
/// beat `best` is the `f64` closest-points routine run, and its witnesses' direction gives a
/// second proved bound. A pair whose proved bounds stay at or below the best is pushed on
/// `open` with the larger bound.
pub(crate) fn examine_pair(
    x: u32,
    p: &[V<f64>; 3],
    y: u32,
    q: &[V<f64>; 3],
    best: f64,
    open: &mut Open,
) -> f64 {
    let centres = separation(&sub(&centroid3(q), &centroid3(p)), p, q);
    if centres.is_some_and(|s| separated_beyond(s, best)) {
        return f64::INFINITY; // proved farther than the best so far
    }

    let (d2, wx, wy) = triangle_triangle(p, q);
    let witnesses = separation(&sub(&wy, &wx), p, q);
    let seps = [centres, witnesses];
    if !seps
        .iter()
        .flatten()
        .any(|&s| separated_beyond(s, best.min(d2)))
    {
        let lb = seps
            .iter()
            .flatten()
            .map(|&s| separation_bound(s))
            .fold(0.0, f64::max);
        open.push((lb, x, y));
    }
    d2
}

/// The certified result of a mesh search that found the pair `(i, j)` and left `open` (see
/// [`examine_pair`]); `tri_a(i)` and `tri_b(j)` give the triangles' corners.
///
/// Every pair not in `open` is proved farther than the best `f64` squared distance, hence than
/// any `c` the certification tries for the lower end (`c < distance`): only `open` can bring
/// the distance down to `c`. So the bound depends on the pair `(i, j)` and on the meshes, not
/// on the order of the search.
pub(crate) fn certified_mesh_distance(
    (i, j): (u32, u32),
    open: &Open,
    tri_a: impl Fn(u32) -> [V<f64>; 3],
    tri_b: impl Fn(u32) -> [V<f64>; 3],
) -> Distance {
    let (s, t) = (tri_a(i), tri_b(j));
    let (d2, x, y) = triangle_triangle(&s, &t);
    let distance = d2.sqrt();
    let error_bound = certify(
        distance,
        scale_of(&[&s[0], &s[1], &s[2], &t[0], &t[1], &t[2]]),
        || triangles_within(&s, &t, 0.0),
        |c| triangles_within(&s, &t, c),
        |c| {
            open.iter()
                .any(|&(lb, x, y)| lb <= c && triangles_within(&tri_a(x), &tri_b(y), c))
        },
    );
    Distance {
        distance,
        error_bound,
        witness_a: Point3::from(x),
        witness_b: Point3::from(y),
        triangles: Some((i, j)),
    }
}

/// The minimum distance between the surfaces of two meshes (in the same frame, see
/// [`Collider::placed`]), with witnesses, the triangle pair `(i, j)` attaining it and a
/// certified error bound; `None` if a mesh has no triangles.
///
/// The `f64` search is best-first branch and bound on the hierarchies: node pairs are ordered
/// and pruned by a proved lower bound from boxes fitted to the geometry (principal axes, or the
/// coordinate axes when those fit better) and the axis-aligned boxes; triangle pairs by their
/// box distance and by separation bounds. Among pairs with the same `f64` squared distance, the
/// smallest `(i, j)` is kept.
///
/// The bound is proved over **all** triangle pairs, so it holds for the meshes' true distance
/// even when several pairs nearly tie. The upper end: the exact clearance test of the pair
/// found. The lower end: every other pair is either pruned by its box distance (a rounding
/// margin of `1e-9` relative), or proved farther by an `f64` separation bound with every
/// rounding accounted for, or decided by the exact clearance test (the few pairs whose proved
/// bound does not beat the best `f64` distance: the winner and near-ties).
///
/// ```
/// use cga_collide::{nalgebra::{Isometry3, Point3}, query::{self, Collider}, TriMesh};
/// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
/// let moved = cube.placed(&Isometry3::translation(1.5, 0.25, 0.0))?;
/// let d = query::mesh_distance(&cube, &moved).unwrap();
/// assert!((d.distance - 0.5).abs() <= d.error_bound && d.error_bound < 1e-12);
/// # Ok::<(), cga_collide::mesh::MeshError>(())
/// ```
pub fn mesh_distance(a: &Collider, b: &Collider) -> Option<Distance> {
    let mut open = Vec::new();
    let (_, i, j) = nearest_pair(a, b, |x, p, y, q, best| {
        examine_pair(x, p, y, q, best, &mut open)
    })?;
    Some(certified_mesh_distance(
        (i, j),
        &open,
        |x| mesh_tri(a, x),
        |y| mesh_tri(b, y),
    ))
}

/// The minimum distance between the surfaces of two meshes, exactly: the squared distance,
/// witnesses and the triangle pair as exact rationals; `None` if a mesh has no triangles.
/// The exact nearest pair is chosen among the pairs within the certified upper bound of
/// [`mesh_distance`] (found with the exact clearance test), so near-ties are resolved exactly.
pub fn exact_mesh_distance(a: &Collider, b: &Collider) -> Option<ExactDistance> {
    let d = mesh_distance(a, b)?;
    let hi = (d.distance + d.error_bound).next_up();
    let mut best: Option<(Near<Rational>, u32, u32)> = None;
    for (i, j) in crate::query::clearance::mesh_pairs_within_distance(a, b, hi) {
        let near = triangle_triangle(
            &mesh_tri(a, i).map(|p| qv(&p)),
            &mesh_tri(b, j).map(|p| qv(&p)),
        );
        if best.as_ref().is_none_or(|(b, _, _)| near.0 < b.0) {
            best = Some((near, i, j));
        }
    }
    best.map(|(near, i, j)| exact(near, Some((i, j))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            2 => (-3i32..=3).prop_map(f64::from),
            3 => -3.0f64..3.0,
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e-9),
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e150),
        ]
    }

    fn point() -> impl Strategy<Value = V<f64>> {
        [coord(), coord(), coord()]
    }

    fn triangle() -> impl Strategy<Value = [V<f64>; 3]> {
        [point(), point(), point()]
    }

    fn exact2(p: &[V<f64>; 3], q: &[V<f64>; 3]) -> Rational {
        triangle_triangle(&p.map(|v| qv(&v)), &q.map(|v| qv(&v))).0
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20))]

        /// The separation along any direction (random, normals, centroids, the `f64` witnesses'
        /// direction) is a proved lower bound: checked against the exact rational distance, for
        /// the bound itself and for the squared comparison used to prune.
        #[test]
        fn separation_never_exceeds_the_exact_distance(
            p in triangle(),
            q in triangle(),
            n in point(),
            shift in point(),
        ) {
            // Also a copy of q moved away, so that separated pairs are frequent.
            let far = q.map(|v| [v[0] + shift[0], v[1] + shift[1], v[2] + shift[2]]);
            for q in [q, far] {
                let exact = exact2(&p, &q);
                let (_, wx, wy) = triangle_triangle(&p, &q);
                for n in [n, normal(&p), normal(&q), sub(&centroid3(&q), &centroid3(&p)), sub(&wy, &wx)] {
                    let Some(s) = separation(&n, &p, &q) else { continue };
                    let lb = separation_bound(s);
                    prop_assert!(lb >= 0.0);
                    prop_assert!(q_sq(lb) <= exact, "bound {lb} above the distance");
                    // Pruning: proved beyond `best` only if the exact distance is.
                    let e = Real::to_f64(&exact);
                    for best in [e, e.next_down(), e.next_up(), e * (1.0 - 1e-15), lb * lb] {
                        if best.is_finite() && separated_beyond(s, best) {
                            prop_assert!(exact > rational_from_f64(best).unwrap());
                        }
                    }
                }
            }
        }
    }

    fn q_sq(x: f64) -> Rational {
        let r = q(x);
        &r * &r
    }

    #[test]
    fn separation_of_far_apart_triangles_is_nearly_their_distance() {
        let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let q = p.map(|v| [v[0], v[1], v[2] + 0.5]);
        let s = separation(&normal(&p), &p, &q).unwrap();
        let lb = separation_bound(s);
        assert!(lb <= 0.5 && lb > 0.5 * (1.0 - 1e-14), "{lb}");
        // Overlapping projections and degenerate directions give nothing.
        assert_eq!(separation(&[1.0, 0.0, 0.0], &p, &q), None);
        assert_eq!(separation(&[0.0, 0.0, 0.0], &p, &q), None);
        assert_eq!(separation(&[f64::NAN, 0.0, 1.0], &p, &q), None);
        assert_eq!(separation(&[0.0, 0.0, 1e300], &p, &q), None);
    }
}
