//! Exact pair tests for shapes that are a convex polytope grown by a ball, and half-spaces.
//! (Being written: every pair currently answers through the placeholder below.)

use crate::query::CertifiedDistance;
use crate::shape::Shape;

pub(crate) fn intersects(a: &Shape, b: &Shape) -> bool {
    let _ = (a, b);
    unimplemented!("polytopal::intersects")
}

pub(crate) fn within_distance(a: &Shape, b: &Shape, c: f64) -> bool {
    let _ = (a, b, c);
    unimplemented!("polytopal::within_distance")
}

pub(crate) fn distance(a: &Shape, b: &Shape) -> CertifiedDistance {
    let _ = (a, b);
    unimplemented!("polytopal::distance")
}
