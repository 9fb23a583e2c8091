//! Queries: does A meet B, and which parts of two meshes meet.
//!
//! # Naming rule
//! * `query::intersects_<a>_<b>(&a, &b) -> bool` is the **exact** test of a pair of bounded
//!   shapes (closed sets: touching counts), e.g. [`intersects_segment_triangle`]. The same tests
//!   are methods through the [`Intersects`] trait (`a.intersects(&b)`, both argument orders),
//!   and [`IntersectsWith`] runs them with another sign [`Kernel`](crate::exact::Kernel).
//! * [`baseline`]`::<a>_<b>` are the plain-`f64` Euclidean tests (Möller, Möller–Trumbore,
//!   closest points): fast, not exact; baselines for benchmarks and comparisons.
//! * [`convex`] decides whether two convex solids intersect (certified GJK).
//! * [`Collider`] answers mesh queries (shape against mesh, mesh against mesh, containment)
//!   with a [`Bvh`](crate::bvh::Bvh) or by brute force ([`Mode`]).
//! * [`posed`]: the same mesh queries under rigid poses (`*_at` methods of [`Collider`]), with
//!   no per-pose work proportional to the mesh size, and the `*_batch` methods for many poses at once,
//!   spread over the cores.
//!
//! Every exact answer is the true answer for the real numbers the `f64` inputs denote; the
//! signs come from [`crate::exact`].

pub mod baseline;
mod batch;
pub mod clearance;
mod collider;
pub mod contact;
mod containment;
pub mod convex;
pub mod distance;
mod intersects;
mod oriented_boxes;
mod proximity;
pub mod self_intersection;

pub use clearance::{
    mesh_pairs_within_distance, meshes_within_distance, within_distance_ball_ball,
    within_distance_ball_sphere, within_distance_segment_ball, within_distance_segment_segment,
    within_distance_segment_sphere, within_distance_segment_triangle,
    within_distance_sphere_sphere, within_distance_triangle_ball, within_distance_triangle_sphere,
    within_distance_triangle_triangle, WithinDistance,
};
mod placed_leaves;
mod pose_tree;
pub mod posed;

pub use batch::{BatchError, PosePair};
pub use collider::{Collider, Mode};
pub use contact::{
    contact_class, contact_geometry, triangle_intersection, Contact, ContactGeometry, ExactPoint,
};
pub use containment::{point_in_solid, ray_crosses_triangle};
pub use distance::{
    distance_ball_ball, distance_ball_sphere, distance_segment_ball, distance_segment_segment,
    distance_segment_sphere, distance_segment_triangle, distance_sphere_sphere,
    distance_triangle_ball, distance_triangle_sphere, distance_triangle_triangle,
    exact_distance_segment_segment, exact_distance_segment_triangle,
    exact_distance_triangle_triangle, exact_mesh_distance, mesh_distance, Distance, ExactDistance,
};
pub use intersects::{
    intersects_ball_ball, intersects_segment_ball, intersects_segment_segment,
    intersects_segment_sphere, intersects_segment_triangle, intersects_sphere_sphere,
    intersects_triangle_ball, intersects_triangle_sphere, intersects_triangle_triangle, Intersects,
    IntersectsWith,
};
pub use posed::PoseError;
pub use self_intersection::{self_intersections, self_intersections_brute, self_intersects};
