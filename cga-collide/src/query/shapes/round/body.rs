//! The filter's view of a shape: its defining points scaled by one power of two (exactly, or
//! the filter declines), with three things the filter needs of it: an `f64` support point of
//! the shape shrunk by a distance (for the search), interval bounds on its support function
//! (for separation proofs) and an interval test that a box lies inside it (for common-point
//! proofs).

use nalgebra::Point3;

use super::interval::{cross_norm2, dot3, lift, norm2, sub3, Iv, IvP3};
use crate::shape::Shape;

/// A point or vector in `f64`.
pub(super) type P3 = [f64; 3];

/// A convex shape in scaled coordinates.
pub(in crate::query::shapes) enum Body {
    /// The convex hull of points: `f64` values for the search, interval boxes holding the
    /// exact points (a cuboid's corners are sums) for the proofs.
    Points(Vec<P3>, Vec<IvP3>),
    Ball(P3, f64),
    Capsule(P3, P3, f64),
    /// Axis end points and radius.
    Cylinder(P3, P3, f64),
    /// Apex, base centre, base radius.
    Cone(P3, P3, f64),
}

#[inline]
pub(super) fn dot(a: &P3, b: &P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub(super) fn sub(a: &P3, b: &P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
fn axpy(a: f64, x: &P3, y: &P3) -> P3 {
    [a * x[0] + y[0], a * x[1] + y[1], a * x[2] + y[2]]
}

/// The largest absolute value among a shape's numbers (`None` for a half-space, which the
/// filter treats on its own).
pub(super) fn magnitude(s: &Shape) -> f64 {
    let pts = |ps: &[&Point3<f64>]| {
        ps.iter()
            .flat_map(|p| p.iter())
            .fold(0.0f64, |m, x| m.max(x.abs()))
    };
    match s {
        Shape::Ball(b) => pts(&[b.centre()]).max(b.radius()),
        Shape::Capsule(c) => pts(&[c.a(), c.b()]).max(c.radius()),
        Shape::Cylinder(c) => pts(&[c.a(), c.b()]).max(c.radius()),
        Shape::Cone(c) => pts(&[c.apex(), c.base()]).max(c.radius()),
        Shape::Segment(g) => pts(&[g.a(), g.b()]),
        Shape::Triangle(t) => pts(&t.vertices().iter().collect::<Vec<_>>()),
        Shape::ConvexHull(h) => pts(&h.extreme_points().iter().collect::<Vec<_>>()),
        Shape::Cuboid(c) => {
            let axes = c.half_axes();
            pts(&[c.centre()]).max(
                axes.iter()
                    .flat_map(|h| h.iter())
                    .fold(0.0f64, |m, x| m.max(x.abs())),
            )
        }
        Shape::HalfSpace(h) => pts(&[h.point()]),
    }
}

/// `x · scale` when that is exact (a power-of-two `scale`, no underflow).
#[inline]
pub(super) fn scaled(x: f64, scale: f64) -> Option<f64> {
    let y = x * scale;
    (y / scale == x && (y == 0.0 || y.abs() >= f64::MIN_POSITIVE) && y.is_finite()).then_some(y)
}

pub(super) fn scaled_point(p: &Point3<f64>, scale: f64) -> Option<P3> {
    Some([
        scaled(p.x, scale)?,
        scaled(p.y, scale)?,
        scaled(p.z, scale)?,
    ])
}

fn exact_points(ps: &[Point3<f64>], scale: f64) -> Option<Body> {
    let approx = ps
        .iter()
        .map(|p| scaled_point(p, scale))
        .collect::<Option<Vec<_>>>()?;
    let boxes = approx.iter().map(lift).collect();
    Some(Body::Points(approx, boxes))
}

fn cuboid_corners(c: &crate::shape::Cuboid, scale: f64) -> Option<Body> {
    let centre = lift(&scaled_point(c.centre(), scale)?);
    let mut axes = [[Iv::point(0.0); 3]; 3];
    for (axis, h) in axes.iter_mut().zip(c.half_axes()) {
        *axis = lift(&scaled_point(&Point3::from(*h), scale)?);
    }
    let mut boxes = Vec::with_capacity(8);
    for signs in 0..8u8 {
        let mut p = centre;
        for (k, axis) in axes.iter().enumerate() {
            let term = if signs & (1 << k) != 0 {
                axis.map(Iv::neg)
            } else {
                *axis
            };
            p = [p[0].add(term[0]), p[1].add(term[1]), p[2].add(term[2])];
        }
        boxes.push(p);
    }
    let approx = boxes
        .iter()
        .map(|b: &IvP3| b.map(|x| 0.5 * x.lo + 0.5 * x.hi))
        .collect();
    Some(Body::Points(approx, boxes))
}

impl Body {
    /// The body of a bounded shape scaled by `scale`; `None` for a half-space, a degenerate
    /// cylinder or cone (zero radius or axis) and inexact scaling.
    pub(super) fn new(s: &Shape, scale: f64) -> Option<Body> {
        let r = |x: f64| scaled(x, scale);
        let p = |q: &Point3<f64>| scaled_point(q, scale);
        let body = match s {
            Shape::Ball(b) => Body::Ball(p(b.centre())?, r(b.radius())?),
            Shape::Capsule(c) => Body::Capsule(p(c.a())?, p(c.b())?, r(c.radius())?),
            Shape::Cylinder(c) => Body::Cylinder(p(c.a())?, p(c.b())?, r(c.radius())?),
            Shape::Cone(c) => Body::Cone(p(c.apex())?, p(c.base())?, r(c.radius())?),
            Shape::Segment(g) => exact_points(&[*g.a(), *g.b()], scale)?,
            Shape::Triangle(t) => exact_points(t.vertices(), scale)?,
            Shape::ConvexHull(h) => exact_points(h.extreme_points(), scale)?,
            Shape::Cuboid(c) => cuboid_corners(c, scale)?,
            Shape::HalfSpace(_) => return None,
        };
        match &body {
            Body::Cylinder(a, b, radius) | Body::Cone(a, b, radius) if a == b || *radius <= 0.0 => {
                None
            }
            Body::Points(v, _) if v.is_empty() => None,
            _ => Some(body),
        }
    }

    /// How far the body can be shrunk and stay a body of its kind (`0` for points).
    pub(super) fn max_shrink(&self) -> f64 {
        match self {
            Body::Points(..) => 0.0,
            Body::Ball(_, r) | Body::Capsule(_, _, r) => *r,
            Body::Cylinder(a, b, r) => r.min(0.5 * dot(&sub(b, a), &sub(b, a)).sqrt()),
            Body::Cone(apex, base, r) => {
                let h = dot(&sub(base, apex), &sub(base, apex)).sqrt();
                h * r / (r + (h * h + r * r).sqrt())
            }
        }
    }

    /// A support point of the body shrunk by `s` (every point at depth `≥ s`, in exact
    /// arithmetic) in direction `d`, in plain `f64`: a guide for the search, never a proof.
    /// Returns the point and, for points bodies, its index.
    pub(super) fn support(&self, d: &P3, s: f64) -> (P3, usize) {
        match self {
            Body::Points(v, _) => {
                let mut best = (0, f64::NEG_INFINITY);
                for (i, p) in v.iter().enumerate() {
                    let h = dot(p, d);
                    if h > best.1 {
                        best = (i, h);
                    }
                }
                (v[best.0], best.0)
            }
            Body::Ball(c, r) => (grow(c, d, r - s), 0),
            Body::Capsule(a, b, r) => (grow(farther(a, b, d), d, r - s), 0),
            Body::Cylinder(a, b, r) => {
                let (unit, _) = unit_axis(a, b);
                let a2 = axpy(s, &unit, a);
                let b2 = axpy(-s, &unit, b);
                (rim(farther(&a2, &b2, d), &unit, d, r - s), 0)
            }
            Body::Cone(apex, base, r) => {
                let (unit, h) = unit_axis(apex, base);
                let slant = (h * h + r * r).sqrt();
                let h2 = (h - s - s * slant / r).max(0.0);
                let apex2 = axpy(s * slant / r, &unit, apex);
                let base2 = axpy(-s, &unit, base);
                let rim_point = rim(&base2, &unit, d, r * h2 / h);
                if dot(&apex2, d) >= dot(&rim_point, d) {
                    (apex2, 0)
                } else {
                    (rim_point, 0)
                }
            }
        }
    }

    /// Bounds on `max over the body of d·x` (the exact body, not shrunk).
    pub(in crate::query::shapes) fn support_value(&self, d: &P3) -> Iv {
        let di = lift(d);
        match self {
            Body::Points(_, boxes) => boxes
                .iter()
                .map(|b| dot3(&di, b))
                .reduce(Iv::max)
                .unwrap_or(Iv::point(f64::INFINITY)),
            Body::Ball(c, r) => dot3(&di, &lift(c)).add(Iv::point(*r).mul(norm2(&di).sqrt())),
            Body::Capsule(a, b, r) => dot3(&di, &lift(a))
                .max(dot3(&di, &lift(b)))
                .add(Iv::point(*r).mul(norm2(&di).sqrt())),
            Body::Cylinder(a, b, r) => {
                let (a, b) = (lift(a), lift(b));
                let radial = disc_reach(&di, &sub3(&b, &a), *r);
                dot3(&di, &a).max(dot3(&di, &b)).add(radial)
            }
            Body::Cone(apex, base, r) => {
                let (apex, base) = (lift(apex), lift(base));
                let radial = disc_reach(&di, &sub3(&base, &apex), *r);
                dot3(&di, &apex).max(dot3(&di, &base).add(radial))
            }
        }
    }

    /// Whether every point of the box is certainly in the body (`false` when unproved;
    /// always `false` for points bodies, whose common points the filter builds instead).
    pub(super) fn holds(&self, x: &IvP3) -> bool {
        match self {
            Body::Points(..) => false,
            Body::Ball(c, r) => norm2(&sub3(x, &lift(c))).hi <= Iv::point(*r).sqr().lo,
            Body::Capsule(a, b, r) => {
                let (a, b, r2) = (lift(a), lift(b), Iv::point(*r).sqr());
                norm2(&sub3(x, &a)).hi <= r2.lo
                    || norm2(&sub3(x, &b)).hi <= r2.lo
                    || in_slab_within(x, &a, &b, r2)
            }
            Body::Cylinder(a, b, r) => {
                let (a, b) = (lift(a), lift(b));
                in_slab_within(x, &a, &b, Iv::point(*r).sqr())
            }
            Body::Cone(apex, base, r) => {
                let (apex, base) = (lift(apex), lift(base));
                let u = sub3(&base, &apex);
                let uu = norm2(&u);
                let rel = sub3(x, &apex);
                let t = dot3(&rel, &u);
                // Radial distance `|rel × u| / |u|` at most `r·t / |u|²·|u|`, squared.
                t.lo >= 0.0
                    && t.hi <= uu.lo
                    && cross_norm2(&rel, &u).mul(uu).hi <= Iv::point(*r).sqr().mul(t.sqr()).lo
            }
        }
    }
}

/// `0 ≤ (x − a)·u ≤ u·u` and `|(x − a) × u|² ≤ r²·u·u` for `u = b − a`: the box is in the
/// cylinder of radius `r` on `ab`.
fn in_slab_within(x: &IvP3, a: &IvP3, b: &IvP3, r2: Iv) -> bool {
    let u = sub3(b, a);
    let uu = norm2(&u);
    let rel = sub3(x, a);
    let t = dot3(&rel, &u);
    t.lo >= 0.0 && t.hi <= uu.lo && cross_norm2(&rel, &u).hi <= r2.mul(uu).lo
}

/// `r·|d × u| / |u|`: how far a disc of radius `r` perpendicular to `u` reaches along `d`.
fn disc_reach(d: &IvP3, u: &IvP3, r: f64) -> Iv {
    Iv::point(r).mul(cross_norm2(d, u).div_positive(norm2(u)).sqrt())
}

fn farther<'a>(a: &'a P3, b: &'a P3, d: &P3) -> &'a P3 {
    if dot(a, d) >= dot(b, d) {
        a
    } else {
        b
    }
}

/// `c + r·d/|d|`.
fn grow(c: &P3, d: &P3, r: f64) -> P3 {
    let n = dot(d, d).sqrt();
    if n > 0.0 && n.is_finite() {
        axpy(r / n, d, c)
    } else {
        *c
    }
}

/// The unit axis from `a` to `b` and the length.
fn unit_axis(a: &P3, b: &P3) -> (P3, f64) {
    let u = sub(b, a);
    let h = dot(&u, &u).sqrt();
    (u.map(|x| x / h), h)
}

/// The point of the disc centred at `c`, perpendicular to `unit`, of radius `r`, farthest
/// along `d`.
fn rim(c: &P3, unit: &P3, d: &P3, r: f64) -> P3 {
    let w = axpy(-dot(d, unit), unit, d);
    grow(c, &w, r)
}
