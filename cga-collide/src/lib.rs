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
//! | [`query`] | operations between two primitives: `intersects_<a>_<b>`, `within_distance_<a>_<b>`, `distance_<a>_<b>` |
//! | [`bounding`] | how candidates are found: the box tree over a mesh's triangles ([`bounding::Bvh`]) |
//! | [`collider`] | [`Collider`]: a mesh built once, and every question about it |
//! | [`motion`] | continuous collision: vertex–face and edge–edge contact while points move between two poses, exactly, and the first contact time |
//! | [`scene`] | [`scene::Scene`]: many placed colliders, a broad phase that follows them, exact answers for every pair |
//! | [`robot`] | [`robot::Robot`]: a URDF's kinematic tree and collision geometry; self- and environment collisions, clearance and distance at any configuration |
//! | [`hierarchy`] | the papers' sphere hierarchies: the double outer/inner sphere tree, octree sphere trees |
//! | `gpu` | the thesis's brute-force batches on a GPU (wgpu), exact answers (feature `gpu`) |
//! | `testing` | test oracles, adversarial inputs, plain-`f64` baselines and signs, exact-stage counters, brute-force twins, the double-sphere experiment's convex reference (feature `testing`) |
//!
//! Errors of every kind are one type, [`Error`], saying what was wrong and where.
//!
//! # Features
//! | feature | what it adds | default |
//! |---|---|---|
//! | `parallel` | brute-force scans, pair lists, batches and tree builds over all cores (rayon) | on |
//! | `builtin-meshes` | the bunny, bunny00 and armadillo fixture meshes compiled in (about 1.8 MB) | off |
//! | `gpu` | the thesis's brute-force batches on a GPU (wgpu), exact after a CPU re-decision | off |
//! | `testing` | oracles, adversarial inputs, `f64` baselines and signs, exact-stage counters, the papers' research variants | off |
//!
//! # One calling style
//! Every question about meshes is a method of the [`Collider`] that holds the built data: in one
//! frame `a.x(&b)`, under poses `a.x_at(&pose_a, &b, &pose_b)` (coal's and parry's order), many
//! poses at once `a.x_batch(&b, &poses)`. How a query is run (box tree or brute force) is the
//! collider's [`collider::Mode`], the same in both frames. The table of questions is in
//! [`collider`]; operations between two primitives are the free functions of [`query`]. New
//! kinds of objects (scenes, motion between poses) follow the same shape.
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
//! # Ok::<(), cga_collide::Error>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bounding;
pub mod collider;
pub mod conformal;
pub mod error;
pub mod exact;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod hierarchy;
pub mod motion;
mod parallel;
pub mod query;
pub mod robot;
pub mod scene;
pub mod shape;
#[cfg(feature = "testing")]
pub mod testing;

pub use collider::Collider;
pub use error::Error;
pub use query::Intersects;
pub use shape::{mesh, Ball, Segment, Sphere, TriMesh, Triangle};

pub use ga_core;
pub use nalgebra;

/// The repository README's Rust snippets, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
