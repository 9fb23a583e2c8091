//! Conformal primitives: thin typed wrappers over blades of [`ga_core::cga`].
//!
//! | type | outer (OPNS) blade, as in the thesis | inner (IPNS) form |
//! |---|---|---|
//! | [`Point`] | `P = F(x)` (grade 1) | the same vector |
//! | [`PointPair`] | `P1 ∧ P2` (grade 2) | its dual (grade 3) |
//! | [`FlatPoint`] | `P ∧ n_inf` (grade 2) | its dual (grade 3) |
//! | [`Line`] | `P1 ∧ P2 ∧ n_inf` (grade 3) | its dual (grade 2) |
//! | [`Circle`] | `P1 ∧ P2 ∧ P3` (grade 3) | its dual (grade 2) |
//! | [`Plane`] | `P1 ∧ P2 ∧ P3 ∧ n_inf` (grade 4) | `n + d n_inf` (grade 1) |
//! | [`Sphere`] | `P1 ∧ P2 ∧ P3 ∧ P4` (grade 4) | `F(c) − r² n_inf` (grade 1) |
//!
//! (This `Sphere` is the conformal sphere, with meets and versors, a different type from the
//! bounded [`crate::Sphere`] that the pair queries take; write `conformal::Sphere`. `From`
//! converts a bounded sphere exactly, `TryFrom` goes back, failing for an imaginary sphere.)
//!
//! # Conventions
//! * `n_inf = e4 + e5`, `n_0 = (e5 − e4)/2`, `dual(A) = A I⁻¹`, `undual(A) = A I`
//!   (`docs/conventions.md`). The IPNS form of every primitive is `dual` of its OPNS blade
//!   ([`Plane::ipns`], [`Sphere::ipns`], ...), and `undual` goes back.
//! * Points are embedded at the thesis's scale `F(x) = 2x + |x|² n_inf − n̄ = 2 up(x)` (with
//!   `n̄ = e4 − e5`). It needs no division, so every blade is a polynomial in the inputs and the
//!   same generic code runs on `f64`, on error-bounded `f64` ([`crate::exact::ErrF64`]) and on
//!   exact rationals. Blades are homogeneous: every extraction below is invariant under
//!   nonzero scaling (and sign) of the blade.
//! * Orientation: the IPNS vector of `Plane::from_points(a, b, c)` is `dual(P1∧P2∧P3∧n_inf)`,
//!   whose normal is `(c − a) × (b − a)` (the thesis's blade order gives the clockwise normal);
//!   [`Plane::from_normal_offset`] keeps the given normal.
//!
//! # Exactness
//! Every primitive remembers the `f64` data it was built from (points, centre and radius,
//! normal and offset, point and direction). **The primitive is the exact geometric object
//! those `f64` numbers denote**: constructors decide degeneracy exactly, and the
//! classifications of [`meet`] are exact for these objects (certified `f64` first, exact
//! rationals rebuilt from the same data when the sign is uncertain). The stored `f64` blade
//! ([`Line::blade`], ...) is the rounded value of that exact blade; [`Line::exact_blade`]
//! gives the exact one. Extracted Euclidean data (centres, radii, intersection points) are
//! `f64` approximations. A transformed primitive ([`versor`]) is the primitive built exactly
//! from the rounded Euclidean data of the transformed blade.
//!
//! ```
//! use cga_collide::conformal::{Line, Sphere, meet::{line_sphere, LineSphere}};
//! use cga_collide::nalgebra::{Point3, Vector3};
//!
//! let s = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
//! let l = Line::from_point_direction(Point3::new(0.0, 1.0, 0.0), Vector3::x())?; // touches s
//! assert!(matches!(line_sphere(&l, &s), LineSphere::Tangent(p) if (p - Point3::new(0.0, 1.0, 0.0)).norm() < 1e-12));
//! # Ok::<(), cga_collide::Error>(())
//! ```
//!
//! # API tour
//!
//! ```
//! use cga_collide::conformal::meet::{LinePlane, LineSphere, Meet, SpherePlane, SphereSphere};
//! use cga_collide::conformal::{Line, Plane, Point, Reflection, Sphere, Transform, Versor};
//! use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
//!
//! // Primitives from points (outer forms, as in the thesis) or from Euclidean data (inner forms).
//! let l = Line::from_points(Point3::new(-2.0, 0.0, 1.0), Point3::new(2.0, 0.0, 1.0))?;
//! let s = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
//! let p = Plane::from_normal_offset(Vector3::z(), 1.0)?; // z = 1
//! let t = Sphere::from_points([Point3::new(1.0, 0.0, 0.0), Point3::new(-1.0, 0.0, 0.0),
//!                              Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, -1.0)])?;
//!
//! // Exact classification of the meet; the variants carry f64 geometry.
//! assert!(matches!(l.meet(&s), LineSphere::Tangent(x) if (x - Point3::new(0.0, 0.0, 1.0)).norm() < 1e-12));
//! assert_eq!(l.meet(&p), LinePlane::Contained);
//! assert!(matches!(s.meet(&p), SpherePlane::Tangent(_)));
//! assert_eq!(s.meet(&t), SphereSphere::Coincident);
//!
//! // Tangency stays exact at any scale: the certified f64 filter defers to exact rationals.
//! let k = 2f64.powi(400); // about 2.6e120: every f64 product overflows
//! let a = Sphere::from_centre_radius(Point3::origin(), 5.0 * k)?;
//! let b = Sphere::from_centre_radius(Point3::new(0.0, 8.0 * k, 0.0), 3.0 * k)?;
//! assert!(matches!(a.meet(&b), SphereSphere::TangentExternal(_)));
//!
//! // Degenerate input is a typed error, decided exactly.
//! assert!(Plane::from_points(Point3::origin(), Point3::new(1.0, 1.0, 1.0), Point3::new(2.0, 2.0, 2.0)).is_err());
//!
//! // Versors: translators, rotors, dilators, reflections, and nalgebra isometries.
//! let iso = Isometry3::new(Vector3::new(0.0, 0.0, 5.0), Vector3::y() * std::f64::consts::FRAC_PI_2);
//! let moved = s.transform(&Versor::from(iso))?;
//! assert!((moved.centre() - Point3::new(0.0, 0.0, 5.0)).norm() < 1e-12);
//! let grown = s.transform(&Versor::dilator(3.0)?)?;
//! assert!((grown.radius().unwrap() - 3.0).abs() < 1e-12);
//! let mirrored = Point::new(Point3::new(0.0, 0.0, 3.0))?.reflect(&Reflection::new(&p))?;
//! assert!((mirrored.position().unwrap() - Point3::new(0.0, 0.0, -1.0)).norm() < 1e-12);
//!
//! // Outer ↔ inner forms (dual(A) = A I⁻¹) and back to Euclidean data.
//! let p2 = Plane::from_blade(*p.blade())?;
//! assert_eq!((p2.normal(), p2.offset()), (Vector3::z(), 1.0));
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod blades;
mod circle;
mod flat_point;
mod line;
pub mod meet;
mod plane;
mod point;
mod point_pair;
mod sphere;
pub mod versor;

pub(crate) use crate::exact::{all_zero, decide, CertifiedScalar};
pub(crate) use blades::*;
pub use circle::Circle;
pub use flat_point::FlatPoint;
pub use line::Line;
pub(crate) use line::LineDef;
pub use plane::Plane;
pub use point::Point;
pub use point_pair::PointPair;
pub use sphere::Sphere;
pub use versor::{Reflection, Transform, Versor};
