//! Exact pair tests for every pair with a cylinder or a cone.
//!
//! Every query first tries the closed forms of the ball, segment, capsule and half-space pairs
//! ([`closed`], the distance in the solid's meridian half-plane bounded in interval
//! arithmetic), then the certified floating-point filter ([`filter`]): a separating
//! direction or a common point proposed by an `f64` search and proved in interval arithmetic.
//! Only the pairs it cannot prove (touching, a few ulps apart, degenerate) reach the exact
//! methods of the table, so the answers are theirs.
//!
//! | pair | `intersects` | `within_distance(c)` | method |
//! |---|---|---|---|
//! | round – half-space | exact | exact | lowest cap disc or apex along the normal; `a + b√c` signs ([`half_space`]) |
//! | round – ball (and any point-like shape) | exact | exact | meridian half-plane, signs in `Q(√x, √y)` ([`meridian`]) |
//! | round – segment, triangle, cuboid, hull | exact | exact for `c = 0` | cylinder: cap disc against the polytope swept by the axis; cone: central projection from the apex ([`section`]) |
//! | round – segment, capsule | exact | exact | the segment's parameter against the pieces of the solid grown by `c` (and the radius), each a polynomial condition decided with Sturm sequences ([`segment`], [`univariate`]) |
//! | round – triangle, cuboid, hull | (above) | `UnsupportedPair` for `c > 0` | not done |
//! | cylinder – cylinder, parallel axes | exact | exact | interval × disc in a frame along the axis ([`curved`]) |
//! | cylinder/cone – cylinder/cone, otherwise | where an exact certificate applies, else `UnsupportedPair` | same | axis lines apart, slabs missed, closest axis points within the local radii, end points inside, then a separating plane or a common point suggested in `f64` and proved exactly ([`curved`]) |
//!
//! `distance` is certified for the half-space, ball, segment and capsule pairs (an `f64`
//! estimate, its bound proved by the exact `within_distance`, [`distance`]); for the others
//! (a triangle, cuboid, hull, cylinder or cone) by bounds proved in interval arithmetic
//! around the filter's search ([`bounded_distance`]): a separating direction bounds the
//! distance below, two witness points proved inside the bodies bound it above, and a proved
//! common point makes it exactly `0`. Those bounds are as tight as the search converges
//! (from `1e-12` to `1e-4` of the sizes involved on the tests' pairs: a search between two
//! curved bodies, or along a flush face, converges slowly); touching pairs get an interval
//! from `0`.
//!
//! Shapes that collapse (a zero radius, a capsule with equal ends, a polytope of one point) are
//! replaced by the segment or point they are, so more pairs answer exactly.

use ga_core::scalar::Rational;
use nalgebra::Point3;
use num_traits::Zero;

use crate::error::Error;
use crate::query::CertifiedDistance;
use crate::shape::Shape;

mod body;
mod bounded_distance;
#[cfg(test)]
mod bounded_distance_tests;
mod closed;
#[cfg(test)]
mod closed_tests;
mod curved;
mod distance;
mod exact3;
mod filter;
#[cfg(test)]
mod filter_tests;
mod half_space;
pub(super) mod interval;
mod meridian;
mod meridian_signs;
#[cfg(test)]
mod meridian_signs_tests;
mod planar;
mod section;
mod segment;
mod surd;
mod univariate;

/// The filter's support functions of cylinders and cones, which the depth search also bounds.
pub(super) use body::Body;
use exact3::{add, point, q, sub, Round, V3};

fn unsupported(query: &'static str, a: &Shape, b: &Shape) -> Error {
    Error::UnsupportedPair {
        query,
        a: a.kind(),
        b: b.kind(),
    }
}

/// The other shape of a pair, in the form the round tests take.
enum Other {
    /// The convex hull of exact points (not empty).
    Polytope(Vec<V3>),
    /// A ball (radius `0`: a point).
    Ball(Box<V3>, Rational),
    HalfSpace(crate::shape::HalfSpace),
    /// A capsule: the segment between the two points grown by the radius.
    Capsule(Box<[V3; 2]>, Rational),
    /// Another curved shape: a cylinder or cone with a positive radius, or a capsule.
    Curved,
}

