//! Euclidean reference tests in plain `f64`: baselines for the benchmarks and (in general
//! position) oracles for the exact tests.
//!
//! * [`moller_tri_tri`]: Möller's 1997 triangle–triangle test ("A Fast Triangle-Triangle
//!   Intersection Test", JGT 2(2)), faithful to the paper's reference code: interval test on
//!   the line of intersection of the two planes, with `USE_EPSILON_TEST` on and
//!   [`MOLLER_EPSILON`] `= 1e-6`, and the coplanar branch (projection on the axis plane where
//!   the normal is largest, edge–edge tests and point-in-triangle tests).
//! * [`moller_trumbore_segment_triangle`]: the Möller–Trumbore ray–triangle test (1997) with its
//!   `EPSILON = 1e-6` determinant cull, restricted to the segment parameter range `[0, 1]`.
//! * [`segment_ball`], [`segment_sphere`], [`triangle_ball`], [`triangle_sphere`],
//!   [`sphere_sphere`], [`ball_ball`]: closest-point / distance tests in `f64`.
//!
//! # Where they can be wrong
//! All of them round. In particular:
//! * Möller's epsilon is *absolute* and compares unnormalised plane distances (which scale
//!   with the cube of the coordinates): below roughly unit size everything within `1e-6` is
//!   snapped onto the plane and treated as touching or coplanar (false positives and the
//!   coplanar branch taken for non-coplanar input); for large coordinates the epsilon does
//!   nothing. Vertices that touch the other plane are handled by the interval code, but the
//!   interval end points are computed with divisions and compared with `<`, so touching
//!   configurations are decided by rounding.
//! * The coplanar branch's point-in-triangle test is strict, and its edge–edge test uses
//!   rounded 2D determinants: touching at a vertex or along an edge can go either way.
//! * Degenerate triangles (collinear vertices) give a zero normal: every distance is `0` and
//!   the coplanar branch runs with a meaningless projection.
//! * Products of coordinates overflow to infinity beyond about `1e102` and underflow to zero
//!   below about `1e-103` (three factors), after which the answers are arbitrary.
//! * Möller–Trumbore rejects every segment lying in the triangle's plane (`|det| < 1e-6`, again
//!   absolute and scale dependent) and decides edge hits by rounding.
//! * The sphere tests compare rounded squared distances: tangency is decided by rounding.
//!
//! The exact tests in [`crate::query`] have none of these failure modes; the table in the
//! README counts how often these references are wrong on a fixed adversarial set.

use nalgebra::{Point3, Vector3};

use crate::shape::{Ball, Segment, Sphere, Triangle};

/// Möller's `EPSILON` (the `USE_EPSILON_TEST` threshold on plane distances).
pub const MOLLER_EPSILON: f64 = 1e-6;

type V = Vector3<f64>;

fn at(p: &Point3<f64>, i: usize) -> f64 {
    p.coords[i]
}

