//! Collision between two [`SphereTree`]s: the simultaneous descent behind
//! [`SphereTree::collides`], and the paper's method with the references the tests and the
//! experiments compare it with (re-exported under `cga_collide::testing::sphere_tree`).
//!
//! Two trees collide when a leaf ball of one meets a leaf ball of the other (closed balls:
//! touching counts, as the paper's `sumaRadio >= distancia`). Every ball–ball test is exact
//! ([`crate::exact::balls_meet`]: the conformal `BallBall` predicate, certified `f64` with exact
//! fall-back), where the paper's C++ computes `sqrt` in `float`.
//!
//! # The paper's method (§3.1, `Colision_Arbol` / `Colision_Esfera_Arbol` /
//! `Colision_Real`)
//! 1. test the roots of X and Y; if they meet,
//! 2. descend X from its root, entering every child that meets the root of Y, and list the
//!    leaves of X that meet the root of Y (list `L`);
//! 3. for each leaf of `L`, descend Y from its root towards a leaf that meets it.
//!
//! The C++ of `Colision_Real` returns the answer of the **first** child that meets the leaf
//! (`return m_lstEsferas[i]->Colision_Real(o_esf);`), so it follows a single path down Y and
//! misses a collision that lies under a later child whenever an earlier child's ball meets the
//! leaf but none of that child's leaves do. [`paper_method_as_published`] keeps that quirk (it
//! can answer "no collision" for colliding trees: see the test
//! `paper_method_as_published_misses_a_collision`); [`paper_method`] is the same code with that
//! one line fixed (a child that does not lead to a leaf hit lets the loop go on), which is what
//! the paper's prose (step 3: compare each element of `L` against tree Y *until* a leaf of Y
//! meets it) describes. Both keep the C++'s other quirk: a leaf of X is tested against Y's
//! root twice (once as a child in its parent's loop, once as a leaf), which only shows in the
//! test counts.
//!
//! # Simultaneous descent ([`simultaneous`])
//! Depth-first over pairs of nodes: a pair whose balls do not meet is dropped; a pair of
//! leaves that meet is a collision; otherwise the node with the larger ball (a leaf never) is
//! replaced by its children.
//!
//! # When they agree
//! When every child ball lies inside its parent ball (true of every tree [`octree::build`]
//! makes; [`SphereTree::nesting_violations`] checks it), a pair of meeting leaves implies that
//! all their ancestors meet, so [`paper_method`], [`simultaneous`] and [`brute_force`] (every
//! leaf pair) give the same answer; the tests check it on random trees. On trees that are not
//! nested they may differ (pruning by a parent that does not contain its child).
//!
//! [`octree::build`]: super::octree::build

// The paper's methods and the brute force are only reached through `testing`.
#![cfg_attr(not(any(test, feature = "testing")), allow(dead_code))]

use nalgebra::Isometry3;

use super::{SphereTree, SphereTreeNode};
use crate::exact::balls_meet;

/// The answer of a tree–tree collision query and what it cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CollisionResult {
    /// Whether a leaf ball of X meets a leaf ball of Y (as far as the method looks).
    pub collides: bool,
    /// How many ball–ball tests were made.
    pub sphere_tests: u64,
    /// A meeting pair of leaves (breadth-first indices in X and Y) when `collides`.
    pub witness: Option<(usize, usize)>,
    /// For the paper's methods: how many leaves of X were listed in step 2 before the answer
    /// was known (the whole list: step 2 completes before step 3 starts). 0 for the others.
    pub listed_leaves: usize,
}

struct Counter(u64);

impl Counter {
    #[inline]
    fn meet(&mut self, a: &SphereTreeNode, b: &SphereTreeNode) -> bool {
        self.0 += 1;
        balls_meet(&a.centre, a.radius, &b.centre, b.radius)
    }
}

