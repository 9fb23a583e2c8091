//! Exact pair tests for shapes that are a convex polytope grown by a ball, and half-spaces.
//!
//! Every kind but the half-space is a *core* (the convex hull of finitely many exact points)
//! grown by a ball of radius `r` ([`cores`]): a ball is its centre grown, a capsule its axis
//! grown, a cuboid (its eight exact corners), a hull, a triangle and a segment are their own
//! cores. So two shapes are within `c` exactly when their cores are within
//! `S = r_A + r_B + c`.
//!
//! That is decided in two stages. A floating-point GJK search ([`gjk::search`]) proposes a
//! separating direction, a pair of near points or a tetrahedron around the origin, and each
//! proposal is checked with rigorous error bounds ([`certificate`]); a proposal that checks
//! proves the answer. When none checks (touching, a few ulps apart, degenerate input), the
//! last simplex is tested exactly as the nearest feature pair ([`feature`]: a few polynomial
//! signs on `f64` expansions). Only when that proves neither answer does the
//! same search run in exact rationals ([`gjk::exact_distance2`]), warm-started from the
//! floating-point simplex, and gives the exact squared distance of the cores, compared with
//! `S²` exactly. Half-spaces are decided by their support functions ([`half_space`]). The
//! pairs of balls, triangles and segments keep the crate's exact tests.

mod certificate;
mod cores;
mod feature;
pub(in crate::query::shapes) mod float_simplex;
mod gjk;
mod half_space;
mod simplex;
mod staged;
#[cfg(test)]
mod tests;

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::Point3;

use self::cores::{Core, P3};
use crate::query::distance::certify;
use crate::query::{self, CertifiedDistance, Intersects, WithinDistance};
use crate::shape::Shape;

pub(crate) fn intersects(a: &Shape, b: &Shape) -> bool {
    match (a, b) {
        (Shape::Ball(a), Shape::Ball(b)) => a.intersects(b),
        (Shape::Ball(a), Shape::Segment(b)) => a.intersects(b),
        (Shape::Ball(a), Shape::Triangle(b)) => a.intersects(b),
        (Shape::Segment(a), Shape::Ball(b)) => a.intersects(b),
        (Shape::Segment(a), Shape::Segment(b)) => a.intersects(b),
        (Shape::Segment(a), Shape::Triangle(b)) => a.intersects(b),
        (Shape::Triangle(a), Shape::Ball(b)) => a.intersects(b),
        (Shape::Triangle(a), Shape::Segment(b)) => a.intersects(b),
        (Shape::Triangle(a), Shape::Triangle(b)) => a.intersects(b),
        _ => generic_within(a, b, 0.0),
    }
}

pub(crate) fn within_distance(a: &Shape, b: &Shape, c: f64) -> bool {
    match (a, b) {
        (Shape::Ball(a), Shape::Ball(b)) => a.within_distance(b, c),
        (Shape::Ball(a), Shape::Segment(b)) => b.within_distance(a, c),
        (Shape::Ball(a), Shape::Triangle(b)) => b.within_distance(a, c),
        (Shape::Segment(a), Shape::Ball(b)) => a.within_distance(b, c),
        (Shape::Segment(a), Shape::Segment(b)) => a.within_distance(b, c),
        (Shape::Segment(a), Shape::Triangle(b)) => a.within_distance(b, c),
        (Shape::Triangle(a), Shape::Ball(b)) => a.within_distance(b, c),
        (Shape::Triangle(a), Shape::Segment(b)) => b.within_distance(a, c),
        (Shape::Triangle(a), Shape::Triangle(b)) => a.within_distance(b, c),
        _ => generic_within(a, b, c),
    }
}

fn swap(d: CertifiedDistance) -> CertifiedDistance {
    CertifiedDistance {
        witness_a: d.witness_b,
        witness_b: d.witness_a,
        ..d
    }
}

pub(crate) fn distance(a: &Shape, b: &Shape) -> CertifiedDistance {
    match (a, b) {
        (Shape::Ball(a), Shape::Ball(b)) => query::distance_ball_ball(a, b),
        (Shape::Ball(a), Shape::Segment(b)) => swap(query::distance_segment_ball(b, a)),
        (Shape::Ball(a), Shape::Triangle(b)) => swap(query::distance_triangle_ball(b, a)),
        (Shape::Segment(a), Shape::Ball(b)) => query::distance_segment_ball(a, b),
        (Shape::Segment(a), Shape::Segment(b)) => query::distance_segment_segment(a, b),
        (Shape::Segment(a), Shape::Triangle(b)) => query::distance_segment_triangle(a, b),
        (Shape::Triangle(a), Shape::Ball(b)) => query::distance_triangle_ball(a, b),
        (Shape::Triangle(a), Shape::Segment(b)) => swap(query::distance_segment_triangle(b, a)),
        (Shape::Triangle(a), Shape::Triangle(b)) => query::distance_triangle_triangle(a, b),
        (Shape::HalfSpace(a), Shape::HalfSpace(b)) => half_space::distance_half_spaces(a, b),
        (Shape::HalfSpace(h), other) => match Core::of(other) {
            Some(core) => swap(half_space::distance_core(h, &core)),
            None => unsupported(),
        },
        (other, Shape::HalfSpace(h)) => match Core::of(other) {
            Some(core) => half_space::distance_core(h, &core),
            None => unsupported(),
        },
        _ => match (Core::of(a), Core::of(b)) {
            (Some(a), Some(b)) => distance_cores(&a, &b),
            _ => unsupported(),
        },
    }
}

