//! How candidates are found: box trees over a mesh's triangles and what the queries under poses
//! read from them.
//!
//! | item | what it is |
//! |---|---|
//! | [`Aabb`] (`aabb`) | the axis-aligned box, exact `f64`, and its conservative segment and ball tests |
//! | [`Bvh`] (`bvh`), [`BvhNode`] (`node`) | the box tree over a mesh's triangles (flat node array, children in pairs) and its traversals |
//! | [`BuildStrategy`] (`build`) | how the tree is shaped: binned SAH, full SAH sweep of small nodes, median split, or Morton order for a one-shot build, one file each |
//! | `box_distance` | lower bounds on the distance of two boxes, for the clearance and nearest-pair searches |
//! | `pose_tree` | the same tree laid out for queries under poses (centre and half-extents per node, vertices in leaf order) |
//! | `oriented_boxes` | boxes fitted to each node's geometry, with a proved lower bound on the distance of two of them under a relative pose |
//! | `pose_bounds` | a rigid pose analysed once: its rounded matrix and the proved bounds on the rounding of `pose * v` |
//! | `shape_box` | where a solid primitive may reach: its outward-rounded box, or a half-space itself, and a lower bound on a box's distance to it |
//! | `placed_leaves` | per-thread scratch memory holding the leaves placed by a pose during one traversal |
//!
//! Every test here is conservative: it may let through a candidate that does not meet, never
//! reject one that does. The exact decision is always made afterwards, on the triangles.

mod aabb;
mod box_distance;
mod build;
mod bvh;
mod node;
pub(crate) mod oriented_boxes;
pub(crate) mod placed_leaves;
pub(crate) mod pose_bounds;
pub(crate) mod pose_tree;
pub(crate) mod shape_box;

pub use aabb::{triangle_box, Aabb};
pub(crate) use box_distance::{box_distance2, boxes_within};
pub use build::BuildStrategy;
pub(crate) use bvh::nearest_first;
pub use bvh::Bvh;
pub use node::{BvhNode, MAX_LEAF};
