//! Sweep and prune over the objects' world boxes: the slots sorted by the lower `x` of their
//! boxes, kept sorted as objects move (the sort is adaptive, so a step in which objects move
//! a little costs a linear pass), and the pairs whose boxes overlap found by one sweep.
//!
//! Every test is a closed comparison of `f64` box bounds, so the pairs reported are exactly the
//! pairs whose boxes overlap (touching counts), never fewer: with conservative boxes no touching
//! pair of objects is ever dropped.

use std::sync::{Mutex, MutexGuard, PoisonError};

use crate::bounding::Aabb;

/// From this many objects on, pairs come from a grid rather than a sweep.
const GRID_FROM: usize = 256;
/// A box spanning more cells than this is tested against every box instead of hashed.
const MAX_CELLS: i64 = 64;

/// The broad phase of a scene: for each live slot, its world box; the live slots in order of
/// the boxes' lower `x`. The order is sorted lazily, by the first question after a move, so
/// questions take `&self`; the lock is held only by that sort and the sweep.
#[derive(Debug, Default)]
pub(crate) struct SweepAndPrune {
    /// The world box of each slot (meaningless for free slots, which are not in the order).
    boxes: Vec<Aabb>,
    order: Mutex<Order>,
}

/// Live slots by `boxes[slot].min[0]`, once `sorted` is true.
#[derive(Debug, Clone, Default)]
struct Order {
    slots: Vec<u32>,
    sorted: bool,
}

impl Clone for SweepAndPrune {
    fn clone(&self) -> SweepAndPrune {
        SweepAndPrune {
            boxes: self.boxes.clone(),
            order: Mutex::new(self.lock().clone()),
        }
    }
}

impl SweepAndPrune {
    /// Sets the box of `slot` (a new slot is added to the order).
    pub(crate) fn set(&mut self, slot: u32, b: Aabb) {
        let i = slot as usize;
        if i >= self.boxes.len() {
            self.boxes.resize(i + 1, Aabb::EMPTY);
        }
        let new = self.boxes[i].min[0] > self.boxes[i].max[0];
        self.boxes[i] = b;
        let order = self.order.get_mut().unwrap_or_else(PoisonError::into_inner);
        if new {
            order.slots.push(slot);
        }
        order.sorted = false;
    }

    /// Removes `slot` from the order.
    pub(crate) fn remove(&mut self, slot: u32) {
        let order = self.order.get_mut().unwrap_or_else(PoisonError::into_inner);
        order.slots.retain(|&s| s != slot);
        self.boxes[slot as usize] = Aabb::EMPTY;
    }

    fn lock(&self) -> MutexGuard<'_, Order> {
        // The order is only ever sorted under the lock, so a panic elsewhere leaves it valid.
        self.order.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The box of `slot`.
    pub(crate) fn bounds(&self, slot: u32) -> &Aabb {
        &self.boxes[slot as usize]
    }

