//! Clearance and distance under poses: [`Collider::pairs_within_distance_at`],
//! [`Collider::within_distance_at`] and [`Collider::distance_at`]. The descent, the placed
//! leaves and the rounding arguments are those of the [parent module](super) (its section
//! "Clearance and distance").

use std::ops::ControlFlow;

use nalgebra::{Isometry3, Point3};

use super::PosedPair;
use crate::bounding::oriented_boxes::OrientedGaps;
use crate::bounding::placed_leaves::{with_scratch, Placed, Scratch};
use crate::bounding::pose_tree::PoseNode;
use crate::bounding::{box_distance2, boxes_within};
use crate::collider::distance::{check_distance_range, finite, Bounded};
use crate::collider::nearest::{beyond, child_pairs, enqueue, improves, queued, unqueued};
use crate::collider::{Collider, Mode};
use crate::error::Error;
use crate::query::closest_points::triangle_triangle;
use crate::query::separation::{certified_mesh_distance, examine_pair, Open};
use crate::query::within_distance::{triangles_within, trivial};
use crate::query::CertifiedDistance;

type P3 = [f64; 3];

/// The corners of a placed triangle as raw coordinates.
#[inline(always)]
fn corners(p: &Placed) -> [P3; 3] {
    let [a, b, c] = p.tri.vertices();
    [[a.x, a.y, a.z], [b.x, b.y, b.z], [c.x, c.y, c.z]]
}

/// Triangle `i` of `c` placed at `pose` by the expression of
/// [`TriMesh::transformed`](crate::TriMesh::transformed) (bit-identical to the placed mesh's).
fn placed_corners(c: &Collider, pose: &Isometry3<f64>, i: u32) -> [P3; 3] {
    c.mesh().corners(i).map(|v| {
        let w = pose * v;
        [w.x, w.y, w.z]
    })
}

/// A bound on the magnitude of the placed coordinates: a rotation keeps the extent's
/// Euclidean size (at most `√3` times the largest coordinate), and the translation adds to it.
fn pose_magnitude(c: &Collider, pose: &Isometry3<f64>) -> f64 {
    2.0 * c.extent() + pose.translation.vector.amax()
}

impl PosedPair<'_> {
    /// Conservative for clearance `c ≥ 0`: `false` only if no placed triangle under `x` comes
    /// within `c` of one under `y`. `(wa, wb)` are `c` widened for A's and B's frames.
    #[inline(always)]
    fn may_be_within(&self, x: &PoseNode, y: &PoseNode, (wa, wb): (f64, f64)) -> bool {
        self.rel.may_be_within(x, y, wa) && self.inv.may_be_within(y, x, wb)
    }

    /// `c` widened for the tests in A's and in B's frame.
    fn widened(&self, c: f64) -> (f64, f64) {
        (self.rel.widen(c), self.inv.widen(c))
    }

    /// The lower bound on the distance of the placed triangles under two nodes: their
    /// oriented boxes under the relative motion.
    fn oriented_gaps(&self) -> OrientedGaps {
        OrientedGaps::new(
            (self.rel.r, self.rel.t),
            self.rel.margin,
            self.rel.eta,
            (self.a.extent(), self.b.extent()),
            self.a
                .pose_tree()
                .oriented()
                .eta
                .max(self.b.pose_tree().oriented().eta),
        )
    }

    /// The `f64` nearest pair `(i, j)` by best-first branch and bound under the poses, with
    /// the pairs left open (see [`examine_pair`]). Node pairs are ordered and pruned by
    /// their [oriented boxes](Self::oriented_gaps), triangle pairs by the distance of their exact
    /// placed boxes, and each examined pair is handled exactly as in
    /// [`Collider::distance`](crate::collider::Collider::distance), ties included. Both meshes non-empty.
    ///
    /// Only pairs whose `f64` squared distance is at most `cutoff2` are candidates (`+∞`: every
    /// pair): node and triangle pairs proved farther than `cutoff2` are skipped from the start.
    /// `None` when no pair is a candidate; every pair is then proved farther than `cutoff2` or
    /// left in `open`.
    fn nearest(&self, open: &mut Open, cutoff2: f64) -> Option<(u32, u32)> {
        let (ta, tb) = (self.a.pose_tree(), self.b.pose_tree());
        let (na, nb) = (ta.nodes(), tb.nodes());
        let (fa, fb) = (&ta.oriented().boxes[..], &tb.oriented().boxes[..]);
        let gaps = self.oriented_gaps();
        let bound = |s: &mut Scratch, i: u32, j: u32, best: f64| {
            s.oriented_gap2(&gaps, (i, &fa[i as usize]), (j, &fb[j as usize]), best)
        };
        with_scratch(na.len(), nb.len(), |s| {
            let mut best = (cutoff2, u32::MAX, u32::MAX);
            let mut found = false;
            let mut next = Some(queued(bound(s, 0, 0, cutoff2), 0, 0));
            let mut leaf_b: Vec<(u32, [P3; 3], crate::bounding::Aabb)> = Vec::new();
            while let Some((lower, i, j)) = next.take().map(unqueued) {
                if beyond(lower, best.0) {
                    break; // everything left is farther
                }
                let (x, y) = (&na[i as usize], &nb[j as usize]);
                if x.is_leaf() && y.is_leaf() {
                    let la = s.leaf(0, i, x, ta, &self.pose_a);
                    let lb = s.leaf(1, j, y, tb, &self.pose_b);
                    leaf_b.clear();
                    leaf_b.extend(s.placed(lb).iter().map(|q| (q.index, corners(q), q.bounds)));
                    for p in s.placed(la) {
                        let pc = corners(p);
                        for (y, q, by) in &leaf_b {
                            if beyond(box_distance2(&p.bounds, by), best.0) {
                                continue;
                            }
                            let d = examine_pair(p.index, &pc, *y, q, best.0, open);
                            if d <= cutoff2 && (!found || improves(d, p.index, *y, &best)) {
                                best = (d, p.index, *y);
                                found = true;
                            }
                        }
                    }
                    next = s.heap.pop();
                    continue;
                }
                for (ci, cj) in child_pairs(i, x, j, y) {
                    let d = bound(s, ci, cj, best.0);
                    if !beyond(d, best.0) {
                        enqueue(&mut next, &mut s.heap, queued(d, ci, cj));
                    }
                }
                if next.is_none() {
                    next = s.heap.pop();
                }
            }
            found.then_some((best.1, best.2))
        })
    }
}

