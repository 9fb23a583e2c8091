//! [`Scene`]: many objects, each a [`Collider`] (a mesh) or a solid primitive ([`Shape`])
//! placed by a pose, and exact answers about every pair of them.
//!
//! One collider (a mesh and its trees, built once) can be placed many times without copying:
//! objects hold an `Arc<Collider>`. Objects are added, moved and removed by their
//! [`ObjectId`]; moving one recomputes its world box only. A broad phase (sweep and prune over
//! the world boxes, kept sorted as objects move) finds the pairs whose boxes come close, and each
//! such pair is decided exactly by the colliders' pose queries, spread over the cores: the
//! answers are those of [`Collider::collides_at`] (or [`Collider::collides_solid_at`], see
//! [`Scene::set_solid`]), [`Collider::within_distance_at`] and [`Collider::distance_at`] for every
//! pair, as a brute force over all pairs would give them. The world boxes are conservative (they
//! hold the placed meshes as `placed()` rounds them), so no touching pair is ever dropped.
//!
//! # Shapes beside meshes
//! [`Scene::add_shape`] adds a solid primitive (a box, capsule, cylinder, cone, half-space,
//! convex hull, ball, triangle or segment), placed by its pose by the crate's placement rule
//! ([`Shape::placed`], once, when it is added or moved). Its world box is a box holding the
//! placed shape, rounded outwards; a half-space's is unbounded (the whole space, or one side
//! of a coordinate plane when its normal is along an axis), which the broad phase takes like
//! any other box. Every question then treats shapes and meshes alike, deciding each pair by
//! its own exact query: two shapes by [`query::intersects`](crate::query::intersects),
//! [`query::within_distance`](crate::query::within_distance) and
//! [`query::distance`](crate::query::distance); a mesh and a shape by
//! [`Collider::intersects_shape_at`] (the shape against the mesh's surface; with
//! [`Scene::set_solid`], [`Collider::intersects_shape_solid_at`]: a shape inside a closed mesh,
//! or a mesh inside a shape, counts), [`Collider::shape_within_distance_at`] and
//! [`Collider::distance_to_shape_at`]. A shape is always a solid: two shapes touch when they
//! share a point. Distances between a mesh and a shape are between the mesh's surface and the
//! solid shape; their `triangles` are `(i, 0)` (mesh first) or `(0, i)` (shape first), and
//! `None` between two shapes.
//!
//! Questions follow the crate's calling style: methods of the object that holds the built data,
//! poses in coal's order.
//!
//! | question | call |
//! |---|---|
//! | which pairs of objects touch? | [`Scene::colliding_pairs`] |
//! | what touches this object? | [`Scene::colliding_with`] |
//! | what would an outside collider at a pose touch? | [`Scene::colliding_at`] |
//! | what would an outside shape at a pose touch? | [`Scene::colliding_at_shape`] |
//! | which pairs are within distance `c`? (exact, closed) | [`Scene::pairs_within_distance`] |
//! | which pair is nearest, and how far apart? | [`Scene::nearest_pair`] |
//! | what is nearest to this object? | [`Scene::nearest_to`] |
//! | which objects does a segment hit? | [`Scene::segment_hits`] |
//! | in which order along it, where does it first meet each? (exact parameter) | [`Scene::segment_hits_along`] |
//! | what does a segment hit first? | [`Scene::first_segment_hit`] |
//!
//! Pairs can be left out: [`Scene::exclude_pair`] (parts that touch by design, such as adjacent
//! robot links) and collision groups ([`Scene::set_groups`]: a pair is tested only when each
//! object's groups meet the other's mask).
//!
//! ```
//! use std::sync::Arc;
//! use cga_collide::collider::{pose_from_degrees, Collider};
//! use cga_collide::nalgebra::{Isometry3, Point3};
//! use cga_collide::scene::Scene;
//! use cga_collide::TriMesh;
//! let cube = Arc::new(Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))?));
//! let mut scene = Scene::new();
//! let a = scene.add(cube.clone(), Isometry3::identity())?;
//! let b = scene.add(cube.clone(), Isometry3::translation(1.0, 0.0, 0.0))?; // face to face
//! let c = scene.add(cube.clone(), pose_from_degrees([0.0, 0.0, 45.0], [5.0, 0.0, 0.0]))?;
//! assert_eq!(scene.colliding_pairs()?, vec![(a, b)]);
//! scene.set_pose(c, Isometry3::translation(2.0, 0.0, 0.0))?; // now touching b
//! assert_eq!(scene.colliding_pairs()?, vec![(a, b), (b, c)]);
//! scene.exclude_pair(a, b)?;
//! assert_eq!(scene.colliding_pairs()?, vec![(b, c)]);
//! let (p, q, d) = scene.nearest_pair()?.expect("three objects");
//! assert_eq!((p, q, d.distance), (b, c, 0.0));
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod broad_phase;
mod manifolds;
mod queries;

