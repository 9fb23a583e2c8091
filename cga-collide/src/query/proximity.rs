//! Descending two box hierarchies together by distance: the traversals behind mesh clearance,
//! mesh distance and self-intersection. Only the public shape of [`Bvh`] (nodes and leaf order)
//! is used; triangle boxes are recomputed from the mesh (exact `min`/`max`).

use std::collections::BinaryHeap;
use std::ops::ControlFlow;

use crate::bvh::{triangle_box, Aabb, Bvh};
use crate::shape::mesh::TriMesh;

/// A lower bound on the squared distance between two boxes, in `f64`, never above the true
/// value by more than a few ulps (only used to order and prune the distance search, whose
/// result is certified separately).
#[inline]
pub(crate) fn box_distance2(a: &Aabb, b: &Aabb) -> f64 {
    let mut s = 0.0;
    for k in 0..3 {
        let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
        s += g * g;
    }
    s
}

/// Conservative: `false` only if the closed boxes are certainly farther apart than `c`
/// (`c >= 0`). Per axis, a rounded gap above `c` proves a true gap above `c` (rounding is
/// monotone and `c` is an `f64`); the Euclidean sum gets a relative margin far above its
/// rounding error.
#[inline]
pub(crate) fn boxes_within(a: &Aabb, b: &Aabb, c: f64) -> bool {
    let mut s = 0.0;
    for k in 0..3 {
        let g = (b.min[k] - a.max[k]).max(a.min[k] - b.max[k]).max(0.0);
        if g > c {
            return false;
        }
        s += g * g;
    }
    let c2 = c * c;
    !c2.is_finite() || s * (1.0 - 1e-9) <= c2 * (1.0 + 1e-9) + 1e-300
}

/// The box of triangle `t` of `mesh`.
#[inline]
pub(crate) fn tri_box(mesh: &TriMesh, t: u32) -> Aabb {
    triangle_box(mesh.vertices(), &mesh.triangles()[t as usize])
}

/// Calls `visit(i, j)` for every pair of a triangle `i` of `ma` and `j` of `mb` whose boxes
/// pass `near` (reached through node pairs passing `near`); stops when `visit` breaks.
pub(crate) fn for_each_near_pair<B>(
    (ma, ta): (&TriMesh, &Bvh),
    (mb, tb): (&TriMesh, &Bvh),
    near: impl Fn(&Aabb, &Aabb) -> bool,
    mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
) -> ControlFlow<B> {
    let (na, nb) = (ta.nodes(), tb.nodes());
    let mut stack = Vec::with_capacity(128);
    stack.push((0usize, 0usize));
    while let Some((i, j)) = stack.pop() {
        let (a, b) = (&na[i], &nb[j]);
        if !near(&a.bounds, &b.bounds) {
            continue;
        }
        match (a.is_leaf(), b.is_leaf()) {
            (true, true) => {
                let (sa, sb) = (a.start as usize, b.start as usize);
                for &x in &ta.order()[sa..sa + a.count as usize] {
                    let bx = tri_box(ma, x);
                    if !near(&bx, &b.bounds) {
                        continue;
                    }
                    for &y in &tb.order()[sb..sb + b.count as usize] {
                        if near(&bx, &tri_box(mb, y)) {
                            visit(x, y)?;
                        }
                    }
                }
            }
            (false, true) => {
                stack.push((a.start as usize + 1, j));
                stack.push((a.start as usize, j));
            }
            (true, false) => {
                stack.push((i, b.start as usize + 1));
                stack.push((i, b.start as usize));
            }
            (false, false) => {
                if a.bounds.half_area() >= b.bounds.half_area() {
                    stack.push((a.start as usize + 1, j));
                    stack.push((a.start as usize, j));
                } else {
                    stack.push((i, b.start as usize + 1));
                    stack.push((i, b.start as usize));
                }
            }
        }
    }
    ControlFlow::Continue(())
}

/// A node pair in the best-first distance search, ordered by its box distance (smallest first).
#[derive(PartialEq)]
struct Entry(f64, usize, usize);
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other.0.total_cmp(&self.0)
    }
}

