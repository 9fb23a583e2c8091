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
    /// Linear hierarchy: the triangles sorted once along a Morton (Z-order) curve of their
    /// centroids, each node split where its range's codes first differ. Several times cheaper
    /// to build than [`Sah`](Self::Sah), with somewhat looser boxes.
    Morton,
}

/// Largest number of triangles in a leaf.
pub const MAX_LEAF: usize = 4;
const BINS: usize = 16;
/// Largest node split by a full SAH sweep over its sorted centroids rather than by bins.
const SWEEP: usize = 16;

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

/// A node before its range and box are known.
const BLANK: BvhNode = BvhNode {
    bounds: Aabb::EMPTY,
    start: 0,
    count: 0,
};

/// The shape of a hierarchy over the records (its nodes with empty boxes, and the leaf order).
/// The records are partitioned in place, so each level reads them contiguously; the
/// bounds of the centroids of a node's children come from its split, never from another pass.
fn shape(mut recs: Vec<Record>, strategy: BuildStrategy) -> (Vec<BvhNode>, Vec<u32>) {
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

/// Spreads the low 21 bits of `x` to every third bit.
fn spread_bits(x: u64) -> u64 {
    let mut x = x & 0x1f_ffff;
    x = (x | x << 32) & 0x1f_0000_0000_ffff;
    x = (x | x << 16) & 0x1f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    (x | x << 2) & 0x1249_2492_4924_9249
}

/// [`shape`] for [`BuildStrategy::Morton`]: one sort by the 63-bit Morton code of each
/// centroid (21 bits an axis, over the centroids' bounds), then top-down splits at the first
/// differing bit of a range's codes (found by binary search; the middle where all codes are
/// equal). No record moves after the sort.
fn shape_morton(recs: &[Record]) -> (Vec<BvhNode>, Vec<u32>) {
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

#[inline(always)]
fn mn32(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

#[inline(always)]
fn mx32(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}

/// A box in `f32` (what the build's heuristics read).
#[derive(Clone, Copy)]
struct Box32 {
    lo: [f32; 3],
    hi: [f32; 3],
}

impl Box32 {
    const EMPTY: Box32 = Box32 {
        lo: [f32::INFINITY; 3],
        hi: [f32::NEG_INFINITY; 3],
    };

    #[inline(always)]
    fn union(&self, o: &Box32) -> Box32 {
        Box32 {
            lo: std::array::from_fn(|k| mn32(self.lo[k], o.lo[k])),
            hi: std::array::from_fn(|k| mx32(self.hi[k], o.hi[k])),
        }
    }

    #[inline(always)]
    fn grow(&mut self, p: &[f32; 3]) {
        *self = self.union(&Box32 { lo: *p, hi: *p });
    }

    /// Half the surface area, in `f64` (no overflow); 0 for the empty box.
    fn half_area(&self) -> f64 {
        let d: [f64; 3] = std::array::from_fn(|k| f64::from(self.hi[k]) - f64::from(self.lo[k]));
        if d.iter().any(|x| x.is_nan() || *x < 0.0) {
            return 0.0;
        }
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    }
}

/// A leaf of the build: its box rounded to `f32`, and its index.
#[derive(Clone, Copy)]
#[repr(C, align(32))]
struct Record {
    b: Box32,
    t: u32,
}

impl Record {
    fn new(b: &Aabb, t: u32) -> Record {
        Record {
            b: Box32 {
                lo: b.min.map(|x| x as f32),
                hi: b.max.map(|x| x as f32),
            },
            t,
        }
    }

    #[inline(always)]
    fn centroid(&self) -> [f32; 3] {
        std::array::from_fn(|k| self.b.lo[k] * 0.5 + self.b.hi[k] * 0.5)
    }
}

/// A node still to split: its records `s..e` and the bounds of their centroids.
struct Task {
    node: usize,
    s: usize,
    e: usize,
    cb: Box32,
}

/// A split of a range of records at `mid` (relative to the range), with the bounds of the
/// centroids of each side.
struct Split {
    mid: usize,
    left: Box32,
    right: Box32,
}

/// The box of the records' centroids.
fn centroid_bounds(recs: &[Record]) -> Box32 {
    let mut cb = Box32::EMPTY;
    for r in recs {
        cb.grow(&r.centroid());
    }
    cb
}

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

/// Split at the median centroid along `axis` (also the fallback of the SAH splits).
fn median_split(recs: &mut [Record], axis: usize) -> Split {
    let m = recs.len() / 2;
    recs.select_nth_unstable_by(m, |a, b| a.centroid()[axis].total_cmp(&b.centroid()[axis]));
    Split {
        mid: m,
        left: centroid_bounds(&recs[..m]),
        right: centroid_bounds(&recs[m..]),
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
fn sah_split(recs: &mut [Record], ids: &mut [u8], cb: &Box32, axis: usize) -> Option<Split> {
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

/// Full SAH split of a small range (at most [`SWEEP`] records): sorted by centroid along
/// `axis`, every position between two records is a candidate (the binned splits among them).
fn sweep_split(recs: &mut [Record], axis: usize) -> Option<Split> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
