//! [`Collider`]: a mesh built once (its box tree and the layout the pose queries read), and
//! every question about it.
//!
//! # One calling style
//! Every question about meshes is a method of the `Collider` that holds the built data:
//! * in one frame: `a.x(&b)`, both meshes taken as they are;
//! * under poses: `a.x_at(&pose_a, &b, &pose_b)` (coal's and parry's order), with no work
//!   proportional to the mesh size per pose, and the answer identical to placing the meshes first
//!   ([`Collider::placed`]); a shape or point is in world coordinates: `a.x_at(&pose_a, &shape)`;
//! * many poses at once: `a.x_batch(&b, &poses)`, a [`PosePair`] per query, spread over the cores.
//!
//! How a query runs (the box tree, or every triangle by brute force) is the collider's
//! [`Mode`], set once with [`Collider::with_mode`], the same for both frames; the answers are
//! identical in both modes. Queries that can be refused (a pose that is not finite or not a
//! rotation, coordinates too large to certify) return `Result<_, `[`crate::Error`]`>`.
//!
//! | question | in one frame | under poses | many poses |
//! |---|---|---|---|
//! | do the surfaces touch? | [`collides`](Collider::collides) | [`collides_at`](Collider::collides_at) | [`collides_batch`](Collider::collides_batch) |
//! | which triangle pairs intersect? | [`intersecting_pairs`](Collider::intersecting_pairs) | [`intersecting_pairs_at`](Collider::intersecting_pairs_at) | [`intersecting_pairs_batch`](Collider::intersecting_pairs_batch) |
//! | do the solids overlap (one may be inside)? | [`collides_solid`](Collider::collides_solid) | [`collides_solid_at`](Collider::collides_solid_at) | [`collides_solid_batch`](Collider::collides_solid_batch) |
//! | which triangles does a shape meet? | [`segment_hits`](Collider::segment_hits), `triangle_hits`, `sphere_hits`, `ball_hits`, `spheres_hits` | [`segment_hits_at`](Collider::segment_hits_at), ... | |
//! | a solid primitive ([`Shape`](crate::shape::Shape)) against the mesh | [`shape_hits`](Collider::shape_hits), [`intersects_shape`](Collider::intersects_shape), [`intersects_shape_solid`](Collider::intersects_shape_solid), [`shape_within_distance`](Collider::shape_within_distance), [`distance_to_shape`](Collider::distance_to_shape) | [`shape_hits_at`](Collider::shape_hits_at), [`intersects_shape_at`](Collider::intersects_shape_at), ... | |
//! | within distance `c`? (exact, closed) | [`within_distance`](Collider::within_distance) | [`within_distance_at`](Collider::within_distance_at) | [`within_distance_batch`](Collider::within_distance_batch) |
//! | which pairs within `c`? | [`pairs_within_distance`](Collider::pairs_within_distance) | [`pairs_within_distance_at`](Collider::pairs_within_distance_at) | |
//! | how far apart? ([`CertifiedDistance`](crate::query::CertifiedDistance)) | [`distance`](Collider::distance), [`exact_distance`](Collider::exact_distance) | [`distance_at`](Collider::distance_at) | [`distance_batch`](Collider::distance_batch) |
//! | how do closed meshes touch? | [`contact_class`](Collider::contact_class), [`contacts`](Collider::contacts) | [`contact_class_at`](Collider::contact_class_at), [`contacts_at`](Collider::contacts_at) | |
//! | does the mesh cut itself? | [`self_intersections`](Collider::self_intersections), [`self_intersects`](Collider::self_intersects) | (invariant under poses) | |
//! | is a point in the closed solid? | [`contains_point`](Collider::contains_point) | [`contains_point_at`](Collider::contains_point_at) | |
//!
//! A built collider travels as bytes, its tree included: [`Collider::to_bytes`] and
//! [`Collider::from_bytes`] (checked on reading; the boxes are recomputed, the tree is not
//! rebuilt).
//!
//! Operations between two primitives (segments, triangles, spheres, balls) are free functions
//! in [`crate::query`] (`intersects_<a>_<b>`, `within_distance_<a>_<b>`, `distance_<a>_<b>`).
//! The scenes and motion queries built on colliders follow the same shape.
//!
//! ```
//! use cga_collide::collider::{Collider, PosePair};
//! use cga_collide::nalgebra::{Isometry3, Point3};
//! use cga_collide::TriMesh;
//! let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))?);
//! let here = Isometry3::identity();
//! let there = Isometry3::translation(1.5, 0.0, 0.0); // a gap of exactly 0.5
//! assert!(!cube.collides_at(&here, &cube, &there)?);
//! assert!(cube.within_distance_at(&here, &cube, &there, 0.5)?);
//! let d = cube.distance_at(&here, &cube, &there)?;
//! assert!((d.distance - 0.5).abs() <= d.error_bound);
//! let poses = [PosePair::new(here, there), PosePair::new(here, here)];
//! assert_eq!(cube.collides_batch(&cube, &poses)?, vec![false, true]);
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod batch;
#[cfg(test)]
mod bounding_tests;
mod clearance;
mod contacts;
mod containment;
mod distance;
pub(crate) use distance::Bounded;
mod hits;
mod manifold;
mod nearest;
mod pairs;
mod pose;
pub(crate) mod poses;
mod self_intersection;
mod serial;
mod shapes;
mod signed_distance;
mod solid_sides;

