//! Octree sphere trees (the method of Fuentes Socorro's work): a hierarchy of spheres, one per
//! non-empty cell of an octree over a closed mesh, and collision between two such trees.
//!
//! * [`SphereTree`]: the 8-ary tree itself (this module), stored flat in breadth-first order;
//!   [`NestedNode`] is the recursive form used to build one by hand or from a file.
//! * [`octree`]: building a tree from a closed [`TriMesh`](crate::shape::mesh::TriMesh), cells
//!   classified full / partial / empty exactly (by an exact triangle–box test).
//! * [`SphereTree::collides`] / [`SphereTree::collides_at`]: collision of two trees by a
//!   simultaneous descent; every sphere–sphere test is exact. (The paper's own method, as
//!   published and with its one defect fixed, is kept for the experiments that compare them,
//!   under the `testing` feature.)
//! * [`format`](mod@format): the paper's text format (its annex), reader and writer.
//!
//! ```
//! use cga_collide::hierarchy::sphere_tree::{CellState, NestedNode, SphereTree};
//! let leaf = |x: f64| NestedNode::leaf([x, 0.0, 0.0], 1.0, CellState::Full);
//! let tree = SphereTree::from_nested(&NestedNode {
//!     centre: [0.0; 3],
//!     radius: 3.0,
//!     state: CellState::Partial,
//!     children: vec![leaf(-1.0), leaf(1.0)],
//! })?;
//! assert_eq!(tree.len(), 3);
//! assert_eq!(tree.children(0).len(), 2);
//! assert!(tree.nesting_violations().is_empty());
//! # Ok::<(), cga_collide::Error>(())
//! ```

pub(crate) mod collide;
pub mod format;
pub mod octree;
pub(crate) mod tribox;

pub use collide::CollisionResult;

use std::collections::VecDeque;
use std::ops::Range;

use crate::error::Error;
use crate::exact::ball_inside;
use nalgebra::{Isometry3, Point3};

/// The state of an octree cell, as the paper's format writes it (`1` partial, `0` full).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CellState {
    /// The cell lies wholly inside the solid (format code `0`).
    Full,
    /// The surface meets the closed cell (format code `1`).
    Partial,
}

impl CellState {
    /// The paper's code: `0` full, `1` partial.
    pub fn code(self) -> u8 {
        match self {
            CellState::Full => 0,
            CellState::Partial => 1,
        }
    }

    /// The state of a code of the format (`0` full, `1` partial), `None` for anything else.
    pub fn from_code(code: u8) -> Option<CellState> {
        match code {
            0 => Some(CellState::Full),
            1 => Some(CellState::Partial),
            _ => None,
        }
    }
}

/// One node of a [`SphereTree`]: a closed ball, its cell's state, and where its children are.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereTreeNode {
    /// Centre of the ball.
    pub centre: [f64; 3],
    /// Radius of the ball (finite, not negative).
    pub radius: f64,
    /// State of the octree cell the ball stands for.
    pub state: CellState,
    first_child: u32,
    child_count: u8,
}

impl SphereTreeNode {
    /// Whether the node has no children.
    pub fn is_leaf(&self) -> bool {
        self.child_count == 0
    }

    /// The number of children (at most 8).
    pub fn child_count(&self) -> usize {
        usize::from(self.child_count)
    }
}

/// A sphere-tree node in recursive form (children owned), for building a tree by hand and as
/// the reader's intermediate form. Convert with [`SphereTree::from_nested`] /
/// [`SphereTree::to_nested`].
#[derive(Debug, Clone, PartialEq)]
pub struct NestedNode {
    /// Centre of the ball.
    pub centre: [f64; 3],
    /// Radius of the ball.
    pub radius: f64,
    /// State of the cell.
    pub state: CellState,
    /// The children, at most 8.
    pub children: Vec<NestedNode>,
}

impl NestedNode {
    /// A node without children.
    pub fn leaf(centre: [f64; 3], radius: f64, state: CellState) -> NestedNode {
        NestedNode {
            centre,
            radius,
            state,
            children: Vec::new(),
        }
    }
}

impl Drop for NestedNode {
    /// Drops the subtree iteratively, so that very deep trees (read from a file) cannot
    /// overflow the stack.
    fn drop(&mut self) {
        let mut stack = std::mem::take(&mut self.children);
        while let Some(mut n) = stack.pop() {
            stack.append(&mut n.children);
        }
    }
}