/// Step 2 of the seed (`Colision_Esfera_Arbol`): the leaves of X met by the ball `o`, in the
/// C++'s depth-first order, with its tests (each leaf is tested in its parent's loop and then
/// again as a leaf).
fn list_leaves(x: &SphereTree, o: &SphereTreeNode, tests: &mut Counter) -> Vec<usize> {
    let mut out = Vec::new();
    let mut stack = vec![0usize];
    while let Some(i) = stack.pop() {
        let n = x.node(i);
        if n.is_leaf() {
            if tests.meet(n, o) {
                out.push(i);
            }
        } else {
            // The loop tests every child in order and recurses into a meeting child at once;
            // pushing the meeting ones in reverse visits them in the same order.
            let meeting: Vec<usize> = x
                .children(i)
                .filter(|&c| tests.meet(x.node(c), o))
                .collect();
            stack.extend(meeting.into_iter().rev());
        }
    }
    out
}

/// The paper's `Colision_Real` **as written**: from the root of Y, follow the first child whose
/// ball meets `o`; report whether the leaf reached meets `o`.
fn real_as_written(y: &SphereTree, o: &SphereTreeNode, tests: &mut Counter) -> Option<usize> {
    let mut i = 0usize;
    loop {
        let n = y.node(i);
        if n.is_leaf() {
            return tests.meet(n, o).then_some(i);
        }
        match y.children(i).find(|&c| tests.meet(y.node(c), o)) {
            Some(c) => i = c,
            None => return None,
        }
    }
}

/// `Colision_Real` with the fix: every child whose ball meets `o` is tried in turn (in the
/// C++'s order: a child is tested, entered at once if it meets, and the next child is tested
/// only when that subtree found no leaf).
fn real_fixed(y: &SphereTree, o: &SphereTreeNode, tests: &mut Counter) -> Option<usize> {
    real_fixed_from(y, 0, o, tests)
}

/// [`real_fixed`] from node `start`, iteratively (explicit stack of child cursors) so deep
/// trees cannot overflow the call stack.
fn real_fixed_from(
    y: &SphereTree,
    start: usize,
    o: &SphereTreeNode,
    tests: &mut Counter,
) -> Option<usize> {
    // Each frame: (node, next child to try).
    let mut frames: Vec<(usize, usize)> = Vec::new();
    let mut current = start;
    loop {
        let n = y.node(current);
        if n.is_leaf() {
            if tests.meet(n, o) {
                return Some(current);
            }
        } else {
            frames.push((current, y.children(current).start));
        }
        // Advance the innermost loop to its next meeting child.
        loop {
            let frame = frames.last_mut()?;
            let end = y.children(frame.0).end;
            let mut next = None;
            while frame.1 < end {
                let c = frame.1;
                frame.1 += 1;
                if tests.meet(y.node(c), o) {
                    next = Some(c);
                    break;
                }
            }
            match next {
                Some(c) => {
                    current = c;
                    break;
                }
                None => {
                    frames.pop();
                }
            }
        }
    }
}

fn paper_method_with(
    x: &SphereTree,
    y: &SphereTree,
    real: impl Fn(&SphereTree, &SphereTreeNode, &mut Counter) -> Option<usize>,
) -> CollisionResult {
    let mut tests = Counter(0);
    let mut result = CollisionResult {
        collides: false,
        sphere_tests: 0,
        witness: None,
        listed_leaves: 0,
    };
    if tests.meet(x.root(), y.root()) {
        let leaves = list_leaves(x, y.root(), &mut tests);
        result.listed_leaves = leaves.len();
        for &l in &leaves {
            if let Some(j) = real(y, x.node(l), &mut tests) {
                result.collides = true;
                result.witness = Some((l, j));
                break;
            }
        }
    }
    result.sphere_tests = tests.0;
    result
}

/// The paper's method exactly as its C++ is written, including the first-child quirk of
/// `Colision_Real` (see the module docs): it can miss collisions. For comparison only.
pub fn paper_method_as_published(x: &SphereTree, y: &SphereTree) -> CollisionResult {
    paper_method_with(x, y, real_as_written)
}

/// The paper's method with `Colision_Real` fixed to try every meeting child (see the module
/// docs). Exact on nested trees.
pub fn paper_method(x: &SphereTree, y: &SphereTree) -> CollisionResult {
    paper_method_with(x, y, real_fixed)
}