pub use contacts::{ContactClass, Contacts};
pub use pose::{pose_from_degrees, pose_from_matrix, PosePair, ROTATION_TOLERANCE};
pub use signed_distance::PointDistance;

use std::sync::OnceLock;

use nalgebra::{Isometry3, Point3};

use crate::bounding::pose_tree::PoseTree;
use crate::bounding::{triangle_box, Aabb, BuildStrategy, Bvh};
use crate::error::Error;
use crate::shape::mesh::TriMesh;
use crate::Triangle;

/// How a collider's queries are run: a choice of speed, never of answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum Mode {
    /// Test every triangle (or pair of triangles), spread over the cores, after an exact box
    /// rejection (the thesis's worst case, with its arithmetic made exact). Under poses, the
    /// meshes are placed first (work proportional to their size per pose).
    Brute,
    /// Enumerate candidates with the box trees, then test them exactly.
    #[default]
    Bvh,
}

/// A mesh together with its box tree, the `f32` boxes of its triangles (what the brute-force
/// scans read: 24 bytes a triangle, contiguous) and the layout of the queries under poses
/// (laid out on the first query under poses).
#[derive(Debug, Clone)]
pub struct Collider {
    mesh: TriMesh,
    /// The box tree: built with the collider, except for meshes under [`EAGER_TREE_MIN`]
    /// triangles, which build it on first use (their queries are cheaper than the build).
    bvh: OnceLock<Bvh>,
    /// How the tree is (or will be) built.
    strategy: BuildStrategy,
    /// The `f32` boxes of the triangles, built on first use: only the brute-force scans read
    /// them.
    boxes32: OnceLock<Vec<[f32; 6]>>,
    /// Largest `|coordinate|` of a vertex (the scale of the rounding bounds of pose queries).
    extent: f64,
    /// The hierarchy laid out for pose queries (centre/extent nodes, vertices in leaf order),
    /// built on first use: only the queries under poses read it.
    pose_tree: OnceLock<PoseTree>,
    /// Which side of each triangle is outside, for the signed distance of points (found on
    /// first use).
    sides: OnceLock<solid_sides::SolidSides>,
    mode: Mode,
}

/// Meshes with at least this many triangles build their tree with the collider; smaller ones
/// on the first query that reads it (self-intersection of a tiny mesh never does).
pub(crate) const EAGER_TREE_MIN: usize = 32;

/// Largest absolute vertex coordinate.
pub(super) fn extent(mesh: &TriMesh) -> f64 {
    mesh.vertices()
        .iter()
        .flat_map(|v| v.coords.iter().map(|c| c.abs()))
        .fold(0.0, f64::max)
}

/// An `f32` not above `x`.
pub(super) fn down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x {
        f.next_down()
    } else {
        f
    }
}

/// An `f32` not below `x`.
pub(super) fn up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x {
        f.next_up()
    } else {
        f
    }
}

