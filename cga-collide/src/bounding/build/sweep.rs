//! The full surface-area heuristic of a small node: every position between its records,
//! sorted by centroid, is a candidate.

use crate::bounding::build::records::{centroid_bounds, Box32, Record, Split};

/// Largest node split by a full SAH sweep over its sorted centroids rather than by bins.
pub(super) const SWEEP: usize = 16;

/// Full SAH split of a small range (at most [`SWEEP`] records): sorted by centroid along
/// `axis`, every position between two records is a candidate (the binned splits among them).
pub(super) fn sweep_split(recs: &mut [Record], axis: usize) -> Option<Split> {
    let n = recs.len();
    // Sort (centroid, position) pairs, then the records by them (small moves, no comparator
    // recomputing centroids).
    let mut keys = [(0.0f32, 0u8); SWEEP];
    for (k, r) in keys.iter_mut().zip(recs.iter()) {
        *k = (r.centroid()[axis], 0);
    }
    for (i, k) in keys[..n].iter_mut().enumerate() {
        k.1 = i as u8;
    }
    keys[..n].sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut sorted = [recs[0]; SWEEP];
    for (d, k) in sorted.iter_mut().zip(&keys[..n]) {
        *d = recs[usize::from(k.1)];
    }
    recs.copy_from_slice(&sorted[..n]);
    // right[i]: the union of recs[i..]
    let mut right = [0.0; SWEEP];
    let mut acc = Box32::EMPTY;
    for i in (1..n).rev() {
        acc = acc.union(&recs[i].b);
        right[i] = acc.half_area();
    }
    let (mut best, mut best_cost) = (0, f64::INFINITY);
    let mut acc = Box32::EMPTY;
    for i in 1..n {
        acc = acc.union(&recs[i - 1].b);
        let cost = acc.half_area() * i as f64 + right[i] * (n - i) as f64;
        if cost < best_cost {
            best_cost = cost;
            best = i;
        }
    }
    if !best_cost.is_finite() {
        return None;
    }
    Some(Split {
        mid: best,
        left: centroid_bounds(&recs[..best]),
        right: centroid_bounds(&recs[best..]),
    })
}
