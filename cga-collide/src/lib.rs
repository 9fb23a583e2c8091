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
//! | [`query`] | pairwise tests (`query::intersects_<a>_<b>`), plain-`f64` baselines, the convex test, mesh queries ([`query::Collider`]) |
//! | [`hierarchy`] | bounding-volume hierarchy, the double outer/inner sphere tree, octree sphere trees |
//! | `testing` | test oracles and adversarial inputs (feature `testing`) |
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

pub mod conformal;
pub mod error;
pub mod exact;
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