fn segment_of(a: &Point3<f64>, b: &Point3<f64>) -> Other {
    Other::Polytope(vec![point(a), point(b)])
}

fn other(s: &Shape) -> Other {
    match s {
        Shape::Ball(b) => Other::Ball(Box::new(point(b.centre())), q(b.radius())),
        Shape::HalfSpace(h) => Other::HalfSpace(*h),
        Shape::Segment(s) => segment_of(s.a(), s.b()),
        Shape::Triangle(t) => Other::Polytope(t.vertices().iter().map(point).collect()),
        Shape::ConvexHull(h) => Other::Polytope(h.points().iter().map(point).collect()),
        Shape::Cuboid(c) => {
            let centre = point(c.centre());
            let [u, v, w] = c.half_axes().map(|h| point(&Point3::from(h)));
            let mut corners = Vec::with_capacity(8);
            for su in [false, true] {
                for sv in [false, true] {
                    for sw in [false, true] {
                        let mut p = centre.clone();
                        for (axis, negative) in [(&u, su), (&v, sv), (&w, sw)] {
                            p = if negative {
                                sub(&p, axis)
                            } else {
                                add(&p, axis)
                            };
                        }
                        corners.push(p);
                    }
                }
            }
            Other::Polytope(corners)
        }
        Shape::Capsule(c) if c.radius() == 0.0 => segment_of(c.a(), c.b()),
        Shape::Capsule(c) if c.a() == c.b() => Other::Ball(Box::new(point(c.a())), q(c.radius())),
        Shape::Cylinder(c) if c.radius() == 0.0 => segment_of(c.a(), c.b()),
        Shape::Cone(c) if c.radius() == 0.0 => segment_of(c.apex(), c.base()),
        Shape::Capsule(c) => Other::Capsule(Box::new([point(c.a()), point(c.b())]), q(c.radius())),
        Shape::Cylinder(_) | Shape::Cone(_) => Other::Curved,
    }
}

/// A polytope of one point is that point.
fn collapse(o: Other) -> Other {
    match o {
        Other::Polytope(p) if p.iter().all(|v| *v == p[0]) => {
            Other::Ball(Box::new(p[0].clone()), Rational::zero())
        }
        o => o,
    }
}

fn round(s: &Shape) -> Option<Round> {
    match s {
        Shape::Cylinder(c) => Some(Round::cylinder(c)),
        Shape::Cone(c) => Some(Round::cone(c)),
        _ => None,
    }
}

/// The exact answer of `within_distance(r, o, e)`, or `None` where it is not available.
fn decide(r: &Round, o: Other, e: &Rational) -> Option<bool> {
    match collapse(o) {
        Other::Ball(centre, radius) => Some(meridian::point_within(r, &centre, &(radius + e))),
        Other::HalfSpace(h) => Some(half_space::within(r, &h, e)),
        Other::Polytope(vertices) if e.is_zero() => Some(section::meets_polytope(r, &vertices)),
        Other::Polytope(v) if v.len() == 2 => Some(segment::within(r, &v[0], &v[1], e)),
        Other::Capsule(ends, radius) => Some(segment::within(r, &ends[0], &ends[1], &(radius + e))),
        Other::Polytope(_) | Other::Curved => None,
    }
}

/// The answer of `within_distance(a, b, c)` where the closed forms, the filter or the
/// integer-sign stage prove it (microseconds); `None` leaves it to the exact methods, which
/// can take milliseconds between two curved bodies.
pub(crate) fn within_distance_filtered(a: &Shape, b: &Shape, c: f64) -> Option<bool> {
    closed::within(a, b, c)
        .or_else(|| filter::within(a, b, c))
        .or_else(|| meridian_signs::within(a, b, c))
}

