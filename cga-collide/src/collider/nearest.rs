//! The best-first search behind mesh distance: two box hierarchies descended together, node pairs
//! ordered by a proved lower bound on their distance. The pair enumerations (within a distance,
//! or one mesh against itself) are [`Bvh`](crate::bounding::Bvh)'s. The search reads the
//! colliders' pose layout (nodes, oriented boxes, vertices in leaf order).

use std::collections::BinaryHeap;

use crate::bounding::oriented_boxes::OrientedGaps;
use crate::bounding::pose_tree::{PoseNode, PoseTree};
use crate::bounding::{box_distance2, Aabb, MAX_LEAF};
use crate::collider::Collider;

/// Whether a pair `(i, j)` at `f64` squared distance `d2` replaces `best` in the nearest-pair
/// search: nearer, or as near with a smaller `(i, j)`. The winner among equal distances then
/// does not depend on the order of the search (so placed and pose queries agree).
#[inline(always)]
pub(crate) fn improves(d2: f64, i: u32, j: u32, best: &(f64, u32, u32)) -> bool {
    d2 < best.0 || (d2 == best.0 && (i, j) < (best.1, best.2))
}

/// Whether a pair whose squared distance is at least `lower` (up to the rounding of a box
/// distance) can be skipped: `lower` exceeds `best` with a relative margin `1e-9`, far above
/// the boxes' rounding, so every skipped pair is truly farther than `best`.
#[inline(always)]
pub(crate) fn beyond(lower: f64, best: f64) -> bool {
    lower * (1.0 - 1e-9) > best
}

/// A node pair `(i, j)` with the lower bound `d2` on its squared distance, packed for a
/// max-heap that pops the least bound first (ties: the larger pair first). Squared distances
/// are never negative (nor NaN), so their bit patterns order like the values, and one integer
/// comparison orders the entries.
#[inline(always)]
pub(crate) fn queued(d2: f64, i: u32, j: u32) -> u128 {
    (u128::from(!d2.to_bits()) << 64) | (u128::from(i) << 32) | u128::from(j)
}

/// The bound and the pair of a [`queued`] entry.
#[inline(always)]
pub(crate) fn unqueued(e: u128) -> (f64, u32, u32) {
    (
        f64::from_bits(!((e >> 64) as u64)),
        (e >> 32) as u32,
        e as u32,
    )
}

/// The two child pairs of a node pair `(i, j)` that is not a pair of leaves: the larger node
/// (by box area) is split, a leaf never.
#[inline(always)]
pub(crate) fn child_pairs(i: u32, x: &PoseNode, j: u32, y: &PoseNode) -> [(u32, u32); 2] {
    if !x.is_leaf() && (y.is_leaf() || x.size >= y.size) {
        [(x.start, j), (x.start + 1, j)]
    } else {
        [(i, y.start), (i, y.start + 1)]
    }
}

/// Queues a child `entry` (see [`queued`]) of a best-first search whose next pair is `next`: a
/// child that would be popped next anyway (nearest of all) is kept as `next`, to be descended
/// at once without a trip through the heap; the order stays best first.
#[inline(always)]
pub(crate) fn enqueue(next: &mut Option<u128>, heap: &mut BinaryHeap<u128>, entry: u128) {
    match *next {
        None if heap.peek().is_none_or(|top| entry >= *top) => *next = Some(entry),
        Some(n) if entry > n => {
            heap.push(n);
            *next = Some(entry);
        }
        _ => heap.push(entry),
    }
}

/// The corners of a triangle of a mesh as raw coordinates.
pub(crate) type Corners = [[f64; 3]; 3];

/// The corners of the triangle at leaf position `k` of `tree`.
#[inline]
fn corners(tree: &PoseTree, k: usize) -> Corners {
    tree.vertices(k).map(|p| [p.x, p.y, p.z])
}

