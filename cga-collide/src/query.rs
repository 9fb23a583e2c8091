//! Exact queries against meshes: which triangles a segment, triangle, sphere, ball or set of
//! spheres meets, every intersecting triangle pair of two meshes, and a first-hit boolean.
//!
//! A [`Collider`] is a mesh placed in the world (its vertices transformed once, in `f64`) with
//! its [`Bvh`]. Every answer is exact for those `f64` coordinates (see [`crate::intersect`])
//! and identical in both [`Mode`]s:
//! * [`Mode::Brute`]: every triangle (or every pair of triangles) is tested, in parallel with
//!   rayon, after an exact box rejection (the thesis's worst case, with its arithmetic made
//!   exact);
//! * [`Mode::Bvh`]: the hierarchy enumerates candidates conservatively and the same exact test
//!   decides each one (single-threaded).
//!
//! ```
//! use cga_collide::query::{Collider, Mode};
//! use cga_collide::{mesh::TriMesh, nalgebra::{Isometry3, Point3, Vector3}, Segment};
//! let bunny = Collider::new(TriMesh::bunny());
//! let seg = Segment::new(Point3::new(0.0, 0.0, -10.0), Point3::new(0.0, 0.0, 10.0)).unwrap();
//! assert_eq!(bunny.segment_hits(&seg, Mode::Bvh), bunny.segment_hits(&seg, Mode::Brute));
//! let moved = bunny.placed(&Isometry3::translation(0.5, 0.0, 0.0)).unwrap();
//! let pairs = bunny.intersecting_pairs(&moved, Mode::Bvh);
//! assert_eq!(!pairs.is_empty(), bunny.collides(&moved, Mode::Bvh));
//! ```

use std::ops::ControlFlow;

use nalgebra::Isometry3;
use rayon::prelude::*;

use crate::bvh::{triangle_box, Aabb, BuildStrategy, Bvh};
use crate::mesh::{MeshError, TriMesh};
use crate::{Ball, Intersects, Segment, Sphere, Triangle};

/// How a query is answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum Mode {
    /// Test every triangle (or pair), in parallel with rayon.
    Brute,
    /// Enumerate candidates with the bounding-volume hierarchy, then test them exactly.
    #[default]
    Bvh,
}

/// A mesh in world coordinates together with its hierarchy.
#[derive(Debug, Clone)]
pub struct Collider {
    mesh: TriMesh,
    bvh: Bvh,
}

impl Collider {
    /// Builds the hierarchy (binned SAH) over a mesh, taken as already in world coordinates.
    pub fn new(mesh: TriMesh) -> Collider {
        Self::with_strategy(mesh, BuildStrategy::Sah)
    }

    /// Builds the hierarchy with a chosen split strategy.
    pub fn with_strategy(mesh: TriMesh, strategy: BuildStrategy) -> Collider {
        let bvh = Bvh::build_with(mesh.vertices(), mesh.triangles(), strategy);
        Collider { mesh, bvh }
    }

    /// This collider moved by `iso`: the vertices are transformed once, in `f64` (the exact
    /// tests are then exact on the transformed coordinates), and the same tree is refit to
    /// them (exact boxes, so still conservative). Fails only if a coordinate overflows.
    pub fn placed(&self, iso: &Isometry3<f64>) -> Result<Collider, MeshError> {
        let mesh = self.mesh.transformed(iso)?;
        let mut bvh = self.bvh.clone();
        bvh.refit(mesh.vertices(), mesh.triangles());
        Ok(Collider { mesh, bvh })
    }

    /// The mesh, in world coordinates.
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    /// The hierarchy.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// Triangle `i` as an exact-test shape.
    #[inline]
    pub fn triangle(&self, i: u32) -> Triangle {
        let [a, b, c] = self.mesh.triangle(i as usize);
        // Vertices of a TriMesh are finite, so this cannot fail.
        Triangle::new(a, b, c).unwrap_or_else(|_| unreachable!("TriMesh vertices are finite"))
    }

    fn tri_box(&self, i: usize) -> Aabb {
        triangle_box(self.mesh.vertices(), &self.mesh.triangles()[i])
    }

    /// Sorted indices of the triangles for which `hit` holds, among those whose box passes
    /// `test` (brute: all triangles, in parallel; bvh: candidates of the hierarchy).
    fn hits(
        &self,
        mode: Mode,
        test: impl Fn(&Aabb) -> bool + Sync,
        hit: impl Fn(&Triangle) -> bool + Sync,
    ) -> Vec<u32> {
        match mode {
            Mode::Brute => (0..self.mesh.num_triangles())
                .into_par_iter()
                .filter(|&i| test(&self.tri_box(i)) && hit(&self.triangle(i as u32)))
                .map(|i| i as u32)
                .collect(),
            Mode::Bvh => {
                let mut out = Vec::new();
                let _ = self.bvh.for_each_candidate::<()>(&test, |t| {
                    if hit(&self.triangle(t)) {
                        out.push(t);
                    }
                    ControlFlow::Continue(())
                });
                out.sort_unstable();
                out
            }
        }
    }

