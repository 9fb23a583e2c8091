//! Exact collision detection in the 5D conformal model of Euclidean space.
//!
//! Every yes/no answer is exact: it is the true answer for the real numbers the `f64` inputs
//! denote, with no tolerance anywhere (touching counts as intersecting). Signs are certified in
//! `f64` and recomputed exactly only when the certificate fails.
//!
//! # Where things are
//! | module | what it holds |
//! |---|---|
//! | [`exact`] | the bottom layer: certified signs of polynomial predicates, error-bounded `f64`, exact fall-backs |
//! | [`shape`] | [`Segment`], [`Triangle`], [`Sphere`] (surface), [`Ball`] (solid), convex polyhedra, [`TriMesh`] and its loaders |
//! | [`conformal`] | conformal primitives (points, point pairs, flat points, lines, circles, planes, spheres), versors, exact meets |
//! | [`bvh`] | the box tree over a mesh's triangles that the mesh queries descend |
//! | [`query`] | pairwise tests (`query::intersects_<a>_<b>`), plain-`f64` baselines, the convex test, mesh queries ([`query::Collider`]) |
//! | [`hierarchy`] | the papers' sphere hierarchies: the double outer/inner sphere tree, octree sphere trees |
//! | `gpu` | the thesis's brute-force batches on a GPU (wgpu), exact answers (feature `gpu`) |
//! | `testing` | test oracles and adversarial inputs (feature `testing`) |
//!
//! # Choosing a query
//! | question | call |
//! |---|---|
//! | do two shapes (segment, triangle, sphere surface, ball) meet? | [`query::intersects_segment_triangle`] and the other `query::intersects_<a>_<b>`, or `a.intersects(&b)` |
//! | which triangles of a mesh does a shape meet? | [`query::Collider::segment_hits`], `triangle_hits`, `sphere_hits`, `ball_hits` (`*_at` under a pose) |
//! | do two meshes touch at these poses? | [`query::Collider::collides_at`] |
//! | which triangle pairs intersect? | [`query::Collider::intersecting_pairs_at`] |
//! | many poses at once, over the cores? | [`query::Collider::collides_batch`], [`query::Collider::intersecting_pairs_batch`] |
//! | do two closed solids overlap (one may be inside the other)? | [`query::Collider::collides_solid_at`] |
//! | are they within distance `c`? (exact, closed) | [`query::meshes_within_distance`], `query::within_distance_<a>_<b>` |
//! | how far apart, and where? | [`query::mesh_distance`] (proved error bound), [`query::exact_mesh_distance`] |
//! | how do they touch? | [`query::contact_class`], [`query::contact_geometry`] |
//! | does a mesh cut itself? | [`query::self_intersections`] |
//! | does a point lie in a closed mesh? | [`query::point_in_solid`], [`query::Collider::contains_point_at`] |
//! | how do a line and a sphere meet (conformal)? | [`conformal::meet`] |
//!
//! The repository README has a quickstart (compiled as a doctest) and examples under
//! `cga-collide/examples/`.
//!
//! Layers depend only on the layers above them in this table. Conventions (basis, blade order,
//! signs, dual, null vectors, what touching means) are in the repository's
//! `docs/conventions.md`.
//!
//! ```
//! use cga_collide::nalgebra::Point3;
//! use cga_collide::{query, Intersects, Segment, Triangle};
//! let p = |x, y, z| Point3::new(x, y, z);
//! let t = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.))?;
//! let s = Segment::new(p(0.5, 0.5, -1.), p(0.5, 0.5, 1.))?; // passes through an edge
//! assert!(query::intersects_segment_triangle(&s, &t));
//! assert!(t.intersects(&s));
//! # Ok::<(), cga_collide::GeometryError>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bvh;
pub mod conformal;
pub mod error;
pub mod exact;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod hierarchy;
mod parallel;
pub mod query;
pub mod shape;
#[cfg(feature = "testing")]
pub mod testing;

pub use error::GeometryError;
pub use query::{Intersects, IntersectsWith};
pub use shape::{mesh, Ball, Segment, Sphere, TriMesh, Triangle};

pub use ga_core;
pub use nalgebra;

/// The repository README's Rust snippets, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