/// A child ball that is not inside its parent ball (see [`SphereTree::nesting_violations`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NestingViolation {
    /// Breadth-first index of the parent.
    pub parent: usize,
    /// Breadth-first index of the child.
    pub child: usize,
    /// `|c_child - c_parent| + r_child - r_parent` in `f64` (positive: how far the child ball
    /// sticks out).
    pub excess: f64,
}

/// An 8-ary tree of closed balls, stored flat in breadth-first order: node 0 is the root and
/// the children of every node are contiguous. The layout is canonical (it depends only on the
/// tree's shape and contents), so two trees are equal exactly when they have the same nodes in
/// the same order.
///
/// The collision test ([`collides`](Self::collides)) treats the union of the leaf balls as the
/// object; it is exact (and agrees with the paper's method and with every leaf pair) when every
/// child ball lies inside its parent ball, which [`octree::build`] guarantees and
/// [`nesting_violations`](Self::nesting_violations) checks.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereTree {
    nodes: Vec<SphereTreeNode>,
}

impl SphereTree {
    /// A tree of a single ball.
    pub fn single(centre: [f64; 3], radius: f64, state: CellState) -> Result<SphereTree, Error> {
        Self::from_nested(&NestedNode::leaf(centre, radius, state))
    }

    /// The tree of a recursive node, laid out breadth-first. Checks that every value is finite,
    /// every radius non-negative and no node has more than 8 children.
    pub fn from_nested(root: &NestedNode) -> Result<SphereTree, Error> {
        let mut nodes: Vec<SphereTreeNode> = Vec::new();
        let mut queue: VecDeque<&NestedNode> = VecDeque::new();
        queue.push_back(root);
        // Index that the next pushed node will get.
        let mut next = 1usize;
        while let Some(n) = queue.pop_front() {
            let index = nodes.len();
            for (what, value) in [
                ("centre x", n.centre[0]),
                ("centre y", n.centre[1]),
                ("centre z", n.centre[2]),
                ("radius", n.radius),
            ] {
                if !value.is_finite() {
                    return Err(Error::SphereTreeNonFinite {
                        node: index,
                        what,
                        value,
                    });
                }
            }
            if n.radius < 0.0 {
                return Err(Error::SphereTreeNegativeRadius {
                    node: index,
                    radius: n.radius,
                });
            }
            if n.children.len() > 8 {
                return Err(Error::SphereTreeTooManyChildren {
                    node: index,
                    count: n.children.len(),
                });
            }
            if next + n.children.len() > u32::MAX as usize {
                return Err(Error::SphereTreeTooLarge {
                    count: next + n.children.len(),
                });
            }
            nodes.push(SphereTreeNode {
                centre: n.centre,
                radius: n.radius,
                state: n.state,
                first_child: if n.children.is_empty() {
                    0
                } else {
                    next as u32
                },
                child_count: n.children.len() as u8,
            });
            next += n.children.len();
            queue.extend(n.children.iter());
        }
        Ok(SphereTree { nodes })
    }

    /// Builds from nodes already in the canonical layout (used by the octree builder).
    pub(crate) fn from_raw(nodes: Vec<SphereTreeNode>) -> SphereTree {
        SphereTree { nodes }
    }

    pub(crate) fn raw_node(
        centre: [f64; 3],
        radius: f64,
        state: CellState,
        first_child: u32,
        child_count: u8,
    ) -> SphereTreeNode {
        SphereTreeNode {
            centre,
            radius,
            state,
            first_child,
            child_count,
        }
    }

    /// The recursive form (for writing depth-first).
    pub fn to_nested(&self) -> NestedNode {
        self.nested_at(0)
    }

    fn nested_at(&self, root: usize) -> NestedNode {
        // Iterative post-order so that deep trees cannot overflow the stack.
        let mut built: Vec<Option<NestedNode>> = vec![None; self.nodes.len()];
        let mut stack = vec![(root, false)];
        while let Some((i, expanded)) = stack.pop() {
            if expanded {
                let n = &self.nodes[i];
                let children = self
                    .children(i)
                    .map(|c| {
                        built[c]
                            .take()
                            .unwrap_or_else(|| unreachable!("child built"))
                    })
                    .collect();
                built[i] = Some(NestedNode {
                    centre: n.centre,
                    radius: n.radius,
                    state: n.state,
                    children,
                });
            } else {
                stack.push((i, true));
                stack.extend(self.children(i).map(|c| (c, false)));
            }
        }
        built[root]
            .take()
            .unwrap_or_else(|| unreachable!("root built"))
    }

