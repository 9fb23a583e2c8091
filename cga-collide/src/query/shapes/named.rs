//! The pair functions of the crate's naming rule for the solid primitives
//! (`intersects_<a>_<b>`, `within_distance_<a>_<b>`, `distance_<a>_<b>`), one per unordered
//! pair, in the order segment, triangle, ball, cuboid, capsule, cylinder, cone, half-space,
//! convex hull (`intersects_ball_cuboid`, `distance_cuboid_capsule`). Each is the generic
//! query ([`intersects`](crate::query::intersects) and the rest) on that pair, with the same answer.
//!
//! Signatures: a pair of two kinds whose constructors check every value against
//! [`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE) (cuboid, capsule, half-space, convex hull)
//! is always answered, so `intersects_*` gives a `bool` and `distance_*` a
//! [`CertifiedDistance`]; every other pair (with a segment, triangle or ball, whose
//! constructors accept any finite value, or with a cylinder or cone) returns
//! `Result<_, Error>`. `within_distance_*` always returns `Result<bool, Error>`: the clearance
//! `c` may be refused ([`Error::InvalidClearance`]).
//!
//! ```
//! use cga_collide::{nalgebra::{Point3, Vector3}, query, shape::{Capsule, Cuboid}};
//! let cube = Cuboid::axis_aligned(Point3::origin(), Vector3::new(1.0, 1.0, 1.0))?;
//! // The capsule touches the face x = 1 along a segment.
//! let touching = Capsule::new(Point3::new(2.0, -1.0, 0.0), Point3::new(2.0, 1.0, 0.0), 1.0)?;
//! assert!(query::intersects_cuboid_capsule(&cube, &touching));
//! assert_eq!(query::distance_cuboid_capsule(&cube, &touching).distance, 0.0);
//! let apart = Capsule::new(Point3::new(2.5, -1.0, 0.0), Point3::new(2.5, 1.0, 0.0), 1.0)?;
//! assert!(!query::intersects_cuboid_capsule(&cube, &apart));
//! assert!(query::within_distance_cuboid_capsule(&cube, &apart, 0.5)?);
//! # Ok::<(), cga_collide::Error>(())
//! ```

// One macro for every kind: most are `Copy`, the hull is not, so each is cloned.
#![allow(clippy::clone_on_copy)]

use crate::error::Error;
use crate::query::shapes::{distance, intersects, polytopal, within_distance};
use crate::query::CertifiedDistance;
use crate::shape::{
    Ball, Capsule, Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Segment, Shape, Triangle,
};

macro_rules! pairs {
    ($($arm:ident $a:ident, $b:ident: $intersects:ident, $within:ident, $distance:ident;)*) => {
        $(pairs!(@$arm $a, $b, $intersects, $within, $distance);)*
    };
    (@checked $a:ident, $b:ident, $intersects:ident, $within:ident, $distance:ident) => {
        #[doc = concat!("Exact: does the `", stringify!($a), "` meet the `", stringify!($b), "`? ([`intersects`](crate::query::intersects) on the pair)")]
        pub fn $intersects(a: &$a, b: &$b) -> bool {
            polytopal::intersects(&Shape::from(a.clone()), &Shape::from(b.clone()))
        }
        pairs!(@within $a, $b, $within);
        #[doc = concat!("The certified distance between the `", stringify!($a), "` and the `", stringify!($b), "` ([`distance`](crate::query::distance) on the pair).")]
        pub fn $distance(a: &$a, b: &$b) -> CertifiedDistance {
            polytopal::distance(&Shape::from(a.clone()), &Shape::from(b.clone()))
        }
    };
    (@fallible $a:ident, $b:ident, $intersects:ident, $within:ident, $distance:ident) => {
        #[doc = concat!("Exact: does the `", stringify!($a), "` meet the `", stringify!($b), "`? ([`intersects`](crate::query::intersects) on the pair)")]
        pub fn $intersects(a: &$a, b: &$b) -> Result<bool, Error> {
            intersects(&Shape::from(a.clone()), &Shape::from(b.clone()))
        }
        pairs!(@within $a, $b, $within);
        #[doc = concat!("The certified distance between the `", stringify!($a), "` and the `", stringify!($b), "` ([`distance`](crate::query::distance) on the pair).")]
        pub fn $distance(a: &$a, b: &$b) -> Result<CertifiedDistance, Error> {
            distance(&Shape::from(a.clone()), &Shape::from(b.clone()))
        }
    };
    (@within $a:ident, $b:ident, $within:ident) => {
        #[doc = concat!("Exact: is the `", stringify!($a), "` within distance `c` of the `", stringify!($b), "`? ([`within_distance`](crate::query::within_distance) on the pair)")]
        pub fn $within(a: &$a, b: &$b, c: f64) -> Result<bool, Error> {
            within_distance(&Shape::from(a.clone()), &Shape::from(b.clone()), c)
        }
    };
}

