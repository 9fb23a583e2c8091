//! A bounding-volume hierarchy over the triangles of a mesh: axis-aligned boxes in `f64`,
//! binned-SAH (or median) build, a flat node array with children stored in pairs, leaves of at
//! most a few triangles.
//!
//! # Conservativeness
//! Boxes are computed with `min`/`max` of the `f64` vertex coordinates, which is exact: a
//! triangle's box contains the triangle, and a node's box contains its children's. Box–box tests
//! are closed comparisons of `f64` values, also exact. So the pair enumeration
//! ([`Bvh::for_each_pair`]) yields **exactly** the pairs of triangles whose boxes overlap (touching
//! counts), never fewer. The segment and ball/sphere box tests round, and are widened by a
//! relative slack far larger than their rounding error, so they never reject a box that the
//! exact real segment or ball meets.
//!
//! Moving a mesh rigidly: the vertices are transformed once in `f64` and the hierarchy is
//! [`refit`](Bvh::refit) to those coordinates (same tree, new exact boxes), so it is
//! conservative for exactly the coordinates the exact tests see.

use std::ops::ControlFlow;

use nalgebra::Point3;

use crate::bounding::aabb::{triangle_box, Aabb};
use crate::bounding::build::{shape, BuildStrategy, Record};
use crate::bounding::node::BvhNode;

/// A bounding-volume hierarchy over the triangles of one mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Bvh {
    nodes: Vec<BvhNode>,
    /// Triangle indices in leaf order.
    order: Vec<u32>,
    /// Boxes of the triangles, in leaf order.
    boxes: Vec<Aabb>,
}

impl Bvh {
    /// Builds the hierarchy over `triangles` (indices into `vertices`) with the binned SAH.
    ///
    /// Panics if an index is out of range; a [`TriMesh`](crate::shape::mesh::TriMesh) never has one.
    pub fn build(vertices: &[Point3<f64>], triangles: &[[u32; 3]]) -> Bvh {
        Self::build_with(vertices, triangles, BuildStrategy::Sah)
    }

    /// Builds the hierarchy with the given split strategy.
    pub fn build_with(
        vertices: &[Point3<f64>],
        triangles: &[[u32; 3]],
        strategy: BuildStrategy,
    ) -> Bvh {
        let recs = triangles
            .iter()
            .enumerate()
            .map(|(t, tri)| Record::new(&triangle_box(vertices, tri), t as u32))
            .collect();
        let (nodes, order) = shape(recs, strategy);
        // The exact boxes in leaf order, straight from the triangles (no box array in triangle
        // order to allocate and gather from).
        let boxes = order
            .iter()
            .map(|&t| triangle_box(vertices, &triangles[t as usize]))
            .collect();
        let mut bvh = Bvh {
            nodes,
            order,
            boxes,
        };
        bvh.refit_nodes();
        bvh
    }

    /// Builds the hierarchy over arbitrary boxes (leaf `i` is `boxes[i]`): e.g. the boxes that
    /// moving primitives sweep during a time step. [`refit`](Self::refit) applies only to
    /// hierarchies over triangles.
    ///
    /// The splits are chosen on `f32` copies of the boxes (half the memory to move, and only a
    /// heuristic: any split is correct); the boxes of the tree are then computed exactly from
    /// the `f64` boxes, bottom-up, as [`refit_boxes`](Self::refit_boxes) does.
    pub fn from_boxes(tri_boxes: Vec<Aabb>, strategy: BuildStrategy) -> Bvh {
        let recs = tri_boxes
            .iter()
            .enumerate()
            .map(|(t, b)| Record::new(b, t as u32))
            .collect();
        let (nodes, order) = shape(recs, strategy);
        let boxes = order.iter().map(|&t| tri_boxes[t as usize]).collect();
        let mut bvh = Bvh {
            nodes,
            order,
            boxes,
        };
        bvh.refit_nodes();
        bvh
    }

    /// Recomputes every box for new vertex coordinates (same triangles, same tree), e.g. after
    /// transforming the vertices rigidly. Exact, like the build.
    pub fn refit(&mut self, vertices: &[Point3<f64>], triangles: &[[u32; 3]]) {
        self.refit_boxes(|t| triangle_box(vertices, &triangles[t as usize]));
    }

    /// Recomputes every box from `leaf_box(i)` for leaf `i` (same tree, no rebuild): e.g. the
    /// boxes the triangles sweep while the mesh moves between two poses.
    pub fn refit_boxes(&mut self, leaf_box: impl Fn(u32) -> Aabb) {
        for (b, &t) in self.boxes.iter_mut().zip(&self.order) {
            *b = leaf_box(t);
        }
        self.refit_nodes();
    }