mod pair;

pub use manifolds::PairManifolds;
pub use queries::{NearestPair, SegmentHit};

use std::collections::HashSet;
use std::sync::Arc;

use nalgebra::Isometry3;

use crate::bounding::shape_box::shape_box;
use crate::bounding::Aabb;
use crate::collider::Collider;
use crate::error::Error;
use crate::shape::Shape;
use broad_phase::SweepAndPrune;

/// A handle to an object of a [`Scene`]: its slot and the slot's generation, so a handle to a
/// removed object is refused rather than taken for the object that reused its slot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ObjectId {
    index: u32,
    generation: u32,
}

impl ObjectId {
    /// The object's slot: objects added to a fresh scene get 0, 1, 2, ... in order, and a slot
    /// is reused only after its object is removed.
    pub fn index(self) -> u32 {
        self.index
    }
}

/// What a scene object is: a mesh collider (shared, not copied) or a solid primitive in its
/// own frame.
#[derive(Debug, Clone)]
pub enum Body {
    /// A mesh, through its collider.
    Mesh(Arc<Collider>),
    /// A solid primitive.
    Shape(Shape),
}

/// An object's body as the queries read it.
#[derive(Debug, Clone)]
enum Held {
    Mesh(Arc<Collider>),
    /// The shape as given, and placed by the object's pose (what every query reads).
    Shape {
        shape: Shape,
        placed: Shape,
    },
}

impl Held {
    fn kind(&self) -> &'static str {
        match self {
            Held::Mesh(_) => "mesh",
            Held::Shape { shape, .. } => shape.kind(),
        }
    }
}

/// One placed object.
#[derive(Debug, Clone)]
struct Object {
    held: Held,
    pose: Isometry3<f64>,
    generation: u32,
    /// The groups the object belongs to, and the groups it may collide with.
    groups: u32,
    mask: u32,
}

/// Many placed colliders, a broad phase over their world boxes, and exact answers for every
/// pair (see the [module docs](self)).
#[derive(Debug, Clone, Default)]
pub struct Scene {
    slots: Vec<Option<Object>>,
    /// Generation of each slot's next object.
    generations: Vec<u32>,
    free: Vec<u32>,
    broad: SweepAndPrune,
    excluded: HashSet<(u32, u32)>,
    solid: bool,
}

impl Scene {
    /// An empty scene.
    pub fn new() -> Scene {
        Scene::default()
    }

    /// Number of objects.
    pub fn len(&self) -> usize {
        self.slots.iter().flatten().count()
    }

    /// Whether the scene has no object.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Adds `collider` placed at `pose`. The collider is shared, not copied: place one built
    /// collider as often as needed. Fails, adding nothing, when the pose is not a finite rigid
    /// motion or the placed coordinates are out of range ([`Error`]).
    pub fn add(
        &mut self,
        collider: Arc<Collider>,
        pose: Isometry3<f64>,
    ) -> Result<ObjectId, Error> {
        let world = collider.world_box(&pose)?;
        Ok(self.insert(Held::Mesh(collider), pose, world))
    }

