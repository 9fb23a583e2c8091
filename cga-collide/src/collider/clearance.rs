//! Exact clearance between two meshes: whether their surfaces come within a distance `c`, and
//! every triangle pair that does (closed: a distance of exactly `c` counts).

use std::ops::ControlFlow;

use crate::bounding::boxes_within;
use crate::collider::Collider;
use crate::parallel::*;
use crate::query::within_distance::{triangles_within, trivial};

impl Collider {
    /// Every pair `(i, j)` of a triangle `i` of `self` and `j` of `other` within distance `c` of each
    /// other, exactly (closed: distance exactly `c` counts; intersecting pairs are at distance 0),
    /// sorted. The hierarchies enumerate the node pairs whose boxes come within `c`
    /// (conservatively), and the candidate pairs are decided in parallel by the exact
    /// triangle–triangle clearance test. `c` outside `[0, ∞)`: NaN and negative `c` give no pair (for
    /// `c = ∞` every pair is returned).
    ///
    /// Both meshes are taken in one frame; under poses, [`pairs_within_distance_at`](Self::pairs_within_distance_at).
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let moved = cube.placed(&Isometry3::translation(1.5, 0.0, 0.0))?; // a gap of exactly 0.5
    /// assert!(cube.pairs_within_distance(&moved, 0.4).is_empty());
    /// assert!(!cube.pairs_within_distance(&moved, 0.5).is_empty());
    /// assert!(cube.within_distance(&moved, 0.5));
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn pairs_within_distance(&self, other: &Collider, c: f64) -> Vec<(u32, u32)> {
        if trivial(c) == Some(false) {
            return Vec::new();
        }
        let mut candidates = Vec::new();
        let _ = self.bvh().for_each_pair_where::<()>(
            other.bvh(),
            |x, y| boxes_within(x, y, c),
            |i, j| {
                candidates.push((i, j));
                ControlFlow::Continue(())
            },
        );
        let mut out: Vec<(u32, u32)> = candidates
            .par_iter()
            .copied()
            .filter(|&(i, j)| triangles_within(&self.corners(i), &other.corners(j), c))
            .collect();
        out.sort_unstable();
        out
    }

    /// Whether some triangle of `self` is within distance `c` of some triangle of `other`,
    /// exactly (the surfaces' clearance; stops at the first pair found). See
    /// [`pairs_within_distance`](Self::pairs_within_distance).
    pub fn within_distance(&self, other: &Collider, c: f64) -> bool {
        if let Some(answer) = trivial(c) {
            return answer;
        }
        self.bvh()
            .for_each_pair_where(
                other.bvh(),
                |x, y| boxes_within(x, y, c),
                |i, j| {
                    if triangles_within(&self.corners(i), &other.corners(j), c) {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                },
            )
            .is_break()
    }
}