    /// Recomputes every node's box from the leaf boxes (exact).
    fn refit_nodes(&mut self) {
        if self.order.is_empty() {
            return; // the root of no boxes (count 0) is not a leaf, and has the empty box
        }
        // Children always come after their parent, so a reverse sweep is bottom-up.
        for i in (0..self.nodes.len()).rev() {
            let node = self.nodes[i];
            let s = node.start as usize;
            self.nodes[i].bounds = if node.is_leaf() {
                self.boxes[s..s + node.count as usize]
                    .iter()
                    .fold(Aabb::EMPTY, |acc, b| acc.union(b))
            } else {
                self.nodes[s].bounds.union(&self.nodes[s + 1].bounds)
            };
        }
    }

    /// A hierarchy with a given shape (`nodes`' `start` and `count`, and the leaf `order`) over
    /// `triangles`, every box recomputed from the geometry (as [`refit`](Self::refit) does).
    /// The caller has checked the shape: children after their parent and in range, every
    /// position of `order` in exactly one leaf of at most [`MAX_LEAF`](super::MAX_LEAF)
    /// triangles, `order` a permutation of the triangles (`collider::serial` does, for colliders read back).
    pub(crate) fn from_checked_shape(
        nodes: Vec<BvhNode>,
        order: Vec<u32>,
        vertices: &[Point3<f64>],
        triangles: &[[u32; 3]],
    ) -> Bvh {
        let mut bvh = Bvh {
            boxes: vec![Aabb::EMPTY; order.len()],
            nodes,
            order,
        };
        bvh.refit(vertices, triangles);
        bvh
    }

    /// The nodes (root first).
    pub fn nodes(&self) -> &[BvhNode] {
        &self.nodes
    }

    /// Triangle indices in leaf order.
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// Box of the whole mesh.
    pub fn bounds(&self) -> Aabb {
        self.nodes[0].bounds
    }

