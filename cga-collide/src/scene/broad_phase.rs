//! Sweep and prune over the objects' world boxes: the slots sorted by the lower `x` of their
//! boxes, kept sorted as objects move (the sort is adaptive, so a step in which objects move
//! a little costs a linear pass), and the pairs whose boxes overlap found by one sweep.
//!
//! Every test is a closed comparison of `f64` box bounds, so the pairs reported are exactly the
//! pairs whose boxes overlap (touching counts), never fewer: with conservative boxes no touching
//! pair of objects is ever dropped.

use std::sync::{Mutex, MutexGuard, PoisonError};

use crate::bounding::Aabb;

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
    /// on every axis (`reach = 0`: the boxes overlap, touching counts).
    pub(crate) fn pairs(&self, reach: f64) -> Vec<(u32, u32)> {
        let order = self.sorted();
        let mut out = Vec::new();
        for (k, &a) in order.slots.iter().enumerate() {
            let ba = &self.boxes[a as usize];
            let limit = ba.max[0] + reach;
            for &b in &order.slots[k + 1..] {
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
