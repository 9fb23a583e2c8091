//! Support features: the part of a shape's boundary that faces a direction (a point, a
//! segment, a flat convex polygon or a plane), found in `f64` with an angular tolerance so
//! that a face resting almost flat on another gives a polygon rather than one corner.

use nalgebra::{Point3, Vector3};

use crate::shape::Shape;

/// A feature's points lie on the shape up to rounding (or inside it: rim polygons of discs).
#[derive(Debug, Clone)]
pub(super) enum Feature {
    /// One point.
    Point(Point3<f64>),
    /// A segment of the boundary.
    Segment(Point3<f64>, Point3<f64>),
    /// A flat convex polygon, corners in order around it (either orientation).
    Polygon(Vec<Point3<f64>>),
    /// A half-space's boundary plane: a point on it and its outward normal.
    Plane(Point3<f64>, Vector3<f64>),
}

/// The cosine of the largest angle between a face's outward normal and the direction for the
/// face to count as facing it (about 2.6 degrees).
const FACE_COS: f64 = 0.999;
/// The sine of that angle: a segment counts as facing the direction when it is this close to
/// perpendicular to it.
const EDGE_SIN: f64 = 0.045;
/// Points on a disc's rim used for a facing cap or base (the manifold keeps at most four).
const RIM_POINTS: usize = 8;

/// The feature of `shape` facing the unit direction `d`.
pub(super) fn support_feature(shape: &Shape, d: &Vector3<f64>) -> Feature {
    match shape {
        Shape::Ball(b) => Feature::Point(b.centre() + d * b.radius()),
        Shape::Capsule(c) => grown_segment(c.a(), c.b(), c.radius(), d),
        Shape::Segment(s) => grown_segment(s.a(), s.b(), 0.0, d),
        Shape::Triangle(t) => polytope(t.vertices(), d),
        Shape::Cuboid(c) => {
            let (o, ax) = (c.centre(), c.half_axes());
            let corners: Vec<Point3<f64>> = (0..8)
                .map(|i| {
                    let s = |k: usize| if i >> k & 1 == 1 { 1.0 } else { -1.0 };
                    o + ax[0] * s(0) + ax[1] * s(1) + ax[2] * s(2)
                })
                .collect();
            polytope(&corners, d)
        }
        Shape::ConvexHull(h) => polytope(h.extreme_points(), d),
        Shape::HalfSpace(h) => Feature::Plane(*h.point(), *h.normal()),
        Shape::Cylinder(c) => cylinder(c.a(), c.b(), c.radius(), d),
        Shape::Cone(c) => cone(c.apex(), c.base(), c.radius(), d),
    }
}

/// A segment `ab` grown by a ball of radius `r`.
fn grown_segment(a: &Point3<f64>, b: &Point3<f64>, r: f64, d: &Vector3<f64>) -> Feature {
    let shift = d * r;
    let axis = b - a;
    let len = axis.norm();
    if len > 0.0 && (axis.dot(d) / len).abs() <= EDGE_SIN {
        Feature::Segment(a + shift, b + shift)
    } else if axis.dot(d) > 0.0 {
        Feature::Point(b + shift)
    } else {
        Feature::Point(a + shift)
    }
}

/// The points of a convex polytope facing `d`: those within the angular tolerance of the
/// support plane (measured against the polytope's size), ordered into a convex polygon.
fn polytope(points: &[Point3<f64>], d: &Vector3<f64>) -> Feature {
    let heights: Vec<f64> = points.iter().map(|p| p.coords.dot(d)).collect();
    let top = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let size = points
        .iter()
        .map(|p| (p - points[0]).amax())
        .fold(0.0, f64::max);
    let slack = size * (1.0 - FACE_COS * FACE_COS).sqrt();
    let near: Vec<Point3<f64>> = points
        .iter()
        .zip(&heights)
        .filter(|(_, &h)| top - h <= slack)
        .map(|(p, _)| *p)
        .collect();
    match near.len() {
        0 => Feature::Point(points[0]),
        1 => Feature::Point(near[0]),
        2 => Feature::Segment(near[0], near[1]),
        _ => ordered_polygon(near, d),
    }
}