    /// Adds the solid primitive `shape` placed at `pose` ([`Shape::placed`]; see the
    /// [module docs](self)). Fails, adding nothing, when the pose is not a finite rigid motion
    /// or the placed shape leaves the range of the primitives
    /// ([`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE)).
    ///
    /// ```
    /// use std::sync::Arc;
    /// use cga_collide::nalgebra::{Isometry3, Point3};
    /// use cga_collide::{scene::Scene, Ball, Collider, TriMesh};
    /// let cube = Arc::new(Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?));
    /// let mut scene = Scene::new();
    /// let block = scene.add(cube, Isometry3::identity())?;
    /// let unit_ball = Ball::new(Point3::origin(), 0.5)?;
    /// // Resting on the top face z = 1, and high above it.
    /// let resting = scene.add_shape(unit_ball.into(), Isometry3::translation(0.5, 0.5, 1.5))?;
    /// let above = scene.add_shape(unit_ball.into(), Isometry3::translation(0.5, 0.5, 3.0))?;
    /// assert_eq!(scene.colliding_pairs()?, vec![(block, resting)]);
    /// assert_eq!(scene.kind(above)?, "ball");
    /// assert!(scene.collider(above).is_err());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn add_shape(&mut self, shape: Shape, pose: Isometry3<f64>) -> Result<ObjectId, Error> {
        let (placed, world) = placed_shape(&shape, &pose)?;
        Ok(self.insert(Held::Shape { shape, placed }, pose, world))
    }

    fn insert(&mut self, held: Held, pose: Isometry3<f64>, world: Aabb) -> ObjectId {
        let index = self.free.pop().unwrap_or_else(|| {
            self.slots.push(None);
            self.generations.push(0);
            (self.slots.len() - 1) as u32
        });
        let generation = self.generations[index as usize];
        self.slots[index as usize] = Some(Object {
            held,
            pose,
            generation,
            groups: u32::MAX,
            mask: u32::MAX,
        });
        self.broad.set(index, world);
        ObjectId { index, generation }
    }

    /// Removes a mesh object, returning its collider. A shape object is refused
    /// ([`Error::WrongObjectKind`]) and stays: remove it with
    /// [`remove_object`](Self::remove_object).
    pub fn remove(&mut self, id: ObjectId) -> Result<Arc<Collider>, Error> {
        self.collider(id)?;
        match self.remove_object(id)? {
            Body::Mesh(collider) => Ok(collider),
            // Checked to be a mesh above.
            Body::Shape(shape) => Err(Error::WrongObjectKind {
                index: id.index,
                expected: "mesh",
                found: shape.kind(),
                accessor: "remove_object",
            }),
        }
    }

    /// Removes an object of either kind, returning what it was.
    pub fn remove_object(&mut self, id: ObjectId) -> Result<Body, Error> {
        self.object(id)?;
        let object = self.slots[id.index as usize].take().ok_or(unknown(id))?;
        self.generations[id.index as usize] = id.generation.wrapping_add(1);
        self.free.push(id.index);
        self.broad.remove(id.index);
        self.excluded
            .retain(|&(a, b)| a != id.index && b != id.index);
        Ok(match object.held {
            Held::Mesh(collider) => Body::Mesh(collider),
            Held::Shape { shape, .. } => Body::Shape(shape),
        })
    }

    /// Moves an object to `pose`: its world box is recomputed and nothing else. On an error
    /// (a pose that is not a finite rigid motion, coordinates out of range) the object stays
    /// where it was.
    pub fn set_pose(&mut self, id: ObjectId, pose: Isometry3<f64>) -> Result<(), Error> {
        let (world, placed) = self.object(id)?.moved(&pose)?;
        self.place(id, pose, world, placed);
        Ok(())
    }

    /// Sets an object's pose, world box and (for a shape) placed shape, all checked.
    fn place(&mut self, id: ObjectId, pose: Isometry3<f64>, world: Aabb, placed: Option<Shape>) {
        if let Some(o) = self.slots[id.index as usize].as_mut() {
            o.pose = pose;
            if let (Held::Shape { placed: old, .. }, Some(new)) = (&mut o.held, placed) {
                *old = new;
            }
        }
        self.broad.set(id.index, world);
    }

    /// Moves many objects at once (a robot configuration, a simulation step). Every pose is
    /// checked first: on an error nothing moves, and the error says which entry
    /// ([`Error::InBatch`], its index in `poses`).
    pub fn set_poses(&mut self, poses: &[(ObjectId, Isometry3<f64>)]) -> Result<(), Error> {
        use crate::parallel::*;
        let boxes: Vec<_> = poses
            .par_iter()
            .enumerate()
            .map(|(index, (id, pose))| {
                self.object(*id)
                    .and_then(|o| o.moved(pose))
                    .map_err(|source| Error::InBatch {
                        index,
                        source: Box::new(source),
                    })
            })
            .collect::<Vec<_>>()
            .into_iter()
            .collect::<Result<_, _>>()?;
        for ((id, pose), (world, placed)) in poses.iter().zip(boxes) {
            self.place(*id, *pose, world, placed);
        }
        Ok(())
    }

    /// The pose of an object.
    pub fn pose(&self, id: ObjectId) -> Result<&Isometry3<f64>, Error> {
        Ok(&self.object(id)?.pose)
    }

    /// The collider of a mesh object; a shape object is [`Error::WrongObjectKind`].
    pub fn collider(&self, id: ObjectId) -> Result<&Arc<Collider>, Error> {
        match &self.object(id)?.held {
            Held::Mesh(collider) => Ok(collider),
            other => Err(Error::WrongObjectKind {
                index: id.index,
                expected: "mesh",
                found: other.kind(),
                accessor: "shape",
            }),
        }
    }

    /// The shape of a shape object, in its own frame (as given to
    /// [`add_shape`](Self::add_shape)); a mesh object is [`Error::WrongObjectKind`].
    pub fn shape(&self, id: ObjectId) -> Result<&Shape, Error> {
        match &self.object(id)?.held {
            Held::Shape { shape, .. } => Ok(shape),
            Held::Mesh(_) => Err(Error::WrongObjectKind {
                index: id.index,
                expected: "shape",
                found: "mesh",
                accessor: "collider",
            }),
        }
    }

    /// What an object is: `"mesh"`, or its shape's kind ([`Shape::kind`], e.g. `"ball"`).
    pub fn kind(&self, id: ObjectId) -> Result<&'static str, Error> {
        Ok(self.object(id)?.held.kind())
    }

    /// The objects, in slot order.
    pub fn ids(&self) -> Vec<ObjectId> {
        self.slots
            .iter()
            .enumerate()
            .filter_map(|(index, o)| {
                o.as_ref().map(|o| ObjectId {
                    index: index as u32,
                    generation: o.generation,
                })
            })
            .collect()
    }

    /// Leaves the pair `(a, b)` out of every pair question (parts that touch by design).
    pub fn exclude_pair(&mut self, a: ObjectId, b: ObjectId) -> Result<(), Error> {
        self.object(a)?;
        self.object(b)?;
        self.excluded
            .insert((a.index.min(b.index), a.index.max(b.index)));
        Ok(())
    }

    /// Puts back a pair left out by [`exclude_pair`](Self::exclude_pair).
    pub fn include_pair(&mut self, a: ObjectId, b: ObjectId) -> Result<(), Error> {
        self.object(a)?;
        self.object(b)?;
        self.excluded
            .remove(&(a.index.min(b.index), a.index.max(b.index)));
        Ok(())
    }

    /// Collision groups: the object belongs to the groups whose bits are set in `groups`, and
    /// is tested against objects of the groups set in `mask`. A pair is tested only when each
    /// object's groups meet the other's mask. New objects are in every group with every bit of
    /// the mask set.
    pub fn set_groups(&mut self, id: ObjectId, groups: u32, mask: u32) -> Result<(), Error> {
        self.object(id)?;
        if let Some(o) = self.slots[id.index as usize].as_mut() {
            o.groups = groups;
            o.mask = mask;
        }
        Ok(())
    }

    /// What "touch" means for the pair questions: `false` (the default) the surfaces meet
    /// ([`Collider::collides_at`]); `true` the closed solids share a point, so an object wholly
    /// inside another counts ([`Collider::collides_solid_at`]; meant for closed meshes). A
    /// shape is always a solid: against a mesh, `false` asks whether it meets the mesh's
    /// surface ([`Collider::intersects_shape_at`]), `true` whether it shares a point with the
    /// mesh's solid ([`Collider::intersects_shape_solid_at`]).
    pub fn set_solid(&mut self, solid: bool) {
        self.solid = solid;
    }

    fn object(&self, id: ObjectId) -> Result<&Object, Error> {
        self.slots
            .get(id.index as usize)
            .and_then(Option::as_ref)
            .filter(|o| o.generation == id.generation)
            .ok_or(unknown(id))
    }

    /// The object in a live slot (the broad phase holds live slots only).
    fn slot(&self, index: u32) -> &Object {
        self.slots[index as usize]
            .as_ref()
            .unwrap_or_else(|| unreachable!("the broad phase holds live slots only"))
    }

    fn id_of(&self, index: u32) -> ObjectId {
        let generation = self.slots[index as usize]
            .as_ref()
            .map_or(0, |o| o.generation);
        ObjectId { index, generation }
    }

    /// Whether the pair of slots is asked about at all (exclusions and groups).
    fn tested(&self, a: u32, b: u32) -> bool {
        let (Some(x), Some(y)) = (&self.slots[a as usize], &self.slots[b as usize]) else {
            return false;
        };
        x.groups & y.mask != 0
            && y.groups & x.mask != 0
            && !self.excluded.contains(&(a.min(b), a.max(b)))
    }
}

impl Object {
    /// The world box (and for a shape, the placed shape) of this object at `pose`.
    fn moved(&self, pose: &Isometry3<f64>) -> Result<(Aabb, Option<Shape>), Error> {
        match &self.held {
            Held::Mesh(collider) => Ok((collider.world_box(pose)?, None)),
            Held::Shape { shape, .. } => {
                let (placed, world) = placed_shape(shape, pose)?;
                Ok((world, Some(placed)))
            }
        }
    }
}

/// The shape placed by `pose`, checked against the range, and its world box.
fn placed_shape(shape: &Shape, pose: &Isometry3<f64>) -> Result<(Shape, Aabb), Error> {
    let placed = shape.placed(pose)?;
    placed.check_range()?;
    let world = shape_box(&placed);
    Ok((placed, world))
}

fn unknown(id: ObjectId) -> Error {
    Error::UnknownObject {
        index: id.index,
        generation: id.generation,
    }
}
