//! The papers' sphere hierarchies. They find candidate pairs fast; every final answer is still
//! decided by the exact tests of [`crate::query`]. The box tree over a mesh's triangles that the
//! mesh queries use is [`crate::bounding`].
//!
//! | module | what it is | answers |
//! |---|---|---|
//! | [`double_sphere`] | double hierarchy of outer and inner spheres of a convex polyhedron | exact, convex solids |
//! | [`sphere_tree`] | octree sphere trees with their text format | approximate (outer spheres only), any closed mesh |

pub mod double_sphere;
pub mod sphere_tree;