/// The convex hull, in the plane across `d`, of points near one plane (gift wrapping on their
/// projections; few points). Collinear projections give a segment.
fn ordered_polygon(points: Vec<Point3<f64>>, d: &Vector3<f64>) -> Feature {
    let (u, v) = plane_basis(d);
    let q: Vec<[f64; 2]> = points
        .iter()
        .map(|p| [p.coords.dot(&u), p.coords.dot(&v)])
        .collect();
    let start = (0..q.len())
        .min_by(|&i, &j| {
            q[i].partial_cmp(&q[j])
                .unwrap_or(core::cmp::Ordering::Equal)
        })
        .unwrap_or(0);
    let mut hull = vec![start];
    let mut current = start;
    loop {
        let mut next = (current + 1) % q.len();
        for k in 0..q.len() {
            let c = cross2(&q[current], &q[next], &q[k]);
            let farther = c == 0.0 && dist2(&q[current], &q[k]) > dist2(&q[current], &q[next]);
            if c < 0.0 || farther {
                next = k;
            }
        }
        if next == start || hull.len() > q.len() {
            break;
        }
        hull.push(next);
        current = next;
    }
    match hull.len() {
        1 => Feature::Point(points[hull[0]]),
        2 => Feature::Segment(points[hull[0]], points[hull[1]]),
        _ => Feature::Polygon(hull.into_iter().map(|i| points[i]).collect()),
    }
}

fn cross2(o: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

fn dist2(a: &[f64; 2], b: &[f64; 2]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
}

/// An orthonormal pair spanning the plane across the unit vector `n`, the same for the same
/// `n` (deterministic).
pub(super) fn plane_basis(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let helper = if n.x.abs() <= n.y.abs() && n.x.abs() <= n.z.abs() {
        Vector3::x()
    } else if n.y.abs() <= n.z.abs() {
        Vector3::y()
    } else {
        Vector3::z()
    };
    let u = n.cross(&helper).normalize();
    (u, n.cross(&u))
}

/// The rim of the disc of centre `c`, radius `r`, across the unit axis `w`.
fn rim(c: &Point3<f64>, r: f64, w: &Vector3<f64>) -> Feature {
    let (u, v) = plane_basis(w);
    Feature::Polygon(
        (0..RIM_POINTS)
            .map(|k| {
                let t = core::f64::consts::TAU * k as f64 / RIM_POINTS as f64;
                c + (u * t.cos() + v * t.sin()) * r
            })
            .collect(),
    )
}

/// The part of `d` across the unit axis `w`, unit; `None` when `d` is along the axis.
fn across(d: &Vector3<f64>, w: &Vector3<f64>) -> Option<Vector3<f64>> {
    let p = d - w * d.dot(w);
    let n = p.norm();
    (n > 0.0).then(|| p / n)
}

/// A cylinder of axis `ab` and radius `r`.
fn cylinder(a: &Point3<f64>, b: &Point3<f64>, r: f64, d: &Vector3<f64>) -> Feature {
    let w = (b - a).normalize();
    let along = w.dot(d);
    let cap = if along >= 0.0 { b } else { a };
    if along.abs() >= FACE_COS {
        return rim(cap, r, &w);
    }
    let side = across(d, &w).unwrap_or_else(|| plane_basis(&w).0) * r;
    if along.abs() <= EDGE_SIN {
        Feature::Segment(a + side, b + side)
    } else {
        Feature::Point(cap + side)
    }
}

/// A cone of apex `p`, base centre `c` and base radius `r`.
fn cone(p: &Point3<f64>, c: &Point3<f64>, r: f64, d: &Vector3<f64>) -> Feature {
    let w = (c - p).normalize();
    if w.dot(d) >= FACE_COS {
        return rim(c, r, &w);
    }
    let side = across(d, &w).unwrap_or_else(|| plane_basis(&w).0);
    let rim_point = c + side * r;
    let generator = rim_point - p;
    if (generator.dot(d) / generator.norm()).abs() <= EDGE_SIN {
        Feature::Segment(*p, rim_point)
    } else if generator.dot(d) > 0.0 {
        Feature::Point(rim_point)
    } else {
        Feature::Point(*p)
    }
}
