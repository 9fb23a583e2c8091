//! The triangles of a leaf placed under a pose, on demand, each leaf at most once per
//! traversal, in scratch memory that a thread keeps from one query to the next (no allocation
//! per pose once it has grown).
//!
//! A triangle is placed with **the expression `pose * v` of
//! [`TriMesh::transformed`](crate::TriMesh::transformed)** (hence of
//! [`Collider::placed`](crate::collider::Collider::placed)), so its coordinates are bit-identical
//! to the placed mesh's.

use std::cell::RefCell;
use std::collections::BinaryHeap;
use std::ops::Range;

use nalgebra::Isometry3;

use crate::bounding::oriented_boxes::{Carried, OrientedBox, OrientedGaps};
use crate::bounding::pose_tree::{PoseNode, PoseTree};
use crate::bounding::Aabb;
use crate::Triangle;

/// A triangle placed exactly as [`Collider::placed`](crate::collider::Collider::placed) places
/// it, with its (exact) box and its index in the mesh.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Placed {
    pub tri: Triangle,
    pub bounds: Aabb,
    pub index: u32,
}

/// Places the triangle at leaf position `k` of `tree`.
#[inline]
pub(crate) fn place(tree: &PoseTree, k: usize, iso: &Isometry3<f64>) -> Placed {
    let [a, b, d] = tree.vertices(k);
    // The expression of `TriMesh::transformed`, hence bit-identical coordinates.
    let (a, b, d) = (iso * a, iso * b, iso * d);
    let bounds = Aabb::of_points(&[a, b, d]);
    // The range check of every pose query keeps the coordinates finite (no overflow).
    let tri = Triangle::new(a, b, d)
        .unwrap_or_else(|_| unreachable!("range-checked pose gives finite coordinates"));
    Placed {
        tri,
        bounds,
        index: tree.index(k),
    }
}

/// Which leaves of one tree are placed in the current traversal: `stamp[node]` equals the
/// traversal's epoch when leaf `node` is placed, at `first[node]..` in [`Scratch::placed`].
#[derive(Debug, Default)]
struct Stamps {
    stamp: Vec<u32>,
    first: Vec<u32>,
}

/// Per-thread memory of the pose traversals.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    epoch: u32,
    trees: [Stamps; 2],
    placed: Vec<Placed>,
    /// The traversal's stack of node pairs.
    pub stack: Vec<(u32, u32)>,
    /// The best-first search's queue of node pairs (see `proximity::queued`).
    pub heap: BinaryHeap<u128>,
    /// The distance search's parts of the oriented-box bound of A's nodes and of B's (see
    /// [`OrientedGaps`]), each computed once per traversal: valid where the stamp is the
    /// traversal's epoch.
    offsets: Vec<(u32, [f64; 3])>,
    carried: Vec<(u32, Carried)>,
}

impl Scratch {
    /// Starts a traversal of two trees of `nodes_a` and `nodes_b` nodes: no leaf is placed.
    fn begin(&mut self, nodes_a: usize, nodes_b: usize) {
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            for t in &mut self.trees {
                t.stamp.fill(0);
            }
            self.epoch = 1;
        }
        for (t, n) in self.trees.iter_mut().zip([nodes_a, nodes_b]) {
            if t.stamp.len() < n {
                t.stamp.resize(n, 0);
                t.first.resize(n, 0);
            }
        }
        if self.epoch == 1 {
            self.offsets.fill((0, [0.0; 3]));
            self.carried.fill((0, Carried::default()));
        }
        if self.offsets.len() < nodes_a {
            self.offsets.resize(nodes_a, (0, [0.0; 3]));
        }
        if self.carried.len() < nodes_b {
            self.carried.resize(nodes_b, (0, Carried::default()));
        }
        self.placed.clear();
        self.stack.clear();
        self.heap.clear();
    }

    /// The oriented-box bound of node `i` of A (box `fa`) and node `j` of B (box `fb`) under
    /// `gaps`, from the per-node parts kept for this traversal (see
    /// [`OrientedGaps::gap2_carried`]).
    #[inline(always)]
    pub fn oriented_gap2(
        &mut self,
        gaps: &OrientedGaps,
        (i, fa): (u32, &OrientedBox),
        (j, fb): (u32, &OrientedBox),
        best: f64,
    ) -> f64 {
        let epoch = self.epoch;
        let o = &mut self.offsets[i as usize];
        if o.0 != epoch {
            *o = (epoch, gaps.offset(fa));
        }
        let at = o.1;
        let c = &mut self.carried[j as usize];
        if c.0 != epoch {
            *c = (epoch, gaps.carry(fb));
        }
        gaps.gap2_carried(fa, &at, fb, &c.1, best)
    }

    /// The placed triangles of leaf `node` of tree `side` (0: A, 1: B), placing them on first
    /// use in this traversal.
    #[inline]
    pub fn leaf(
        &mut self,
        side: usize,
        node: u32,
        n: &PoseNode,
        tree: &PoseTree,
        iso: &Isometry3<f64>,
    ) -> Range<usize> {
        let t = &mut self.trees[side];
        let i = node as usize;
        let count = n.count as usize;
        if t.stamp[i] == self.epoch {
            let s = t.first[i] as usize;
            return s..s + count;
        }
        let s = self.placed.len();
        t.stamp[i] = self.epoch;
        t.first[i] = s as u32;
        let start = n.start as usize;
        self.placed
            .extend((start..start + count).map(|k| place(tree, k, iso)));
        s..s + count
    }

    /// The placed triangles of a range returned by [`leaf`](Self::leaf).
    #[inline(always)]
    pub fn placed(&self, r: Range<usize>) -> &[Placed] {
        &self.placed[r]
    }
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// Runs `f` with this thread's scratch, set up for a traversal of two trees of `nodes_a` and
/// `nodes_b` nodes (a fresh one if the thread's is in use, e.g. by a caller up the stack).
pub(crate) fn with_scratch<R>(
    nodes_a: usize,
    nodes_b: usize,
    f: impl FnOnce(&mut Scratch) -> R,
) -> R {
    SCRATCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut s) => {
            s.begin(nodes_a, nodes_b);
            f(&mut s)
        }
        Err(_) => {
            let mut s = Scratch::default();
            s.begin(nodes_a, nodes_b);
            f(&mut s)
        }
    })
}