    /// All nodes, breadth-first (root first).
    pub fn nodes(&self) -> &[SphereTreeNode] {
        &self.nodes
    }

    /// Node `i` (breadth-first index).
    pub fn node(&self, i: usize) -> &SphereTreeNode {
        &self.nodes[i]
    }

    /// The root.
    pub fn root(&self) -> &SphereTreeNode {
        &self.nodes[0]
    }

    /// The number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Always `false`: a tree has at least its root.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The indices of the children of node `i`.
    pub fn children(&self, i: usize) -> Range<usize> {
        let n = &self.nodes[i];
        let s = n.first_child as usize;
        s..s + n.child_count as usize
    }

    /// The number of leaves.
    pub fn leaf_count(&self) -> usize {
        self.nodes.iter().filter(|n| n.is_leaf()).count()
    }

    /// The number of edges on the longest root-to-leaf path (0 for a single ball).
    pub fn height(&self) -> usize {
        let mut depth = vec![0usize; self.nodes.len()];
        let mut h = 0;
        for i in 0..self.nodes.len() {
            for c in self.children(i) {
                depth[c] = depth[i] + 1;
                h = h.max(depth[c]);
            }
        }
        h
    }

    /// Heap bytes of the node array (what a query reads).
    pub fn heap_bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<SphereTreeNode>()
    }

    /// Every child ball that is not inside its parent ball, decided exactly: the child is
    /// inside when `r_parent - r_child >= |c_child - c_parent|`.
    pub fn nesting_violations(&self) -> Vec<NestingViolation> {
        let mut out = Vec::new();
        for i in 0..self.nodes.len() {
            let p = &self.nodes[i];
            for c in self.children(i) {
                let n = &self.nodes[c];
                if !ball_inside(&n.centre, n.radius, &p.centre, p.radius) {
                    let d = Point3::from(n.centre) - Point3::from(p.centre);
                    out.push(NestingViolation {
                        parent: i,
                        child: c,
                        excess: d.norm() + n.radius - p.radius,
                    });
                }
            }
        }
        out
    }

    /// The same tree with every parent radius raised (bottom-up, centres kept) just enough that
    /// it contains its children's balls, decided exactly. Afterwards
    /// [`nesting_violations`](Self::nesting_violations) is empty.
    pub fn nested_enclosing(&self) -> SphereTree {
        let mut nodes = self.nodes.clone();
        for i in (0..nodes.len()).rev() {
            let mut r = nodes[i].radius;
            for c in self.children(i) {
                let (cc, cr) = (nodes[c].centre, nodes[c].radius);
                let d = (Point3::from(cc) - Point3::from(nodes[i].centre)).norm();
                let mut need = d + cr;
                while !ball_inside(&cc, cr, &nodes[i].centre, need) {
                    need = need.max(f64::MIN_POSITIVE).next_up();
                }
                r = r.max(need);
            }
            nodes[i].radius = r;
        }
        SphereTree { nodes }
    }

    /// The tree moved by a rigid motion: every centre is mapped in `f64`, radii are kept and
    /// then raised by a margin of `16·2^-52·(|c|∞ + |t|∞ + r)` (rounded up), meant to cover the
    /// rounding of the rotated centre and of the mesh vertices that
    /// [`TriMesh::transformed`](crate::shape::mesh::TriMesh::transformed) moves the same way, so that
    /// the union of the leaf balls still contains the moved solid. This margin is a generous
    /// estimate of those `f64` errors, not a proof (the ball–ball tests themselves are exact).
    pub fn transformed(&self, iso: &Isometry3<f64>) -> SphereTree {
        let t = iso.translation.vector.abs().max();
        let nodes = self
            .nodes
            .iter()
            .map(|n| {
                let p = iso.transform_point(&Point3::from(n.centre));
                let scale = Point3::from(n.centre).coords.abs().max() + t + n.radius;
                let margin = 16.0 * f64::EPSILON * scale;
                SphereTreeNode {
                    centre: [p.x, p.y, p.z],
                    radius: (n.radius + margin).next_up(),
                    ..*n
                }
            })
            .collect();
        SphereTree { nodes }
    }

    /// The tree translated by `v` ([`transformed`](Self::transformed) by a pure translation:
    /// centres moved in `f64`, radii raised by the same rounding margin).
    pub fn translated(&self, v: [f64; 3]) -> SphereTree {
        self.transformed(&Isometry3::translation(v[0], v[1], v[2]))
    }
}
