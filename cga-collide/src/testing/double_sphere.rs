//! Internal steps of the double-sphere tree ([`crate::hierarchy::double_sphere`]) and their
//! brute-force references, for tests: the nodes' sub-polyhedra, the smallest enclosing ball
//! (Welzl) and the inner spheres.

pub use crate::hierarchy::double_sphere::clip::{FaceOrigin, SubPolyhedron};
pub use crate::hierarchy::double_sphere::enclosing::{
    smallest_enclosing_ball, smallest_enclosing_ball_brute,
};
pub use crate::hierarchy::double_sphere::inscribed::{
    centroid_sphere, chebyshev_brute, chebyshev_sphere, depth,
};
use crate::hierarchy::double_sphere::DoubleSphereTree;

/// The convex sub-polyhedron of node `i` of `tree` (the root's is the solid itself; the two
/// children's are its clippings by the node's split plane).
///
/// ```
/// use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
/// use cga_collide::shape::polyhedron::ConvexPolyhedron;
/// use cga_collide::testing::double_sphere::part;
/// let t = DoubleSphereTree::build(&ConvexPolyhedron::cube(), 1, InnerSphereKind::Centroid)?;
/// let [a, b] = t.nodes()[0].children.unwrap();
/// let sum = part(&t, a as usize).volume() + part(&t, b as usize).volume();
/// assert!((sum - part(&t, 0).volume()).abs() < 1e-12);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn part(tree: &DoubleSphereTree, i: usize) -> &SubPolyhedron {
    tree.part(i)
}
