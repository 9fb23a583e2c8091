//! Exact collision tests in the 5D conformal model of Euclidean space.
//!
//! * [`shapes`]: the bounded shapes [`Segment`], [`Triangle`], [`Sphere`] (surface) and
//!   [`Ball`] (solid), built by fallible constructors ([`GeometryError`]).
//! * [`intersect`]: exact tests `a.intersects(&b)` ([`Intersects`]) between them, built on the
//!   certified polynomial predicates of [`predicates`] and [`filter`].
//! * [`conformal`]: the conformal primitives (points, point pairs, lines, circles, planes,
//!   spheres, flat points) as typed blades of `ga_core::cga`, versors acting on them, and the
//!   exact meet classification of the thesis's six pairs ([`conformal::meet`]).
//! * [`euclid`]: Euclidean `f64` reference tests (Möller 1997, Möller–Trumbore, sphere tests).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod adversarial;
pub mod bvh;
pub mod conformal;
pub mod convex;
pub mod double_sphere;
pub mod error;
pub mod euclid;
pub mod experiment;
pub mod filter;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod intersect;
pub mod oracle;
pub mod plot;
pub mod polyhedron;
pub mod predicates;
pub mod query;
pub mod shapes;
pub mod sphere_tree;

pub use error::GeometryError;
pub use intersect::{Intersects, IntersectsWith};
pub use shapes::{Ball, Segment, Sphere, Triangle};

pub use ga_core;
pub use nalgebra;

pub mod mesh;
