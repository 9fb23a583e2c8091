//! The contact manifolds of every touching pair of a scene.

use super::pair::Placed;
use super::{ObjectId, Scene};
use crate::error::Error;
use crate::parallel::*;
use crate::query::{self, ContactManifold};

/// The contact manifolds of one touching pair of a [`Scene`] (`a` before `b`).
#[derive(Debug, Clone, PartialEq)]
pub struct PairManifolds {
    /// The first object.
    pub a: ObjectId,
    /// The second object.
    pub b: ObjectId,
    /// One manifold per contact region, normals from `a` to `b`.
    pub manifolds: Vec<ContactManifold>,
}

impl Scene {
    /// The contact manifolds of every touching pair (the pairs of
    /// [`colliding_pairs`](Self::colliding_pairs), sorted), computed in parallel: two shapes by
    /// [`query::contact_manifold`] with margin `0` (one manifold), two meshes by
    /// [`Collider::contact_manifolds_at`](crate::Collider::contact_manifolds_at) (one per contact
    /// region). Pairs whose surfaces meet but have no manifold (a mesh inside another, with
    /// [`set_solid`](Self::set_solid)) are left out. Refused ([`Error::UnsupportedPair`]): a mesh
    /// touching a shape (not computed yet), and the shape pairs
    /// [`query::contact_manifold`] refuses.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3, Vector3}, scene::Scene, shape::Cuboid};
    /// let mut scene = Scene::new();
    /// let cube = Cuboid::axis_aligned(Point3::origin(), Vector3::new(0.5, 0.5, 0.5))?;
    /// let a = scene.add_shape(cube.clone().into(), Isometry3::identity())?;
    /// let b = scene.add_shape(cube.into(), Isometry3::translation(0.0, 0.0, 0.9))?;
    /// let pairs = scene.contact_manifolds()?;
    /// assert_eq!((pairs[0].a, pairs[0].b), (a, b));
    /// assert_eq!(pairs[0].manifolds[0].points.len(), 4);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contact_manifolds(&self) -> Result<Vec<PairManifolds>, Error> {
        let candidates = self.candidates(0.0);
        let answers = candidates
            .par_iter()
            .map(|&(a, b)| {
                if !self.touch(a, b)? {
                    return Ok(None);
                }
                let manifolds = manifolds_of(self.slot(a).placed(), self.slot(b).placed())?;
                Ok((!manifolds.is_empty()).then(|| PairManifolds {
                    a: self.id_of(a),
                    b: self.id_of(b),
                    manifolds,
                }))
            })
            .collect::<Result<Vec<Option<PairManifolds>>, Error>>()?;
        let mut out: Vec<PairManifolds> = answers.into_iter().flatten().collect();
        out.sort_unstable_by_key(|p| (p.a, p.b));
        Ok(out)
    }
}

fn manifolds_of(a: Placed, b: Placed) -> Result<Vec<ContactManifold>, Error> {
    match (a, b) {
        (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.contact_manifolds_at(pa, b, pb),
        (Placed::Shape(a), Placed::Shape(b)) => {
            Ok(query::contact_manifold(a, b, 0.0)?.into_iter().collect())
        }
        (Placed::Mesh(..), Placed::Shape(s)) => Err(mesh_shape(s.kind(), false)),
        (Placed::Shape(s), Placed::Mesh(..)) => Err(mesh_shape(s.kind(), true)),
    }
}

fn mesh_shape(kind: &'static str, shape_first: bool) -> Error {
    let (a, b) = if shape_first {
        (kind, "mesh")
    } else {
        ("mesh", kind)
    };
    Error::UnsupportedPair {
        query: "contact_manifolds",
        a,
        b,
    }
}
