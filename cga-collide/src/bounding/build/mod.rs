//! How a hierarchy's shape is chosen: the split strategy, and the top-down loop of the SAH and
//! median builds. The splits are chosen on `f32` copies of the boxes ([`records`]): only a
//! heuristic, since any split is correct; the tree's boxes are computed exactly afterwards.
//!
//! | module | what it holds |
//! |---|---|
//! | [`records`] | the build's `f32` boxes, records and splits |
//! | [`sah`] | the binned surface-area heuristic (16 bins, longest centroid axis) |
//! | [`sweep`] | the full SAH sweep of a small node over its sorted centroids |
//! | [`median`] | the median split (also the SAH's fall-back) |
//! | [`morton`] | the linear build along a Morton curve of the centroids |

mod median;
mod morton;
mod records;
mod sah;
mod sweep;

pub(crate) use records::Record;

use crate::bounding::build::median::median_split;
use crate::bounding::build::morton::shape_morton;
use crate::bounding::build::records::{centroid_bounds, Box32};
use crate::bounding::build::sah::sah_split;
use crate::bounding::build::sweep::{sweep_split, SWEEP};
use crate::bounding::node::{BvhNode, BLANK, MAX_LEAF};

/// How the hierarchy chooses its splits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BuildStrategy {
    /// Binned surface-area heuristic (16 bins per split, longest centroid axis).
    #[default]
    Sah,
    /// Split at the median centroid along the longest centroid axis.
    Median,
    /// Linear hierarchy: the triangles sorted once along a Morton (Z-order) curve of their
    /// centroids, each node split where its range's codes first differ. Several times cheaper
    /// to build than [`Sah`](Self::Sah), with somewhat looser boxes.
    Morton,
}

/// The shape of a hierarchy over the records (its nodes with empty boxes, and the leaf order).
/// The records are partitioned in place, so each level reads them contiguously; the
/// bounds of the centroids of a node's children come from its split, never from another pass.
pub(crate) fn shape(mut recs: Vec<Record>, strategy: BuildStrategy) -> (Vec<BvhNode>, Vec<u32>) {
    if strategy == BuildStrategy::Morton {
        return shape_morton(&recs);
    }
    let n = recs.len();
    let mut ids = vec![0u8; n];
    // At most 2n - 1 nodes (leaves of one); the unused room is given back at the end, so the
    // array is never copied while it grows.
    let mut nodes = Vec::with_capacity((2 * n).max(1));
    nodes.push(BLANK);
    let mut stack = vec![Task {
        node: 0,
        s: 0,
        e: n,
        cb: centroid_bounds(&recs),
    }];
    while let Some(Task { node, s, e, cb }) = stack.pop() {
        let count = e - s;
        if count <= MAX_LEAF {
            nodes[node].start = s as u32;
            nodes[node].count = count as u32;
            continue;
        }
        let ext = [
            cb.hi[0] - cb.lo[0],
            cb.hi[1] - cb.lo[1],
            cb.hi[2] - cb.lo[2],
        ];
        let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
            0
        } else if ext[1] >= ext[2] {
            1
        } else {
            2
        };
        let mut split = None;
        if strategy == BuildStrategy::Sah && ext[axis] > 0.0 {
            split = if count <= SWEEP {
                sweep_split(&mut recs[s..e], axis)
            } else {
                sah_split(&mut recs[s..e], &mut ids[s..e], &cb, axis)
            };
        }
        let split = split.unwrap_or_else(|| median_split(&mut recs[s..e], axis));
        let mid = s + split.mid;
        let left = nodes.len();
        nodes.push(BLANK);
        nodes.push(BLANK);
        nodes[node].start = left as u32;
        stack.push(Task {
            node: left + 1,
            s: mid,
            e,
            cb: split.right,
        });
        stack.push(Task {
            node: left,
            s,
            e: mid,
            cb: split.left,
        });
    }
    nodes.shrink_to_fit();
    (nodes, recs.iter().map(|r| r.t).collect())
}

/// A node still to split: its records `s..e` and the bounds of their centroids.
struct Task {
    node: usize,
    s: usize,
    e: usize,
    cb: Box32,
}
