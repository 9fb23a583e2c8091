//! Exact pair tests for every pair with a cylinder or a cone.

use crate::error::Error;
use crate::query::CertifiedDistance;
use crate::shape::Shape;

fn unsupported(query: &'static str, a: &Shape, b: &Shape) -> Error {
    Error::UnsupportedPair {
        query,
        a: a.kind(),
        b: b.kind(),
    }
}

pub(crate) fn intersects(a: &Shape, b: &Shape) -> Result<bool, Error> {
    Err(unsupported("intersects", a, b))
}

pub(crate) fn within_distance(a: &Shape, b: &Shape, c: f64) -> Result<bool, Error> {
    let _ = c;
    Err(unsupported("within_distance", a, b))
}

pub(crate) fn distance(a: &Shape, b: &Shape) -> Result<CertifiedDistance, Error> {
    Err(unsupported("distance", a, b))
}
