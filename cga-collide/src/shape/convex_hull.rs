//! The convex hull of a set of points.

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::shape::limits::check_point;

/// The closed convex hull of finitely many points, exactly: the set of all convex combinations
/// of the given `f64` points. Points inside the hull are allowed (they change nothing); one
/// point, collinear points and coplanar points give the point, segment or flat polygon they
/// span, which are valid shapes. An empty set is refused.
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::ConvexHull};
/// let tetra = ConvexHull::new(vec![
///     Point3::origin(), Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, 1.0),
/// ])?;
/// assert_eq!(tetra.points().len(), 4);
/// assert!(ConvexHull::new(vec![]).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexHull {
    points: Vec<Point3<f64>>,
    /// The points that span the hull (computed once by `new`).
    extreme: Vec<Point3<f64>>,
}

impl ConvexHull {
    /// The hull of `points`; fails on an empty set and on non-finite or out-of-range
    /// coordinates (the error names the point's index in `Error::InShapePoint`).
    pub fn new(points: Vec<Point3<f64>>) -> Result<Self, Error> {
        if points.is_empty() {
            return Err(Error::Degenerate {
                constructor: "ConvexHull::new",
                reason: "no points were given",
            });
        }
        for (index, p) in points.iter().enumerate() {
            check_point("ConvexHull", "points", p).map_err(|source| Error::InShapePoint {
                index,
                source: Box::new(source),
            })?;
        }
        let extreme = extreme_points(&points);
        Ok(ConvexHull { points, extreme })
    }

    /// The points, as given.
    pub fn points(&self) -> &[Point3<f64>] {
        &self.points
    }

    /// Points that span the same hull (a subset of [`points`](Self::points), computed once
    /// when the hull is built): the queries search these.
    pub fn extreme_points(&self) -> &[Point3<f64>] {
        &self.extreme
    }

    /// This hull moved by `pose`: every point mapped in `f64` and rounded once, then the hull
    /// of the rounded points.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        ConvexHull::new(self.points.iter().map(|p| pose * p).collect())
    }
}

/// The given points without exact repeats.
fn extreme_points(points: &[Point3<f64>]) -> Vec<Point3<f64>> {
    let mut out: Vec<Point3<f64>> = Vec::with_capacity(points.len());
    for p in points {
        if !out.contains(p) {
            out.push(*p);
        }
    }
    out
}
