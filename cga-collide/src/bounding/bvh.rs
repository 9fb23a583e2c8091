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

#[inline(always)]
fn mn(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

#[inline(always)]
fn mx(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// An axis-aligned box `[min, max]` (closed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: [f64; 3],
    /// Largest corner.
    pub max: [f64; 3],
}

impl Aabb {
    /// The empty box (`min = +∞`, `max = -∞`), identity of [`union`](Self::union).
    pub const EMPTY: Aabb = Aabb {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
    };

    /// The smallest box holding the points (exact).
    pub fn of_points(points: &[Point3<f64>]) -> Aabb {
        let mut b = Aabb::EMPTY;
        for p in points {
            b.grow(p);
        }
        b
    }

    /// Extends the box to hold `p` (exact).
    #[inline]
    pub fn grow(&mut self, p: &Point3<f64>) {
        for k in 0..3 {
            self.min[k] = mn(self.min[k], p[k]);
            self.max[k] = mx(self.max[k], p[k]);
        }
    }

    /// The smallest box holding both (exact).
    #[inline]
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: [
                mn(self.min[0], o.min[0]),
                mn(self.min[1], o.min[1]),
                mn(self.min[2], o.min[2]),
            ],
            max: [
                mx(self.max[0], o.max[0]),
                mx(self.max[1], o.max[1]),
                mx(self.max[2], o.max[2]),
            ],
        }
    }

    /// Whether the closed boxes share a point (exact).
    #[inline]
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
            && self.min[2] <= o.max[2]
            && o.min[2] <= self.max[2]
    }

    /// Half the surface area (the SAH weight); 0 for the empty box.
    pub fn half_area(&self) -> f64 {
        let d = [
            self.max[0] - self.min[0],
            self.max[1] - self.min[1],
            self.max[2] - self.min[2],
        ];
        if d.iter().any(|x| x.is_nan() || *x < 0.0) {
            return 0.0;
        }
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    }

    fn centroid(&self) -> [f64; 3] {
        [
            self.min[0] * 0.5 + self.max[0] * 0.5,
            self.min[1] * 0.5 + self.max[1] * 0.5,
            self.min[2] * 0.5 + self.max[2] * 0.5,
        ]
    }

    /// Conservative test: `false` only if the closed segment `[p, q]` (exact reals) misses the
    /// box. A slab test in `f64` whose parameter interval is widened far beyond its rounding.
    pub fn may_meet_segment(&self, p: &Point3<f64>, q: &Point3<f64>) -> bool {
        for k in 0..3 {
            if p[k].max(q[k]) < self.min[k] || p[k].min(q[k]) > self.max[k] {
                return false;
            }
        }
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for k in 0..3 {
            let d = q[k] - p[k];
            if d == 0.0 {
                continue; // p[k] == q[k], inside the slab by the test above
            }
            if !d.is_finite() {
                return true;
            }
            let ta = (self.min[k] - p[k]) / d;
            let tb = (self.max[k] - p[k]) / d;
            let (lo, hi) = if ta <= tb { (ta, tb) } else { (tb, ta) };
            if lo.is_nan() || hi.is_nan() {
                return true;
            }
            t0 = t0.max(lo);
            t1 = t1.min(hi);
        }
        if !(t0.is_finite() && t1.is_finite()) {
            return true;
        }
        // Each t carries a relative error of a few ulps; 1e-9 relative (plus an absolute term
        // for underflow) is a wide margin.
        t0 <= t1 + (t0.abs() + t1.abs()) * 1e-9 + 1e-300
    }

    /// Squared distances from `c` to the nearest and the farthest point of the box, in `f64`.
    fn distances2(&self, c: &Point3<f64>) -> (f64, f64) {
        let (mut near, mut far) = (0.0, 0.0);
        for k in 0..3 {
            let below = self.min[k] - c[k];
            let above = c[k] - self.max[k];
            let n = below.max(above).max(0.0);
            let f = (c[k] - self.min[k]).max(self.max[k] - c[k]);
            near += n * n;
            far += f * f;
        }
        (near, far)
    }

    /// Conservative test: `false` only if the closed ball (centre `c`, radius `r`) misses the
    /// Whether the closed box meets the ray from `p` along `+x` (exact: comparisons only); the
    /// candidates of the ray-parity point-in-solid test.
    #[inline]
    pub fn meets_x_ray(&self, p: &Point3<f64>) -> bool {
        self.min[1] <= p.y
            && p.y <= self.max[1]
            && self.min[2] <= p.z
            && p.z <= self.max[2]
            && self.max[0] >= p.x
    }

    /// box.
    pub fn may_meet_ball(&self, c: &Point3<f64>, r: f64) -> bool {
        let (near, _) = self.distances2(c);
        let r2 = r * r;
        !(near.is_finite() && r2.is_finite()) || near * (1.0 - 1e-9) <= r2 * (1.0 + 1e-9) + 1e-300
    }

    /// Conservative test: `false` only if the sphere *surface* (centre `c`, radius `r`) misses
    /// the box, i.e. the box is away from the ball or strictly inside it.
    pub fn may_meet_sphere(&self, c: &Point3<f64>, r: f64) -> bool {
        let (near, far) = self.distances2(c);
        let r2 = r * r;
        if !(near.is_finite() && far.is_finite() && r2.is_finite()) {
            return true;
        }
        near * (1.0 - 1e-9) <= r2 * (1.0 + 1e-9) + 1e-300
            && far * (1.0 + 1e-9) + 1e-300 >= r2 * (1.0 - 1e-9)
    }
}

