//! Exact collision tests in the 5D conformal model of Euclidean space.
//!
//! * [`shapes`]: the bounded shapes [`Segment`], [`Triangle`], [`Sphere`] (surface) and
//!   [`Ball`] (solid), built by fallible constructors ([`GeometryError`]).
//! * [`euclid`]: Euclidean `f64` reference tests (Möller 1997, Möller–Trumbore, sphere tests).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod error;
pub mod euclid;
pub mod shapes;

pub use error::GeometryError;
pub use shapes::{Ball, Segment, Sphere, Triangle};

pub use ga_core;
pub use nalgebra;
