//! Exact queries against meshes: which triangles a segment, triangle, sphere, ball or set of
//! spheres meets, every intersecting triangle pair of two meshes, and a first-hit boolean.
//!
//! A [`Collider`] is a mesh placed in the world (its vertices transformed once, in `f64`) with
//! its [`Bvh`]. Every answer is exact for those `f64` coordinates (see [`crate::query`])
//! and identical in both [`Mode`]s:
//! * [`Mode::Brute`]: every triangle (or every pair of triangles) is tested, in parallel with
//!   rayon, after an exact box rejection (the thesis's worst case, with its arithmetic made
//!   exact);
//! * [`Mode::Bvh`]: the hierarchy enumerates candidates conservatively and the same exact test
//!   decides each one (single-threaded).
//!
//! ```
//! use cga_collide::query::{Collider, Mode};
//! use cga_collide::{shape::mesh::TriMesh, nalgebra::{Isometry3, Point3, Vector3}, Segment};
//! let bunny = Collider::new(TriMesh::bunny());
//! let seg = Segment::new(Point3::new(0.0, 0.0, -10.0), Point3::new(0.0, 0.0, 10.0)).unwrap();
//! assert_eq!(bunny.segment_hits(&seg, Mode::Bvh), bunny.segment_hits(&seg, Mode::Brute));
//! let moved = bunny.placed(&Isometry3::translation(0.5, 0.0, 0.0)).unwrap();
//! let pairs = bunny.intersecting_pairs(&moved, Mode::Bvh);
//! assert_eq!(!pairs.is_empty(), bunny.collides(&moved, Mode::Bvh));
//! ```

use std::ops::ControlFlow;

use crate::parallel::*;
use nalgebra::{Isometry3, Point3};

use crate::query::pose_tree::PoseTree;
use crate::query::ray_crosses_triangle;

use crate::bvh::{triangle_box, Aabb, BuildStrategy, Bvh};
use crate::shape::mesh::{MeshError, TriMesh};
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

/// A mesh in world coordinates together with its hierarchy, and the boxes of its triangles
/// in `f32` rounded outwards (what the brute-force scans read: 24 bytes a triangle, contiguous).
#[derive(Debug, Clone)]
pub struct Collider {
    mesh: TriMesh,
    bvh: Bvh,
    boxes32: Vec<[f32; 6]>,
    /// Largest `|coordinate|` of a vertex (the scale of the rounding bounds of pose queries).
    extent: f64,
    /// The hierarchy laid out for pose queries (centre/extent nodes, vertices in leaf order).
    pose_tree: PoseTree,
}

/// Largest absolute vertex coordinate.
fn extent(mesh: &TriMesh) -> f64 {
    mesh.vertices()
        .iter()
        .flat_map(|v| v.coords.iter().map(|c| c.abs()))
        .fold(0.0, f64::max)
}

/// An `f32` not above `x`.
fn down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x {
        f.next_down()
    } else {
        f
    }
}

/// An `f32` not below `x`.
fn up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x {
        f.next_up()
    } else {
        f
    }
}

