//! Operations between two primitives: segments, triangles, sphere surfaces and solid balls.
//!
//! # Naming rule
//! * `query::intersects_<a>_<b>(&a, &b) -> bool`: the **exact** test of a pair of bounded
//!   shapes (closed sets: touching counts), e.g. [`intersects_segment_triangle`]. The same tests
//!   are methods through the [`Intersects`] trait (`a.intersects(&b)`, both argument orders).
//! * `query::within_distance_<a>_<b>(&a, &b, c) -> bool`: exact clearance, also through
//!   [`WithinDistance`].
//! * `query::distance_<a>_<b>(&a, &b)`: the minimum distance with witnesses and a proved error
//!   bound ([`CertifiedDistance`]); `query::exact_distance_<a>_<b>` in rationals
//!   ([`ExactDistance`]).
//! * [`triangle_intersection`]: the exact intersection of two triangles ([`ContactGeometry`]);
//!   [`ray_crosses_triangle`]: the exact ray-parity step of point-in-solid tests.
//! * [`segment_triangle_entry`]: the exact parameter at which a segment first meets a triangle
//!   (the first hit of a segment cast).
//!
//! * The solid primitives ([`Shape`](crate::shape::Shape): cuboids, capsules, cylinders,
//!   cones, half-spaces, convex hulls, with balls, triangles and segments) go through one
//!   generic entry point: [`intersects`], [`within_distance`], [`distance`], their `_at` forms
//!   under poses and `_batch` forms over many [`PosePair`](crate::shape::PosePair)s; the pair
//!   functions of the naming rule exist for every pair of them too
//!   (`intersects_cuboid_capsule`, `distance_ball_cylinder`, ...; see each for its
//!   signature).
//!
//! Each test takes one shape of each kind; the questions about whole meshes are built on them,
//! over box trees of the triangles.
//! Every exact answer is the true answer for the real numbers the `f64` inputs denote; the
//! signs come from [`crate::exact`].

pub(crate) mod closest_points;
pub(crate) mod contact;
pub(crate) mod containment;
pub(crate) mod coplanar;
pub(crate) mod distance;
pub(crate) mod intersects;
pub(crate) mod prepared;
pub(crate) mod segment_entry;
pub(crate) mod separation;
pub(crate) mod shapes;
pub(crate) mod within_distance;

pub use contact::{triangle_intersection, ContactGeometry, ExactPoint};
pub use containment::ray_crosses_triangle;
pub use distance::{
    distance_ball_ball, distance_ball_sphere, distance_segment_ball, distance_segment_segment,
    distance_segment_sphere, distance_segment_triangle, distance_sphere_sphere,
    distance_triangle_ball, distance_triangle_sphere, distance_triangle_triangle,
    exact_distance_segment_segment, exact_distance_segment_triangle,
    exact_distance_triangle_triangle, CertifiedDistance, ExactDistance,
};
pub use intersects::{
    intersects_ball_ball, intersects_ball_sphere, intersects_segment_ball,
    intersects_segment_segment, intersects_segment_sphere, intersects_segment_triangle,
    intersects_sphere_sphere, intersects_triangle_ball, intersects_triangle_sphere,
    intersects_triangle_triangle, Intersects,
};
pub use segment_entry::segment_triangle_entry;
pub use shapes::depth::{
    signed_distance, signed_distance_at, signed_distance_batch, SignedDistance, SignedDistanceKind,
    MAX_HULL_POINTS,
};
pub use shapes::manifold::{
    contact_manifold, contact_manifold_at, contact_manifold_batch, ContactManifold, ManifoldPoint,
    MAX_POINTS_PER_REGION,
};
pub use shapes::named::*;
pub use shapes::{
    distance, distance_at, distance_batch, intersects, intersects_at, intersects_batch,
    within_distance, within_distance_at, within_distance_batch,
};
pub use within_distance::{
    within_distance_ball_ball, within_distance_ball_sphere, within_distance_segment_ball,
    within_distance_segment_segment, within_distance_segment_sphere,
    within_distance_segment_triangle, within_distance_sphere_sphere, within_distance_triangle_ball,
    within_distance_triangle_sphere, within_distance_triangle_triangle, WithinDistance,
};
