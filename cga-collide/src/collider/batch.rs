//! Many poses in one call: the pose queries (`*_at`) over a slice of pose pairs, spread over the cores (rayon, feature `parallel`; run inside a
//! `rayon::ThreadPool::install` to choose the number of threads). Each pose is answered on one
//! thread, sequentially, so the speed-up comes from answering poses side by side.
//!
//! ```
//! use cga_collide::collider::{Collider, PosePair};
//! use cga_collide::{nalgebra::{Isometry3, Point3}, TriMesh};
//! let a = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))?);
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

use crate::collider::{Collider, PosePair};
use crate::error::Error;
use crate::parallel::over_batch;
use crate::query::CertifiedDistance;

fn over_poses<T: Send>(
    poses: &[PosePair],
    query: impl Fn(&PosePair) -> Result<T, Error> + Sync,
) -> Result<Vec<T>, Error> {
    over_batch(poses, query)
}

impl Collider {
    /// For each pose pair, whether the two placed meshes touch
    /// ([`collides_at`](Self::collides_at)).
    pub fn collides_batch(&self, other: &Collider, poses: &[PosePair]) -> Result<Vec<bool>, Error> {
        over_poses(poses, |p| self.collides_at(&p.a, other, &p.b))
    }

    /// For each pose pair, every intersecting triangle pair, sorted
    /// ([`intersecting_pairs_at`](Self::intersecting_pairs_at)); each pose is answered on one
    /// thread.
    pub fn intersecting_pairs_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
    ) -> Result<Vec<Vec<(u32, u32)>>, Error> {
        over_poses(poses, |p| {
            self.intersecting_pairs_at_sequential(&p.a, other, &p.b)
        })
    }

    /// For each pose pair, whether the closed solids share a point
    /// ([`collides_solid_at`](Self::collides_solid_at)).
    pub fn collides_solid_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
    ) -> Result<Vec<bool>, Error> {
        over_poses(poses, |p| self.collides_solid_at(&p.a, other, &p.b))
    }

    /// For each pose pair, whether the surfaces come within distance `c`
    /// ([`within_distance_at`](Self::within_distance_at)).
    pub fn within_distance_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
        c: f64,
    ) -> Result<Vec<bool>, Error> {
        over_poses(poses, |p| self.within_distance_at(&p.a, other, &p.b, c))
    }

    /// For each pose pair, the certified minimum distance
    /// ([`distance_at`](Self::distance_at)).
    pub fn distance_batch(
        &self,
        other: &Collider,
        poses: &[PosePair],
    ) -> Result<Vec<CertifiedDistance>, Error> {
        over_poses(poses, |p| self.distance_at(&p.a, other, &p.b))
    }
}
