//! Queries under poses: a [`Collider`] built once in its own frame answers for any rigid pose
//! (`nalgebra::Isometry3<f64>`) with no work proportional to the mesh size, and every answer is
//! **identical** to placing the mesh first ([`Collider::placed`]) and asking the placed copy
//! (for [`Collider::distance_at`], see exactly what is equal in "Clearance and distance").
//!
//! # How
//! * Mesh against mesh: the two hierarchies are descended together under the relative motion.
//!   Each node is read as a centre and half-extents (`pose_tree`: one 64-byte cache line per
//!   node). B's box is carried into A's frame by a rounded relative transform and tested on
//!   A's three axes, then A's box into B's frame on B's three axes (the six face axes of the
//!   separating-axis test of two oriented boxes); each test is widened by a margin that bounds
//!   every rounding on the way (below), so no pair of triangles that meets after placing is
//!   ever pruned.
//! * Mesh against a shape: each box of the hierarchy is carried into the world by the pose,
//!   widened the same way, and tested against the shape.
//! * Clearance and distance: the same descent, with the relative box test widened by the
//!   clearance, or turned into a lower bound on the distance (section "Clearance and
//!   distance").
//! * At the leaves, only the candidate triangles are transformed, with **the very expression
//!   `pose * v` that [`TriMesh::transformed`](crate::TriMesh::transformed) uses**, so they are
//!   bit-identical to the placed mesh's triangles; the placed query's exact box filter and exact
//!   test then decide, on the same numbers. The vertices are read from a copy in leaf order
//!   (contiguous), and each leaf is placed at most once per traversal, in scratch memory each
//!   thread keeps from one query to the next (no allocation per pose once it has grown; 8 bytes
//!   per node of the largest trees the thread has met, 128 per triangle placed in its largest
//!   traversal, and 16 per node pair queued by its largest distance search).
//!
//! # The rounding bound
//! Proved in [`crate::bounding::pose_bounds`] (crate-private; its docs are in the source): every
//! box test under a pose is widened by a margin that pays for every rounding on the way.
//!
//! # Clearance and distance
//! [`Collider::pairs_within_distance_at`], [`Collider::within_distance_at`] and
//! [`Collider::distance_at`] run on the same descent, placed leaves and relative boxes; only
//! the node test changes.
//! * **Clearance `c`** (`0 ≤ c < ∞`; other `c` are answered as by
//!   [`Collider::pairs_within_distance`](crate::collider::Collider::pairs_within_distance) without a
//!   descent). If placed points `x`, `y` of the two meshes have `|x - y| ≤ c`, then on axis `i`
//!   of A's frame the two points `D x - D τ_A` and `D y - D τ_A` of the boxes above differ by
//!   `|Dᵢ · (x - y)| ≤ |Dᵢ|₂ c`, where `Dᵢ` is row `i` of `D`. As `D = M̂_Aᵀ`,
//!   `|Dᵢ|₂² = (D M̂_A)ᵢᵢ ≤ 1 + η_A` with `η_A` the bound on `|D M̂_A - I|` that `r_A` is built
//!   from (it includes the rounding of the computed product). So each axis test is widened by
//!   `w = fl(fl(c · fl(1 + η_A)) · (1 + 2⁻⁴⁸)) ≥ c (1 + η_A)(1 - u)³(1 + 32u) ≥ c √(1 + η_A)
//!   (1 + 16u)`: the `16u c √(1 + η_A)` beyond the need pays for the rounding that the new term
//!   adds to the sum (as the `16u` allowance does for the others), and an underflow of `w` is
//!   paid by the margin's `2⁻¹⁰⁰⁰`. Likewise in B's frame. At the leaves, the placed triangles
//!   (bit-identical to the placed mesh's) go through the placed query's conservative box
//!   filter and its exact clearance test. So the pairs found are exactly the pairs within `c`,
//!   as the placed query's are: the lists are **identical**, and so are the booleans.
//! * **CertifiedDistance.** With the same notation, a placed point of A's node lies within `r_A` (per
//!   coordinate of A's frame `D (x - τ_A)`) of any convex set holding the node's local
//!   triangles, and a placed point of B's node within `r_B` of `R̂` times such a set plus `t̂`.
//!   The sets used are the nodes' oriented boxes (fitted to the geometry, so that turned parts
//!   keep tight bounds), and the lower bound on `|x - y|²` from their gaps on the six box axes,
//!   every rounding paid, is proved in the module `oriented_boxes` (crate-private; its docs
//!   are in the source). It orders a best-first search over node pairs, as
//!   [`Collider::distance`](crate::collider::Collider::distance) does with the same boxes in one frame;
//!   triangle pairs are examined, pruned and certified by the very code of `distance`, on
//!   the placed triangles.
//!
//! **What `distance_at` has in common with `distance` on the placed copies.** Always: the
//! same certified guarantee — the true distance of the placed meshes lies in
//! `[distance - error_bound, distance + error_bound]`, the witnesses are the `f64` nearest
//! points of the triangle pair reported, on the placed mesh's coordinates, and that pair's
//! `f64` distance is `distance`. Both searches keep, among the pairs they examine, the least
//! `f64` squared distance, and among equal ones the smallest pair `(i, j)`; both skip only
//! pairs **proved** farther than the best so far. The error bound is a function of that pair
//! and of the meshes alone (the lower end is decided over all pairs, see
//! [`Collider::distance`](crate::collider::Collider::distance)). So the two results are **identical in every
//! field** unless a pair's `f64` squared distance is at or below the result while its true
//! distance is above it (rounding of the `f64` closest-points routine, so a near-tie at the
//! level of the last bits); only then may the two searches, which visit pairs in different
//! orders, report different pairs of that near-tie, each with its own certified bound. No test
//! has met such a case (the agreement tests compare every field, ties of dyadic cubes included).
//!
//! Poses whose quaternion is far from unit (`|q|²` outside `[1/2, 2]`), non-finite poses, and
//! meshes or translations so large that the bounds could overflow (`|coordinate| ≥ 2⁹⁹⁰`) get a
//! [`Error`] instead of an answer.
//!
//! ```
//! use cga_collide::collider::{Collider, Mode};
//! use cga_collide::{nalgebra::{Isometry3, Vector3}, TriMesh};
//! let a = Collider::new(TriMesh::bunny().unit());
//! let b = Collider::new(TriMesh::bunny().unit());
//! let pa = Isometry3::identity();
//! let pb = Isometry3::new(Vector3::new(0.3, 0.05, 0.0), Vector3::new(0.0, 0.5, 0.0));
//! let pairs = a.intersecting_pairs_at(&pa, &b, &pb)?;
//! // Identical to placing both meshes first:
//! let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
//! assert_eq!(pairs, wa.intersecting_pairs(&wb));
//! assert_eq!(a.collides_at(&pa, &b, &pb)?, !pairs.is_empty());
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod distance;