/// The answer for cylinders and cones, which the dispatch in [`super`] never sends here: no
/// claim at all (an unbounded error).
fn unsupported() -> CertifiedDistance {
    CertifiedDistance {
        distance: 0.0,
        error_bound: f64::INFINITY,
        witness_a: Point3::origin(),
        witness_b: Point3::origin(),
        triangles: None,
    }
}

/// Every pair but the ball/segment/triangle ones.
fn generic_within(a: &Shape, b: &Shape, c: f64) -> bool {
    match (a, b) {
        (Shape::HalfSpace(a), Shape::HalfSpace(b)) => half_space::within_half_spaces(a, b, c),
        (Shape::HalfSpace(h), other) | (other, Shape::HalfSpace(h)) => {
            Core::of(other).is_some_and(|core| half_space::within_core(h, &core, c))
        }
        _ => match (Core::of(a), Core::of(b)) {
            (Some(a), Some(b)) => cores_within(&a, &b, c),
            // Cylinders and cones are dispatched elsewhere ([`super`]).
            _ => false,
        },
    }
}

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

/// Exact: are the grown cores within `c`?
fn cores_within(a: &Core, b: &Core, c: f64) -> bool {
    let found = gjk::search(a, b);
    let s = [a.radius, b.radius, c];
    let reach = (s[0] + s[1] + s[2]) * found.scale;
    let v2: f64 = found.v.iter().map(|x| x * x).sum();
    let far = v2 > reach * reach;
    if far && certificate::apart(a, b, &found.v, &s) {
        return false;
    }
    if certificate::close(a, b, &found, &s) || certificate::inside(a, b, &found) {
        return true;
    }
    if !far && certificate::apart(a, b, &found.v, &s) {
        return false;
    }
    if let Some(answer) = feature::decide(a, b, found.pairs(), s) {
        return answer;
    }
    let d2 = gjk::exact_distance2(a, b, found.pairs());
    let reach = q(s[0]) + q(s[1]) + q(s[2]);
    d2 <= &reach * &reach
}

fn norm(v: &P3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The distance between two grown cores: the `f64` search's witnesses moved by the radii,
/// the bound proved by [`certify`] with exact clearance tests.
fn distance_cores(a: &Core, b: &Core) -> CertifiedDistance {
    let found = gjk::search(a, b);
    let (x, y) = found.witnesses(a, b);
    let gap: P3 = core::array::from_fn(|k| y[k] - x[k]);
    let between = norm(&gap);
    let radii = a.radius + b.radius;
    let at = |t: f64| Point3::new(x[0] + t * gap[0], x[1] + t * gap[1], x[2] + t * gap[2]);
    let meet = cores_within(a, b, 0.0);
    let (distance, wa, wb) = if !meet && between > radii && between.is_finite() {
        (
            between - radii,
            at(a.radius / between),
            at(1.0 - b.radius / between),
        )
    } else {
        let t = if radii > 0.0 { a.radius / radii } else { 0.0 };
        (0.0, at(t), at(t))
    };
    let scale = a.magnitude().max(b.magnitude());
    let within = |c: f64| !c.is_finite() || cores_within(a, b, c);
    CertifiedDistance {
        distance,
        error_bound: certify(distance, scale, || meet, within, within),
        witness_a: wa,
        witness_b: wb,
        triangles: None,
    }
}

/// For the signed distance ([`super::depth`]): the exact squared distance between the cores
/// of two polytopal shapes (radii left out) and the `f64` nearest points of the cores; `None`
/// for half-spaces, cylinders and cones.
pub(crate) fn exact_core_distance2(a: &Shape, b: &Shape) -> Option<(Rational, [f64; 3], [f64; 3])> {
    let (a, b) = (Core::of(a)?, Core::of(b)?);
    let found = gjk::search(&a, &b);
    let (x, y) = found.witnesses(&a, &b);
    Some((gjk::exact_distance2(&a, &b, found.pairs()), x, y))
}