/// Möller's 1997 triangle–triangle test (with its epsilon and coplanar branch).
///
/// ```
/// use cga_collide::{nalgebra::Point3, Triangle, testing::baseline::moller_tri_tri};
/// let t = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
///     Triangle::new(a.into(), b.into(), c.into()).unwrap()
/// };
/// let a = t([0., 0., 0.], [2., 0., 0.], [0., 2., 0.]);
/// let b = t([0.5, 0.5, -1.], [0.5, 0.5, 1.], [1.5, 1.5, 0.]);
/// assert!(moller_tri_tri(&a, &b));
/// ```
pub fn moller_tri_tri(t1: &Triangle, t2: &Triangle) -> bool {
    let [v0, v1, v2] = *t1.vertices();
    let [u0, u1, u2] = *t2.vertices();

    // Plane of triangle 1: N1·X + d1 = 0.
    let n1: V = (v1 - v0).cross(&(v2 - v0));
    let d1 = -n1.dot(&v0.coords);
    let mut du0 = n1.dot(&u0.coords) + d1;
    let mut du1 = n1.dot(&u1.coords) + d1;
    let mut du2 = n1.dot(&u2.coords) + d1;
    if du0.abs() < MOLLER_EPSILON {
        du0 = 0.0;
    }
    if du1.abs() < MOLLER_EPSILON {
        du1 = 0.0;
    }
    if du2.abs() < MOLLER_EPSILON {
        du2 = 0.0;
    }
    let du0du1 = du0 * du1;
    let du0du2 = du0 * du2;
    if du0du1 > 0.0 && du0du2 > 0.0 {
        return false;
    }

    // Plane of triangle 2.
    let n2: V = (u1 - u0).cross(&(u2 - u0));
    let d2 = -n2.dot(&u0.coords);
    let mut dv0 = n2.dot(&v0.coords) + d2;
    let mut dv1 = n2.dot(&v1.coords) + d2;
    let mut dv2 = n2.dot(&v2.coords) + d2;
    if dv0.abs() < MOLLER_EPSILON {
        dv0 = 0.0;
    }
    if dv1.abs() < MOLLER_EPSILON {
        dv1 = 0.0;
    }
    if dv2.abs() < MOLLER_EPSILON {
        dv2 = 0.0;
    }
    let dv0dv1 = dv0 * dv1;
    let dv0dv2 = dv0 * dv2;
    if dv0dv1 > 0.0 && dv0dv2 > 0.0 {
        return false;
    }

    // Direction of the intersection line and the axis it is largest along.
    let d: V = n1.cross(&n2);
    let mut max = d.x.abs();
    let mut index = 0;
    if d.y.abs() > max {
        max = d.y.abs();
        index = 1;
    }
    if d.z.abs() > max {
        index = 2;
    }
    let (vp0, vp1, vp2) = (at(&v0, index), at(&v1, index), at(&v2, index));
    let (up0, up1, up2) = (at(&u0, index), at(&u1, index), at(&u2, index));

    let Some(mut i1) = compute_intervals([vp0, vp1, vp2], [dv0, dv1, dv2], dv0dv1, dv0dv2) else {
        return coplanar_tri_tri(&n1, [v0, v1, v2], [u0, u1, u2]);
    };
    let Some(mut i2) = compute_intervals([up0, up1, up2], [du0, du1, du2], du0du1, du0du2) else {
        return coplanar_tri_tri(&n1, [v0, v1, v2], [u0, u1, u2]);
    };
    if i1[0] > i1[1] {
        i1.swap(0, 1);
    }
    if i2[0] > i2[1] {
        i2.swap(0, 1);
    }
    !(i1[1] < i2[0] || i2[1] < i1[0])
}

/// The interval of a triangle on the intersection line (`None`: coplanar).
fn compute_intervals(vv: [f64; 3], d: [f64; 3], d0d1: f64, d0d2: f64) -> Option<[f64; 2]> {
    let isect = |a: usize, b: usize, c: usize| {
        [
            vv[a] + (vv[b] - vv[a]) * d[a] / (d[a] - d[b]),
            vv[a] + (vv[c] - vv[a]) * d[a] / (d[a] - d[c]),
        ]
    };
    if d0d1 > 0.0 {
        // d0 and d1 on the same side, d2 on the other or on the plane.
        Some(isect(2, 0, 1))
    } else if d0d2 > 0.0 {
        Some(isect(1, 0, 2))
    } else if d[1] * d[2] > 0.0 || d[0] != 0.0 {
        Some(isect(0, 1, 2))
    } else if d[1] != 0.0 {
        Some(isect(1, 0, 2))
    } else if d[2] != 0.0 {
        Some(isect(2, 0, 1))
    } else {
        None
    }
}