use std::ops::ControlFlow;

use ga_core::scalar::Rational;
use nalgebra::{Isometry3, Point3};

use crate::bounding::placed_leaves::{place, with_scratch, Placed, Scratch};
use crate::bounding::pose_bounds::{PoseMap, Relative, WorldBoxes};
use crate::bounding::pose_tree::PoseNode;
use crate::bounding::{Aabb, Bvh};
use crate::collider::{Collider, Mode};
use crate::error::Error;
use crate::parallel::*;
use crate::query::{ray_crosses_triangle, segment_triangle_entry};
use crate::{Ball, Intersects, Segment, Sphere, Triangle};

/// Two colliders under their poses, ready to be traversed together.
struct PosedPair<'a> {
    a: &'a Collider,
    b: &'a Collider,
    pose_a: Isometry3<f64>,
    pose_b: Isometry3<f64>,
    /// B's boxes in A's frame.
    rel: Relative,
    /// A's boxes in B's frame (the other three face axes of the separating-axis test).
    inv: Relative,
}

impl<'a> PosedPair<'a> {
    fn new(
        a: &'a Collider,
        pose_a: &Isometry3<f64>,
        b: &'a Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<PosedPair<'a>, Error> {
        let pa = PoseMap::new(pose_a)?;
        let pb = PoseMap::new(pose_b)?;
        pa.check_range(a.extent())?;
        pb.check_range(b.extent())?;
        let rel = Relative::new(&pa, a.extent(), &pb, b.extent());
        let inv = Relative::new(&pb, b.extent(), &pa, a.extent());
        Ok(PosedPair {
            a,
            b,
            pose_a: *pose_a,
            pose_b: *pose_b,
            rel,
            inv,
        })
    }

    /// `false` only if nothing placed under node `x` of A meets anything placed under node
    /// `y` of B: B's box tested in A's frame, then A's box in B's frame (the six face axes of
    /// the separating-axis test).
    #[inline(always)]
    fn may_overlap(&self, x: &PoseNode, y: &PoseNode) -> bool {
        self.rel.may_overlap(x, y) && self.inv.may_overlap(y, x)
    }

    /// How deeply the boxes of nodes `x` of A and `y` of B overlap (the least slack of the
    /// six axis tests, [`Relative::depth`]): orders the descent of a first-hit search, never
    /// decides anything.
    #[inline(always)]
    fn depth(&self, x: &PoseNode, y: &PoseNode) -> f64 {
        self.rel.depth(x, y).min(self.inv.depth(y, x))
    }

    /// Whether two placed triangles meet (exact), behind a test of their exact boxes.
    #[inline(always)]
    fn meet(p: &Placed, q: &Placed) -> bool {
        p.bounds.overlaps(&q.bounds) && p.tri.intersects(&q.tri)
    }

    /// The descent below the node pairs on `scratch.stack`, each of which has passed `near`:
    /// node pairs failing `near` are pruned, and `visit(i, j)` gets every pair of placed
    /// triangles passing `keep`; stops when `visit` breaks. `near` must be conservative for
    /// `keep` (module docs). With `deepest_first`, of two child pairs that both pass, the one
    /// whose boxes overlap more deeply is descended first: a search that stops at its first
    /// hit reaches one sooner where the meshes interpenetrate (what it finds may differ, not
    /// whether it finds one).
    fn traverse_where<B>(
        &self,
        scratch: &mut Scratch,
        deepest_first: bool,
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
        mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let (ta, tb) = (self.a.pose_tree(), self.b.pose_tree());
        let (na, nb) = (ta.nodes(), tb.nodes());
        while let Some((i, j)) = scratch.stack.pop() {
            let (x, y) = (&na[i as usize], &nb[j as usize]);
            let split_a = match (x.is_leaf(), y.is_leaf()) {
                (true, true) => {
                    // Leaves meet many leaves of the other tree: each is placed once per
                    // traversal.
                    let la = scratch.leaf(0, i, x, ta, &self.pose_a);
                    let lb = scratch.leaf(1, j, y, tb, &self.pose_b);
                    let (pa, pb) = (scratch.placed(la), scratch.placed(lb));
                    for p in pa {
                        for q in pb {
                            if keep(p, q) {
                                visit(p.index, q.index)?;
                            }
                        }
                    }
                    continue;
                }
                (false, true) => true,
                (true, false) => false,
                (false, false) => x.size >= y.size,
            };
            // Both children are read and tested together, before either is queued: their
            // two node reads (adjacent cache lines) overlap instead of waiting one after the
            // other, and pruned pairs never reach the stack.
            let stack = &mut scratch.stack;
            if split_a {
                let s = x.start;
                let (c0, c1) = (&na[s as usize], &na[s as usize + 1]);
                let (k0, k1) = (near(c0, y), near(c1, y));
                if k0 && k1 && deepest_first && self.depth(c1, y) > self.depth(c0, y) {
                    stack.extend([(s, j), (s + 1, j)]);
                    continue;
                }
                if k1 {
                    stack.push((s + 1, j));
                }
                if k0 {
                    stack.push((s, j));
                }
            } else {
                let s = y.start;
                let (c0, c1) = (&nb[s as usize], &nb[s as usize + 1]);
                let (k0, k1) = (near(x, c0), near(x, c1));
                if k0 && k1 && deepest_first && self.depth(x, c1) > self.depth(x, c0) {
                    stack.extend([(i, s), (i, s + 1)]);
                    continue;
                }
                if k1 {
                    stack.push((i, s + 1));
                }
                if k0 {
                    stack.push((i, s));
                }
            }
        }
        ControlFlow::Continue(())
    }

    /// The search for intersecting pairs from the node pairs `start`, deepest overlap first,
    /// with this thread's scratch memory (for a `visit` that stops at its first pair).
    fn run<B>(
        &self,
        start: &[(u32, u32)],
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.run_ordered(
            start,
            true,
            |x, y| self.may_overlap(x, y),
            Self::meet,
            visit,
        )
    }

    /// [`traverse_where`](Self::traverse_where) from the node pairs `start` with this
    /// thread's scratch memory.
    fn run_where<B>(
        &self,
        start: &[(u32, u32)],
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.run_ordered(start, false, near, keep, visit)
    }

    /// [`run_where`](Self::run_where), descending deepest overlap first if `deepest_first`.
    fn run_ordered<B>(
        &self,
        start: &[(u32, u32)],
        deepest_first: bool,
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let (na, nb) = (self.a.pose_tree().nodes(), self.b.pose_tree().nodes());
        with_scratch(na.len(), nb.len(), |scratch| {
            let seeds = start.iter().copied();
            scratch
                .stack
                .extend(seeds.filter(|&(i, j)| near(&na[i as usize], &nb[j as usize])));
            self.traverse_where(scratch, deepest_first, near, keep, visit)
        })
    }

    /// Every intersecting pair below the node pairs `start`, unsorted.
    fn collect_pairs(&self, start: &[(u32, u32)]) -> Vec<(u32, u32)> {
        self.collect_pairs_where(start, |x, y| self.may_overlap(x, y), Self::meet)
    }

    /// Every pair passing `keep` below the node pairs `start` (pruned by `near`), unsorted.
    fn collect_pairs_where(
        &self,
        start: &[(u32, u32)],
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
    ) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        let _ = self.run_where::<()>(start, near, keep, |i, j| {
            out.push((i, j));
            ControlFlow::Continue(())
        });
        out
    }

