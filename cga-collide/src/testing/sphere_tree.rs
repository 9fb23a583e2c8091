//! The octree sphere trees' research variants and internal steps
//! ([`crate::hierarchy::sphere_tree`]), for tests and the papers' experiments: the paper's
//! collision method (as published, and with its one defect fixed), the simultaneous descent
//! behind [`SphereTree::collides`](crate::hierarchy::sphere_tree::SphereTree::collides), every
//! leaf pair by brute force, and the octree builder's exact cell tests.
//!
//! The paper's C++ of `Colision_Real` follows only the **first** child whose ball meets the
//! leaf, so it misses a collision under a later child: [`paper_method_as_published`] keeps that
//! quirk, [`paper_method`] tries every meeting child (what the paper's prose describes). On
//! nested trees (every child ball inside its parent, as the octree builder makes them)
//! [`paper_method`], [`simultaneous`] and [`brute_force`] agree.
//!
//! ```
//! use cga_collide::hierarchy::sphere_tree::{CellState, SphereTree};
//! use cga_collide::testing::sphere_tree::{brute_force, paper_method, simultaneous};
//! let a = SphereTree::single([0.0, 0.0, 0.0], 1.0, CellState::Full)?;
//! let b = SphereTree::single([2.0, 0.0, 0.0], 1.0, CellState::Full)?; // touching
//! assert!(paper_method(&a, &b).collides);
//! assert!(simultaneous(&a, &b).collides);
//! assert!(brute_force(&a, &b).collides);
//! # Ok::<(), cga_collide::Error>(())
//! ```

pub use crate::hierarchy::sphere_tree::collide::{
    brute_force, paper_method, paper_method_as_published, simultaneous,
};
use crate::hierarchy::sphere_tree::octree;
pub use crate::hierarchy::sphere_tree::tribox::triangle_meets_box;

use crate::bounding::Aabb;

/// Whether the ball `(c, r)` contains the closed box `b` (all eight corners), exactly.
///
/// ```
/// use cga_collide::bounding::Aabb;
/// use cga_collide::testing::sphere_tree::ball_contains_box;
/// let b = Aabb { min: [-1.0; 3], max: [1.0; 3] };
/// assert!(ball_contains_box(&[0.0; 3], 3f64.sqrt().next_up(), &b));
/// assert!(!ball_contains_box(&[0.0; 3], 1.7, &b));
/// ```
pub fn ball_contains_box(c: &[f64; 3], r: f64, b: &Aabb) -> bool {
    octree::ball_contains_box(c, r, b)
}

/// The closed box of a node of a tree built by
/// [`octree::build`], from its centre, the root
/// cube's side ([`BuildReport::side`](crate::hierarchy::sphere_tree::octree::BuildReport::side))
/// and the node's level: `centre ± side / 2^(level+1)` (exact on the builder's grid).
///
/// ```
/// use cga_collide::testing::sphere_tree::cell_of;
/// let b = cell_of(&[1.0, 1.0, 1.0], 4.0, 1);
/// assert_eq!((b.min, b.max), ([0.0; 3], [2.0; 3]));
/// ```
pub fn cell_of(centre: &[f64; 3], side: f64, level: u32) -> Aabb {
    octree::cell_of(centre, side, level)
}
