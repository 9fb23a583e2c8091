//! `Collider`: a mesh built once, and every question about it, in the crate's calling style.

use std::sync::Arc;

use cga_collide::collider::{Collider as RsCollider, Mode, PosePair};
use cga_collide::nalgebra::{Isometry3, Point3};
use cga_collide::shape::Shape;
use cga_collide::{Ball, Error, Segment, Sphere, TriMesh, Triangle};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};

use crate::answers::{contact_tuples, exact_distance_tuple};
use crate::convert::{self, bools, err, value_error, Arg, Bools, Indices, Pairs};
use crate::distance::{distance_batch, Distance, DistanceBatch};
use crate::points::{point_distances, PointDistances};
use crate::shape_queries::shape as shape_arg;

/// A triangle mesh built once (its box tree and the layout the pose queries read), and every
/// question about it.
///
/// Build it from arrays, ``Collider(vertices, faces)`` with vertices ``(n, 3)`` numbers and
/// faces ``(m, 3)`` integers (0-based), or from a file with ``Collider.load(path)`` (.obj,
/// .off, .ply, .stl, optionally .gz). Numbers float64 does not hold exactly, a wrong shape, a
/// non-finite coordinate, an index out of range or an empty mesh raise ``CgaError`` (a
/// ``ValueError``) naming the argument, vertex or face.
///
/// Every question comes in the crate's three forms: in one frame ``a.x(b)``; under poses
/// ``a.x_at(pose_a, b, pose_b)`` with ``(4, 4)`` homogeneous matrices; and many poses
/// at once ``a.x_batch(b, poses_a, poses_b)`` with ``(k, 4, 4)`` arrays (either may be one
/// ``(4, 4)`` pose used for every query), answered in one call with numpy arrays back. Yes/no
/// answers are exact: touching counts as colliding, with no tolerance anywhere.
///
/// ``mode`` is ``"bvh"`` (the default: box tree) or ``"brute"`` (every triangle): a choice of
/// speed, never of answer.
#[pyclass(frozen, module = "cga_collide")]
pub struct Collider {
    pub inner: Arc<RsCollider>,
}

/// What `Collider.__reduce__` returns: the function that restores a collider, and its
/// argument (the collider's bytes).
type Reduced<'py> = (Bound<'py, PyAny>, (Bound<'py, PyBytes>,));

fn mode_of(mode: &str) -> PyResult<Mode> {
    match mode {
        "bvh" => Ok(Mode::Bvh),
        "brute" => Ok(Mode::Brute),
        other => Err(value_error(format!("mode: expected \"bvh\" or \"brute\", got {other:?}"))),
    }
}

fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Bvh => "bvh",
        Mode::Brute => "brute",
    }
}

fn segment(p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>) -> PyResult<Segment> {
    Segment::new(convert::point(p, "p")?, convert::point(q, "q")?).map_err(err)
}

fn triangle(t: &Bound<'_, PyAny>) -> PyResult<Triangle> {
    let name = "triangle_corners";
    let [a, b, c] = convert::read(t, name, &[Some(3), Some(3)], |v| {
        Ok([0, 1, 2].map(|i| Point3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]])))
    })?;
    Triangle::new(a, b, c).map_err(err)
}

/// The questions of the Python methods, each asked through one of these with the GIL
/// released: the poses read (and refused with the argument's name) in one place.
impl Collider {
    fn new_from(mesh: TriMesh, mode: Mode) -> Collider {
        Collider { inner: Arc::new(RsCollider::new(mesh).with_mode(mode)) }
    }

    /// A question about this mesh alone, in its own frame.
    fn alone<T: Send>(&self, py: Python<'_>, q: impl FnOnce(&RsCollider) -> T + Send) -> T {
        let a = &*self.inner;
        py.detach(|| q(a))
    }

    /// A question about this mesh placed at `pose`.
    fn placed<T: Send>(
        &self, py: Python<'_>, pose: &Arg,
        q: impl FnOnce(&RsCollider, &Isometry3<f64>) -> Result<T, Error> + Send,
    ) -> PyResult<T> {
        let pose = convert::pose(pose, "pose")?;
        self.alone(py, |a| q(a, &pose)).map_err(err)
    }