pub(super) fn boxes32(mesh: &TriMesh) -> Vec<[f32; 6]> {
    mesh.triangles()
        .iter()
        .map(|t| {
            let b = triangle_box(mesh.vertices(), t);
            [
                down(b.min[0]),
                down(b.min[1]),
                down(b.min[2]),
                up(b.max[0]),
                up(b.max[1]),
                up(b.max[2]),
            ]
        })
        .collect()
}

/// An `f32` box containing `b`, one `f32` step wider on every side (so it also contains the box
/// of anything `b` approximates to within `f64` rounding, e.g. `centre ± radius`).
pub(super) fn query_box32(b: &Aabb) -> [f32; 6] {
    let lo = |x: f64| down(x).next_down();
    let hi = |x: f64| up(x).next_up();
    [
        lo(b.min[0]),
        lo(b.min[1]),
        lo(b.min[2]),
        hi(b.max[0]),
        hi(b.max[1]),
        hi(b.max[2]),
    ]
}

/// Triangles per work item of the brute-force scans.
pub(super) const CHUNK: usize = 1 << 14;

#[inline(always)]
pub(super) fn overlap32(a: &[f32; 6], b: &[f32; 6]) -> bool {
    // Non-short-circuit `&`: branch-free, so the scan vectorises.
    (a[0] <= b[3])
        & (b[0] <= a[3])
        & (a[1] <= b[4])
        & (b[1] <= a[4])
        & (a[2] <= b[5])
        & (b[2] <= a[5])
}

pub(super) fn ball_box(c: &Point3<f64>, r: f64) -> Aabb {
    Aabb {
        min: [c.x - r, c.y - r, c.z - r],
        max: [c.x + r, c.y + r, c.z + r],
    }
}

/// The `f64` box of an outward-rounded `f32` box (contains the exact triangle box).
#[inline]
pub(super) fn widen(b: &[f32; 6]) -> Aabb {
    Aabb {
        min: [f64::from(b[0]), f64::from(b[1]), f64::from(b[2])],
        max: [f64::from(b[3]), f64::from(b[4]), f64::from(b[5])],
    }
}

impl Collider {
    /// Builds the hierarchy (binned SAH) over a mesh, taken as already in world coordinates
    /// (a mesh of fewer than 32 triangles builds it on the first query that reads it).
    pub fn new(mesh: TriMesh) -> Collider {
        Self::with_strategy(mesh, BuildStrategy::Sah)
    }

