//! Hierarchies that find candidate pairs fast; every final answer is still decided by the exact
//! tests of [`crate::query`].
//!
//! | module | what it is | answers |
//! |---|---|---|
//! | [`bvh`] | axis-aligned box tree over a mesh's triangles | exact, any mesh (used by [`crate::query::Collider`]) |
//! | [`double_sphere`] | double hierarchy of outer and inner spheres of a convex polyhedron | exact, convex solids |
//! | [`sphere_tree`] | octree sphere trees with their text format | approximate (outer spheres only), any closed mesh |

pub mod bvh;
pub mod double_sphere;
pub mod sphere_tree;

pub use bvh::Bvh;
