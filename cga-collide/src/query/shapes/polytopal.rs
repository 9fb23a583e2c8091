//! Exact pair tests for shapes that are a convex polytope grown by a ball, and half-spaces.
//!
//! Being written: the pairs of balls, triangles and segments answer through the crate's
//! existing exact tests; every other pair is still a placeholder.

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
        _ => unimplemented!("polytopal::intersects {} {}", a.kind(), b.kind()),
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
        _ => unimplemented!("polytopal::within_distance {} {}", a.kind(), b.kind()),
    }
}

pub(crate) fn distance(a: &Shape, b: &Shape) -> CertifiedDistance {
    let swap = |d: CertifiedDistance| CertifiedDistance {
        witness_a: d.witness_b,
        witness_b: d.witness_a,
        ..d
    };
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
        _ => unimplemented!("polytopal::distance {} {}", a.kind(), b.kind()),
    }
}