fn boxes32(mesh: &TriMesh) -> Vec<[f32; 6]> {
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
fn query_box32(b: &Aabb) -> [f32; 6] {
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
const CHUNK: usize = 1 << 14;

#[inline(always)]
fn overlap32(a: &[f32; 6], b: &[f32; 6]) -> bool {
    // Non-short-circuit `&`: branch-free, so the scan vectorises.
    (a[0] <= b[3])
        & (b[0] <= a[3])
        & (a[1] <= b[4])
        & (b[1] <= a[4])
        & (a[2] <= b[5])
        & (b[2] <= a[5])
}

fn ball_box(c: &Point3<f64>, r: f64) -> Aabb {
    Aabb {
        min: [c.x - r, c.y - r, c.z - r],
        max: [c.x + r, c.y + r, c.z + r],
    }
}

/// The `f64` box of an outward-rounded `f32` box (contains the exact triangle box).
#[inline]
fn widen(b: &[f32; 6]) -> Aabb {
    Aabb {
        min: [f64::from(b[0]), f64::from(b[1]), f64::from(b[2])],
        max: [f64::from(b[3]), f64::from(b[4]), f64::from(b[5])],
    }
}

impl Collider {
    /// Builds the hierarchy (binned SAH) over a mesh, taken as already in world coordinates.
    pub fn new(mesh: TriMesh) -> Collider {
        Self::with_strategy(mesh, BuildStrategy::Sah)
    }

    /// Builds the hierarchy with a chosen split strategy.
    pub fn with_strategy(mesh: TriMesh, strategy: BuildStrategy) -> Collider {
        let bvh = Bvh::build_with(mesh.vertices(), mesh.triangles(), strategy);
        let boxes32 = boxes32(&mesh);
        let extent = extent(&mesh);
        let pose_tree = PoseTree::new(&bvh, |i| mesh.triangle(i), extent);
        Collider {
            mesh,
            bvh,
            boxes32,
            extent,
            pose_tree,
        }
    }

    /// This collider moved by `iso`: the vertices are transformed once, in `f64` (the exact
    /// tests are then exact on the transformed coordinates), and the same tree is refit to
    /// them (exact boxes, so still conservative). Fails only if a coordinate overflows.
    pub fn placed(&self, iso: &Isometry3<f64>) -> Result<Collider, MeshError> {
        let mesh = self.mesh.transformed(iso)?;
        let mut bvh = self.bvh.clone();
        bvh.refit(mesh.vertices(), mesh.triangles());
        let boxes32 = boxes32(&mesh);
        let extent = extent(&mesh);
        let pose_tree = PoseTree::new(&bvh, |i| mesh.triangle(i), extent);
        Ok(Collider {
            mesh,
            bvh,
            boxes32,
            extent,
            pose_tree,
        })
    }

    /// Largest absolute coordinate of a vertex.
    pub(crate) fn extent(&self) -> f64 {
        self.extent
    }

    /// The hierarchy laid out for pose queries.
    pub(crate) fn pose_tree(&self) -> &PoseTree {
        &self.pose_tree
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
    /// `query` is a box holding the query shape up to `f64` rounding (used, widened to `f32`,
    /// as the first filter of the brute-force scan).
    fn hits(
        &self,
        mode: Mode,
        query: &Aabb,
        test: impl Fn(&Aabb) -> bool + Sync,
        hit: impl Fn(&Triangle) -> bool + Sync,
    ) -> Vec<u32> {
        match mode {
            Mode::Brute => {
                let q = query_box32(query);
                let chunks: Vec<Vec<u32>> = self
                    .boxes32
                    .par_chunks(CHUNK)
                    .enumerate()
                    .map(|(c, boxes)| {
                        let mut out = Vec::new();
                        for (k, b) in boxes.iter().enumerate() {
                            if overlap32(b, &q) {
                                let i = (c * CHUNK + k) as u32;
                                if test(&widen(b)) && hit(&self.triangle(i)) {
                                    out.push(i);
                                }
                            }
                        }
                        out
                    })
                    .collect();
                chunks.concat()
            }
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
        let query = Aabb::of_points(&[p, q]);
        self.hits(
            mode,
            &query,
            |b| b.may_meet_segment(&p, &q),
            |t| t.intersects(s),
        )
    }

    /// Sorted indices of the triangles the closed triangle meets.
    pub fn triangle_hits(&self, t: &Triangle, mode: Mode) -> Vec<u32> {
        let tb = Aabb::of_points(t.vertices());
        self.hits(mode, &tb, |b| b.overlaps(&tb), |u| u.intersects(t))
    }

    /// Sorted indices of the triangles the sphere *surface* meets.
    pub fn sphere_hits(&self, s: &Sphere, mode: Mode) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(
            mode,
            &ball_box(&c, r),
            |b| b.may_meet_sphere(&c, r),
            |t| t.intersects(s),
        )
    }

    /// Sorted indices of the triangles the solid ball meets.
    pub fn ball_hits(&self, s: &Ball, mode: Mode) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(
            mode,
            &ball_box(&c, r),
            |b| b.may_meet_ball(&c, r),
            |t| t.intersects(s),
        )
    }

    /// Sorted indices of the triangles met by at least one of the sphere surfaces.
    pub fn spheres_hits(&self, spheres: &[Sphere], mode: Mode) -> Vec<u32> {
        let mut out: Vec<u32> = match mode {
            Mode::Brute => {
                let qs: Vec<[f32; 6]> = spheres
                    .iter()
                    .map(|s| query_box32(&ball_box(s.centre(), s.radius())))
                    .collect();
                (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .filter(|&i| {
                        let b32 = &self.boxes32[i];
                        spheres.iter().zip(&qs).any(|(s, q)| {
                            overlap32(b32, q)
                                && widen(b32).may_meet_sphere(s.centre(), s.radius())
                                && self.triangle(i as u32).intersects(s)
                        })
                    })
                    .map(|i| i as u32)
                    .collect()
            }
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

impl Collider {
    /// Whether `p` lies in the closed solid bounded by this mesh: on a triangle, or inside by
    /// the parity of the crossings of a ray from `p` along `+x`. Exact: the ray is perturbed
    /// symbolically (simulation of simplicity in the `(y, z)` projection), so rays through
    /// edges and vertices are counted consistently, and every sign is an exact predicate.
    ///
    /// The answer is the solid's for a closed mesh (every edge used by an even number of
    /// triangles, see [`TriMesh::is_closed`]); for other meshes it is the even–odd rule of
    /// that one ray.
    pub fn contains_point(&self, p: &Point3<f64>, mode: Mode) -> bool {
        let Ok(point) = Segment::new(*p, *p) else {
            return false;
        };
        let on_ray = |b: &Aabb| {
            b.min[1] <= p.y
                && p.y <= b.max[1]
                && b.min[2] <= p.z
                && p.z <= b.max[2]
                && b.max[0] >= p.x
        };
        // (on the surface, crossings)
        let visit = |i: u32| -> (bool, bool) {
            let tri = self.mesh.triangle(i as usize);
            let t = self.triangle(i);
            if t.intersects(&point) {
                (true, false)
            } else {
                (false, ray_crosses_triangle(&tri, p))
            }
        };
        match mode {
            Mode::Brute => {
                let (on, crossings) = (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .filter(|&i| on_ray(&widen(&self.boxes32[i])))
                    .map(|i| {
                        let (on, c) = visit(i as u32);
                        (on, usize::from(c))
                    })
                    .collect::<Vec<_>>()
                    .into_iter()
                    .fold((false, 0), |x, y| (x.0 || y.0, x.1 + y.1));
                on || crossings % 2 == 1
            }
            Mode::Bvh => {
                let mut crossings = 0usize;
                let on = self
                    .bvh
                    .for_each_candidate(on_ray, |i| {
                        let (on, c) = visit(i);
                        if on {
                            return ControlFlow::Break(());
                        }
                        crossings += usize::from(c);
                        ControlFlow::Continue(())
                    })
                    .is_break();
                on || crossings % 2 == 1
            }
        }
    }

    /// Whether the closed solids bounded by the two closed meshes share a point: their surfaces
    /// intersect, or one lies wholly inside the other (which [`collides`](Self::collides),
    /// a surface test, does not report). Exact.
    pub fn collides_solid(&self, other: &Collider, mode: Mode) -> bool {
        self.collides(other, mode)
            || self
                .mesh
                .vertices()
                .first()
                .is_some_and(|v| other.contains_point(v, mode))
            || other
                .mesh
                .vertices()
                .first()
                .is_some_and(|v| self.contains_point(v, mode))
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
