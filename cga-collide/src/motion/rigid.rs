//! Two colliders, each moving between two poses: every vertex moves linearly from its position
//! placed by the first pose to its position placed by the second (the CCD benchmark's model of
//! motion; not a screw motion), and every vertex–face and edge–edge pair of the two meshes that
//! touches during the motion is found, exactly, with the first contact time.
//!
//! The placed positions are the `f64` points `pose * vertex` (nalgebra's transform, as
//! [`Collider::placed`] computes them), taken as the exact numbers they are. The broad phase
//! reuses each collider's box tree, refitted (not rebuilt) to the boxes its triangles sweep;
//! those boxes hold both placed copies of each triangle, so they hold it during the whole
//! motion and no touching pair is dropped.

use std::collections::HashSet;
use std::ops::ControlFlow;

use nalgebra::{Isometry3, Point3};

use super::ContactTime;
use crate::bounding::Aabb;
use crate::collider::Collider;
use crate::error::Error;
use crate::parallel::*;

/// A pair of primitives of two moving meshes, `self`'s first (vertex and edge indices of the
/// mesh, edges as their two vertices, smaller first).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum MotionPair {
    /// A vertex of the first mesh and a face of the second.
    VertexFace(u32, u32),
    /// A face of the first mesh and a vertex of the second.
    FaceVertex(u32, u32),
    /// An edge of the first mesh and an edge of the second.
    EdgeEdge([u32; 2], [u32; 2]),
}

/// What touches while two colliders move ([`Collider::contacts_during`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MotionContacts {
    /// Every pair that touches at some `t ∈ [0, 1]`, sorted.
    pub pairs: Vec<MotionPair>,
    /// The earliest contact of all, to the tolerance asked for; `None` when nothing touches.
    pub first_contact: Option<ContactTime>,
    /// The pairs whose own first contact may be the earliest: those whose contact interval
    /// meets `first_contact`'s (exactly the pairs attaining it when the bounds are exact).
    pub first_pairs: Vec<MotionPair>,
}

fn placed(c: &Collider, pose: &Isometry3<f64>) -> Result<Vec<Point3<f64>>, Error> {
    // The same checks as every pose query (finite, unit rotation).
    crate::bounding::pose_bounds::PoseMap::new(pose)?;
    let out: Vec<Point3<f64>> = c.mesh().vertices().iter().map(|v| pose * v).collect();
    if let Some(p) = out.iter().find(|p| p.iter().any(|x| !x.is_finite())) {
        return Err(Error::OutOfRange {
            magnitude: p.iter().fold(0.0f64, |m, x| m.max(x.abs())),
            limit: f64::MAX,
        });
    }
    Ok(out)
}

fn edges_of(t: &[u32; 3]) -> [[u32; 2]; 3] {
    [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])].map(|(a, b)| [a.min(b), a.max(b)])
}