/// Clearance and distance under poses: `self` at `pose_a`, `other` at `pose_b`. Each answer
/// equals the answer of the same query on [`Collider::placed`] copies (see
/// the pose queries (`collider/poses.rs`, crate-private; its docs are in the source), section "Clearance and distance").
impl Collider {
    /// Every pair `(i, j)` (triangle `i` of `self` at `pose_a`, `j` of `other` at `pose_b`)
    /// within distance `c` of each other, exactly (closed: distance exactly `c` counts), sorted;
    /// the traversal is split over the cores (rayon, feature `parallel`). Equal to
    /// `self.placed(pose_a)?.pairs_within_distance(&other.placed(pose_b)?, c)`,
    /// `c` outside `[0, ∞)` included (NaN and negative: no pair; `+∞`: every pair).
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let (id, moved) = (Isometry3::identity(), Isometry3::translation(1.5, 0.0, 0.0));
    /// // A gap of exactly 0.5, without placing the cube.
    /// assert!(cube.pairs_within_distance_at(&id, &cube, &moved, 0.4)?.is_empty());
    /// let pairs = cube.pairs_within_distance_at(&id, &cube, &moved, 0.5)?;
    /// assert!(!pairs.is_empty());
    /// let placed = cube.placed(&moved).unwrap();
    /// assert_eq!(pairs, cube.pairs_within_distance(&placed, 0.5));
    /// assert!(cube.within_distance_at(&id, &cube, &moved, 0.5)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn pairs_within_distance_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
        c: f64,
    ) -> Result<Vec<(u32, u32)>, Error> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        if trivial(c) == Some(false) {
            return Ok(Vec::new());
        }
        let w = pair.widened(c);
        Ok(pair.all_pairs_where(
            |x, y| pair.may_be_within(x, y, w),
            |p, q| {
                boxes_within(&p.bounds, &q.bounds, c)
                    && triangles_within(&corners(p), &corners(q), c)
            },
        ))
    }

    /// Whether some triangle of `self` at `pose_a` is within distance `c` of some triangle of
    /// `other` at `pose_b`, exactly (stops at the first pair; single-threaded). Equal to
    /// `self.placed(pose_a)?.within_distance(&other.placed(pose_b)?, c)`.
    pub fn within_distance_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
        c: f64,
    ) -> Result<bool, Error> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        if let Some(answer) = trivial(c) {
            return Ok(answer);
        }
        let w = pair.widened(c);
        Ok(pair
            .run_where(
                &[(0, 0)],
                |x, y| pair.may_be_within(x, y, w),
                |p, q| {
                    boxes_within(&p.bounds, &q.bounds, c)
                        && triangles_within(&corners(p), &corners(q), c)
                },
                |_, _| ControlFlow::Break(()),
            )
            .is_break())
    }

    /// The minimum distance between the surfaces of `self` at `pose_a` and `other` at
    /// `pose_b`, with witnesses (world coordinates), the triangle pair and a certified error
    /// bound; `None` if a mesh has no triangles. Equal to
    /// `self.placed(pose_a)?.distance(&other.placed(pose_b)?)`: the same
    /// certified guarantee always, and the same value in every field (distance, witnesses,
    /// pair, bound) unless rounding makes a pair's `f64` distance fall below its true distance
    /// by more than the searches' proofs allow for (see the pose queries (`collider/poses.rs`, crate-private; its docs are in the source), section
    /// "Clearance and distance", for exactly what is equal).
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let (id, moved) = (Isometry3::identity(), Isometry3::translation(1.5, 0.25, 0.0));
    /// let d = cube.distance_at(&id, &cube, &moved)?;
    /// assert!((d.distance - 0.5).abs() <= d.error_bound && d.error_bound < 1e-12);
    /// let placed = cube.placed(&moved).unwrap();
    /// assert_eq!(d, cube.distance(&placed)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn distance_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<CertifiedDistance, Error> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        let magnitude = pose_magnitude(self, pose_a).max(pose_magnitude(other, pose_b));
        check_distance_range(magnitude)?;
        let mut open = Vec::new();
        // With no cutoff the search always finds a pair (both meshes are non-empty).
        let found = pair.nearest(&mut open, f64::INFINITY).unwrap_or((0, 0));
        let d = certified_mesh_distance(
            found,
            &open,
            |x| placed_corners(self, pose_a, x),
            |y| placed_corners(other, pose_b, y),
        );
        finite(d, magnitude)
    }

    /// [`distance_at`](Self::distance_at) when the meshes are nearer than `cutoff` (in `f64`):
    /// the same answer, found by a search that skips everything proved farther than `cutoff`
    /// from the start; otherwise [`Bounded::AtLeast`] with a proved lower bound on their
    /// distance, `cutoff` rounded down by at most a few units in the last place (the few
    /// triangle pairs the search could not prove farther are decided by the exact clearance
    /// test). `cutoff = +∞` is `distance_at`. The running bound of a search over many
    /// pairs (a robot's nearest link pair) goes in as `cutoff`.
    pub(crate) fn distance_below_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
        cutoff: f64,
    ) -> Result<Bounded, Error> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        let magnitude = pose_magnitude(self, pose_a).max(pose_magnitude(other, pose_b));
        check_distance_range(magnitude)?;
        let cutoff = cutoff.max(0.0);
        let cutoff2 = cutoff * cutoff;
        let mut open = Vec::new();
        let Some(found) = pair.nearest(&mut open, cutoff2) else {
            // Every pair not in `open` is proved farther than `cutoff2` (squared): farther than
            // its correctly rounded square root less one ulp. An open pair not within that
            // (exact test) is farther too; one within it keeps only its proved bound.
            let lower = cutoff2.sqrt().next_down().max(0.0);
            let open_lower = open
                .iter()
                .filter(|&&(lb, x, y)| {
                    lb < lower
                        && triangles_within(
                            &placed_corners(self, pose_a, x),
                            &placed_corners(other, pose_b, y),
                            lower,
                        )
                })
                .fold(lower, |m, &(lb, _, _)| m.min(lb));
            return Ok(Bounded::AtLeast(open_lower));
        };
        let d = certified_mesh_distance(
            found,
            &open,
            |x| placed_corners(self, pose_a, x),
            |y| placed_corners(other, pose_b, y),
        );
        finite(d, magnitude).map(Bounded::Below)
    }

    /// Distance 0 when the surfaces of `self` at `pose_a` and `other` at `pose_b` meet, found
    /// without a distance search: the first intersecting triangle pair `(i, j)` of the early-exit
    /// collision test ([`collides_at`](Self::collides_at)'s traversal, stopped there) proves,
    /// exactly, that the distance is 0, so `distance` and `error_bound` are both 0. The
    /// witnesses are the `f64` nearest points of those two placed triangles (each on its
    /// triangle up to rounding, and equal when the `f64` routine finds the triangles meeting).
    /// `Ok(None)` when the surfaces do not meet (poses refused as by
    /// [`collides_at`](Self::collides_at)); meeting surfaces out of the range of
    /// [`distance_at`](Self::distance_at) are refused as it refuses them.
    pub(crate) fn touching_distance_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Option<CertifiedDistance>, Error> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        let first = if self.mode() == Mode::Brute {
            let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
            a.intersecting_pairs(&b).first().copied()
        } else {
            match pair.run(&[(0, 0)], |i, j| ControlFlow::Break((i, j))) {
                ControlFlow::Break(found) => Some(found),
                ControlFlow::Continue(()) => None,
            }
        };
        if first.is_some() {
            // Refused where `distance_at` refuses; surfaces that do not meet are answered
            // wherever `collides_at` answers.
            let magnitude = pose_magnitude(self, pose_a).max(pose_magnitude(other, pose_b));
            check_distance_range(magnitude)?;
        }
        Ok(first.map(|(i, j)| {
            let (s, t) = (
                placed_corners(self, pose_a, i),
                placed_corners(other, pose_b, j),
            );
            let (_, x, y) = triangle_triangle(&s, &t);
            CertifiedDistance {
                distance: 0.0,
                error_bound: 0.0,
                witness_a: Point3::from(x),
                witness_b: Point3::from(y),
                triangles: Some((i, j)),
            }
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::exact_distance_triangle_triangle;
    use crate::TriMesh;
    use ga_core::scalar::{rational_from_f64, Rational};
    use nalgebra::{Point3, Vector3};
    use proptest::prelude::*;

    /// The least `f64` `c` with the placed meshes within `c` (the exact distance rounded up).
    fn threshold(a: &Collider, b: &Collider) -> f64 {
        let d = a.distance(b).unwrap();
        let (mut lo, mut hi) = (
            (d.distance - d.error_bound).max(0.0),
            d.distance + d.error_bound,
        );
        assert!(a.within_distance(b, hi));
        if a.within_distance(b, lo) {
            return lo;
        }
        // Bisection on the bit patterns (ordered like the values for non-negative floats).
        while hi.to_bits() - lo.to_bits() > 1 {
            let mid = f64::from_bits(lo.to_bits() + (hi.to_bits() - lo.to_bits()) / 2);
            if a.within_distance(b, mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }

    /// Leaf positions `[s, e)` under each node (every node covers a contiguous range).
    fn ranges(c: &Collider) -> Vec<(usize, usize)> {
        let nodes = c.pose_tree().nodes();
        fn go(nodes: &[PoseNode], i: usize, out: &mut [(usize, usize)]) -> (usize, usize) {
            let n = &nodes[i];
            let r = if n.is_leaf() {
                (n.start as usize, (n.start + n.count) as usize)
            } else {
                let (l, r) = (
                    go(nodes, n.start as usize, out),
                    go(nodes, n.start as usize + 1, out),
                );
                assert_eq!(l.1, r.0, "children cover adjacent ranges");
                (l.0, r.1)
            };
            out[i] = r;
            r
        }
        let mut out = vec![(0, 0); nodes.len()];
        go(nodes, 0, &mut out);
        out
    }

    fn soup(seed: u64, n: usize) -> TriMesh {
        super::super::tests::soup(seed, n, 1.0, 0.3, false)
    }

    fn pose(t: [f64; 3], r: [f64; 3]) -> Isometry3<f64> {
        Isometry3::new(Vector3::from(t), Vector3::from(r))
    }

    proptest! {
        // Exact rational distances cost about 10 ms a pair: few cases.
        #![proptest_config(ProptestConfig::with_cases(8))]

        /// For every pair of nodes, the lower bound is at most the exact squared distance of
        /// every pair of placed triangles under them, and the clearance test keeps the node
        /// pair at that exact distance rounded up.
        #[test]
        fn node_bounds_hold_for_every_node_pair(
            seed in any::<u64>(),
            ta in prop::array::uniform3(-2.0f64..2.0), ra in prop::array::uniform3(-3.0f64..3.0),
            tb in prop::array::uniform3(-2.0f64..2.0), rb in prop::array::uniform3(-3.0f64..3.0),
        ) {
            let a = Collider::new(soup(seed, 8));
            let b = Collider::new(soup(seed ^ 0x77, 6));
            let (pa, pb) = (pose(ta, ra), pose(tb, rb));
            let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
            let (ka, kb) = (a.pose_tree(), b.pose_tree());
            // Exact squared distances of the placed triangles, by leaf positions.
            let exact: Vec<Vec<Rational>> = (0..8)
                .map(|p| {
                    (0..6)
                        .map(|q| {
                            exact_distance_triangle_triangle(
                                &wa.triangle(ka.index(p)),
                                &wb.triangle(kb.index(q)),
                            )
                            .distance2
                        })
                        .collect()
                })
                .collect();
            // Rank the pairs by exact distance once, and round each distance up to an f64.
            let mut order: Vec<(usize, usize)> =
                (0..8).flat_map(|p| (0..6).map(move |q| (p, q))).collect();
            order.sort_by(|&(p, q), &(r, s)| exact[p][q].cmp(&exact[r][s]));
            let mut rank = vec![vec![0usize; 6]; 8];
            for (k, &(p, q)) in order.iter().enumerate() {
                rank[p][q] = k;
            }
            let up = |x: &Rational| {
                let mut c = ga_core::scalar::Real::to_f64(x).sqrt();
                while &(rational_from_f64(c).unwrap() * rational_from_f64(c).unwrap()) < x {
                    c = c.next_up();
                }
                c
            };
            let pair = PosedPair::new(&a, &pa, &b, &pb).unwrap();
            let gaps = pair.oriented_gaps();
            let (na, nb) = (ka.nodes(), kb.nodes());
            let (ra_, rb_) = (ranges(&a), ranges(&b));
            for (ix, (x, &(xs, xe))) in na.iter().zip(&ra_).enumerate() {
                for (iy, (y, &(ys, ye))) in nb.iter().zip(&rb_).enumerate() {
                    let k = (xs..xe)
                        .flat_map(|p| (ys..ye).map(move |q| (p, q)))
                        .map(|(p, q)| rank[p][q])
                        .min()
                        .unwrap();
                    let (p, q) = order[k];
                    let lb = gaps.gap2(&ka.oriented().boxes[ix], &kb.oriented().boxes[iy]);
                    let lb = rational_from_f64(lb).unwrap();
                    prop_assert!(lb <= exact[p][q]);
                    // The nearest pair under them is within its exact distance rounded up.
                    prop_assert!(pair.may_be_within(x, y, pair.widened(up(&exact[p][q]))));
                }
            }
        }
    }

    /// Without the rounding margin the node tests are wrong: cubes facing each other far from
    /// the origin (where placing rounds coordinates by about `1e-10`) are pruned at their exact
    /// distance, and the lower bound exceeds it; with the margin, never.
    #[test]
    fn the_rounding_margin_matters() {
        let a =
            Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap());
        let root = &a.pose_tree().nodes()[0];
        let frame = &a.pose_tree().oriented().boxes[0];
        let (mut pruned, mut above) = (0, 0);
        for k in 0..48 {
            let kf = k as f64;
            let pa = pose(
                [1048576.3 + 0.37 * kf, 0.1 * kf, -7.0],
                [0.1 * kf, 0.2, 0.3],
            );
            // B beside A along A's x axis, a gap of about 0.5.
            let pb = pa * pose([1.5 + 1e-3 * kf, 0.2, 0.1], [0.0, 0.0, 0.0]);
            let (wa, wb) = (a.placed(&pa).unwrap(), a.placed(&pb).unwrap());
            let c = threshold(&wa, &wb);
            let pair = PosedPair::new(&a, &pa, &a, &pb).unwrap();
            assert!(pair.may_be_within(root, root, pair.widened(c)));
            assert!(pair.oriented_gaps().gap2(frame, frame).sqrt() <= c);
            assert!(a.within_distance_at(&pa, &a, &pb, c).unwrap());
            let mut bare = PosedPair::new(&a, &pa, &a, &pb).unwrap();
            bare.rel.margin = 0.0;
            bare.inv.margin = 0.0;
            pruned += usize::from(!bare.may_be_within(root, root, bare.widened(c)));
            let bare_gap2 = bare.oriented_gaps().without_allowance().gap2(frame, frame);
            above += usize::from(bare_gap2.sqrt() > c * (1.0 + 1e-12));
        }
        assert!(pruned > 0 && above > 0, "{pruned} {above}");
    }
}
