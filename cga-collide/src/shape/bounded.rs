//! The bounded shapes: closed segments, closed triangles, spherical surfaces and solid balls.
//!
//! All of them are built from `nalgebra::Point3<f64>` and `f64` by fallible constructors that
//! reject non-finite coordinates and negative or non-finite radii. Once built, a shape denotes
//! the set of real points described by its (exact) `f64` data; the intersection tests in
//! [`crate::query`] answer exactly for those real numbers.
//!
//! Degenerate shapes are valid: a zero-length [`Segment`] is a point, a [`Triangle`] whose
//! vertices are collinear is the segment (or point) it collapses to, and a [`Sphere`] or
//! [`Ball`] of radius `0` is the single point at its centre (the surface of a ball of radius 0
//! is its centre, so both shapes denote the same one-point set).

use nalgebra::Point3;

use crate::error::Error;

fn check_point(shape: &'static str, argument: &'static str, p: &Point3<f64>) -> Result<(), Error> {
    for (axis, value) in ["x", "y", "z"].into_iter().zip(p.coords.iter()) {
        if !value.is_finite() {
            return Err(Error::NonFiniteCoordinate {
                shape,
                argument,
                axis,
                value: *value,
            });
        }
    }
    Ok(())
}

fn check_radius(shape: &'static str, r: f64) -> Result<(), Error> {
    if !r.is_finite() {
        return Err(Error::NonFiniteRadius { shape, value: r });
    }
    if r < 0.0 {
        return Err(Error::NegativeRadius { shape, value: r });
    }
    Ok(())
}

/// The closed segment between two points (a point when they coincide).
///
/// ```
/// use cga_collide::{nalgebra::Point3, Segment};
/// let s = Segment::new(Point3::origin(), Point3::new(1.0, 0.0, 0.0)).unwrap();
/// assert_eq!(s.b().x, 1.0);
/// assert!(Segment::new(Point3::new(f64::NAN, 0.0, 0.0), Point3::origin()).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    a: Point3<f64>,
    b: Point3<f64>,
}

impl Segment {
    /// The segment `[a, b]`; fails if a coordinate is not finite.
    pub fn new(a: Point3<f64>, b: Point3<f64>) -> Result<Self, Error> {
        check_point("Segment", "a", &a)?;
        check_point("Segment", "b", &b)?;
        Ok(Segment { a, b })
    }
    /// The first end point.
    pub fn a(&self) -> &Point3<f64> {
        &self.a
    }
    /// The second end point.
    pub fn b(&self) -> &Point3<f64> {
        &self.b
    }
}

/// The closed triangle with three vertices (a segment or point when they are collinear).
///
/// ```
/// use cga_collide::{nalgebra::Point3, Triangle, Error};
/// let t = Triangle::new(Point3::origin(), Point3::new(1.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0));
/// assert!(t.is_ok());
/// let bad = Triangle::new(Point3::origin(), Point3::origin(), Point3::new(0.0, f64::INFINITY, 0.0));
/// assert!(matches!(bad, Err(Error::NonFiniteCoordinate { argument: "c", axis: "y", .. })));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Triangle {
    v: [Point3<f64>; 3],
}

impl Triangle {
    /// A triangle from corners already known to be finite (a [`TriMesh`](crate::TriMesh)'s).
    #[inline]
    pub(crate) fn from_finite(v: [Point3<f64>; 3]) -> Triangle {
        debug_assert!(v.iter().all(|p| p.iter().all(|x| x.is_finite())));
        Triangle { v }
    }

    /// The triangle `abc`; fails if a coordinate is not finite.
    pub fn new(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> Result<Self, Error> {
        check_point("Triangle", "a", &a)?;
        check_point("Triangle", "b", &b)?;
        check_point("Triangle", "c", &c)?;
        Ok(Triangle { v: [a, b, c] })
    }
    /// The three vertices in construction order.
    pub fn vertices(&self) -> &[Point3<f64>; 3] {
        &self.v
    }
}

/// The spherical *surface* with a centre and a radius (a point for radius 0).
///
/// A triangle strictly inside a sphere does not meet it; use [`Ball`] for the solid. The
/// conformal sphere of the same surface (meets, versors) is
/// [`conformal::Sphere`](crate::conformal::Sphere), converted with `From` and `TryFrom`.
///
/// ```
/// use cga_collide::{nalgebra::Point3, Sphere, Error};
/// assert!(Sphere::new(Point3::origin(), 2.0).is_ok());
/// assert!(matches!(Sphere::new(Point3::origin(), -1.0), Err(Error::NegativeRadius { .. })));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    centre: Point3<f64>,
    radius: f64,
}

impl Sphere {
    /// The sphere of the given centre and radius; fails on non-finite coordinates and on a
    /// negative or non-finite radius. Radius `0` is allowed and denotes the centre point.
    pub fn new(centre: Point3<f64>, radius: f64) -> Result<Self, Error> {
        check_point("Sphere", "centre", &centre)?;
        check_radius("Sphere", radius)?;
        Ok(Sphere { centre, radius })
    }
    /// The centre.
    pub fn centre(&self) -> &Point3<f64> {
        &self.centre
    }
    /// The radius (non-negative).
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// The closed solid ball with a centre and a radius (a point for radius 0).
///
/// ```
/// use cga_collide::{nalgebra::Point3, Ball, Error};
/// assert!(Ball::new(Point3::origin(), 0.0).is_ok());
/// assert!(matches!(Ball::new(Point3::origin(), f64::NAN), Err(Error::NonFiniteRadius { .. })));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ball {
    centre: Point3<f64>,
    radius: f64,
}

impl Ball {
    /// The ball of the given centre and radius; fails on non-finite coordinates and on a
    /// negative or non-finite radius. Radius `0` is allowed and denotes the centre point.
    pub fn new(centre: Point3<f64>, radius: f64) -> Result<Self, Error> {
        check_point("Ball", "centre", &centre)?;
        check_radius("Ball", radius)?;
        Ok(Ball { centre, radius })
    }
    /// The centre.
    pub fn centre(&self) -> &Point3<f64> {
        &self.centre
    }
    /// The radius (non-negative).
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

impl From<Sphere> for Ball {
    /// The solid ball bounded by a sphere.
    fn from(s: Sphere) -> Ball {
        Ball {
            centre: s.centre,
            radius: s.radius,
        }
    }
}

impl From<Ball> for Sphere {
    /// The boundary surface of a ball.
    fn from(b: Ball) -> Sphere {
        Sphere {
            centre: b.centre,
            radius: b.radius,
        }
    }
}

/// A point's coordinates as a plain array (what the predicates and `f64` searches read).
#[inline(always)]
pub(crate) fn coords(p: &Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}

/// A triangle's corners as plain arrays.
#[inline(always)]
pub(crate) fn corner_coords(t: &Triangle) -> [[f64; 3]; 3] {
    let [a, b, c] = t.vertices();
    [coords(a), coords(b), coords(c)]
}