/// Simultaneous descent over pairs of nodes, splitting the larger ball first.
pub fn simultaneous(x: &SphereTree, y: &SphereTree) -> CollisionResult {
    let mut tests = Counter(0);
    let mut stack = vec![(0usize, 0usize)];
    let mut witness = None;
    while let Some((i, j)) = stack.pop() {
        let (a, b) = (x.node(i), y.node(j));
        if !tests.meet(a, b) {
            continue;
        }
        let split_x = match (a.is_leaf(), b.is_leaf()) {
            (true, true) => {
                witness = Some((i, j));
                break;
            }
            (false, true) => true,
            (true, false) => false,
            (false, false) => a.radius >= b.radius,
        };
        if split_x {
            stack.extend(x.children(i).rev().map(|c| (c, j)));
        } else {
            stack.extend(y.children(j).rev().map(|c| (i, c)));
        }
    }
    CollisionResult {
        collides: witness.is_some(),
        sphere_tests: tests.0,
        witness,
        listed_leaves: 0,
    }
}

/// Every leaf of X against every leaf of Y (the reference answer; quadratic).
pub fn brute_force(x: &SphereTree, y: &SphereTree) -> CollisionResult {
    let mut tests = Counter(0);
    let lx: Vec<usize> = (0..x.len()).filter(|&i| x.node(i).is_leaf()).collect();
    let ly: Vec<usize> = (0..y.len()).filter(|&j| y.node(j).is_leaf()).collect();
    let mut witness = None;
    'outer: for &i in &lx {
        for &j in &ly {
            if tests.meet(x.node(i), y.node(j)) {
                witness = Some((i, j));
                break 'outer;
            }
        }
    }
    CollisionResult {
        collides: witness.is_some(),
        sphere_tests: tests.0,
        witness,
        listed_leaves: 0,
    }
}

impl SphereTree {
    /// Whether a leaf ball of this tree meets a leaf ball of `other` (closed balls: touching
    /// counts; every ball–ball test exact), by a simultaneous depth-first descent over pairs of
    /// nodes that splits the larger ball first, with a meeting leaf pair as witness and the
    /// number of ball tests made. Both trees in the same frame; on nested trees (every child
    /// ball inside its parent, as [`octree::build`](super::octree::build) makes them) the
    /// answer is that of testing every leaf pair.
    ///
    /// ```
    /// use cga_collide::hierarchy::sphere_tree::{CellState, SphereTree};
    /// let a = SphereTree::single([0.0, 0.0, 0.0], 1.0, CellState::Full)?;
    /// let b = SphereTree::single([2.0, 0.0, 0.0], 1.0, CellState::Full)?; // touching
    /// let c = SphereTree::single([2.0 + 1e-15, 0.0, 0.0], 1.0, CellState::Full)?;
    /// assert!(a.collides(&b).collides);
    /// assert_eq!(a.collides(&b).witness, Some((0, 0)));
    /// assert!(!a.collides(&c).collides);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn collides(&self, other: &SphereTree) -> CollisionResult {
        simultaneous(self, other)
    }

    /// [`collides`](Self::collides) with this tree moved by `pose` and `other` by
    /// `other_pose`: both trees are [`transformed`](Self::transformed) (a new tree each, with
    /// the radii raised by its rounding margin) and then tested.
    ///
    /// ```
    /// use cga_collide::hierarchy::sphere_tree::{CellState, SphereTree};
    /// use cga_collide::nalgebra::Isometry3;
    /// let a = SphereTree::single([0.0, 0.0, 0.0], 1.0, CellState::Full)?;
    /// let here = Isometry3::identity();
    /// assert!(a.collides_at(&here, &a, &Isometry3::translation(1.5, 0.0, 0.0)).collides);
    /// assert!(!a.collides_at(&here, &a, &Isometry3::translation(2.5, 0.0, 0.0)).collides);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn collides_at(
        &self,
        pose: &Isometry3<f64>,
        other: &SphereTree,
        other_pose: &Isometry3<f64>,
    ) -> CollisionResult {
        simultaneous(&self.transformed(pose), &other.transformed(other_pose))
    }
}