impl Collider {
    /// Every vertex–face and edge–edge pair of `self` and `other` that touches while `self`
    /// moves from `poses[0]` to `poses[1]` and `other` from `other_poses[0]` to
    /// `other_poses[1]` (each vertex linearly between its two placed positions), exactly, with
    /// the first contact time bounded to `tolerance` (see
    /// [`vertex_face_first_contact`](super::vertex_face_first_contact)).
    ///
    /// # Errors
    /// The pose errors of the pose queries ([`Error::NonFinitePose`],
    /// [`Error::NotUnitRotation`]), or [`Error::OutOfRange`] when a placed vertex overflows.
    ///
    /// ```
    /// use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
    /// use cga_collide::{Collider, TriMesh};
    /// let cube = |lo: f64, hi: f64| {
    ///     TriMesh::cuboid(Point3::new(lo, lo, lo), Point3::new(hi, hi, hi)).map(Collider::new)
    /// };
    /// let (wall, bullet) = (cube(0.0, 1.0)?, cube(0.0, 0.1)?);
    /// let still = Isometry3::identity();
    /// // The bullet flies through the wall between two frames: no overlap at either pose.
    /// let before = Isometry3::translation(-1.0, 0.45, 0.45);
    /// let after = Isometry3::translation(2.0, 0.45, 0.45);
    /// assert!(!bullet.collides_at(&before, &wall, &still)? && !bullet.collides_at(&after, &wall, &still)?);
    /// let hit = bullet.contacts_during([&before, &after], &wall, [&still, &still], 1e-9)?;
    /// let first = hit.first_contact.expect("tunnelling is caught");
    /// assert!(first.lo() <= 0.3 && 0.3 <= first.hi()); // the front face reaches x = 0 at t = 0.3
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contacts_during(
        &self,
        poses: [&Isometry3<f64>; 2],
        other: &Collider,
        other_poses: [&Isometry3<f64>; 2],
        tolerance: f64,
    ) -> Result<MotionContacts, Error> {
        let a = [placed(self, poses[0])?, placed(self, poses[1])?];
        let b = [
            placed(other, other_poses[0])?,
            placed(other, other_poses[1])?,
        ];
        let (fa, fb) = (self.mesh().triangles(), other.mesh().triangles());
        let swept = |x: &[Vec<Point3<f64>>; 2], t: &[u32; 3]| {
            let mut bx = Aabb::EMPTY;
            for &v in t {
                bx.grow(&x[0][v as usize]);
                bx.grow(&x[1][v as usize]);
            }
            bx
        };
        let mut ta = self.bvh().clone();
        ta.refit_boxes(|i| swept(&a, &fa[i as usize]));
        let mut tb = other.bvh().clone();
        tb.refit_boxes(|j| swept(&b, &fb[j as usize]));
        let mut candidates: HashSet<MotionPair> = HashSet::new();
        let _ = ta.for_each_pair(&tb, |i, j| {
            let (s, t) = (fa[i as usize], fb[j as usize]);
            for v in s {
                candidates.insert(MotionPair::VertexFace(v, j));
            }
            for v in t {
                candidates.insert(MotionPair::FaceVertex(i, v));
            }
            for ea in edges_of(&s) {
                for eb in edges_of(&t) {
                    candidates.insert(MotionPair::EdgeEdge(ea, eb));
                }
            }
            ControlFlow::<()>::Continue(())
        });
        let track = |x: &[Vec<Point3<f64>>; 2], v: u32| -> [[f64; 3]; 2] {
            let (p, q) = (x[0][v as usize], x[1][v as usize]);
            [[p.x, p.y, p.z], [q.x, q.y, q.z]]
        };
        let first = |pair: &MotionPair, tolerance: f64| -> Option<ContactTime> {
            match *pair {
                MotionPair::VertexFace(v, f) => {
                    let t = fb[f as usize];
                    super::points_vertex_face_first_contact(
                        &[
                            track(&a, v),
                            track(&b, t[0]),
                            track(&b, t[1]),
                            track(&b, t[2]),
                        ],
                        tolerance,
                    )
                }
                MotionPair::FaceVertex(f, v) => {
                    let t = fa[f as usize];
                    super::points_vertex_face_first_contact(
                        &[
                            track(&b, v),
                            track(&a, t[0]),
                            track(&a, t[1]),
                            track(&a, t[2]),
                        ],
                        tolerance,
                    )
                }
                MotionPair::EdgeEdge(ea, eb) => super::points_edge_edge_first_contact(
                    &[
                        track(&a, ea[0]),
                        track(&a, ea[1]),
                        track(&b, eb[0]),
                        track(&b, eb[1]),
                    ],
                    tolerance,
                ),
            }
        };
        let candidates: Vec<MotionPair> = candidates.into_iter().collect();
        let mut hits: Vec<(MotionPair, ContactTime)> = candidates
            .par_iter()
            .filter_map(|p| first(p, f64::INFINITY).map(|t| (*p, t)))
            .collect();
        hits.sort_unstable_by_key(|(p, _)| *p);
        let earliest_hi = hits
            .iter()
            .map(|(_, t)| t.hi())
            .fold(f64::INFINITY, f64::min);
        let refined: Vec<(MotionPair, ContactTime)> = hits
            .par_iter()
            .filter(|(_, t)| t.lo() <= earliest_hi)
            .filter_map(|(p, _)| first(p, tolerance).map(|t| (*p, t)))
            .collect();
        let first_contact = ContactTime::earliest(refined.iter().map(|(_, t)| *t));
        let mut first_pairs: Vec<MotionPair> = match first_contact {
            None => Vec::new(),
            Some(f) => refined
                .iter()
                .filter(|(_, t)| t.lo() <= f.hi())
                .map(|(p, _)| *p)
                .collect(),
        };
        first_pairs.sort_unstable();
        Ok(MotionContacts {
            pairs: hits.into_iter().map(|(p, _)| p).collect(),
            first_contact,
            first_pairs,
        })
    }
}
