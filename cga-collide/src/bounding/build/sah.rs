//! The binned surface-area heuristic: the records binned along the split axis, the cheapest
//! boundary between bins chosen, the records partitioned in place.

use crate::bounding::build::records::{Box32, Record, Split};

const BINS: usize = 16;

/// One bin of a SAH split: the union of its boxes, the box of their centroids, their number.
#[derive(Clone, Copy)]
struct Bin {
    b: Box32,
    c: Box32,
    n: usize,
}

impl Bin {
    const EMPTY: Bin = Bin {
        b: Box32::EMPTY,
        c: Box32::EMPTY,
        n: 0,
    };

    #[inline(always)]
    fn add(&mut self, b: &Box32, c: &[f32; 3]) {
        self.n += 1;
        self.b = self.b.union(b);
        self.c.grow(c);
    }

    fn merge(&self, o: &Bin) -> Bin {
        Bin {
            b: self.b.union(&o.b),
            c: self.c.union(&o.c),
            n: self.n + o.n,
        }
    }
}
/// The bins of the records along `AXIS` (bin `k` holds the centroids in
/// `lo + [k, k + 1) / scale`, the last bin also what lies above), each record's bin in `ids`.
fn bin_records<const AXIS: usize>(
    recs: &[Record],
    ids: &mut [u8],
    lo: f32,
    scale: f32,
) -> [Bin; BINS] {
    let bin = |c: f32| -> usize {
        // `as` saturates (NaN to 0); the clamp is on integers.
        (((c - lo) * scale) as i32).clamp(0, BINS as i32 - 1) as usize
    };
    // Two sets of bins, for even and odd records: consecutive records often share a bin, and
    // one set would chain every update on the previous one.
    let mut even = [Bin::EMPTY; BINS];
    let mut odd = [Bin::EMPTY; BINS];
    let mut pairs = recs.chunks_exact(2);
    let mut id_pairs = ids.chunks_exact_mut(2);
    for (r, id) in (&mut pairs).zip(&mut id_pairs) {
        let (c0, c1) = (r[0].centroid(), r[1].centroid());
        let (k0, k1) = (bin(c0[AXIS]), bin(c1[AXIS]));
        even[k0].add(&r[0].b, &c0);
        odd[k1].add(&r[1].b, &c1);
        (id[0], id[1]) = (k0 as u8, k1 as u8);
    }
    if let ([r], [id]) = (pairs.remainder(), id_pairs.into_remainder()) {
        let c = r.centroid();
        let k = bin(c[AXIS]);
        even[k].add(&r.b, &c);
        *id = k as u8;
    }
    std::array::from_fn(|k| even[k].merge(&odd[k]))
}

/// Binned SAH split of `recs` along `axis` (whose centroids lie in `cb`); `None` when no split
/// is finite or a side would be empty (the caller then splits at the median). `ids` is work
/// space as long as `recs` (each record's bin).
pub(super) fn sah_split(
    recs: &mut [Record],
    ids: &mut [u8],
    cb: &Box32,
    axis: usize,
) -> Option<Split> {
    let lo = cb.lo[axis];
    let scale = BINS as f32 / (cb.hi[axis] - lo);
    let bins = match axis {
        0 => bin_records::<0>(recs, ids, lo, scale),
        1 => bin_records::<1>(recs, ids, lo, scale),
        _ => bin_records::<2>(recs, ids, lo, scale),
    };
    // Sweep from the right to get suffix areas and counts.
    let mut right_area = [0.0; BINS];
    let mut right_count = [0usize; BINS];
    let (mut acc, mut cnt) = (Box32::EMPTY, 0);
    for b in (1..BINS).rev() {
        acc = acc.union(&bins[b].b);
        cnt += bins[b].n;
        right_area[b] = acc.half_area();
        right_count[b] = cnt;
    }
    let (mut best, mut best_cost) = (0, f64::INFINITY);
    let (mut acc, mut cnt) = (Box32::EMPTY, 0);
    for b in 0..BINS - 1 {
        acc = acc.union(&bins[b].b);
        cnt += bins[b].n;
        if cnt == 0 || right_count[b + 1] == 0 {
            continue;
        }
        let cost = acc.half_area() * cnt as f64 + right_area[b + 1] * right_count[b + 1] as f64;
        if cost < best_cost {
            best_cost = cost;
            best = b + 1;
        }
    }
    if !best_cost.is_finite() {
        return None;
    }
    let side = |bins: &[Bin]| bins.iter().fold(Bin::EMPTY, |acc, b| acc.merge(b));
    let (left, right) = (side(&bins[..best]), side(&bins[best..]));
    // Partition in place (branch-free): bins < best to the left. Each record is looked at
    // once, at its original position `k` (what moves to `k` is already looked at).
    let mut l = 0;
    for (k, &id) in ids.iter().enumerate() {
        recs.swap(l, k);
        l += usize::from(usize::from(id) < best);
    }
    (left.n > 0 && right.n > 0).then_some(Split {
        mid: left.n,
        left: left.c,
        right: right.c,
    })
}