/// The box of a triangle of a mesh (exact).
#[inline]
pub fn triangle_box(vertices: &[Point3<f64>], t: &[u32; 3]) -> Aabb {
    let (a, b, c) = (
        &vertices[t[0] as usize],
        &vertices[t[1] as usize],
        &vertices[t[2] as usize],
    );
    Aabb {
        min: [
            mn(mn(a.x, b.x), c.x),
            mn(mn(a.y, b.y), c.y),
            mn(mn(a.z, b.z), c.z),
        ],
        max: [
            mx(mx(a.x, b.x), c.x),
            mx(mx(a.y, b.y), c.y),
            mx(mx(a.z, b.z), c.z),
        ],
    }
}

/// How the hierarchy chooses its splits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BuildStrategy {
    /// Binned surface-area heuristic (16 bins per split, longest centroid axis).
    #[default]
    Sah,
    /// Split at the median centroid along the longest centroid axis.
    Median,
}

/// Largest number of triangles in a leaf.
pub const MAX_LEAF: usize = 4;
const BINS: usize = 16;

/// A node: its box, and either a leaf range of [`Bvh::order`] (`count > 0`) or the index of
/// its left child (the right one follows it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BvhNode {
    /// Box of everything below.
    pub bounds: Aabb,
    /// Leaf: first position in the triangle order; inner: index of the left child.
    pub start: u32,
    /// Leaf: number of triangles; inner: 0.
    pub count: u32,
}