fn answer(query: &'static str, a: &Shape, b: &Shape, c: f64) -> Result<bool, Error> {
    match within_distance_filtered(a, b, c) {
        Some(proved) => Ok(proved),
        None => exact_answer(query, a, b, c),
    }
}

/// The exact methods alone (what the filter's proofs must agree with).
fn exact_answer(query: &'static str, a: &Shape, b: &Shape, c: f64) -> Result<bool, Error> {
    let e = &q(c);
    let found = match (round(a), round(b)) {
        (Some(ra), _) => decide(&ra, other(b), e).or_else(|| {
            // The first one may be the simpler side (a zero radius).
            round(b).and_then(|rb| decide(&rb, other(a), e))
        }),
        (None, Some(rb)) => decide(&rb, other(a), e),
        (None, None) => None,
    }
    .or_else(|| curved::within(a, b, e));
    found.ok_or_else(|| unsupported(query, a, b))
}

pub(crate) fn intersects(a: &Shape, b: &Shape) -> Result<bool, Error> {
    answer("intersects", a, b, 0.0)
}

pub(crate) fn within_distance(a: &Shape, b: &Shape, c: f64) -> Result<bool, Error> {
    answer("within_distance", a, b, c)
}

fn solid(s: &Shape) -> Option<distance::Solid> {
    match s {
        Shape::Cylinder(c) => Some(distance::Solid::cylinder(c)),
        Shape::Cone(c) => Some(distance::Solid::cone(c)),
        _ => None,
    }
}

/// The certified distance with the round shape first, where it is available.
fn distance_round_first(
    round: &Shape,
    other: &Shape,
    within: impl Fn(f64) -> bool,
) -> Option<CertifiedDistance> {
    let s = solid(round)?;
    match other {
        Shape::Ball(b) => Some(distance::to_ball(&s, b, within)),
        Shape::HalfSpace(h) => Some(distance::to_half_space(&s, h, within)),
        Shape::Capsule(c) => Some(distance::to_segment(&s, c.a(), c.b(), c.radius(), within)),
        Shape::Segment(g) => Some(distance::to_segment(&s, g.a(), g.b(), 0.0, within)),
        _ => None,
    }
}

/// Whether the distance of `round` (a cylinder or cone) and `other` has a closed form here.
fn closed_distance(round: &Shape, other: &Shape) -> bool {
    solid(round).is_some()
        && matches!(
            other,
            Shape::Ball(_) | Shape::HalfSpace(_) | Shape::Capsule(_) | Shape::Segment(_)
        )
}

/// A proved lower bound on the distance of a pair whose [`distance`] is the interval search
/// (tens of microseconds), from a short search (a few); `None` for the pairs with a closed
/// form (already quick) and where nothing is proved. For callers that can often set a pair
/// aside on a bound without its distance.
pub(crate) fn distance_lower_bound(a: &Shape, b: &Shape) -> Option<f64> {
    let searched = !(closed_distance(a, b)
        || closed_distance(b, a)
        || matches!(a, Shape::HalfSpace(_))
        || matches!(b, Shape::HalfSpace(_)));
    if searched {
        bounded_distance::lower(a, b)
    } else {
        None
    }
}

pub(crate) fn distance(a: &Shape, b: &Shape) -> Result<CertifiedDistance, Error> {
    // `within_distance` always decides these pairs; `false` is never reached.
    let within = |c: f64| answer("within_distance", a, b, c).unwrap_or(false);
    if let Some(d) = distance_round_first(a, b, within) {
        return Ok(d);
    }
    if let Some(d) = distance_round_first(b, a, within) {
        return Ok(CertifiedDistance {
            witness_a: d.witness_b,
            witness_b: d.witness_a,
            ..d
        });
    }
    let bounded = match (a, b) {
        (Shape::HalfSpace(_), _) | (_, Shape::HalfSpace(_)) => None,
        _ => bounded_distance::distance(a, b),
    };
    bounded.ok_or_else(|| unsupported("distance", a, b))
}