fn coplanar_tri_tri(n: &V, v: [Point3<f64>; 3], u: [Point3<f64>; 3]) -> bool {
    // Project onto the axis-aligned plane where the triangle's area is largest.
    let a = n.abs();
    let (i0, i1) = if a.x > a.y {
        if a.x > a.z {
            (1, 2)
        } else {
            (0, 1)
        }
    } else if a.z > a.y {
        (0, 1)
    } else {
        (0, 2)
    };
    let p = |q: &Point3<f64>| [q.coords[i0], q.coords[i1]];
    let (v0, v1, v2) = (p(&v[0]), p(&v[1]), p(&v[2]));
    let (u0, u1, u2) = (p(&u[0]), p(&u[1]), p(&u[2]));
    edge_against_tri_edges(v0, v1, u0, u1, u2)
        || edge_against_tri_edges(v1, v2, u0, u1, u2)
        || edge_against_tri_edges(v2, v0, u0, u1, u2)
        || point_in_tri(v0, u0, u1, u2)
        || point_in_tri(u0, v0, v1, v2)
}

fn edge_against_tri_edges(
    v0: [f64; 2],
    v1: [f64; 2],
    u0: [f64; 2],
    u1: [f64; 2],
    u2: [f64; 2],
) -> bool {
    let ax = v1[0] - v0[0];
    let ay = v1[1] - v0[1];
    edge_edge_test(v0, ax, ay, u0, u1)
        || edge_edge_test(v0, ax, ay, u1, u2)
        || edge_edge_test(v0, ax, ay, u2, u0)
}

/// Möller's edge–edge test (from Franklin Antonio's "Faster Line Segment Intersection").
fn edge_edge_test(v0: [f64; 2], ax: f64, ay: f64, u0: [f64; 2], u1: [f64; 2]) -> bool {
    let bx = u0[0] - u1[0];
    let by = u0[1] - u1[1];
    let cx = v0[0] - u0[0];
    let cy = v0[1] - u0[1];
    let f = ay * bx - ax * by;
    let d = by * cx - bx * cy;
    if (f > 0.0 && d >= 0.0 && d <= f) || (f < 0.0 && d <= 0.0 && d >= f) {
        let e = ax * cy - ay * cx;
        if f > 0.0 {
            if e >= 0.0 && e <= f {
                return true;
            }
        } else if e <= 0.0 && e >= f {
            return true;
        }
    }
    false
}

fn point_in_tri(v0: [f64; 2], u0: [f64; 2], u1: [f64; 2], u2: [f64; 2]) -> bool {
    let side = |p: [f64; 2], q: [f64; 2]| {
        let a = q[1] - p[1];
        let b = -(q[0] - p[0]);
        let c = -a * p[0] - b * p[1];
        a * v0[0] + b * v0[1] + c
    };
    let d0 = side(u0, u1);
    let d1 = side(u1, u2);
    let d2 = side(u2, u0);
    d0 * d1 > 0.0 && d0 * d2 > 0.0
}

/// Möller–Trumbore (1997) applied to a segment: the ray from `a` along `b - a`, hit accepted for
/// the parameter range `[0, 1]`. Segments with `|det| < 1e-6` (parallel to, or lying in, the
/// triangle's plane, and every segment at small scale) are reported as not intersecting.
///
/// ```
/// use cga_collide::{nalgebra::Point3, Segment, Triangle, testing::baseline::moller_trumbore_segment_triangle};
/// let t = Triangle::new(Point3::origin(), Point3::new(2., 0., 0.), Point3::new(0., 2., 0.)).unwrap();
/// let s = Segment::new(Point3::new(0.5, 0.5, -1.), Point3::new(0.5, 0.5, 1.)).unwrap();
/// assert!(moller_trumbore_segment_triangle(&s, &t));
/// ```
pub fn moller_trumbore_segment_triangle(s: &Segment, t: &Triangle) -> bool {
    let [v0, v1, v2] = *t.vertices();
    let orig = s.a();
    let dir: V = s.b() - s.a();
    let edge1: V = v1 - v0;
    let edge2: V = v2 - v0;
    let pvec = dir.cross(&edge2);
    let det = edge1.dot(&pvec);
    if det > -MOLLER_EPSILON && det < MOLLER_EPSILON {
        return false;
    }
    let inv_det = 1.0 / det;
    let tvec: V = orig - v0;
    let u = tvec.dot(&pvec) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return false;
    }
    let qvec = tvec.cross(&edge1);
    let v = dir.dot(&qvec) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return false;
    }
    let t = edge2.dot(&qvec) * inv_det;
    (0.0..=1.0).contains(&t)
}