    /// A question about this mesh at `pose` and a shape placed by `shape_pose`.
    fn with_shape<T: Send>(
        &self, py: Python<'_>, pose: &Arg, s: &Arg, shape_pose: &Arg,
        q: impl FnOnce(&RsCollider, &Isometry3<f64>, &Shape, &Isometry3<f64>) -> Result<T, Error> + Send,
    ) -> PyResult<T> {
        let s = shape_arg(s, "shape")?;
        let (pose, shape_pose) =
            (convert::pose(pose, "pose")?, convert::pose(shape_pose, "shape_pose")?);
        self.alone(py, |a| q(a, &pose, s, &shape_pose)).map_err(err)
    }

    /// A question about `self` and `other` in one frame.
    fn with<T: Send>(
        &self, py: Python<'_>, other: &Collider,
        q: impl FnOnce(&RsCollider, &RsCollider) -> T + Send,
    ) -> T {
        let (a, b) = (&*self.inner, &*other.inner);
        py.detach(|| q(a, b))
    }

    /// A question with `self` at `pose_a` and `other` at `pose_b`.
    fn at<T: Send>(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
        q: impl FnOnce(&RsCollider, &Isometry3<f64>, &RsCollider, &Isometry3<f64>) -> Result<T, Error>
            + Send,
    ) -> PyResult<T> {
        let pa = convert::pose(pose_a, "pose_a")?;
        let pb = convert::pose(pose_b, "pose_b")?;
        self.with(py, other, |a, b| q(a, &pa, b, &pb)).map_err(err)
    }

    /// A question for every pose pair of `poses_a` and `poses_b`.
    fn batch<T: Send>(
        &self, py: Python<'_>, other: &Collider, poses_a: &Arg, poses_b: &Arg,
        q: impl FnOnce(&RsCollider, &RsCollider, &[PosePair]) -> Result<T, Error> + Send,
    ) -> PyResult<T> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        self.with(py, other, |a, b| q(a, b, &poses)).map_err(err)
    }
}

#[pymethods]
impl Collider {
    // `Collider(vertices, faces, mode)`: Python shows the class docstring for the constructor.
    #[new]
    #[pyo3(signature = (vertices, faces, mode = "bvh"))]
    fn py_new(
        py: Python<'_>, vertices: &Bound<'_, PyAny>, faces: &Bound<'_, PyAny>, mode: &str,
    ) -> PyResult<Collider> {
        let mode = mode_of(mode)?;
        let v = convert::vertices(vertices)?;
        let f = convert::faces(faces, v.len())?;
        py.detach(|| {
            let mesh = TriMesh::new(v, f).map_err(err)?;
            Ok(Collider::new_from(mesh, mode))
        })
    }

    /// Reads a mesh file (.obj, .off, .ply, .stl, each optionally .gz; the format from the
    /// extension) and builds its collider. Errors name the file and line (or byte).
    #[staticmethod]
    #[pyo3(signature = (path, mode = "bvh"))]
    fn load(py: Python<'_>, path: std::path::PathBuf, mode: &str) -> PyResult<Collider> {
        let mode = mode_of(mode)?;
        py.detach(|| {
            let mesh = TriMesh::load(&path).map_err(err)?;
            Ok(Collider::new_from(mesh, mode))
        })
    }

    /// An axis-aligned box from corner ``lo`` to corner ``hi`` (``(3,)`` each).
    #[staticmethod]
    #[pyo3(signature = (lo, hi, mode = "bvh"))]
    fn cuboid(lo: &Bound<'_, PyAny>, hi: &Bound<'_, PyAny>, mode: &str) -> PyResult<Collider> {
        let mode = mode_of(mode)?;
        let mesh =
            TriMesh::cuboid(convert::point(lo, "lo")?, convert::point(hi, "hi")?).map_err(err)?;
        Ok(Collider::new_from(mesh, mode))
    }

    /// The same mesh and trees with another mode (``"bvh"`` or ``"brute"``).
    fn with_mode(&self, mode: &str) -> PyResult<Collider> {
        Ok(Collider { inner: Arc::new((*self.inner).clone().with_mode(mode_of(mode)?)) })
    }