/// Branch and bound: visits triangle pairs nearest boxes first; `pair(i, j, best)` returns the
/// pair's squared distance (it may return early with anything `>= best` when it can tell the
/// pair is no better). Node pairs whose box distance exceeds the best found so far (times
/// `1 + 1e-9`, for the boxes' rounding) are skipped. Returns the best squared distance and
/// its pair, `None` for an empty mesh.
pub(crate) fn nearest_pair(
    (ma, ta): (&TriMesh, &Bvh),
    (mb, tb): (&TriMesh, &Bvh),
    mut pair: impl FnMut(u32, u32, f64) -> f64,
) -> Option<(f64, u32, u32)> {
    let (na, nb) = (ta.nodes(), tb.nodes());
    if ma.num_triangles() == 0 || mb.num_triangles() == 0 {
        return None;
    }
    let mut best = (f64::INFINITY, 0u32, 0u32);
    let prune = |d2: f64, best: f64| d2 * (1.0 - 1e-9) > best;
    let mut heap = BinaryHeap::with_capacity(256);
    heap.push(Entry(box_distance2(&na[0].bounds, &nb[0].bounds), 0, 0));
    while let Some(Entry(d2, i, j)) = heap.pop() {
        if prune(d2, best.0) {
            break; // everything left is farther
        }
        let (a, b) = (&na[i], &nb[j]);
        match (a.is_leaf(), b.is_leaf()) {
            (true, true) => {
                let (sa, sb) = (a.start as usize, b.start as usize);
                for &x in &ta.order()[sa..sa + a.count as usize] {
                    let bx = tri_box(ma, x);
                    for &y in &tb.order()[sb..sb + b.count as usize] {
                        if prune(box_distance2(&bx, &tri_box(mb, y)), best.0) {
                            continue;
                        }
                        let d = pair(x, y, best.0);
                        if d < best.0 {
                            best = (d, x, y);
                        }
                    }
                }
            }
            _ => {
                let split_a =
                    !a.is_leaf() && (b.is_leaf() || a.bounds.half_area() >= b.bounds.half_area());
                let children = if split_a {
                    let s = a.start as usize;
                    [(s, j), (s + 1, j)]
                } else {
                    let s = b.start as usize;
                    [(i, s), (i, s + 1)]
                };
                for (ci, cj) in children {
                    let d = box_distance2(&na[ci].bounds, &nb[cj].bounds);
                    if !prune(d, best.0) {
                        heap.push(Entry(d, ci, cj));
                    }
                }
            }
        }
    }
    Some(best)
}

/// Calls `visit(i, j)` (with `i != j`, each unordered pair once) for every pair of triangles of
/// one mesh whose boxes overlap (closed, exact); stops when `visit` breaks.
pub(crate) fn for_each_self_pair<B>(
    mesh: &TriMesh,
    tree: &Bvh,
    mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
) -> ControlFlow<B> {
    let nodes = tree.nodes();
    if mesh.num_triangles() == 0 {
        return ControlFlow::Continue(());
    }
    let order = tree.order();
    let mut stack = Vec::with_capacity(128);
    stack.push((0usize, 0usize));
    while let Some((i, j)) = stack.pop() {
        let (a, b) = (&nodes[i], &nodes[j]);
        if i == j {
            let s = a.start as usize;
            if a.is_leaf() {
                let leaf = &order[s..s + a.count as usize];
                for (k, &x) in leaf.iter().enumerate() {
                    let bx = tri_box(mesh, x);
                    for &y in &leaf[k + 1..] {
                        if bx.overlaps(&tri_box(mesh, y)) {
                            visit(x, y)?;
                        }
                    }
                }
            } else {
                stack.push((s, s + 1));
                stack.push((s + 1, s + 1));
                stack.push((s, s));
            }
            continue;
        }
        if !a.bounds.overlaps(&b.bounds) {
            continue;
        }
        match (a.is_leaf(), b.is_leaf()) {
            (true, true) => {
                let (sa, sb) = (a.start as usize, b.start as usize);
                for &x in &order[sa..sa + a.count as usize] {
                    let bx = tri_box(mesh, x);
                    if !bx.overlaps(&b.bounds) {
                        continue;
                    }
                    for &y in &order[sb..sb + b.count as usize] {
                        if bx.overlaps(&tri_box(mesh, y)) {
                            visit(x, y)?;
                        }
                    }
                }
            }
            (false, true) => {
                stack.push((a.start as usize + 1, j));
                stack.push((a.start as usize, j));
            }
            (true, false) => {
                stack.push((i, b.start as usize + 1));
                stack.push((i, b.start as usize));
            }
            (false, false) => {
                if a.bounds.half_area() >= b.bounds.half_area() {
                    stack.push((a.start as usize + 1, j));
                    stack.push((a.start as usize, j));
                } else {
                    stack.push((i, b.start as usize + 1));
                    stack.push((i, b.start as usize));
                }
            }
        }
    }
    ControlFlow::Continue(())
}
