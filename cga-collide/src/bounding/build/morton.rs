//! The linear build: the records sorted once along a Morton (Z-order) curve of their centroids,
//! each node split where its range's codes first differ.

use crate::bounding::build::records::{centroid_bounds, Record};
use crate::bounding::node::{BvhNode, BLANK, MAX_LEAF};

/// Spreads the low 21 bits of `x` to every third bit.
fn spread_bits(x: u64) -> u64 {
    let mut x = x & 0x1f_ffff;
    x = (x | x << 32) & 0x1f_0000_0000_ffff;
    x = (x | x << 16) & 0x1f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    (x | x << 2) & 0x1249_2492_4924_9249
}

/// [`shape`](super::shape) for [`BuildStrategy::Morton`]: one sort by the 63-bit Morton code of each
/// centroid (21 bits an axis, over the centroids' bounds), then top-down splits at the first
/// differing bit of a range's codes (found by binary search; the middle where all codes are
/// equal). No record moves after the sort.
pub(super) fn shape_morton(recs: &[Record]) -> (Vec<BvhNode>, Vec<u32>) {
    let n = recs.len();
    let cb = centroid_bounds(recs);
    let scale: [f32; 3] = std::array::from_fn(|k| {
        let ext = cb.hi[k] - cb.lo[k];
        if ext > 0.0 {
            2_097_151.0 / ext
        } else {
            0.0
        }
    });
    let mut keys: Vec<(u64, u32)> = recs
        .iter()
        .map(|r| {
            let c = r.centroid();
            // `as` saturates (NaN to 0).
            let q = |k: usize| spread_bits(((c[k] - cb.lo[k]) * scale[k]) as u64);
            (q(0) << 2 | q(1) << 1 | q(2), r.t)
        })
        .collect();
    keys.sort_unstable_by_key(|&(code, _)| code);
    let mut nodes = Vec::with_capacity((2 * n).max(1));
    nodes.push(BLANK);
    let mut stack = vec![(0usize, 0usize, n)];
    while let Some((node, s, e)) = stack.pop() {
        if e - s <= MAX_LEAF {
            nodes[node].start = s as u32;
            nodes[node].count = (e - s) as u32;
            continue;
        }
        let (first, last) = (keys[s].0, keys[e - 1].0);
        let mid = if first == last {
            s + (e - s) / 2
        } else {
            // The first code in the range with the highest differing bit set.
            let bit = 63 - (first ^ last).leading_zeros();
            s + keys[s..e].partition_point(|&(code, _)| code >> bit & 1 == 0)
        };
        let left = nodes.len();
        nodes.push(BLANK);
        nodes.push(BLANK);
        nodes[node].start = left as u32;
        stack.push((left + 1, mid, e));
        stack.push((left, s, mid));
    }
    nodes.shrink_to_fit();
    (nodes, keys.iter().map(|&(_, t)| t).collect())
}