    /// ``"bvh"`` or ``"brute"``.
    #[getter]
    fn mode(&self) -> &'static str {
        mode_name(self.inner.mode())
    }

    /// The vertices, a fresh ``(n, 3)`` float64 array.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let v = self.inner.mesh().vertices();
        Array2::from_shape_fn((v.len(), 3), |(i, c)| v[i][c]).into_pyarray(py)
    }

    /// The faces, a fresh ``(m, 3)`` int64 array.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        let t = self.inner.mesh().triangles();
        Array2::from_shape_fn((t.len(), 3), |(i, c)| i64::from(t[i][c])).into_pyarray(py)
    }

    /// Number of triangles.
    #[getter]
    fn num_triangles(&self) -> usize {
        self.inner.mesh().num_triangles()
    }

    /// The axis-aligned bounds of the mesh, ``(2, 3)`` float64: ``[min, max]``.
    #[getter]
    fn bounds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let (lo, hi) = self.inner.mesh().bounds();
        Array2::from_shape_fn((2, 3), |(r, c)| if r == 0 { lo[c] } else { hi[c] }).into_pyarray(py)
    }

    /// Whether the mesh is closed (every edge shared by exactly two triangles).
    fn is_closed(&self) -> bool {
        self.inner.mesh().is_closed()
    }

    fn __repr__(&self) -> String {
        format!(
            "Collider(triangles={}, vertices={}, mode={:?})",
            self.inner.mesh().num_triangles(),
            self.inner.mesh().vertices().len(),
            self.mode()
        )
    }

    /// Pickling: the collider's bytes (`Collider::to_bytes` of the Rust crate: the mesh, the
    /// mode and the shape of its box tree). Unpickling does not rebuild the tree: it checks the
    /// bytes and recomputes the boxes from the vertices, a linear pass.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Reduced<'py>> {
        let py = slf.py();
        let inner = Arc::clone(&slf.get().inner);
        let bytes = py.detach(|| inner.to_bytes());
        let restore = py.get_type::<Collider>().getattr("_from_bytes")?;
        Ok((restore, (PyBytes::new(py, &bytes),)))
    }

    /// The collider of bytes from ``__reduce__`` (the Rust ``Collider::to_bytes``), its tree
    /// not rebuilt; bad bytes raise ``CgaError``.
    #[staticmethod]
    fn _from_bytes(py: Python<'_>, data: &[u8]) -> PyResult<Collider> {
        let c = py.detach(|| RsCollider::from_bytes(data)).map_err(err)?;
        Ok(Collider { inner: Arc::new(c) })
    }

    /// The collider as bytes (mesh, mode, shape of the box tree); ``Collider.from_bytes``
    /// reads them back without rebuilding the tree.
    fn to_bytes<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        let inner = &self.inner;
        let bytes = py.detach(|| inner.to_bytes());
        PyBytes::new(py, &bytes)
    }

    /// A collider from ``to_bytes``' bytes, without rebuilding its tree.
    #[staticmethod]
    fn from_bytes(py: Python<'_>, data: &[u8]) -> PyResult<Collider> {
        Collider::_from_bytes(py, data)
    }

    // ------------------------------------------------------------------ surfaces touch

    /// Whether the two surfaces touch (in one frame), exactly.
    fn collides(&self, py: Python<'_>, other: &Collider) -> bool {
        self.with(py, other, RsCollider::collides)
    }

    /// Whether the surfaces touch with ``self`` at ``pose_a`` and ``other`` at ``pose_b``
    /// (``(4, 4)`` homogeneous rigid motions).
    fn collides_at(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<bool> {
        self.at(py, pose_a, other, pose_b, RsCollider::collides_at)
    }

    /// ``collides_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
    /// (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array.
    fn collides_batch<'py>(
        &self, py: Python<'py>, other: &Collider, poses_a: &Arg, poses_b: &Arg,
    ) -> PyResult<Bools<'py>> {
        let hits = self.batch(py, other, poses_a, poses_b, RsCollider::collides_batch)?;
        Ok(bools(py, hits))
    }

    // ------------------------------------------------------------------ triangle pairs

    /// Every intersecting triangle pair ``(i, j)`` (``i`` in ``self``, ``j`` in ``other``),
    /// sorted, as a ``(p, 2)`` int64 array.
    fn intersecting_pairs<'py>(&self, py: Python<'py>, other: &Collider) -> Pairs<'py> {
        convert::pairs(py, &self.with(py, other, RsCollider::intersecting_pairs))
    }

    /// ``intersecting_pairs`` under poses.
    fn intersecting_pairs_at<'py>(
        &self, py: Python<'py>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<Pairs<'py>> {
        let p = self.at(py, pose_a, other, pose_b, RsCollider::intersecting_pairs_at)?;
        Ok(convert::pairs(py, &p))
    }

    /// ``intersecting_pairs_at`` for every pose pair: a list of ``(p, 2)`` int64 arrays.
    fn intersecting_pairs_batch<'py>(
        &self, py: Python<'py>, other: &Collider, poses_a: &Arg, poses_b: &Arg,
    ) -> PyResult<Vec<Pairs<'py>>> {
        let all = self.batch(py, other, poses_a, poses_b, RsCollider::intersecting_pairs_batch)?;
        Ok(all.iter().map(|p| convert::pairs(py, p)).collect())
    }

    // ------------------------------------------------------------------ solids

    /// Whether the closed solids share a point (one may be inside the other), in one frame.
    fn collides_solid(&self, py: Python<'_>, other: &Collider) -> bool {
        self.with(py, other, RsCollider::collides_solid)
    }

    /// ``collides_solid`` under poses.
    fn collides_solid_at(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<bool> {
        self.at(py, pose_a, other, pose_b, RsCollider::collides_solid_at)
    }

    /// ``collides_solid_at`` for every pose pair: a ``(k,)`` bool array.
    fn collides_solid_batch<'py>(
        &self, py: Python<'py>, other: &Collider, poses_a: &Arg, poses_b: &Arg,
    ) -> PyResult<Bools<'py>> {
        let hits = self.batch(py, other, poses_a, poses_b, RsCollider::collides_solid_batch)?;
        Ok(bools(py, hits))
    }

    /// Whether the point ``p`` (``(3,)``, finite) is in the closed solid (on the surface
    /// counts). The mesh should be closed.
    fn contains_point(&self, py: Python<'_>, p: &Arg) -> PyResult<bool> {
        let p = convert::point(p, "p")?;
        Ok(self.alone(py, |a| a.contains_point(&p)))
    }

    /// ``contains_point`` with the mesh at ``pose`` and ``p`` in world coordinates.
    fn contains_point_at(&self, py: Python<'_>, pose: &Arg, p: &Arg) -> PyResult<bool> {
        let p = convert::point(p, "p")?;
        self.placed(py, pose, |a, pose| a.contains_point_at(pose, &p))
    }

    /// The signed distance of every point of ``points`` (``(n, 3)``, finite) to the surface:
    /// negative inside, ``0`` on the surface (which is inside), with a proved error bound, the
    /// exact inside/outside (``contains_point``'s even–odd rule), the nearest point and its
    /// triangle (a ``PointDistances`` of arrays). Spread over the cores.
    fn signed_distance(&self, py: Python<'_>, points: &Arg) -> PyResult<PointDistances> {
        let points = convert::points(points, "points")?;
        let d = self.alone(py, |a| a.signed_distances(&points)).map_err(err)?;
        Ok(point_distances(py, &d))
    }

    /// ``signed_distance`` with the mesh at ``pose`` and the points in world coordinates.
    fn signed_distance_at(
        &self, py: Python<'_>, pose: &Arg, points: &Arg,
    ) -> PyResult<PointDistances> {
        let points = convert::points(points, "points")?;
        let d = self.placed(py, pose, |a, pose| a.signed_distances_at(pose, &points))?;
        Ok(point_distances(py, &d))
    }

    // ------------------------------------------------------------------ distances

    /// Whether the surfaces come within distance ``c`` (closed: exactly ``c`` counts), exactly.
    fn within_distance(&self, py: Python<'_>, other: &Collider, c: f64) -> PyResult<bool> {
        let c = convert::distance_bound(c, "c")?;
        Ok(self.with(py, other, |a, b| a.within_distance(b, c)))
    }

    /// ``within_distance`` under poses.
    fn within_distance_at(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg, c: f64,
    ) -> PyResult<bool> {
        let c = convert::distance_bound(c, "c")?;
        self.at(py, pose_a, other, pose_b, |a, pa, b, pb| a.within_distance_at(pa, b, pb, c))
    }

    /// ``within_distance_at`` for every pose pair: a ``(k,)`` bool array.
    fn within_distance_batch<'py>(
        &self, py: Python<'py>, other: &Collider, poses_a: &Arg, poses_b: &Arg, c: f64,
    ) -> PyResult<Bools<'py>> {
        let c = convert::distance_bound(c, "c")?;
        let hits =
            self.batch(py, other, poses_a, poses_b, |a, b, p| a.within_distance_batch(b, p, c))?;
        Ok(bools(py, hits))
    }

    /// Every triangle pair whose triangles come within ``c``, sorted, ``(p, 2)`` int64.
    fn pairs_within_distance<'py>(
        &self, py: Python<'py>, other: &Collider, c: f64,
    ) -> PyResult<Pairs<'py>> {
        let c = convert::distance_bound(c, "c")?;
        Ok(convert::pairs(py, &self.with(py, other, |a, b| a.pairs_within_distance(b, c))))
    }

    /// ``pairs_within_distance`` under poses.
    fn pairs_within_distance_at<'py>(
        &self, py: Python<'py>, pose_a: &Arg, other: &Collider, pose_b: &Arg, c: f64,
    ) -> PyResult<Pairs<'py>> {
        let c = convert::distance_bound(c, "c")?;
        let p = self.at(py, pose_a, other, pose_b, |a, pa, b, pb| {
            a.pairs_within_distance_at(pa, b, pb, c)
        })?;
        Ok(convert::pairs(py, &p))
    }

    /// The certified minimum distance between the surfaces (a ``Distance``), in one frame.
    fn distance(&self, py: Python<'_>, other: &Collider) -> PyResult<Distance> {
        let d = self.with(py, other, RsCollider::distance).map_err(err)?;
        Ok(Distance::from(&d))
    }

    /// ``distance`` under poses (witnesses in world coordinates).
    fn distance_at(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<Distance> {
        let d = self.at(py, pose_a, other, pose_b, RsCollider::distance_at)?;
        Ok(Distance::from(&d))
    }

    /// ``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays.
    fn distance_batch(
        &self, py: Python<'_>, other: &Collider, poses_a: &Arg, poses_b: &Arg,
    ) -> PyResult<DistanceBatch> {
        let ds = self.batch(py, other, poses_a, poses_b, RsCollider::distance_batch)?;
        Ok(distance_batch(py, &ds))
    }

    /// The exact minimum distance: ``(distance2, witness_a, witness_b, triangles)`` with the
    /// squared distance and the witnesses' coordinates as ``fractions.Fraction``.
    fn exact_distance<'py>(
        &self, py: Python<'py>, other: &Collider,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let d = self.with(py, other, RsCollider::exact_distance).map_err(err)?;
        exact_distance_tuple(py, &d)
    }

    // ------------------------------------------------------------------ contacts

    /// How two closed meshes touch: ``"disjoint"``, ``"touching"``, ``"penetrating"``,
    /// ``"a_inside_b"`` or ``"b_inside_a"``.
    fn contact_class(&self, py: Python<'_>, other: &Collider) -> &'static str {
        self.with(py, other, RsCollider::contact_class).name()
    }

    /// ``contact_class`` under poses.
    fn contact_class_at(
        &self, py: Python<'_>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<&'static str> {
        Ok(self.at(py, pose_a, other, pose_b, RsCollider::contact_class_at)?.name())
    }

    /// Every intersecting triangle pair with its exact intersection: a list of
    /// ``((i, j), kind, points)`` with ``kind`` ``"point"``, ``"segment"`` or ``"polygon"`` and
    /// ``points`` a ``(c, 3)`` float64 array of its corners (nearest values of the exact ones).
    fn contacts<'py>(
        &self, py: Python<'py>, other: &Collider,
    ) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        contact_tuples(py, &self.with(py, other, RsCollider::contacts))
    }

    /// ``contacts`` under poses (world coordinates).
    fn contacts_at<'py>(
        &self, py: Python<'py>, pose_a: &Arg, other: &Collider, pose_b: &Arg,
    ) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        contact_tuples(py, &self.at(py, pose_a, other, pose_b, RsCollider::contacts_at)?)
    }

    // ------------------------------------------------------------------ motion

    /// Every vertex–face and edge–edge pair of ``self`` and ``other`` that touches while
    /// ``self`` moves from ``poses[0]`` to ``poses[1]`` and ``other`` from ``other_poses[0]`` to
    /// ``other_poses[1]`` (``(2, 4, 4)`` arrays; each vertex moves linearly between its
    /// two placed positions), exactly, with the first contact time bounded to ``tolerance``.
    /// Returns a ``cga_collide.motion.MotionContacts``; a refused pose raises ``CgaError``.
    #[pyo3(signature = (poses, other, other_poses, tolerance = 1e-9))]
    fn contacts_during(
        &self, py: Python<'_>, poses: &Bound<'_, PyAny>, other: &Collider,
        other_poses: &Bound<'_, PyAny>, tolerance: f64,
    ) -> PyResult<crate::motion::MotionContacts> {
        crate::motion::contacts_during(py, &self.inner, poses, &other.inner, other_poses, tolerance)
    }

    // ------------------------------------------------------------------ self-intersection

    /// Every pair of non-adjacent triangles of the mesh that intersect, ``(p, 2)`` int64.
    fn self_intersections<'py>(&self, py: Python<'py>) -> Pairs<'py> {
        convert::pairs(py, &self.alone(py, RsCollider::self_intersections))
    }

    /// Whether the mesh cuts itself.
    fn self_intersects(&self, py: Python<'_>) -> bool {
        self.alone(py, RsCollider::self_intersects)
    }

    // ------------------------------------------------------------------ shapes

    /// The triangles the closed segment ``p``–``q`` meets, an int64 array of indices.
    fn segment_hits<'py>(&self, py: Python<'py>, p: &Arg, q: &Arg) -> PyResult<Indices<'py>> {
        let s = segment(p, q)?;
        Ok(convert::indices(py, &self.alone(py, |a| a.segment_hits(&s))))
    }

    /// ``segment_hits`` with the mesh at ``pose`` and the segment in world coordinates.
    fn segment_hits_at<'py>(
        &self, py: Python<'py>, pose: &Arg, p: &Arg, q: &Arg,
    ) -> PyResult<Indices<'py>> {
        let s = segment(p, q)?;
        let hits = self.placed(py, pose, |a, pose| a.segment_hits_at(pose, &s))?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles a triangle (``(3, 3)``, one corner per row) meets.
    fn triangle_hits<'py>(
        &self, py: Python<'py>, triangle_corners: &Arg,
    ) -> PyResult<Indices<'py>> {
        let t = triangle(triangle_corners)?;
        Ok(convert::indices(py, &self.alone(py, |a| a.triangle_hits(&t))))
    }

    /// ``triangle_hits`` with the mesh at ``pose``.
    fn triangle_hits_at<'py>(
        &self, py: Python<'py>, pose: &Arg, triangle_corners: &Arg,
    ) -> PyResult<Indices<'py>> {
        let t = triangle(triangle_corners)?;
        let hits = self.placed(py, pose, |a, pose| a.triangle_hits_at(pose, &t))?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles the sphere surface (``centre`` ``(3,)``, ``radius``) meets.
    fn sphere_hits<'py>(
        &self, py: Python<'py>, centre: &Arg, radius: f64,
    ) -> PyResult<Indices<'py>> {
        let s = Sphere::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        Ok(convert::indices(py, &self.alone(py, |a| a.sphere_hits(&s))))
    }

    /// ``sphere_hits`` with the mesh at ``pose``.
    fn sphere_hits_at<'py>(
        &self, py: Python<'py>, pose: &Arg, centre: &Arg, radius: f64,
    ) -> PyResult<Indices<'py>> {
        let s = Sphere::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let hits = self.placed(py, pose, |a, pose| a.sphere_hits_at(pose, &s))?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles the solid ball (``centre`` ``(3,)``, ``radius``) meets.
    fn ball_hits<'py>(&self, py: Python<'py>, centre: &Arg, radius: f64) -> PyResult<Indices<'py>> {
        let s = Ball::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        Ok(convert::indices(py, &self.alone(py, |a| a.ball_hits(&s))))
    }

    /// ``ball_hits`` with the mesh at ``pose``.
    fn ball_hits_at<'py>(
        &self, py: Python<'py>, pose: &Arg, centre: &Arg, radius: f64,
    ) -> PyResult<Indices<'py>> {
        let s = Ball::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let hits = self.placed(py, pose, |a, pose| a.ball_hits_at(pose, &s))?;
        Ok(convert::indices(py, &hits))
    }

    // ------------------------------------------------------------------ solid primitives

    /// The triangles the closed ``shape`` (a ``Shape``) meets, an int64 array of indices, found
    /// through the box tree (the same as testing every triangle).
    fn shape_hits<'py>(&self, py: Python<'py>, shape: &Arg) -> PyResult<Indices<'py>> {
        let s = shape_arg(shape, "shape")?;
        let hits = self.alone(py, |a| a.shape_hits(s)).map_err(err)?;
        Ok(convert::indices(py, &hits))
    }

    /// ``shape_hits`` with the mesh at ``pose`` and the shape placed by ``shape_pose``
    /// (``Shape.placed``'s rule).
    fn shape_hits_at<'py>(
        &self, py: Python<'py>, pose: &Arg, shape: &Arg, shape_pose: &Arg,
    ) -> PyResult<Indices<'py>> {
        let hits = self.with_shape(py, pose, shape, shape_pose, RsCollider::shape_hits_at)?;
        Ok(convert::indices(py, &hits))
    }

    /// Whether the closed ``shape`` meets the surface (a shape inside a closed mesh does not).
    fn intersects_shape(&self, py: Python<'_>, shape: &Arg) -> PyResult<bool> {
        let s = shape_arg(shape, "shape")?;
        self.alone(py, |a| a.intersects_shape(s)).map_err(err)
    }

    /// ``intersects_shape`` under poses.
    fn intersects_shape_at(
        &self, py: Python<'_>, pose: &Arg, shape: &Arg, shape_pose: &Arg,
    ) -> PyResult<bool> {
        self.with_shape(py, pose, shape, shape_pose, RsCollider::intersects_shape_at)
    }

    /// Whether the closed ``shape`` meets the closed solid of the mesh (inside counts). The
    /// mesh should be closed.
    fn intersects_shape_solid(&self, py: Python<'_>, shape: &Arg) -> PyResult<bool> {
        let s = shape_arg(shape, "shape")?;
        self.alone(py, |a| a.intersects_shape_solid(s)).map_err(err)
    }

    /// ``intersects_shape_solid`` under poses.
    fn intersects_shape_solid_at(
        &self, py: Python<'_>, pose: &Arg, shape: &Arg, shape_pose: &Arg,
    ) -> PyResult<bool> {
        self.with_shape(py, pose, shape, shape_pose, RsCollider::intersects_shape_solid_at)
    }

    /// Whether the closed ``shape`` comes within distance ``c`` of the surface (closed:
    /// exactly ``c`` counts; ``c`` finite and at least 0), exactly.
    fn shape_within_distance(&self, py: Python<'_>, shape: &Arg, c: f64) -> PyResult<bool> {
        let s = shape_arg(shape, "shape")?;
        self.alone(py, |a| a.shape_within_distance(s, c)).map_err(err)
    }

    /// ``shape_within_distance`` under poses.
    fn shape_within_distance_at(
        &self, py: Python<'_>, pose: &Arg, shape: &Arg, shape_pose: &Arg, c: f64,
    ) -> PyResult<bool> {
        self.with_shape(py, pose, shape, shape_pose, |a, p, s, sp| {
            a.shape_within_distance_at(p, s, sp, c)
        })
    }

    /// The certified minimum distance between the surface and the closed ``shape`` (a
    /// ``Distance``: ``witness_a`` on the mesh, ``witness_b`` on the shape, ``triangles``
    /// ``(i, 0)`` with ``i`` the triangle of ``witness_a``).
    fn distance_to_shape(&self, py: Python<'_>, shape: &Arg) -> PyResult<Distance> {
        let s = shape_arg(shape, "shape")?;
        let d = self.alone(py, |a| a.distance_to_shape(s)).map_err(err)?;
        Ok(Distance::from(&d))
    }

    /// ``distance_to_shape`` under poses (witnesses in world coordinates).
    fn distance_to_shape_at(
        &self, py: Python<'_>, pose: &Arg, shape: &Arg, shape_pose: &Arg,
    ) -> PyResult<Distance> {
        let d = self.with_shape(py, pose, shape, shape_pose, RsCollider::distance_to_shape_at)?;
        Ok(Distance::from(&d))
    }
}
