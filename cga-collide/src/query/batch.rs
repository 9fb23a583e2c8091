//! Many poses in one call: the pose queries of [`crate::query::posed`] over a slice of pose
//! pairs, spread over the cores (rayon, feature `parallel`; run inside a
//! `rayon::ThreadPool::install` to choose the number of threads). Each pose is answered on one
//! thread, sequentially, so the speed-up comes from answering poses side by side.
//!
//! ```
//! use cga_collide::query::{Collider, PosePair};
//! use cga_collide::{nalgebra::Isometry3, TriMesh};
//! let a = Collider::new(TriMesh::bunny().unit());
//! let poses: Vec<PosePair> = (0..8)
//!     .map(|k| PosePair::new(Isometry3::identity(), Isometry3::translation(0.2 * k as f64, 0.0, 0.0)))
//!     .collect();
//! let hits = a.collides_batch(&a, &poses)?;
//! let pairs = a.intersecting_pairs_batch(&a, &poses)?;
//! for ((hit, pairs), p) in hits.iter().zip(&pairs).zip(&poses) {
//!     assert_eq!(*hit, !pairs.is_empty());
//!     assert_eq!(*hit, a.collides_at(&p.a, &a, &p.b)?);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::Isometry3;
use thiserror::Error;

use crate::parallel::*;
use crate::query::{Collider, PoseError};

/// The poses of the two meshes of one query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PosePair {
    /// Pose of the first mesh (`self` of the query).
    pub a: Isometry3<f64>,
    /// Pose of the second mesh.
    pub b: Isometry3<f64>,
}

impl PosePair {
    /// The pair of poses.
    pub fn new(a: Isometry3<f64>, b: Isometry3<f64>) -> PosePair {
        PosePair { a, b }
    }
}

/// A pose of a batch that has no answer, with its position in the batch.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("pose {index} of the batch: {source}")]
pub struct BatchError {
    /// Position of the pose in the slice.
    pub index: usize,
    /// Why it has no answer.
    #[source]
    pub source: PoseError,
}

impl Collider {
    /// For each pose pair, whether the two placed meshes touch
    /// ([`collides_at`](Self::collides_at)); poses are spread over the cores.
    pub fn collides_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
    ) -> Result<Vec<bool>, BatchError> {
        poses
            .par_iter()
            .enumerate()
            .map(|(index, p)| {
                self.collides_at(&p.a, other, &p.b)
                    .map_err(|source| BatchError { index, source })
            })
            .collect()
    }

    /// For each pose pair, every intersecting triangle pair, sorted
    /// ([`intersecting_pairs_at`](Self::intersecting_pairs_at)); poses are spread over the
    /// cores, each answered on one thread.
    pub fn intersecting_pairs_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
    ) -> Result<Vec<Vec<(u32, u32)>>, BatchError> {
        poses
            .par_iter()
            .enumerate()
            .map(|(index, p)| {
                self.intersecting_pairs_at_sequential(&p.a, other, &p.b)
                    .map_err(|source| BatchError { index, source })
            })
            .collect()
    }
}