    /// Every pair passing `keep` (pruned by `near`), sorted, the traversal split over the
    /// cores (rayon, feature `parallel`).
    fn all_pairs_where(
        &self,
        near: impl Fn(&PoseNode, &PoseNode) -> bool + Sync,
        keep: impl Fn(&Placed, &Placed) -> bool + Sync,
    ) -> Vec<(u32, u32)> {
        let threads = cores();
        let mut out = if threads <= 1 {
            self.collect_pairs_where(&[(0, 0)], &near, &keep)
        } else {
            let tasks = self.split_where(threads * TASKS_PER_CORE, &near);
            tasks
                .par_iter()
                .flat_map_iter(|&task| self.collect_pairs_where(&[task], &near, &keep))
                .collect()
        };
        out.sort_unstable();
        out
    }

    /// Node pairs covering the whole traversal pruned by `near`, at least `want` of them when
    /// the trees allow (breadth-first split of the root pair), for spreading over the cores.
    fn split_where(
        &self,
        want: usize,
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
    ) -> Vec<(u32, u32)> {
        let (na, nb) = (self.a.pose_tree().nodes(), self.b.pose_tree().nodes());
        let mut level = vec![(0u32, 0u32)];
        for _ in 0..64 {
            if level.len() >= want {
                break;
            }
            let mut next = Vec::with_capacity(level.len() * 2);
            let mut grew = false;
            for &(i, j) in &level {
                let (x, y) = (&na[i as usize], &nb[j as usize]);
                if !near(x, y) {
                    continue;
                }
                let split_a = match (x.is_leaf(), y.is_leaf()) {
                    (true, true) => {
                        next.push((i, j));
                        continue;
                    }
                    (false, true) => true,
                    (true, false) => false,
                    (false, false) => x.size >= y.size,
                };
                grew = true;
                if split_a {
                    let s = x.start;
                    next.extend([(s, j), (s + 1, j)]);
                } else {
                    let s = y.start;
                    next.extend([(i, s), (i, s + 1)]);
                }
            }
            level = next;
            if !grew {
                break;
            }
        }
        level
    }
}