    /// Sorted indices of the triangles the closed segment meets.
    pub fn segment_hits(&self, s: &Segment, mode: Mode) -> Vec<u32> {
        let (p, q) = (*s.a(), *s.b());
        self.hits(mode, |b| b.may_meet_segment(&p, &q), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles the closed triangle meets.
    pub fn triangle_hits(&self, t: &Triangle, mode: Mode) -> Vec<u32> {
        let tb = Aabb::of_points(t.vertices());
        self.hits(mode, |b| b.overlaps(&tb), |u| u.intersects(t))
    }

    /// Sorted indices of the triangles the sphere *surface* meets.
    pub fn sphere_hits(&self, s: &Sphere, mode: Mode) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(mode, |b| b.may_meet_sphere(&c, r), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles the solid ball meets.
    pub fn ball_hits(&self, s: &Ball, mode: Mode) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(mode, |b| b.may_meet_ball(&c, r), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles met by at least one of the sphere surfaces.
    pub fn spheres_hits(&self, spheres: &[Sphere], mode: Mode) -> Vec<u32> {
        let mut out: Vec<u32> = match mode {
            Mode::Brute => (0..self.mesh.num_triangles())
                .into_par_iter()
                .filter(|&i| {
                    let b = self.tri_box(i);
                    let t = self.triangle(i as u32);
                    spheres
                        .iter()
                        .any(|s| b.may_meet_sphere(s.centre(), s.radius()) && t.intersects(s))
                })
                .map(|i| i as u32)
                .collect(),
            Mode::Bvh => spheres
                .par_iter()
                .flat_map_iter(|s| self.sphere_hits(s, Mode::Bvh))
                .collect(),
        };
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Every pair `(i, j)` of a triangle `i` of `self` and `j` of `other` that intersect
    /// (closed triangles, exact), sorted.
    pub fn intersecting_pairs(&self, other: &Collider, mode: Mode) -> Vec<(u32, u32)> {
        let mut out = match mode {
            Mode::Brute => {
                let other_boxes: Vec<Aabb> = (0..other.mesh.num_triangles())
                    .map(|j| other.tri_box(j))
                    .collect();
                (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .flat_map_iter(|i| {
                        let bi = self.tri_box(i);
                        let ti = self.triangle(i as u32);
                        let other_boxes = &other_boxes;
                        (0..other.mesh.num_triangles()).filter_map(move |j| {
                            (bi.overlaps(&other_boxes[j])
                                && ti.intersects(&other.triangle(j as u32)))
                            .then_some((i as u32, j as u32))
                        })
                    })
                    .collect()
            }
            Mode::Bvh => {
                let mut out = Vec::new();
                let _ = self.bvh.for_each_pair::<()>(&other.bvh, |i, j| {
                    if self.triangle(i).intersects(&other.triangle(j)) {
                        out.push((i, j));
                    }
                    ControlFlow::Continue(())
                });
                out
            }
        };
        out.sort_unstable();
        out
    }

    /// Whether any triangle of `self` meets any triangle of `other` (stops at the first hit).
    pub fn collides(&self, other: &Collider, mode: Mode) -> bool {
        match mode {
            Mode::Brute => {
                let other_boxes: Vec<Aabb> = (0..other.mesh.num_triangles())
                    .map(|j| other.tri_box(j))
                    .collect();
                (0..self.mesh.num_triangles()).into_par_iter().any(|i| {
                    let bi = self.tri_box(i);
                    let ti = self.triangle(i as u32);
                    (0..other.mesh.num_triangles()).any(|j| {
                        bi.overlaps(&other_boxes[j]) && ti.intersects(&other.triangle(j as u32))
                    })
                })
            }
            Mode::Bvh => self
                .bvh
                .for_each_pair(&other.bvh, |i, j| {
                    if self.triangle(i).intersects(&other.triangle(j)) {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                })
                .is_break(),
        }
    }

    /// Pairs of triangles whose boxes overlap, by brute force (the ground truth the hierarchy's
    /// enumeration is tested against), sorted.
    pub fn box_pairs_brute(&self, other: &Collider) -> Vec<(u32, u32)> {
        let other_boxes: Vec<Aabb> = (0..other.mesh.num_triangles())
            .map(|j| other.tri_box(j))
            .collect();
        (0..self.mesh.num_triangles())
            .into_par_iter()
            .flat_map_iter(|i| {
                let bi = self.tri_box(i);
                let other_boxes = &other_boxes;
                (0..other_boxes.len())
                    .filter(move |&j| bi.overlaps(&other_boxes[j]))
                    .map(move |j| (i as u32, j as u32))
            })
            .collect()
    }

    /// Pairs of triangles whose boxes overlap, enumerated by the hierarchies, sorted.
    pub fn box_pairs_bvh(&self, other: &Collider) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        let _ = self.bvh.for_each_pair::<()>(&other.bvh, |i, j| {
            out.push((i, j));
            ControlFlow::Continue(())
        });
        out.sort_unstable();
        out
    }
}
