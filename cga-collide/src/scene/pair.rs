//! How a pair of placed objects is decided: each kind pair (mesh–mesh, mesh–shape,
//! shape–shape) by its own exact query, so the scene asks one question whatever the objects
//! are.

use nalgebra::Isometry3;

use super::{Held, Object, Scene};
use crate::collider::Collider;
use crate::error::Error;
use crate::query::{self, CertifiedDistance};
use crate::shape::Shape;

/// One object as the pair queries read it: a mesh at its pose, or a placed shape.
#[derive(Clone, Copy)]
pub(super) enum Placed<'a> {
    Mesh(&'a Collider, &'a Isometry3<f64>),
    Shape(&'a Shape),
}

impl Object {
    pub(super) fn placed(&self) -> Placed<'_> {
        match &self.held {
            Held::Mesh(collider) => Placed::Mesh(collider, &self.pose),
            Held::Shape { placed, .. } => Placed::Shape(placed),
        }
    }
}

/// The shapes are placed already: the identity places them again exactly (every product
/// with its rotation is by 0 or 1, every sum with 0).
const IDENTITY: Isometry3<f64> = Isometry3 {
    rotation: nalgebra::UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(
        1.0, 0.0, 0.0, 0.0,
    )),
    translation: nalgebra::Translation3::new(0.0, 0.0, 0.0),
};

/// The same certified distance seen from the other object.
fn swapped(d: CertifiedDistance) -> CertifiedDistance {
    CertifiedDistance {
        witness_a: d.witness_b,
        witness_b: d.witness_a,
        triangles: d.triangles.map(|(i, j)| (j, i)),
        ..d
    }
}

impl Placed<'_> {
    /// Whether the two touch: surfaces meet (a shape is a solid), or with `solid` the closed
    /// solids share a point.
    pub(super) fn touches(self, other: Placed, solid: bool) -> Result<bool, Error> {
        match (self, other) {
            (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) if solid => a.collides_solid_at(pa, b, pb),
            (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.collides_at(pa, b, pb),
            (Placed::Mesh(m, pose), Placed::Shape(s))
            | (Placed::Shape(s), Placed::Mesh(m, pose)) => {
                if solid {
                    m.intersects_shape_solid_at(pose, s, &IDENTITY)
                } else {
                    m.intersects_shape_at(pose, s, &IDENTITY)
                }
            }
            (Placed::Shape(a), Placed::Shape(b)) => query::intersects(a, b),
        }
    }

    /// Whether the two (surfaces of meshes, solid shapes) come within `c`, exactly.
    pub(super) fn within(self, other: Placed, c: f64) -> Result<bool, Error> {
        match (self, other) {
            (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.within_distance_at(pa, b, pb, c),
            (Placed::Mesh(m, pose), Placed::Shape(s))
            | (Placed::Shape(s), Placed::Mesh(m, pose)) => {
                m.shape_within_distance_at(pose, s, &IDENTITY, c)
            }
            (Placed::Shape(a), Placed::Shape(b)) => query::within_distance(a, b, c),
        }
    }

    /// The certified distance, witnesses in the pair's order.
    pub(super) fn distance(self, other: Placed) -> Result<CertifiedDistance, Error> {
        match (self, other) {
            (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.distance_at(pa, b, pb),
            (Placed::Mesh(m, pose), Placed::Shape(s)) => m.distance_to_shape_at(pose, s, &IDENTITY),
            (Placed::Shape(s), Placed::Mesh(m, pose)) => {
                m.distance_to_shape_at(pose, s, &IDENTITY).map(swapped)
            }
            (Placed::Shape(a), Placed::Shape(b)) => query::distance(a, b),
        }
    }

    /// The distance when the surfaces (a shape's solid) meet, `None` when they do not: what
    /// the nearest-object searches stop at.
    pub(super) fn touching_distance(
        self,
        other: Placed,
    ) -> Result<Option<CertifiedDistance>, Error> {
        if let (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) = (self, other) {
            return a.touching_distance_at(pa, b, pb);
        }
        if self.touches(other, false)? {
            self.distance(other).map(Some)
        } else {
            Ok(None)
        }
    }
}

impl Scene {
    /// Whether two placed objects touch, in the scene's sense.
    pub(super) fn touch(&self, a: u32, b: u32) -> Result<bool, Error> {
        self.slot(a)
            .placed()
            .touches(self.slot(b).placed(), self.solid)
    }

    pub(super) fn distance(&self, a: u32, b: u32) -> Result<CertifiedDistance, Error> {
        self.slot(a).placed().distance(self.slot(b).placed())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    #[test]
    fn the_identity_constant_is_the_identity() {
        assert_eq!(IDENTITY, Isometry3::identity());
        let p = Point3::new(0.1, -3e-300, 7e300);
        assert_eq!(IDENTITY * p, p);
    }
}
