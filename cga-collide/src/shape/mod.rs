//! The shapes the queries take: bounded primitives, convex polyhedra and triangle meshes.
//!
//! | item | what it is |
//! |---|---|
//! | [`Segment`], [`Triangle`] | closed segment and closed triangle (a degenerate triangle is the segment or point it collapses to) |
//! | [`Sphere`], [`Ball`] | the spherical *surface* and the solid ball |
//! | [`polyhedron::ConvexPolyhedron`] | a validated convex polyhedron (vertices and faces) |
//! | [`mesh::TriMesh`] | an indexed triangle mesh, with OBJ/OFF/PLY/STL loaders and built-in fixtures (feature `builtin-meshes`) |
//!
//! Constructors are fallible: non-finite input is a typed error ([`crate::Error`]), never a
//! panic. The conformal
//! (5D) representations of these objects are in [`crate::conformal`].

pub(crate) mod bounded;
pub mod mesh;
pub mod polyhedron;

pub use bounded::{Ball, Segment, Sphere, Triangle};
pub use mesh::TriMesh;
pub use polyhedron::ConvexPolyhedron;