pairs! {
    fallible Segment, Cuboid: intersects_segment_cuboid, within_distance_segment_cuboid, distance_segment_cuboid;
    fallible Segment, Capsule: intersects_segment_capsule, within_distance_segment_capsule, distance_segment_capsule;
    fallible Segment, Cylinder: intersects_segment_cylinder, within_distance_segment_cylinder, distance_segment_cylinder;
    fallible Segment, Cone: intersects_segment_cone, within_distance_segment_cone, distance_segment_cone;
    fallible Segment, HalfSpace: intersects_segment_half_space, within_distance_segment_half_space, distance_segment_half_space;
    fallible Segment, ConvexHull: intersects_segment_convex_hull, within_distance_segment_convex_hull, distance_segment_convex_hull;
    fallible Triangle, Cuboid: intersects_triangle_cuboid, within_distance_triangle_cuboid, distance_triangle_cuboid;
    fallible Triangle, Capsule: intersects_triangle_capsule, within_distance_triangle_capsule, distance_triangle_capsule;
    fallible Triangle, Cylinder: intersects_triangle_cylinder, within_distance_triangle_cylinder, distance_triangle_cylinder;
    fallible Triangle, Cone: intersects_triangle_cone, within_distance_triangle_cone, distance_triangle_cone;
    fallible Triangle, HalfSpace: intersects_triangle_half_space, within_distance_triangle_half_space, distance_triangle_half_space;
    fallible Triangle, ConvexHull: intersects_triangle_convex_hull, within_distance_triangle_convex_hull, distance_triangle_convex_hull;
    fallible Ball, Cuboid: intersects_ball_cuboid, within_distance_ball_cuboid, distance_ball_cuboid;
    fallible Ball, Capsule: intersects_ball_capsule, within_distance_ball_capsule, distance_ball_capsule;
    fallible Ball, Cylinder: intersects_ball_cylinder, within_distance_ball_cylinder, distance_ball_cylinder;
    fallible Ball, Cone: intersects_ball_cone, within_distance_ball_cone, distance_ball_cone;
    fallible Ball, HalfSpace: intersects_ball_half_space, within_distance_ball_half_space, distance_ball_half_space;
    fallible Ball, ConvexHull: intersects_ball_convex_hull, within_distance_ball_convex_hull, distance_ball_convex_hull;
    checked Cuboid, Cuboid: intersects_cuboid_cuboid, within_distance_cuboid_cuboid, distance_cuboid_cuboid;
    checked Cuboid, Capsule: intersects_cuboid_capsule, within_distance_cuboid_capsule, distance_cuboid_capsule;
    fallible Cuboid, Cylinder: intersects_cuboid_cylinder, within_distance_cuboid_cylinder, distance_cuboid_cylinder;
    fallible Cuboid, Cone: intersects_cuboid_cone, within_distance_cuboid_cone, distance_cuboid_cone;
    checked Cuboid, HalfSpace: intersects_cuboid_half_space, within_distance_cuboid_half_space, distance_cuboid_half_space;
    checked Cuboid, ConvexHull: intersects_cuboid_convex_hull, within_distance_cuboid_convex_hull, distance_cuboid_convex_hull;
    checked Capsule, Capsule: intersects_capsule_capsule, within_distance_capsule_capsule, distance_capsule_capsule;
    fallible Capsule, Cylinder: intersects_capsule_cylinder, within_distance_capsule_cylinder, distance_capsule_cylinder;
    fallible Capsule, Cone: intersects_capsule_cone, within_distance_capsule_cone, distance_capsule_cone;
    checked Capsule, HalfSpace: intersects_capsule_half_space, within_distance_capsule_half_space, distance_capsule_half_space;
    checked Capsule, ConvexHull: intersects_capsule_convex_hull, within_distance_capsule_convex_hull, distance_capsule_convex_hull;
    fallible Cylinder, Cylinder: intersects_cylinder_cylinder, within_distance_cylinder_cylinder, distance_cylinder_cylinder;
    fallible Cylinder, Cone: intersects_cylinder_cone, within_distance_cylinder_cone, distance_cylinder_cone;
    fallible Cylinder, HalfSpace: intersects_cylinder_half_space, within_distance_cylinder_half_space, distance_cylinder_half_space;
    fallible Cylinder, ConvexHull: intersects_cylinder_convex_hull, within_distance_cylinder_convex_hull, distance_cylinder_convex_hull;
    fallible Cone, Cone: intersects_cone_cone, within_distance_cone_cone, distance_cone_cone;
    fallible Cone, HalfSpace: intersects_cone_half_space, within_distance_cone_half_space, distance_cone_half_space;
    fallible Cone, ConvexHull: intersects_cone_convex_hull, within_distance_cone_convex_hull, distance_cone_convex_hull;
    checked HalfSpace, HalfSpace: intersects_half_space_half_space, within_distance_half_space_half_space, distance_half_space_half_space;
    checked HalfSpace, ConvexHull: intersects_half_space_convex_hull, within_distance_half_space_convex_hull, distance_half_space_convex_hull;
    checked ConvexHull, ConvexHull: intersects_convex_hull_convex_hull, within_distance_convex_hull_convex_hull, distance_convex_hull_convex_hull;
}
