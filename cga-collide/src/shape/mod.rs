//! The shapes the queries take: solid primitives, convex polyhedra and triangle meshes.
//!
//! | item | what it is |
//! |---|---|
//! | [`Segment`], [`Triangle`] | closed segment and closed triangle (a degenerate triangle is the segment or point it collapses to) |
//! | [`Sphere`], [`Ball`] | the spherical *surface* and the solid ball |
//! | [`Cuboid`] | a solid box (any parallelepiped: centre and three half axes) |
//! | [`Capsule`] | the points within a radius of a segment |
//! | [`Cylinder`], [`Cone`] | solid cylinder with flat caps, solid cone with its base disc |
//! | [`HalfSpace`] | the closed half-space below a plane |
//! | [`ConvexHull`] | the exact convex hull of points |
//! | [`Shape`] | any solid primitive above (the generic queries' and scenes' argument) |
//! | [`PosePair`] | the poses of the two objects of one query of a batch |
//! | [`polyhedron::ConvexPolyhedron`] | a validated convex polyhedron (vertices and faces) |
//! | [`mesh::TriMesh`] | an indexed triangle mesh, with OBJ/OFF/PLY/STL loaders and built-in fixtures (feature `builtin-meshes`) |
//!
//! # Semantics of the primitives
//! Every primitive is a **closed** set, and it is the set described by the exact real values
//! of the `f64` numbers given: a cuboid's corners `c ± U ± V ± W`, a cylinder's rim, a cone's
//! surface are never rounded. A pose moves a primitive by the crate's one placement rule
//! ([`Shape::placed`]): each defining point is mapped and each defining vector rotated in
//! `f64`, rounded once per coordinate, radii unchanged; the placed primitive is then taken
//! exactly, the same in every frame and batch (meshes follow the same rule for their
//! vertices).
//!
//! Constructors are fallible: non-finite input is a typed error ([`crate::Error`]), never a
//! panic; the primitives added for the generic queries also refuse magnitudes beyond
//! [`MAX_MAGNITUDE`] and negative radii, and name the degenerate cases they refuse (a
//! cylinder or cone whose axis ends coincide, a zero half-space normal, an empty hull).
//! Degenerate cases they accept denote the smaller set they collapse to (a zero radius, a flat
//! cuboid, a flat hull). The conformal (5D) representations of these objects are in
//! [`crate::conformal`].

mod any;
pub(crate) mod bounded;
mod capsule;
mod cone;
mod convex_hull;
mod cuboid;
mod cylinder;
mod exact_hull;
mod half_space;
pub(crate) mod limits;
pub mod mesh;
pub mod polyhedron;
mod pose_pair;

pub use any::Shape;
pub use bounded::{Ball, Segment, Sphere, Triangle};
pub use capsule::Capsule;
pub use cone::Cone;
pub use convex_hull::ConvexHull;
pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use half_space::HalfSpace;
pub use limits::MAX_MAGNITUDE;
pub use mesh::TriMesh;
pub use polyhedron::ConvexPolyhedron;
pub use pose_pair::PosePair;