    /// The order, sorted if objects moved since the last sweep.
    fn sorted(&self) -> MutexGuard<'_, Order> {
        let mut order = self.lock();
        if !order.sorted {
            let boxes = &self.boxes;
            // Stable and adaptive: nearly sorted input (small motions) costs a linear pass.
            order
                .slots
                .sort_by(|&a, &b| boxes[a as usize].min[0].total_cmp(&boxes[b as usize].min[0]));
            order.sorted = true;
        }
        order
    }

    /// Every pair of live slots `(a, b)`, `a < b`, whose boxes come within `reach` of each other
    /// on every axis (`reach = 0`: the boxes overlap, touching counts), in no set order.
    ///
    /// Small scenes are swept along `x`. Larger ones are hashed into a uniform grid of cells as
    /// large as a typical box (the median of the boxes' largest sides, plus `reach`): a pair is
    /// a candidate only in the cell where both boxes start, so each is met once, and the work
    /// per object stays flat as the scene grows (a sweep along one axis meets a number of
    /// `x`-overlapping boxes per object that grows like `N^(2/3)` at a fixed density). Boxes
    /// much larger than a cell (a floor under many parts) are tested against every box instead.
    pub(crate) fn pairs(&self, reach: f64) -> Vec<(u32, u32)> {
        let live = self.sorted().slots.clone();
        if live.len() < GRID_FROM || !reach.is_finite() {
            return self.sweep_pairs(&live, reach);
        }
        let mut sides: Vec<f64> = live
            .iter()
            .map(|&s| {
                let b = &self.boxes[s as usize];
                (0..3).map(|k| b.max[k] - b.min[k]).fold(0.0, f64::max)
            })
            .collect();
        let middle = sides.len() / 2;
        let (_, median, _) = sides.select_nth_unstable_by(middle, f64::total_cmp);
        let h = *median + reach;
        if !(h > 0.0 && h.is_finite()) {
            return self.sweep_pairs(&live, reach);
        }
        // Cell coordinates are monotone in the coordinate (a rounded division, a floor and a
        // saturating conversion), so boxes that overlap once widened by `reach` on their lower
        // sides share the cell where the later-starting one starts, on every axis.
        let cell = |x: f64| (x / h).floor() as i64;
        let range = |b: &Aabb| -> ([i64; 3], [i64; 3]) {
            (
                [0, 1, 2].map(|k| cell(b.min[k] - reach)),
                [0, 1, 2].map(|k| cell(b.max[k])),
            )
        };
        let mut entries: Vec<([i64; 3], u32)> = Vec::with_capacity(live.len() * 8);
        let mut large = Vec::new();
        let mut starts: Vec<[i64; 3]> = vec![[0; 3]; self.boxes.len()];
        for &s in &live {
            let (lo, hi) = range(&self.boxes[s as usize]);
            let span = (0..3).map(|k| hi[k].saturating_sub(lo[k]).saturating_add(1));
            if span.fold(1i64, |n, d| n.saturating_mul(d)) > MAX_CELLS {
                large.push(s);
                continue;
            }
            starts[s as usize] = lo;
            for x in lo[0]..=hi[0] {
                for y in lo[1]..=hi[1] {
                    for z in lo[2]..=hi[2] {
                        entries.push(([x, y, z], s));
                    }
                }
            }
        }
        entries.sort_unstable();
        let mut out = Vec::new();
        for run in entries.chunk_by(|x, y| x.0 == y.0) {
            let here = run[0].0;
            for (k, &(_, a)) in run.iter().enumerate() {
                for &(_, b) in &run[k + 1..] {
                    let (sa, sb) = (starts[a as usize], starts[b as usize]);
                    let first = [0, 1, 2].map(|i| sa[i].max(sb[i]));
                    if first == here
                        && near(&self.boxes[a as usize], &self.boxes[b as usize], reach)
                    {
                        out.push((a.min(b), a.max(b)));
                    }
                }
            }
        }
        for (k, &a) in large.iter().enumerate() {
            let ba = &self.boxes[a as usize];
            for &b in live.iter().filter(|&&b| b != a) {
                let is_large_before = large[..k].contains(&b);
                if !is_large_before && near(ba, &self.boxes[b as usize], reach) {
                    out.push((a.min(b), a.max(b)));
                }
            }
        }
        out
    }

    /// The first pair met by a sweep along `x` whose boxes overlap and for which `accept` holds
    /// (an error from `accept` stops the sweep and is returned). `accept` must not call back
    /// into the broad phase (the order is locked meanwhile).
    pub(crate) fn first_pair<E>(
        &self,
        mut accept: impl FnMut(u32, u32) -> Result<bool, E>,
    ) -> Result<Option<(u32, u32)>, E> {
        // The order stays locked during the sweep (`accept` does not ask the broad phase), so
        // nothing is copied per call.
        let order = self.sorted();
        let order = &order.slots;
        for (k, &a) in order.iter().enumerate() {
            let ba = &self.boxes[a as usize];
            for &b in &order[k + 1..] {
                let bb = &self.boxes[b as usize];
                if bb.min[0] > ba.max[0] {
                    break;
                }
                let (x, y) = (a.min(b), a.max(b));
                if near(ba, bb, 0.0) && accept(x, y)? {
                    return Ok(Some((x, y)));
                }
            }
        }
        Ok(None)
    }

    /// [`pairs`](Self::pairs) by one sweep along `x` over the sorted slots.
    fn sweep_pairs(&self, order: &[u32], reach: f64) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for (k, &a) in order.iter().enumerate() {
            let ba = &self.boxes[a as usize];
            let limit = ba.max[0] + reach;
            for &b in &order[k + 1..] {
                let bb = &self.boxes[b as usize];
                if bb.min[0] > limit {
                    break;
                }
                if near(ba, bb, reach) {
                    out.push((a.min(b), a.max(b)));
                }
            }
        }
        out
    }

    /// Every live slot whose box comes within `reach` of `query` on every axis.
    pub(crate) fn near_box(&self, query: &Aabb, reach: f64) -> Vec<u32> {
        let order = self.sorted();
        let mut out = Vec::new();
        for &a in &order.slots {
            let b = &self.boxes[a as usize];
            if b.min[0] > query.max[0] + reach {
                break;
            }
            if near(b, query, reach) {
                out.push(a);
            }
        }
        out
    }

    /// The live slots in sweep order (for searches that prune on the `x` gap).
    pub(crate) fn sweep_order(&self) -> Vec<u32> {
        self.sorted().slots.clone()
    }
}

/// Whether two closed boxes come within `reach` of each other on every axis. Conservative for
/// a Euclidean clearance `reach` (a per-axis gap above `reach` proves a distance above it; the
/// rounding of `max + reach` is covered by comparing `gap > reach` on each axis directly).
#[inline]
pub(crate) fn near(a: &Aabb, b: &Aabb, reach: f64) -> bool {
    (0..3).all(|k| b.min[k] - a.max[k] <= reach && a.min[k] - b.max[k] <= reach)
}

/// A lower bound on the distance between two boxes (only used to order and prune the nearest
/// pair search; every reported distance is certified by the pair's own query).
#[inline]
pub(crate) fn box_gap(a: &Aabb, b: &Aabb) -> f64 {
    let mut s = 0.0;
    for k in 0..3 {
        let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
        s += g * g;
    }
    // Rounded down a little: the gaps and their squares are rounded to nearest.
    (s * (1.0 - 1e-12)).sqrt() * (1.0 - 1e-12)
}
