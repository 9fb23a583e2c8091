//! `Scene`: many placed colliders with the same method names as the Rust `Scene`.

use std::sync::Arc;

use cga_collide::scene::{Body, ObjectId as RsObjectId, Scene as RsScene};
use cga_collide::Segment;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::collider::Collider;
use crate::convert::{self, err, value_error};
use crate::distance::Distance;
use crate::shape_queries::shape as shape_arg;
use crate::shapes::{shape_object, PyShape};

/// A handle to an object of a ``Scene``: hashable, comparable, with ``index`` (its slot:
/// 0, 1, 2, ... in the order objects are added to a fresh scene). A handle to a removed
/// object is refused, never taken for the object that reused its slot.
#[pyclass(frozen, eq, ord, hash, from_py_object, module = "cga_collide")]
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ObjectId {
    pub inner: RsObjectId,
}

#[pymethods]
impl ObjectId {
    /// The object's slot.
    #[getter]
    fn index(&self) -> u32 {
        self.inner.index()
    }

    fn __int__(&self) -> u32 {
        self.inner.index()
    }

    fn __repr__(&self) -> String {
        format!("ObjectId({})", self.inner.index())
    }
}

fn id(i: RsObjectId) -> ObjectId {
    ObjectId { inner: i }
}

/// Many objects, each a ``Collider`` (a mesh: its surface) or a ``Shape`` (a solid
/// primitive) placed by a pose, and exact answers about every pair of them. One collider can
/// be placed many times without copying. A broad phase (sweep and prune over world boxes)
/// proposes pairs and each is decided exactly by the pair's pose queries, in parallel, with
/// the GIL released.
#[pyclass(module = "cga_collide")]
pub struct Scene {
    pub(crate) inner: RsScene,
}

impl Scene {
    fn pair<'py>(
        py: Python<'py>, (a, b): (RsObjectId, RsObjectId),
    ) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, [id(a), id(b)])
    }
}

#[pymethods]
impl Scene {
    /// An empty scene.
    #[new]
    fn py_new() -> Scene {
        Scene { inner: RsScene::new() }
    }

    /// Number of objects.
    fn __len__(&self) -> usize {
        self.inner.len()
    }

    fn __repr__(&self) -> String {
        format!("Scene(objects={})", self.inner.len())
    }

    /// Adds ``collider`` at ``pose`` (``(4, 4)``; ``None`` is the identity) and
    /// returns its ``ObjectId``. The collider is shared, not copied.
    #[pyo3(signature = (collider, pose = None))]
    fn add(&mut self, collider: &Collider, pose: Option<&Bound<'_, PyAny>>) -> PyResult<ObjectId> {
        let pose = convert::pose_or_identity(pose, "pose")?;
        self.inner.add(Arc::clone(&collider.inner), pose).map(id).map_err(err)
    }

    /// Adds the solid ``shape`` (a ``Shape``) at ``pose`` (``(4, 4)``; ``None`` is the
    /// identity; ``Shape.placed``'s rule) and returns its ``ObjectId``.
    #[pyo3(signature = (shape, pose = None))]
    fn add_shape(
        &mut self, shape: &Bound<'_, PyAny>, pose: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<ObjectId> {
        let s = shape_arg(shape, "shape")?.clone();
        let pose = convert::pose_or_identity(pose, "pose")?;
        self.inner.add_shape(s, pose).map(id).map_err(err)
    }