/// Node pairs per core in the parallel all-pairs traversal.
const TASKS_PER_CORE: usize = 16;

fn cores() -> usize {
    #[cfg(feature = "parallel")]
    {
        rayon::current_num_threads()
    }
    #[cfg(not(feature = "parallel"))]
    {
        1
    }
}

/// Pose queries: `self` at `pose`, the other mesh (if any) at its own pose. Each answer equals
/// the answer of the same query on [`Collider::placed`] copies (see the pose queries (`collider/poses.rs`, crate-private; its docs are in the source)).
impl Collider {
    /// Whether any triangle of `self` placed at `pose_a` meets any triangle of `other` placed
    /// at `pose_b` (stops at the first hit; single-threaded). Equal to
    /// `self.placed(pose_a)?.collides(&other.placed(pose_b)?, mode)`.
    pub fn collides_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<bool, Error> {
        if self.mode() == Mode::Brute {
            let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
            return Ok(a.collides(&b));
        }
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        Ok(pair
            .run(&[(0, 0)], |_, _| ControlFlow::Break(()))
            .is_break())
    }

    /// Every intersecting pair `(i, j)` (triangle `i` of `self` at `pose_a`, `j` of `other` at
    /// `pose_b`), sorted; the traversal is split over the cores (rayon, feature `parallel`).
    /// Equal to `self.placed(pose_a)?.intersecting_pairs(&other.placed(pose_b)?, mode)`.
    pub fn intersecting_pairs_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Vec<(u32, u32)>, Error> {
        if self.mode() == Mode::Brute {
            let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
            return Ok(a.intersecting_pairs(&b));
        }
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        Ok(pair.all_pairs_where(|x, y| pair.may_overlap(x, y), PosedPair::meet))
    }