/// The point of segment `[a, b]` closest to `c`, in `f64`.
pub fn closest_point_on_segment(a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> Point3<f64> {
    let d: V = b - a;
    let dd = d.dot(&d);
    if dd <= 0.0 {
        return *a;
    }
    let t = ((c - a).dot(&d) / dd).clamp(0.0, 1.0);
    a + d * t
}

/// The point of the triangle closest to `p`, in `f64` (Voronoi-region walk over vertices,
/// edges and face, as in Ericson's *Real-Time Collision Detection* §5.1.5).
pub fn closest_point_on_triangle(t: &Triangle, p: &Point3<f64>) -> Point3<f64> {
    let [a, b, c] = *t.vertices();
    let ab: V = b - a;
    let ac: V = c - a;
    let ap: V = p - a;
    let d1 = ab.dot(&ap);
    let d2 = ac.dot(&ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp: V = p - b;
    let d3 = ab.dot(&bp);
    let d4 = ac.dot(&bp);
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp: V = p - c;
    let d5 = ab.dot(&cp);
    let d6 = ac.dot(&cp);
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = va + vb + vc;
    if denom == 0.0 || !denom.is_finite() {
        // Degenerate triangle: the closest of the three edges.
        let cands = [
            closest_point_on_segment(&a, &b, p),
            closest_point_on_segment(&b, &c, p),
            closest_point_on_segment(&c, &a, p),
        ];
        return cands
            .into_iter()
            .min_by(|x, y| (x - p).norm_squared().total_cmp(&(y - p).norm_squared()))
            .unwrap_or(a);
    }
    let v = vb / denom;
    let w = vc / denom;
    a + ab * v + ac * w
}

/// Segment against solid ball, by the rounded closest point.
pub fn segment_ball(s: &Segment, b: &Ball) -> bool {
    let q = closest_point_on_segment(s.a(), s.b(), b.centre());
    (q - b.centre()).norm_squared() <= b.radius() * b.radius()
}

/// Segment against spherical surface: `min distance <= r <= max distance`, rounded.
pub fn segment_sphere(s: &Segment, sp: &Sphere) -> bool {
    let c = sp.centre();
    let r2 = sp.radius() * sp.radius();
    let q = closest_point_on_segment(s.a(), s.b(), c);
    (q - c).norm_squared() <= r2
        && ((s.a() - c).norm_squared() >= r2 || (s.b() - c).norm_squared() >= r2)
}

/// Triangle against solid ball, by the rounded closest point.
pub fn triangle_ball(t: &Triangle, b: &Ball) -> bool {
    let q = closest_point_on_triangle(t, b.centre());
    (q - b.centre()).norm_squared() <= b.radius() * b.radius()
}

/// Triangle against spherical surface: `min distance <= r <= max distance`, rounded.
pub fn triangle_sphere(t: &Triangle, sp: &Sphere) -> bool {
    let c = sp.centre();
    let r2 = sp.radius() * sp.radius();
    let q = closest_point_on_triangle(t, c);
    (q - c).norm_squared() <= r2 && t.vertices().iter().any(|v| (v - c).norm_squared() >= r2)
}

/// Two spherical surfaces: `|r1 - r2| <= |c1 - c2| <= r1 + r2`, rounded.
pub fn sphere_sphere(a: &Sphere, b: &Sphere) -> bool {
    let d2 = (a.centre() - b.centre()).norm_squared();
    let s = a.radius() + b.radius();
    let t = a.radius() - b.radius();
    d2 <= s * s && d2 >= t * t
}

/// Two solid balls: `|c1 - c2| <= r1 + r2`, rounded.
pub fn ball_ball(a: &Ball, b: &Ball) -> bool {
    let d2 = (a.centre() - b.centre()).norm_squared();
    let s = a.radius() + b.radius();
    d2 <= s * s
}