    /// Heap bytes used by the hierarchy (nodes, leaf order and triangle boxes).
    pub fn heap_bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<BvhNode>()
            + self.order.len() * std::mem::size_of::<u32>()
            + self.boxes.len() * std::mem::size_of::<Aabb>()
    }

    /// Calls `visit(triangle)` for every triangle whose box passes `test`, reached through nodes
    /// whose boxes pass `test`; stops early when `visit` breaks.
    pub fn for_each_candidate<B>(
        &self,
        mut test: impl FnMut(&Aabb) -> bool,
        mut visit: impl FnMut(u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let mut stack = Vec::with_capacity(64);
        stack.push(0usize);
        while let Some(i) = stack.pop() {
            let node = &self.nodes[i];
            if !test(&node.bounds) {
                continue;
            }
            let s = node.start as usize;
            if node.is_leaf() {
                for k in s..s + node.count as usize {
                    if node.count == 1 || test(&self.boxes[k]) {
                        visit(self.order[k])?;
                    }
                }
            } else {
                stack.push(s + 1);
                stack.push(s);
            }
        }
        ControlFlow::Continue(())
    }

    /// [`for_each_candidate`](Self::for_each_candidate) for a nearest-pair search: nodes in
    /// increasing order of `gap` (a lower bound on the distance from the box to what is
    /// searched for), and none whose gap exceeds `bound()`, read again before each node and
    /// triangle (the search lowers it as it finds nearer triangles). Visiting the nearest
    /// first lowers the bound early, so far fewer triangles are examined than depth first.
    pub(crate) fn for_each_nearest_first<B>(
        &self,
        gap: impl Fn(&Aabb) -> f64,
        bound: impl Fn() -> f64,
        mut visit: impl FnMut(u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        nearest_first(
            &self.nodes,
            |node| gap(&node.bounds),
            bound,
            |k| (gap(&self.boxes[k]), self.order[k]),
            |_, i| visit(i),
        )
    }

    /// Calls `visit(i, j)` for every pair of a triangle `i` of `self` and `j` of `other` whose
    /// boxes overlap (exactly those pairs: see the module docs); stops early when `visit` breaks.
    /// Both hierarchies must be in the same frame (transform and [`refit`](Self::refit) first).
    pub fn for_each_pair<B>(
        &self,
        other: &Bvh,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.for_each_pair_where(other, Aabb::overlaps, visit)
    }

    /// [`for_each_pair`](Self::for_each_pair) with `near` in place of box overlap: every pair of
    /// triangles whose boxes pass `near`, reached through node pairs passing `near`. No pair is
    /// missed when `near` passes every pair of boxes enclosing a passing pair (e.g. "within
    /// distance `c`").
    pub(crate) fn for_each_pair_where<B>(
        &self,
        other: &Bvh,
        near: impl Fn(&Aabb, &Aabb) -> bool,
        mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.descend_pairs(other, false, near, |ka, kb| {
            visit(self.order[ka as usize], other.order[kb as usize])
        })
    }

    /// Calls `visit(a, b)` once for every unordered pair of distinct triangles of this one mesh
    /// whose boxes overlap, by *slots*: `a` and `b` are positions in [`order`](Self::order)
    /// (the triangles are `order[a]` and `order[b]`), where triangles close in the tree are
    /// close in memory, so callers keeping per-triangle data in slot order read it with good
    /// locality. Stops early when `visit` breaks.
    pub(crate) fn for_each_self_pair_slot<B>(
        &self,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        if self.order.is_empty() {
            return ControlFlow::Continue(()); // an empty mesh's root is not a leaf
        }
        self.descend_pairs(self, true, Aabb::overlaps, visit)
    }

    /// The simultaneous descent behind the pair enumerations, yielding slots (positions in
    /// `order`). With `same_tree` (`other` is `self`), a node paired with itself yields its own
    /// pairs once, and its children's.
    fn descend_pairs<B>(
        &self,
        other: &Bvh,
        same_tree: bool,
        near: impl Fn(&Aabb, &Aabb) -> bool,
        mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let mut stack = Vec::with_capacity(128);
        stack.push((0usize, 0usize));
        while let Some((i, j)) = stack.pop() {
            let (a, b) = (&self.nodes[i], &other.nodes[j]);
            if same_tree && i == j {
                let s = a.start as usize;
                if a.is_leaf() {
                    let e = s + a.count as usize;
                    for ka in s..e {
                        for kb in ka + 1..e {
                            if self.boxes[ka].overlaps(&self.boxes[kb]) {
                                visit(ka as u32, kb as u32)?;
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
            if !near(&a.bounds, &b.bounds) {
                continue;
            }
            match (a.is_leaf(), b.is_leaf()) {
                (true, true) => {
                    let (sa, sb) = (a.start as usize, b.start as usize);
                    for ka in sa..sa + a.count as usize {
                        let ba = &self.boxes[ka];
                        if !near(ba, &b.bounds) {
                            continue;
                        }
                        for kb in sb..sb + b.count as usize {
                            if near(ba, &other.boxes[kb]) {
                                visit(ka as u32, kb as u32)?;
                            }
                        }
                    }
                }
                (false, true) => {
                    let s = a.start as usize;
                    stack.push((s + 1, j));
                    stack.push((s, j));
                }
                (true, false) => {
                    let s = b.start as usize;
                    stack.push((i, s + 1));
                    stack.push((i, s));
                }
                (false, false) => {
                    if a.bounds.half_area() >= b.bounds.half_area() {
                        let s = a.start as usize;
                        stack.push((s + 1, j));
                        stack.push((s, j));
                    } else {
                        let s = b.start as usize;
                        stack.push((i, s + 1));
                        stack.push((i, s));
                    }
                }
            }
        }
        ControlFlow::Continue(())
    }
}

/// The best-first traversal behind [`Bvh::for_each_nearest_first`] and its posed twin: a heap
/// of nodes keyed by `node_gap`, popped nearest first until the nearest left exceeds `bound()`;
/// at a leaf, every position `k` with `leaf_item(k) = (gap, item)` within the bound is visited.
pub(crate) fn nearest_first<T, B>(
    nodes: &[BvhNode],
    node_gap: impl Fn(&BvhNode) -> f64,
    bound: impl Fn() -> f64,
    leaf_item: impl Fn(usize) -> (f64, T),
    mut visit: impl FnMut(usize, T) -> ControlFlow<B>,
) -> ControlFlow<B> {
    use std::cmp::Reverse;
    if nodes.is_empty() {
        return ControlFlow::Continue(());
    }
    // Gaps are never negative nor NaN (lower bounds of distances), so their bit patterns
    // order like the values.
    let mut heap = std::collections::BinaryHeap::with_capacity(64);
    heap.push(Reverse((node_gap(&nodes[0]).max(0.0).to_bits(), 0usize)));
    while let Some(Reverse((g, i))) = heap.pop() {
        if f64::from_bits(g) > bound() {
            break; // every node left is at least as far
        }
        let node = &nodes[i];
        let s = node.start as usize;
        if node.is_leaf() {
            for k in s..s + node.count as usize {
                let (g, item) = leaf_item(k);
                if g <= bound() {
                    visit(k, item)?;
                }
            }
        } else {
            for c in [s, s + 1] {
                let g = node_gap(&nodes[c]);
                if g <= bound() {
                    heap.push(Reverse((g.max(0.0).to_bits(), c)));
                }
            }
        }
    }
    ControlFlow::Continue(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounding::node::MAX_LEAF;

    /// The invariants the queries rely on: `order` a permutation, every position in exactly
    /// one leaf of 1 to `MAX_LEAF` boxes, children after their parent, the leaf boxes those of
    /// `order`, and every node's box the exact union of what is below it.
    fn check(bvh: &Bvh, boxes: &[Aabb]) {
        let n = boxes.len();
        let mut sorted = bvh.order().to_vec();
        sorted.sort_unstable();
        assert!(
            sorted.iter().copied().eq(0..n as u32),
            "order is a permutation"
        );
        for (b, &t) in bvh.boxes.iter().zip(bvh.order()) {
            assert_eq!(*b, boxes[t as usize]);
        }
        let nodes = bvh.nodes();
        if n == 0 {
            assert_eq!(
                nodes,
                [BvhNode {
                    bounds: Aabb::EMPTY,
                    start: 0,
                    count: 0
                }]
            );
            return;
        }
        let mut covered = vec![0; n];
        let mut reached = vec![0; nodes.len()];
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            reached[i] += 1;
            let node = nodes[i];
            let s = node.start as usize;
            let below = if node.is_leaf() {
                assert!(node.count as usize <= MAX_LEAF);
                for c in &mut covered[s..s + node.count as usize] {
                    *c += 1;
                }
                bvh.boxes[s..s + node.count as usize]
                    .iter()
                    .fold(Aabb::EMPTY, |a, b| a.union(b))
            } else {
                assert!(s > i && s + 1 < nodes.len());
                stack.extend([s, s + 1]);
                nodes[s].bounds.union(&nodes[s + 1].bounds)
            };
            assert_eq!(node.bounds, below, "node {i}");
        }
        assert!(reached.iter().all(|&r| r == 1));
        assert!(covered.iter().all(|&c| c == 1));
    }

    fn lcg(x: &mut u64) -> f64 {
        *x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*x >> 11) as f64 / (1u64 << 53) as f64
    }

    #[test]
    fn builds_keep_their_invariants() {
        let mesh = crate::shape::mesh::TriMesh::load(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/bunny.obj"
        ))
        .unwrap();
        let (v, t) = (mesh.vertices(), mesh.triangles());
        let tri_boxes: Vec<Aabb> = t.iter().map(|tri| triangle_box(v, tri)).collect();
        for s in [
            BuildStrategy::Sah,
            BuildStrategy::Median,
            BuildStrategy::Morton,
        ] {
            check(&Bvh::build_with(v, t, s), &tri_boxes);
        }
        let mut seed = 7u64;
        let mut random = |scale: f64, n: usize| -> Vec<Aabb> {
            (0..n)
                .map(|_| {
                    let p: [f64; 3] = std::array::from_fn(|_| (lcg(&mut seed) - 0.5) * scale);
                    let d: [f64; 3] = std::array::from_fn(|_| lcg(&mut seed) * scale * 0.01);
                    Aabb {
                        min: p,
                        max: std::array::from_fn(|k| p[k] + d[k]),
                    }
                })
                .collect()
        };
        let unit = Aabb {
            min: [0.0; 3],
            max: [1.0; 3],
        };
        let cases = [
            vec![],
            vec![unit],
            vec![unit; 100], // every centroid the same: median splits only
            random(1.0, 1000),
            random(1e300, 500), // beyond f32: the splits degrade, the boxes stay exact
            random(1e-300, 500),
            random(1.0, 37)
                .into_iter()
                .chain([unit; 40])
                .chain(random(1e30, 40))
                .collect(),
        ];
        for boxes in cases {
            for s in [
                BuildStrategy::Sah,
                BuildStrategy::Median,
                BuildStrategy::Morton,
            ] {
                check(&Bvh::from_boxes(boxes.clone(), s), &boxes);
            }
        }
    }
}