    /// Like [`intersecting_pairs_at`](Self::intersecting_pairs_at) on the calling thread only
    /// (what the batch queries run per pose).
    pub(crate) fn intersecting_pairs_at_sequential(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Vec<(u32, u32)>, Error> {
        if self.mode() == Mode::Brute {
            return self.intersecting_pairs_at(pose_a, other, pose_b);
        }
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        let mut out = pair.collect_pairs(&[(0, 0)]);
        out.sort_unstable();
        Ok(out)
    }

    /// Whether the solids bounded by the two closed meshes, at their poses, share a point
    /// (surfaces meet, or one lies wholly inside the other). Equal to
    /// [`collides_solid`](Self::collides_solid) on the placed copies.
    pub fn collides_solid_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<bool, Error> {
        if self.collides_at(pose_a, other, pose_b)? {
            return Ok(true);
        }
        // The first placed vertex of each, placed by the same expression as `placed()`.
        let first =
            |c: &Collider, pose: &Isometry3<f64>| c.mesh().vertices().first().map(|v| pose * v);
        if let Some(v) = first(self, pose_a) {
            if other.contains_point_at(pose_b, &v)? {
                return Ok(true);
            }
        }
        if let Some(v) = first(other, pose_b) {
            if self.contains_point_at(pose_a, &v)? {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// Whether the world point `p` lies in the closed solid bounded by this mesh placed at
    /// `pose`. Equal to [`contains_point`](Self::contains_point) on the placed copy.
    pub fn contains_point_at(&self, pose: &Isometry3<f64>, p: &Point3<f64>) -> Result<bool, Error> {
        let world = self.world_boxes(pose)?;
        if self.mode() == Mode::Brute {
            return Ok(self.placed(pose)?.contains_point(p));
        }
        let Ok(point) = Segment::new(*p, *p) else {
            return Ok(false);
        };
        let on_ray = |b: &Aabb| b.meets_x_ray(p);
        let mut crossings = 0usize;
        let on = self
            .posed_candidates(&world, pose, on_ray, |t| {
                if t.tri.intersects(&point) {
                    return ControlFlow::Break(());
                }
                crossings += usize::from(ray_crosses_triangle(t.tri.vertices(), p));
                ControlFlow::Continue(())
            })
            .is_break();
        Ok(on || crossings % 2 == 1)
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the world segment meets.
    pub fn segment_hits_at(&self, pose: &Isometry3<f64>, s: &Segment) -> Result<Vec<u32>, Error> {
        let (p, q) = (*s.a(), *s.b());
        self.hits_at(
            pose,
            |b| b.may_meet_segment(&p, &q),
            |t| t.intersects(s),
            |c| c.segment_hits(s),
        )
    }

    /// Where the world segment `s` first meets this mesh at `pose`: the triangle and the exact
    /// parameter `t ∈ [0, 1]` of the first point `s.a() + t (s.b() − s.a())` on the placed
    /// surface ([`segment_triangle_entry`] of each triangle
    /// [`segment_hits_at`](Self::segment_hits_at) reports; ties to the smaller triangle index).
    /// `None` when the segment misses the surface.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, Segment, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let pose = Isometry3::translation(2.0, 0.0, 0.0); // x from 2 to 3
    /// let s = Segment::new(Point3::new(0.0, 0.5, 0.5), Point3::new(4.0, 0.5, 0.5))?;
    /// let (_, t) = cube.first_segment_hit_at(&pose, &s)?.expect("a hit");
    /// assert_eq!(t.to_string(), "1/2"); // at x = 2
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn first_segment_hit_at(
        &self,
        pose: &Isometry3<f64>,
        s: &Segment,
    ) -> Result<Option<(u32, Rational)>, Error> {
        let hits = self.segment_hits_at(pose, s)?;
        let mut first: Option<(u32, Rational)> = None;
        for i in hits {
            // The placed triangle by the expression `placed()` uses: the triangle that was hit.
            let [a, b, c] = self.mesh().corners(i).map(|v| pose * v);
            let Some(t) = Triangle::new(a, b, c)
                .ok()
                .and_then(|tri| segment_triangle_entry(s, &tri))
            else {
                continue; // unreachable: the same exact test said it meets
            };
            if first.as_ref().is_none_or(|(_, best)| t < *best) {
                first = Some((i, t));
            }
        }
        Ok(first)
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the world triangle meets.
    pub fn triangle_hits_at(&self, pose: &Isometry3<f64>, t: &Triangle) -> Result<Vec<u32>, Error> {
        let tb = Aabb::of_points(t.vertices());
        self.hits_at(
            pose,
            |b| b.overlaps(&tb),
            |u| u.intersects(t),
            |c| c.triangle_hits(t),
        )
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the sphere surface meets.
    pub fn sphere_hits_at(&self, pose: &Isometry3<f64>, s: &Sphere) -> Result<Vec<u32>, Error> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits_at(
            pose,
            |b| b.may_meet_sphere(&c, r),
            |t| t.intersects(s),
            |m| m.sphere_hits(s),
        )
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the solid ball meets.
    pub fn ball_hits_at(&self, pose: &Isometry3<f64>, s: &Ball) -> Result<Vec<u32>, Error> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits_at(
            pose,
            |b| b.may_meet_ball(&c, r),
            |t| t.intersects(s),
            |m| m.ball_hits(s),
        )
    }

    /// A world box holding this mesh placed at `pose` (conservative: every placed vertex, as
    /// `placed()` rounds it, lies inside); what a broad phase sorts.
    pub(crate) fn world_box(&self, pose: &Isometry3<f64>) -> Result<Aabb, Error> {
        Ok(self.world_boxes(pose)?.world(&self.bvh().bounds()))
    }

    pub(super) fn world_boxes(&self, pose: &Isometry3<f64>) -> Result<WorldBoxes, Error> {
        let map = PoseMap::new(pose)?;
        map.check_range(self.extent())?;
        Ok(WorldBoxes::new(&map, self.extent()))
    }

    /// Both meshes placed by their poses, for [`Mode::Brute`]. The poses are checked first
    /// exactly as the tree path checks them, so both modes refuse the same poses.
    pub(crate) fn placed_pair(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<(Collider, Collider), Error> {
        PosedPair::new(self, pose_a, other, pose_b)?;
        Ok((self.placed(pose_a)?, other.placed(pose_b)?))
    }

    fn hits_at(
        &self,
        pose: &Isometry3<f64>,
        test: impl Fn(&Aabb) -> bool,
        hit: impl Fn(&Triangle) -> bool,
        same_frame: impl Fn(&Collider) -> Vec<u32>,
    ) -> Result<Vec<u32>, Error> {
        let world = self.world_boxes(pose)?;
        if self.mode() == Mode::Brute {
            return Ok(same_frame(&self.placed(pose)?));
        }
        let mut out = Vec::new();
        let _ = self.posed_candidates::<()>(&world, pose, test, |t| {
            if hit(&t.tri) {
                out.push(t.index);
            }
            ControlFlow::Continue(())
        });
        out.sort_unstable();
        Ok(out)
    }

    /// Calls `visit` with every placed triangle whose (exact, placed) box passes `test`,
    /// reached through nodes whose conservative world boxes pass `test`.
    pub(super) fn posed_candidates<B>(
        &self,
        world: &WorldBoxes,
        pose: &Isometry3<f64>,
        test: impl Fn(&Aabb) -> bool,
        mut visit: impl FnMut(&Placed) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let bvh: &Bvh = self.bvh();
        let nodes = bvh.nodes();
        let mut stack = Vec::with_capacity(64);
        stack.push(0usize);
        while let Some(i) = stack.pop() {
            let node = &nodes[i];
            if !test(&world.world(&node.bounds)) {
                continue;
            }
            let s = node.start as usize;
            if node.is_leaf() {
                for k in s..s + node.count as usize {
                    let placed = place(self.pose_tree(), k, pose);
                    if test(&placed.bounds) {
                        visit(&placed)?;
                    }
                }
            } else {
                stack.push(s + 1);
                stack.push(s);
            }
        }
        ControlFlow::Continue(())
    }

    /// [`posed_candidates`](Self::posed_candidates) nearest first (see
    /// [`Bvh::for_each_nearest_first`]): nodes by the `gap` of their world boxes, triangles by
    /// that of their placed boxes, none beyond `bound()`.
    pub(super) fn posed_nearest_first<B>(
        &self,
        world: &WorldBoxes,
        pose: &Isometry3<f64>,
        gap: impl Fn(&Aabb) -> f64,
        bound: impl Fn() -> f64,
        mut visit: impl FnMut(&Placed) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        crate::bounding::nearest_first(
            self.bvh().nodes(),
            |node| gap(&world.world(&node.bounds)),
            bound,
            |k| {
                let placed = place(self.pose_tree(), k, pose);
                (gap(&placed.bounds), placed)
            },
            |_, placed| visit(&placed),
        )
    }
}

#[cfg(test)]
pub(crate) mod tests;