/// The box of a triangle's corners (exact `min`/`max`).
#[inline]
fn corners_box(t: &Corners) -> Aabb {
    Aabb {
        min: std::array::from_fn(|k| t[0][k].min(t[1][k]).min(t[2][k])),
        max: std::array::from_fn(|k| t[0][k].max(t[1][k]).max(t[2][k])),
    }
}

/// Branch and bound: visits node pairs nearest first (best first) by the lower bound of their
/// [oriented boxes](crate::bounding::oriented_boxes); `pair(i, p, j, q, best)` gets triangles
/// `i` of `a` and `j` of `b` with their corners and returns their squared distance (or `+∞`
/// when it can tell the pair is no better; ties are broken by [`improves`]). Node pairs whose
/// bound, and triangle pairs whose box distance, exceeds the best found so far (times
/// `1 + 1e-9`, far above the boxes' rounding: [`beyond`]) are skipped, so every skipped pair is
/// truly farther than the best `f64` value returned. Returns the best squared distance and its
/// pair, `None` for an empty mesh.
pub(crate) fn nearest_pair(
    a: &Collider,
    b: &Collider,
    mut pair: impl FnMut(u32, &Corners, u32, &Corners, f64) -> f64,
) -> Option<(f64, u32, u32)> {
    if a.mesh().num_triangles() == 0 || b.mesh().num_triangles() == 0 {
        return None;
    }
    let (ta, tb) = (a.pose_tree(), b.pose_tree());
    let (na, nb) = (ta.nodes(), tb.nodes());
    let (fa, fb) = (&ta.oriented().boxes[..], &tb.oriented().boxes[..]);
    let (boxes_a, boxes_b) = (a.bvh().nodes(), b.bvh().nodes());
    let gaps = OrientedGaps::same_frame(
        (a.extent(), b.extent()),
        ta.oriented().eta.max(tb.oriented().eta),
    );
    // The axis-aligned boxes' bound is cheap: the oriented one is only computed when that
    // does not already prune the pair.
    let bound = |i: u32, j: u32, best: f64| {
        let (i, j) = (i as usize, j as usize);
        let d = box_distance2(&boxes_a[i].bounds, &boxes_b[j].bounds);
        if beyond(d, best) {
            d
        } else {
            d.max(gaps.gap2_same_frame(&fa[i], &fb[j], best))
        }
    };
    let mut best = (f64::INFINITY, 0u32, 0u32);
    let prune = beyond;
    let mut heap = BinaryHeap::with_capacity(256);
    let mut next = Some(queued(bound(0, 0, f64::INFINITY), 0, 0));
    let mut leaf_b: Vec<(u32, Corners, Aabb)> = Vec::with_capacity(MAX_LEAF);
    while let Some((lower, i, j)) = next.take().map(unqueued) {
        if prune(lower, best.0) {
            break; // everything left is farther
        }
        let (x, y) = (&na[i as usize], &nb[j as usize]);
        if x.is_leaf() && y.is_leaf() {
            let (sa, sb) = (x.start as usize, y.start as usize);
            leaf_b.clear();
            leaf_b.extend((sb..sb + y.count as usize).map(|k| {
                let q = corners(tb, k);
                (tb.index(k), q, corners_box(&q))
            }));
            for k in sa..sa + x.count as usize {
                let p = corners(ta, k);
                let bx = corners_box(&p);
                if prune(box_distance2(&bx, &boxes_b[j as usize].bounds), best.0) {
                    continue;
                }
                let xi = ta.index(k);
                for (yi, q, by) in &leaf_b {
                    if prune(box_distance2(&bx, by), best.0) {
                        continue;
                    }
                    let d = pair(xi, &p, *yi, q, best.0);
                    if improves(d, xi, *yi, &best) {
                        best = (d, xi, *yi);
                    }
                }
            }
            next = heap.pop();
            continue;
        }
        for (ci, cj) in child_pairs(i, x, j, y) {
            let d = bound(ci, cj, best.0);
            if !prune(d, best.0) {
                enqueue(&mut next, &mut heap, queued(d, ci, cj));
            }
        }
        if next.is_none() {
            next = heap.pop();
        }
    }
    Some(best)
}
