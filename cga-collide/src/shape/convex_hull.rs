//! The convex hull of a set of points.

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::shape::exact_hull::{exact_hull, ExactHull};
use crate::shape::limits::check_point;

/// The closed convex hull of finitely many points, exactly: the set of all convex combinations
/// of the given `f64` points. Points inside the hull are allowed (they change nothing); one
/// point, collinear points and coplanar points give the point, segment or flat polygon they
/// span, which are valid shapes. An empty set is refused.
///
/// [`new`](Self::new) computes the hull exactly, with exact orientation signs and no
/// tolerance: its [`corners`](Self::corners) (the points no other points' hull contains: a
/// point one ulp outside a face is a corner, one ulp inside is not), its
/// [`dimension`](Self::dimension) and, for a solid hull, a triangulation of its boundary
/// ([`triangles`](Self::triangles)). Time `O(n·h)` for `n` points and `h` boundary triangles.
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::ConvexHull};
/// let tetra = ConvexHull::new(vec![
///     Point3::origin(), Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, 1.0),
/// ])?;
/// assert_eq!(tetra.points().len(), 4);
/// assert_eq!((tetra.corners().len(), tetra.triangles().len(), tetra.dimension()), (4, 4, 3));
/// // A point inside changes nothing; one ulp outside a face it is a corner.
/// let inside = ConvexHull::new(vec![
///     Point3::origin(), Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, 1.0), Point3::new(0.1, 0.1, 0.1),
/// ])?;
/// assert_eq!(inside.corners().len(), 4);
/// assert!(ConvexHull::new(vec![]).is_err());
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexHull {
    points: Vec<Point3<f64>>,
    /// The exact hull (computed once by `new`).
    hull: ExactHull,
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
        let hull = exact_hull(&points);
        Ok(ConvexHull { points, hull })
    }

    /// The points, as given.
    pub fn points(&self) -> &[Point3<f64>] {
        &self.points
    }

    /// The hull's corners, exactly (a subset of [`points`](Self::points), computed once when
    /// the hull is built): one point, the two ends of a segment, a flat polygon's corners in
    /// boundary order, or a solid's vertices. The queries search these.
    pub fn corners(&self) -> &[Point3<f64>] {
        &self.hull.corners
    }

    /// The same as [`corners`](Self::corners) (the name the queries used first).
    pub fn extreme_points(&self) -> &[Point3<f64>] {
        &self.hull.corners
    }

    /// For a solid hull (dimension 3), its boundary as triangles of indices into
    /// [`corners`](Self::corners), counter-clockwise seen from outside; a facet with more than
    /// three corners is split into triangles. Empty for a point, segment or flat polygon.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.hull.triangles
    }

    /// 0 for a point, 1 for a segment, 2 for a flat polygon, 3 for a solid.
    pub fn dimension(&self) -> u8 {
        self.hull.dimension
    }

    /// This hull moved by `pose`: every point mapped in `f64` and rounded once, then the hull
    /// of the rounded points.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Self, Error> {
        ConvexHull::new(self.points.iter().map(|p| pose * p).collect())
    }
}
