//! The minimum distance between two meshes: in `f64` with a certified error bound
//! ([`CertifiedDistance`]), or exactly in rationals ([`ExactDistance`]); in one frame here, under
//! poses in `poses`. Coordinates too large for the squared distances to stay finite get
//! [`Error::OutOfRange`] rather than a number that cannot be certified.

use ga_core::scalar::{rational_from_f64, Rational, Ring};

use crate::collider::nearest::nearest_pair;
use crate::collider::Collider;
use crate::error::Error;
use crate::query::closest_points::{triangle_triangle, Near};
use crate::query::separation::{certified_mesh_distance, examine_pair};
use crate::query::{CertifiedDistance, ExactDistance};

/// The largest coordinate magnitude (`2^500`) a distance query certifies: beyond it the `f64`
/// squared distances of the search could overflow. Covers the crate's promise of coordinates
/// up to `1e150`.
pub(crate) const DISTANCE_RANGE: f64 = 3.273390607896142e150; // 2^500

/// Refuses meshes too large for a certified distance.
pub(crate) fn check_distance_range(magnitude: f64) -> Result<(), Error> {
    if magnitude <= DISTANCE_RANGE {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            magnitude,
            limit: DISTANCE_RANGE,
        })
    }
}

/// A certified distance, or the error saying why none could be certified: never a non-finite
/// number presented as certified.
pub(crate) fn finite(d: CertifiedDistance, magnitude: f64) -> Result<CertifiedDistance, Error> {
    if d.distance.is_finite() && d.error_bound.is_finite() {
        Ok(d)
    } else {
        Err(Error::OutOfRange {
            magnitude,
            limit: DISTANCE_RANGE,
        })
    }
}

/// The answer of a distance search given a cutoff (the best distance a caller already has):
/// the certified distance when the pair is nearer, or a proved lower bound when it is not.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Bounded {
    /// Nearer than the cutoff: the certified distance, as the search without a cutoff gives it.
    Below(CertifiedDistance),
    /// Not nearer than the cutoff: the true distance is at least this (at most the cutoff).
    AtLeast(f64),
}

fn rational(x: f64) -> Rational {
    // Meshes hold finite coordinates only.
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

impl Collider {
    /// The minimum distance between the surfaces of `self` and `other` (in the same frame), with
    /// witnesses, the triangle pair `(i, j)` attaining it and a certified error bound.
    ///
    /// The `f64` search is best-first branch and bound on the hierarchies: node pairs are ordered
    /// and pruned by a proved lower bound from boxes fitted to the geometry (principal axes, or the
    /// coordinate axes when those fit better) and the axis-aligned boxes; triangle pairs by their
    /// box distance and by separation bounds. Among pairs with the same `f64` squared distance, the
    /// smallest `(i, j)` is kept.
    ///
    /// The bound is proved over **all** triangle pairs, so it holds for the meshes' true distance
    /// even when several pairs nearly tie. The upper end: the exact clearance test of the pair
    /// found. The lower end: every other pair is either pruned by its box distance (a rounding
    /// margin of `1e-9` relative), or proved farther by an `f64` separation bound with every
    /// rounding accounted for, or decided by the exact clearance test (the few pairs whose proved
    /// bound does not beat the best `f64` distance: the winner and near-ties).
    ///
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let moved = cube.placed(&Isometry3::translation(1.5, 0.25, 0.0))?;
    /// let d = cube.distance(&moved)?;
    /// assert!((d.distance - 0.5).abs() <= d.error_bound && d.error_bound < 1e-12);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn distance(&self, other: &Collider) -> Result<CertifiedDistance, Error> {
        let magnitude = self.extent().max(other.extent());
        check_distance_range(magnitude)?;
        let mut open = Vec::new();
        let (_, i, j) = nearest_pair(self, other, |x, p, y, q, best| {
            examine_pair(x, p, y, q, best, &mut open)
        })
        .ok_or(Error::Empty {
            file: "Collider".to_owned(),
        })?;
        let d = certified_mesh_distance((i, j), &open, |x| self.corners(x), |y| other.corners(y));
        finite(d, magnitude)
    }

    /// The minimum distance between the surfaces of `self` and `other`, exactly: the squared
    /// distance, witnesses and the triangle pair as exact rationals. The exact nearest pair is
    /// chosen among the pairs within the certified upper bound of [`distance`](Self::distance)
    /// (found with the exact clearance test), so near-ties are resolved exactly.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let moved = cube.placed(&Isometry3::translation(1.5, 0.0, 0.0))?;
    /// let d = cube.exact_distance(&moved)?;
    /// assert_eq!(d.distance2, cga_collide::ga_core::scalar::rational_from_f64(0.25).unwrap());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn exact_distance(&self, other: &Collider) -> Result<ExactDistance, Error> {
        let d = self.distance(other)?;
        let hi = (d.distance + d.error_bound).next_up();
        let mut best: Option<(Near<Rational>, u32, u32)> = None;
        for (i, j) in self.pairs_within_distance(other, hi) {
            let near = triangle_triangle(
                &self.corners(i).map(|p| p.map(rational)),
                &other.corners(j).map(|p| p.map(rational)),
            );
            if best.as_ref().is_none_or(|(b, _, _)| near.0 < b.0) {
                best = Some((near, i, j));
            }
        }
        // The pair `distance` certified is within `hi` of itself, so `best` is never empty.
        let ((distance2, witness_a, witness_b), i, j) = best.ok_or(Error::OutOfRange {
            magnitude: self.extent().max(other.extent()),
            limit: DISTANCE_RANGE,
        })?;
        Ok(ExactDistance {
            distance2,
            witness_a,
            witness_b,
            triangles: Some((i, j)),
        })
    }
}