impl BvhNode {
    /// Whether the node is a leaf.
    #[inline]
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

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
        let tri_boxes: Vec<Aabb> = triangles
            .iter()
            .map(|t| triangle_box(vertices, t))
            .collect();
        Self::from_boxes(tri_boxes, strategy)
    }

    /// Builds the hierarchy over arbitrary boxes (leaf `i` is `boxes[i]`): e.g. the boxes that
    /// moving primitives sweep during a time step. [`refit`](Self::refit) applies only to
    /// hierarchies over triangles.
    pub fn from_boxes(tri_boxes: Vec<Aabb>, strategy: BuildStrategy) -> Bvh {
        let n = tri_boxes.len();
        let centroids: Vec<[f64; 3]> = tri_boxes.iter().map(Aabb::centroid).collect();
        let mut order: Vec<u32> = (0..n as u32).collect();
        let mut nodes = Vec::with_capacity(2 * n / MAX_LEAF + 1);
        nodes.push(BvhNode {
            bounds: Aabb::EMPTY,
            start: 0,
            count: 0,
        });
        let mut stack = vec![(0usize, 0usize, n)];
        while let Some((ni, s, e)) = stack.pop() {
            let mut bounds = Aabb::EMPTY;
            let mut cb = Aabb::EMPTY;
            for &t in &order[s..e] {
                bounds = bounds.union(&tri_boxes[t as usize]);
                let c = centroids[t as usize];
                cb = cb.union(&Aabb { min: c, max: c });
            }
            nodes[ni].bounds = bounds;
            let count = e - s;
            if count <= MAX_LEAF {
                nodes[ni].start = s as u32;
                nodes[ni].count = count as u32;
                continue;
            }
            let ext = [
                cb.max[0] - cb.min[0],
                cb.max[1] - cb.min[1],
                cb.max[2] - cb.min[2],
            ];
            let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
                0
            } else if ext[1] >= ext[2] {
                1
            } else {
                2
            };
            let mut mid = None;
            if strategy == BuildStrategy::Sah && ext[axis] > 0.0 {
                mid = sah_split(&mut order[s..e], &tri_boxes, &centroids, &cb, axis).map(|m| s + m);
            }
            let mid = mid.unwrap_or_else(|| {
                let m = count / 2;
                order[s..e].select_nth_unstable_by(m, |&a, &b| {
                    centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
                });
                s + m
            });
            let left = nodes.len();
            let blank = BvhNode {
                bounds: Aabb::EMPTY,
                start: 0,
                count: 0,
            };
            nodes.push(blank);
            nodes.push(blank);
            nodes[ni].start = left as u32;
            nodes[ni].count = 0;
            stack.push((left + 1, mid, e));
            stack.push((left, s, mid));
        }
        let boxes = order.iter().map(|&t| tri_boxes[t as usize]).collect();
        Bvh {
            nodes,
            order,
            boxes,
        }
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
    /// position of `order` in exactly one leaf of at most [`MAX_LEAF`] triangles, `order` a
    /// permutation of the triangles (`collider::serial` does, for colliders read back).
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

    /// Calls `visit(i, j)` for every pair of a triangle `i` of `self` and `j` of `other` whose
    /// boxes overlap (exactly those pairs: see the module docs); stops early when `visit` breaks.
    /// Both hierarchies must be in the same frame (transform and [`refit`](Self::refit) first).
    pub fn for_each_pair<B>(
        &self,
        other: &Bvh,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.descend_pairs(other, false, Aabb::overlaps, visit)
    }

    /// [`for_each_pair`](Self::for_each_pair) with `near` in place of box overlap: every pair of
    /// triangles whose boxes pass `near`, reached through node pairs passing `near`. No pair is
    /// missed when `near` passes every pair of boxes enclosing a passing pair (e.g. "within
    /// distance `c`").
    pub(crate) fn for_each_pair_where<B>(
        &self,
        other: &Bvh,
        near: impl Fn(&Aabb, &Aabb) -> bool,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.descend_pairs(other, false, near, visit)
    }

    /// Calls `visit(i, j)` once for every unordered pair of distinct triangles of this one mesh
    /// whose boxes overlap; stops early when `visit` breaks.
    pub(crate) fn for_each_self_pair<B>(
        &self,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        if self.order.is_empty() {
            return ControlFlow::Continue(()); // an empty mesh's root is not a leaf
        }
        self.descend_pairs(self, true, Aabb::overlaps, visit)
    }

    /// The simultaneous descent behind the pair enumerations. With `same_tree` (`other` is
    /// `self`), a node paired with itself yields its own pairs once, and its children's.
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
                                visit(self.order[ka], self.order[kb])?;
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
                                visit(self.order[ka], other.order[kb])?;
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

/// Binned SAH split of `order` along `axis`; returns the split position, or `None` when no
/// split beats keeping it whole (only for small ranges) or a side would be empty.
fn sah_split(
    order: &mut [u32],
    boxes: &[Aabb],
    centroids: &[[f64; 3]],
    cb: &Aabb,
    axis: usize,
) -> Option<usize> {
    let lo = cb.min[axis];
    let scale = BINS as f64 / (cb.max[axis] - lo);
    let bin = |t: u32| -> usize {
        let b = ((centroids[t as usize][axis] - lo) * scale) as usize;
        b.min(BINS - 1)
    };
    let mut counts = [0usize; BINS];
    let mut bin_boxes = [Aabb::EMPTY; BINS];
    for &t in order.iter() {
        let b = bin(t);
        counts[b] += 1;
        bin_boxes[b] = bin_boxes[b].union(&boxes[t as usize]);
    }
    // Sweep from the right to get suffix areas and counts.
    let mut right_area = [0.0; BINS];
    let mut right_count = [0usize; BINS];
    let (mut acc, mut cnt) = (Aabb::EMPTY, 0);
    for b in (1..BINS).rev() {
        acc = acc.union(&bin_boxes[b]);
        cnt += counts[b];
        right_area[b] = acc.half_area();
        right_count[b] = cnt;
    }
    let (mut best, mut best_cost) = (0, f64::INFINITY);
    let (mut acc, mut cnt) = (Aabb::EMPTY, 0);
    for b in 0..BINS - 1 {
        acc = acc.union(&bin_boxes[b]);
        cnt += counts[b];
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
    // Partition: bins < best to the left.
    let mut i = 0;
    for k in 0..order.len() {
        if bin(order[k]) < best {
            order.swap(i, k);
            i += 1;
        }
    }
    (i > 0 && i < order.len()).then_some(i)
}

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