    /// Builds the hierarchy with a chosen split strategy. Answers never depend on it; speed
    /// does. [`BuildStrategy::Sah`] (what [`Collider::new`] uses) pays off over many queries,
    /// e.g. under poses. For one question of a fresh collider, such as
    /// [`self_intersections`](Self::self_intersections), [`BuildStrategy::Morton`] builds in
    /// about a third of the time and the whole answer comes 5–20% sooner on meshes of 10,000
    /// triangles and more (see the engineering-meshes page of the docs).
    ///
    /// ```
    /// use cga_collide::bounding::BuildStrategy;
    /// use cga_collide::collider::Collider;
    /// use cga_collide::nalgebra::Point3;
    /// use cga_collide::TriMesh;
    ///
    /// let cube = TriMesh::cuboid(Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 1.0, 1.0))?;
    /// let once = Collider::with_strategy(cube.clone(), BuildStrategy::Morton);
    /// assert_eq!(once.self_intersections(), Collider::new(cube).self_intersections());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn with_strategy(mesh: TriMesh, strategy: BuildStrategy) -> Collider {
        let bvh = OnceLock::new();
        if mesh.num_triangles() >= EAGER_TREE_MIN {
            let _ = bvh.set(Bvh::build_with(mesh.vertices(), mesh.triangles(), strategy));
        }
        let extent = extent(&mesh);
        Collider {
            mesh,
            bvh,
            strategy,
            boxes32: OnceLock::new(),
            extent,
            pose_tree: OnceLock::new(),
            sides: OnceLock::new(),
            mode: Mode::default(),
        }
    }

    /// This collider moved by `iso`: the vertices are transformed once, in `f64` (the exact
    /// tests are then exact on the transformed coordinates), and the same tree is refit to
    /// them (exact boxes, so still conservative). Fails only if a coordinate overflows.
    pub fn placed(&self, iso: &Isometry3<f64>) -> Result<Collider, Error> {
        let mesh = self.mesh.transformed(iso)?;
        let mut bvh = self.bvh().clone();
        bvh.refit(mesh.vertices(), mesh.triangles());
        let extent = extent(&mesh);
        Ok(Collider {
            mesh,
            bvh: OnceLock::from(bvh),
            strategy: self.strategy,
            boxes32: OnceLock::new(),
            extent,
            pose_tree: OnceLock::new(),
            sides: OnceLock::new(),
            mode: self.mode,
        })
    }

    /// The `f32` boxes of the triangles, outward-rounded, in triangle order (what the
    /// brute-force scans read), built on the first call.
    pub(crate) fn boxes32(&self) -> &[[f32; 6]] {
        self.boxes32.get_or_init(|| boxes32(&self.mesh))
    }

    /// Largest absolute coordinate of a vertex.
    pub(crate) fn extent(&self) -> f64 {
        self.extent
    }

    /// The hierarchy laid out for pose queries, built on the first call.
    pub(crate) fn pose_tree(&self) -> &PoseTree {
        self.pose_tree
            .get_or_init(|| PoseTree::new(self.bvh(), |i| self.mesh.corners(i as u32), self.extent))
    }

    /// The mesh, in world coordinates.
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    /// The hierarchy (built here on the first call for meshes of fewer than 32 triangles).
    pub fn bvh(&self) -> &Bvh {
        self.bvh.get_or_init(|| {
            Bvh::build_with(self.mesh.vertices(), self.mesh.triangles(), self.strategy)
        })
    }

    /// Whether the hierarchy has been built (tiny meshes build it on first use).
    pub(crate) fn has_bvh(&self) -> bool {
        self.bvh.get().is_some()
    }

    /// How this collider's queries are run ([`Mode`]).
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// This collider with its queries run another way ([`Mode`]): a choice of speed only, the
    /// answers are identical. The mode of `self` governs a query between two colliders.
    ///
    /// ```
    /// # use cga_collide::{collider::{Collider, Mode}, TriMesh, nalgebra::Point3};
    /// let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))?;
    /// let (bvh, brute) = (Collider::new(cube.clone()), Collider::new(cube).with_mode(Mode::Brute));
    /// assert_eq!(bvh.intersecting_pairs(&bvh), brute.intersecting_pairs(&bvh));
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn with_mode(mut self, mode: Mode) -> Collider {
        self.mode = mode;
        self
    }

    /// Triangle `i` as an exact-test shape (as [`TriMesh::triangle`]).
    #[inline]
    pub fn triangle(&self, i: u32) -> Triangle {
        self.mesh.triangle(i)
    }

    /// The corners of triangle `i` as raw coordinates (what the `f64` searches read).
    #[inline]
    pub(crate) fn corners(&self, i: u32) -> [[f64; 3]; 3] {
        let [a, b, c] = self.mesh.corners(i);
        [[a.x, a.y, a.z], [b.x, b.y, b.z], [c.x, c.y, c.z]]
    }

    /// The exact box of triangle `i`.
    pub(crate) fn tri_box(&self, i: usize) -> Aabb {
        triangle_box(self.mesh.vertices(), &self.mesh.triangles()[i])
    }

    /// The exact box of every triangle, in order (what the brute-force pair scans compare).
    pub(crate) fn triangle_boxes(&self) -> Vec<Aabb> {
        (0..self.mesh.num_triangles())
            .map(|j| self.tri_box(j))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn f32_boxes_round_outwards(m in -1.0f64..1.0, e in -330i32..330) {
            let x = m * 10f64.powi(e);
            prop_assert!(f64::from(down(x)) <= x);
            prop_assert!(f64::from(up(x)) >= x);
        }
    }

    #[test]
    fn f32_rounding_edge_cases() {
        for x in [
            0.0,
            -0.0,
            1e-300,
            -1e-300,
            1e300,
            -1e300,
            0.1,
            -0.1,
            f64::from(f32::MAX),
        ] {
            assert!(f64::from(down(x)) <= x && f64::from(up(x)) >= x, "{x}");
        }
    }
}