    /// Removes an object and returns it (the Rust ``remove_object``): its ``Collider``, or its
    /// ``Shape`` (in its own frame).
    fn remove<'py>(&mut self, py: Python<'py>, object: ObjectId) -> PyResult<Bound<'py, PyAny>> {
        match self.inner.remove_object(object.inner).map_err(err)? {
            Body::Mesh(inner) => Ok(Bound::new(py, Collider { inner })?.into_any()),
            Body::Shape(s) => shape_object(py, s),
        }
    }

    /// Moves an object to ``pose`` (``(4, 4)``).
    fn set_pose(&mut self, object: ObjectId, pose: &Bound<'_, PyAny>) -> PyResult<()> {
        let pose = convert::pose(pose, "pose")?;
        self.inner.set_pose(object.inner, pose).map_err(err)
    }

    /// Moves many objects at once: ``objects`` a sequence of ``ObjectId`` and ``poses`` a
    /// ``(k, 4, 4)`` array of the same length. Nothing moves if any pose is refused.
    fn set_poses(&mut self, objects: Vec<ObjectId>, poses: &Bound<'_, PyAny>) -> PyResult<()> {
        let poses = convert::poses(poses, "poses")?;
        if poses.len() != objects.len() {
            return Err(value_error(format!(
                "set_poses: {} objects and {} poses: give one pose per object",
                objects.len(),
                poses.len()
            )));
        }
        let moves: Vec<_> = objects.iter().map(|o| o.inner).zip(poses).collect();
        self.inner.set_poses(&moves).map_err(err)
    }

    /// The pose of an object, a ``(4, 4)`` float64 array.
    fn pose<'py>(&self, py: Python<'py>, object: ObjectId) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let p = self.inner.pose(object.inner).map_err(err)?;
        Ok(convert::matrix(py, p))
    }

    /// The collider of a mesh object (``CgaError`` for a shape object).
    fn collider(&self, object: ObjectId) -> PyResult<Collider> {
        let c = self.inner.collider(object.inner).map_err(err)?;
        Ok(Collider { inner: Arc::clone(c) })
    }

    /// The shape of a shape object, in its own frame (``CgaError`` for a mesh object).
    fn shape<'py>(&self, py: Python<'py>, object: ObjectId) -> PyResult<Bound<'py, PyAny>> {
        shape_object(py, self.inner.shape(object.inner).map_err(err)?.clone())
    }

    /// What an object is: ``"mesh"``, or its shape's ``kind``.
    fn kind(&self, object: ObjectId) -> PyResult<&'static str> {
        self.inner.kind(object.inner).map_err(err)
    }

    /// The handles of every object, in slot order.
    fn ids(&self) -> Vec<ObjectId> {
        self.inner.ids().into_iter().map(id).collect()
    }

    /// Leaves the pair ``(a, b)`` out of every pair question (parts that touch by design).
    fn exclude_pair(&mut self, a: ObjectId, b: ObjectId) -> PyResult<()> {
        self.inner.exclude_pair(a.inner, b.inner).map_err(err)
    }

    /// Undoes ``exclude_pair``.
    fn include_pair(&mut self, a: ObjectId, b: ObjectId) -> PyResult<()> {
        self.inner.include_pair(a.inner, b.inner).map_err(err)
    }

    /// Collision groups: a pair is tested only when each object's ``groups`` meet the other's
    /// ``mask`` (32-bit masks; by default every object is in every group).
    fn set_groups(&mut self, object: ObjectId, groups: u32, mask: u32) -> PyResult<()> {
        self.inner.set_groups(object.inner, groups, mask).map_err(err)
    }

    /// Whether pairs touch as closed solids (one inside the other counts) rather than
    /// surfaces.
    fn set_solid(&mut self, solid: bool) {
        self.inner.set_solid(solid);
    }

    /// Every pair of objects ``(a, b)`` that touch (surfaces, or solids after ``set_solid``; a
    /// shape is always its solid), exactly, sorted, as a list of tuples of ``ObjectId``.
    fn colliding_pairs<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let s = &self.inner;
        let pairs = py.detach(|| s.colliding_pairs()).map_err(err)?;
        pairs.into_iter().map(|p| Scene::pair(py, p)).collect()
    }

    /// Every object that touches ``object``, sorted.
    fn colliding_with(&self, py: Python<'_>, object: ObjectId) -> PyResult<Vec<ObjectId>> {
        let s = &self.inner;
        let hits = py.detach(|| s.colliding_with(object.inner)).map_err(err)?;
        Ok(hits.into_iter().map(id).collect())
    }

    /// Every object that ``collider`` (a ``Collider`` or a ``Shape``) placed at ``pose`` would
    /// touch (it is not added).
    fn colliding_at(
        &self, py: Python<'_>, collider: &Bound<'_, PyAny>, pose: &Bound<'_, PyAny>,
    ) -> PyResult<Vec<ObjectId>> {
        let s = &self.inner;
        let hits = if let Ok(c) = collider.cast::<Collider>() {
            let (c, pose) = (&c.get().inner, convert::pose(pose, "pose")?);
            py.detach(|| s.colliding_at(c, &pose))
        } else if collider.cast::<PyShape>().is_ok() {
            let (shape, pose) = (shape_arg(collider, "collider")?, convert::pose(pose, "pose")?);
            py.detach(|| s.colliding_at_shape(shape, &pose))
        } else {
            return Err(pyo3::exceptions::PyTypeError::new_err(
                "collider: expected a Collider or a Shape",
            ));
        };
        Ok(hits.map_err(err)?.into_iter().map(id).collect())
    }

    /// Every pair of objects whose surfaces (a shape's solid) come within ``c`` (closed),
    /// sorted.
    fn pairs_within_distance<'py>(
        &self, py: Python<'py>, c: f64,
    ) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let c = convert::distance_bound(c, "c")?;
        let s = &self.inner;
        let pairs = py.detach(|| s.pairs_within_distance(c)).map_err(err)?;
        pairs.into_iter().map(|p| Scene::pair(py, p)).collect()
    }

    /// The nearest pair ``(a, b, Distance)``, or ``None`` with fewer than two objects that may
    /// be paired.
    fn nearest_pair(&self, py: Python<'_>) -> PyResult<Option<(ObjectId, ObjectId, Distance)>> {
        let s = &self.inner;
        let best = py.detach(|| s.nearest_pair()).map_err(err)?;
        Ok(best.map(|(a, b, d)| (id(a), id(b), Distance::from(&d))))
    }

    /// The object nearest to ``object`` and the distance, ``(other, Distance)``, or ``None``.
    fn nearest_to(
        &self, py: Python<'_>, object: ObjectId,
    ) -> PyResult<Option<(ObjectId, Distance)>> {
        let s = &self.inner;
        let best = py.detach(|| s.nearest_to(object.inner)).map_err(err)?;
        Ok(best.map(|(b, d)| (id(b), Distance::from(&d))))
    }

    /// Every object whose surface the closed segment ``p``–``q`` meets, sorted.
    fn segment_hits(
        &self, py: Python<'_>, p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>,
    ) -> PyResult<Vec<ObjectId>> {
        let seg = Segment::new(convert::point(p, "p")?, convert::point(q, "q")?).map_err(err)?;
        let s = &self.inner;
        let hits = py.detach(|| s.segment_hits(&seg)).map_err(err)?;
        Ok(hits.into_iter().map(id).collect())
    }
}
