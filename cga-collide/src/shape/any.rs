//! [`Shape`]: any solid primitive, for the generic queries and for scenes.

use nalgebra::Isometry3;

use crate::error::Error;
use crate::shape::limits::{check_point, check_radius};
use crate::shape::{
    Ball, Capsule, Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Segment, Triangle,
};

/// One solid primitive of any kind: what the generic queries
/// ([`query::intersects`](crate::query::intersects) and the rest) and scenes take.
///
/// Every kind is a closed set (touching counts). Build one with `From` from the concrete
/// shape (`Shape::from(cuboid)`, `cuboid.into()`).
///
/// ```
/// use cga_collide::{nalgebra::Point3, shape::{Capsule, Shape}, Ball};
/// let s: Shape = Capsule::new(Point3::origin(), Point3::new(1.0, 0.0, 0.0), 0.5)?.into();
/// assert_eq!(s.kind(), "capsule");
/// let b: Shape = Ball::new(Point3::origin(), 1.0)?.into();
/// assert_eq!(b.kind(), "ball");
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A solid ball.
    Ball(Ball),
    /// A solid parallelepiped (a box).
    Cuboid(Cuboid),
    /// A capsule.
    Capsule(Capsule),
    /// A solid cylinder with flat caps.
    Cylinder(Cylinder),
    /// A solid cone with its base disc.
    Cone(Cone),
    /// A closed half-space.
    HalfSpace(HalfSpace),
    /// The convex hull of points.
    ConvexHull(ConvexHull),
    /// A closed triangle.
    Triangle(Triangle),
    /// A closed segment.
    Segment(Segment),
}

impl Shape {
    /// The kind's name in lower case, as the command line's JSON spells it (`"ball"`,
    /// `"cuboid"`, `"capsule"`, `"cylinder"`, `"cone"`, `"halfspace"`, `"convex"`,
    /// `"triangle"`, `"segment"`).
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Ball(_) => "ball",
            Shape::Cuboid(_) => "cuboid",
            Shape::Capsule(_) => "capsule",
            Shape::Cylinder(_) => "cylinder",
            Shape::Cone(_) => "cone",
            Shape::HalfSpace(_) => "halfspace",
            Shape::ConvexHull(_) => "convex",
            Shape::Triangle(_) => "triangle",
            Shape::Segment(_) => "segment",
        }
    }

    /// This shape moved by `pose`, by the crate's placement rule: every defining point is
    /// mapped and every defining vector rotated in `f64`, each coordinate rounded once, and
    /// radii are unchanged; the placed shape is then taken exactly. The same rule holds for
    /// every `_at` query, in every frame and batch, so `x_at(a, pa, b, pb)` is always
    /// `x(a.placed(pa), b.placed(pb))`. Fails if a placed value leaves the range
    /// ([`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE)) or a cylinder's or cone's rounded
    /// axis ends coincide.
    pub fn placed(&self, pose: &Isometry3<f64>) -> Result<Shape, Error> {
        Ok(match self {
            Shape::Ball(b) => Shape::Ball(Ball::new(pose * b.centre(), b.radius())?),
            Shape::Cuboid(c) => Shape::Cuboid(c.placed(pose)?),
            Shape::Capsule(c) => Shape::Capsule(c.placed(pose)?),
            Shape::Cylinder(c) => Shape::Cylinder(c.placed(pose)?),
            Shape::Cone(c) => Shape::Cone(c.placed(pose)?),
            Shape::HalfSpace(h) => Shape::HalfSpace(h.placed(pose)?),
            Shape::ConvexHull(h) => Shape::ConvexHull(h.placed(pose)?),
            Shape::Triangle(t) => {
                let [a, b, c] = t.vertices();
                Shape::Triangle(Triangle::new(pose * a, pose * b, pose * c)?)
            }
            Shape::Segment(s) => Shape::Segment(Segment::new(pose * s.a(), pose * s.b())?),
        })
    }

    /// Checks the range rule ([`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE)) for the kinds
    /// whose own constructors predate it (balls, triangles, segments accept every finite
    /// value): the generic queries call this before answering.
    pub(crate) fn check_range(&self) -> Result<(), Error> {
        match self {
            Shape::Ball(b) => {
                check_point("Ball", "centre", b.centre())?;
                check_radius("Ball", b.radius())
            }
            Shape::Triangle(t) => {
                let [a, b, c] = t.vertices();
                check_point("Triangle", "a", a)?;
                check_point("Triangle", "b", b)?;
                check_point("Triangle", "c", c)
            }
            Shape::Segment(s) => {
                check_point("Segment", "a", s.a())?;
                check_point("Segment", "b", s.b())
            }
            _ => Ok(()),
        }
    }
}

macro_rules! from_concrete {
    ($($kind:ident),*) => {$(
        impl From<$kind> for Shape {
            fn from(s: $kind) -> Shape {
                Shape::$kind(s)
            }
        }
    )*};
}
from_concrete!(Ball, Cuboid, Capsule, Cylinder, Cone, HalfSpace, ConvexHull, Triangle, Segment);
