//! `Collider`: a mesh built once, and every question about it, in the crate's calling style.

use std::sync::Arc;

use cga_collide::collider::{Collider as RsCollider, Mode};
use cga_collide::nalgebra::Point3;
use cga_collide::query::{CertifiedDistance, ContactGeometry};
use cga_collide::{Ball, Segment, Sphere, TriMesh, Triangle};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};

use crate::convert::{self, err, value_error};

/// A triangle mesh built once (its box tree and the layout the pose queries read), and every
/// question about it.
///
/// Build it from numpy arrays, ``Collider(vertices, faces)`` with vertices ``(n, 3)`` float64 and
/// faces ``(m, 3)`` integers, or from a file with ``Collider.load(path)`` (.obj, .off, .ply, .stl,
/// optionally .gz).
///
/// Every question comes in the crate's three forms: in one frame ``a.x(b)``; under poses
/// ``a.x_at(pose_a, b, pose_b)`` with ``(4, 4)`` float64 homogeneous matrices; and many poses
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
        other => Err(value_error(format!(
            "mode: expected \"bvh\" or \"brute\", got {other:?}"
        ))),
    }
}

fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Bvh => "bvh",
        Mode::Brute => "brute",
    }
}

/// A certified distance between two meshes: ``distance`` is within ``error_bound`` of the true
/// minimum distance between the surfaces; ``witness_a`` and ``witness_b`` are points on each
/// surface (world coordinates) whose distance is ``distance``; ``triangles`` is the pair of
/// triangle indices they lie on (``None`` when not known).
#[pyclass(frozen, module = "cga_collide")]
#[derive(Clone)]
pub struct Distance {
    /// The distance found (an upper bound, at most ``error_bound`` above the true distance).
    #[pyo3(get)]
    pub distance: f64,
    /// The proved bound on ``|distance − true distance|``.
    #[pyo3(get)]
    pub error_bound: f64,
    wa: [f64; 3],
    wb: [f64; 3],
    /// The triangle pair of the witnesses, or ``None``.
    #[pyo3(get)]
    pub triangles: Option<(u32, u32)>,
}

impl From<&CertifiedDistance> for Distance {
    fn from(d: &CertifiedDistance) -> Self {
        Distance {
            distance: d.distance,
            error_bound: d.error_bound,
            wa: [d.witness_a.x, d.witness_a.y, d.witness_a.z],
            wb: [d.witness_b.x, d.witness_b.y, d.witness_b.z],
            triangles: d.triangles,
        }
    }
}

#[pymethods]
impl Distance {
    /// The witness point on the first mesh, a ``(3,)`` float64 array.
    #[getter]
    fn witness_a<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.wa)
    }

    /// The witness point on the second mesh, a ``(3,)`` float64 array.
    #[getter]
    fn witness_b<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.wb)
    }

    fn __float__(&self) -> f64 {
        self.distance
    }

    fn __repr__(&self) -> String {
        let triangles = match self.triangles {
            Some((i, j)) => format!("({i}, {j})"),
            None => "None".to_owned(),
        };
        format!(
            "Distance(distance={:?}, error_bound={:?}, witness_a={:?}, witness_b={:?}, triangles={triangles})",
            self.distance, self.error_bound, self.wa, self.wb
        )
    }
}

/// The certified distances of a batch, as arrays: ``distance`` and ``error_bound`` ``(k,)``,
/// ``witness_a`` and ``witness_b`` ``(k, 3)``, ``triangles`` ``(k, 2)`` int64 (``-1`` where not
/// known).
#[pyclass(frozen, module = "cga_collide")]
pub struct DistanceBatch {
    /// ``(k,)`` float64.
    #[pyo3(get)]
    distance: Py<PyArray1<f64>>,
    /// ``(k,)`` float64.
    #[pyo3(get)]
    error_bound: Py<PyArray1<f64>>,
    /// ``(k, 3)`` float64.
    #[pyo3(get)]
    witness_a: Py<PyArray2<f64>>,
    /// ``(k, 3)`` float64.
    #[pyo3(get)]
    witness_b: Py<PyArray2<f64>>,
    /// ``(k, 2)`` int64, ``-1`` where not known.
    #[pyo3(get)]
    triangles: Py<PyArray2<i64>>,
}

#[pymethods]
impl DistanceBatch {
    fn __len__(&self, py: Python<'_>) -> usize {
        self.distance.bind(py).len().unwrap_or(0)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!("DistanceBatch(k={})", self.__len__(py))
    }
}

fn distance_batch(py: Python<'_>, ds: &[CertifiedDistance]) -> DistanceBatch {
    let k = ds.len();
    let mut wa = Array2::<f64>::zeros((k, 3));
    let mut wb = Array2::<f64>::zeros((k, 3));
    let mut tr = Array2::<i64>::from_elem((k, 2), -1);
    for (i, d) in ds.iter().enumerate() {
        for c in 0..3 {
            wa[[i, c]] = d.witness_a[c];
            wb[[i, c]] = d.witness_b[c];
        }
        if let Some((x, y)) = d.triangles {
            tr[[i, 0]] = i64::from(x);
            tr[[i, 1]] = i64::from(y);
        }
    }
    DistanceBatch {
        distance: Array1::from_iter(ds.iter().map(|d| d.distance))
            .into_pyarray(py)
            .unbind(),
        error_bound: Array1::from_iter(ds.iter().map(|d| d.error_bound))
            .into_pyarray(py)
            .unbind(),
        witness_a: wa.into_pyarray(py).unbind(),
        witness_b: wb.into_pyarray(py).unbind(),
        triangles: tr.into_pyarray(py).unbind(),
    }
}

/// One contact of [`Collider::contacts`]: the triangle pair, the kind of intersection and its
/// corners (nearest float64 values of the exact rationals).
fn contact_tuple<'py>(
    py: Python<'py>,
    (i, j): (u32, u32),
    g: &ContactGeometry,
) -> PyResult<Bound<'py, PyTuple>> {
    let kind = match g {
        ContactGeometry::Point(_) => "point",
        ContactGeometry::Segment(..) => "segment",
        ContactGeometry::Polygon(_) => "polygon",
    };
    let pts = g.points_f64();
    let mut a = Array2::<f64>::zeros((pts.len(), 3));
    for (k, p) in pts.iter().enumerate() {
        for c in 0..3 {
            a[[k, c]] = p[c];
        }
    }
    PyTuple::new(
        py,
        [
            (i, j).into_pyobject(py)?.into_any(),
            kind.into_pyobject(py)?.into_any(),
            a.into_pyarray(py).into_any(),
        ],
    )
}

fn bools<'py>(py: Python<'py>, v: Vec<bool>) -> Bound<'py, PyArray1<bool>> {
    Array1::from_vec(v).into_pyarray(py)
}

fn segment(p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>) -> PyResult<Segment> {
    Segment::new(convert::point(p, "p")?, convert::point(q, "q")?).map_err(err)
}

fn triangle(t: &Bound<'_, PyAny>) -> PyResult<Triangle> {
    let a = convert::f64_array(t, "triangle")?;
    let r = a.readonly();
    let v = r.as_array();
    convert::check_shape(v.shape(), &[Some(3), Some(3)], "triangle")?;
    let p = |i: usize| Point3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]);
    Triangle::new(p(0), p(1), p(2)).map_err(err)
}

impl Collider {
    fn new_from(mesh: TriMesh, mode: Mode) -> Collider {
        Collider {
            inner: Arc::new(RsCollider::new(mesh).with_mode(mode)),
        }
    }
}

#[pymethods]
impl Collider {
    /// Builds a collider from ``vertices`` (``(n, 3)`` float64) and ``faces`` (``(m, 3)``
    /// integers, 0-based). Raises ``TypeError`` for another dtype and ``CgaError`` (a
    /// ``ValueError``) for a wrong shape, a non-finite coordinate, an index out of range or an
    /// empty mesh, naming the vertex or face.
    #[new]
    #[pyo3(signature = (vertices, faces, mode = "bvh"))]
    fn py_new(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        mode: &str,
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

    /// An axis-aligned box from corner ``lo`` to corner ``hi`` (``(3,)`` float64 each).
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
        Ok(Collider {
            inner: Arc::new((*self.inner).clone().with_mode(mode_of(mode)?)),
        })
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
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.collides(b))
    }

    /// Whether the surfaces touch with ``self`` at ``pose_a`` and ``other`` at ``pose_b``
    /// (``(4, 4)`` float64 homogeneous rigid motions).
    fn collides_at(
        &self,
        py: Python<'_>,
        pose_a: &Bound<'_, PyAny>,
        other: &Collider,
        pose_b: &Bound<'_, PyAny>,
    ) -> PyResult<bool> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.collides_at(&pa, b, &pb)).map_err(err)
    }

    /// ``collides_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
    /// float64 (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array.
    fn collides_batch<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
        poses_a: &Bound<'py, PyAny>,
        poses_b: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<bool>>> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        let (a, b) = (&self.inner, &other.inner);
        let hits = py.detach(|| a.collides_batch(b, &poses)).map_err(err)?;
        Ok(bools(py, hits))
    }

    // ------------------------------------------------------------------ triangle pairs

    /// Every intersecting triangle pair ``(i, j)`` (``i`` in ``self``, ``j`` in ``other``),
    /// sorted, as a ``(p, 2)`` int64 array.
    fn intersecting_pairs<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
    ) -> Bound<'py, PyArray2<i64>> {
        let (a, b) = (&self.inner, &other.inner);
        let p = py.detach(|| a.intersecting_pairs(b));
        convert::pairs(py, &p)
    }

    /// ``intersecting_pairs`` under poses.
    fn intersecting_pairs_at<'py>(
        &self,
        py: Python<'py>,
        pose_a: &Bound<'py, PyAny>,
        other: &Collider,
        pose_b: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        let p = py
            .detach(|| a.intersecting_pairs_at(&pa, b, &pb))
            .map_err(err)?;
        Ok(convert::pairs(py, &p))
    }

    /// ``intersecting_pairs_at`` for every pose pair: a list of ``(p, 2)`` int64 arrays.
    fn intersecting_pairs_batch<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
        poses_a: &Bound<'py, PyAny>,
        poses_b: &Bound<'py, PyAny>,
    ) -> PyResult<Vec<Bound<'py, PyArray2<i64>>>> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        let (a, b) = (&self.inner, &other.inner);
        let all = py
            .detach(|| a.intersecting_pairs_batch(b, &poses))
            .map_err(err)?;
        Ok(all.iter().map(|p| convert::pairs(py, p)).collect())
    }

    // ------------------------------------------------------------------ solids

    /// Whether the closed solids share a point (one may be inside the other), in one frame.
    fn collides_solid(&self, py: Python<'_>, other: &Collider) -> bool {
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.collides_solid(b))
    }

    /// ``collides_solid`` under poses.
    fn collides_solid_at(
        &self,
        py: Python<'_>,
        pose_a: &Bound<'_, PyAny>,
        other: &Collider,
        pose_b: &Bound<'_, PyAny>,
    ) -> PyResult<bool> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.collides_solid_at(&pa, b, &pb)).map_err(err)
    }

    /// ``collides_solid_at`` for every pose pair: a ``(k,)`` bool array.
    fn collides_solid_batch<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
        poses_a: &Bound<'py, PyAny>,
        poses_b: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<bool>>> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        let (a, b) = (&self.inner, &other.inner);
        let hits = py
            .detach(|| a.collides_solid_batch(b, &poses))
            .map_err(err)?;
        Ok(bools(py, hits))
    }

    /// Whether the point ``p`` (``(3,)`` float64) is in the closed solid (on the surface
    /// counts). The mesh should be closed.
    fn contains_point(&self, py: Python<'_>, p: &Bound<'_, PyAny>) -> PyResult<bool> {
        let p = convert::point(p, "p")?;
        let a = &self.inner;
        Ok(py.detach(|| a.contains_point(&p)))
    }

    /// ``contains_point`` with the mesh at ``pose`` and ``p`` in world coordinates.
    fn contains_point_at(
        &self,
        py: Python<'_>,
        pose: &Bound<'_, PyAny>,
        p: &Bound<'_, PyAny>,
    ) -> PyResult<bool> {
        let pose = convert::pose(pose, "pose")?;
        let p = convert::point(p, "p")?;
        let a = &self.inner;
        py.detach(|| a.contains_point_at(&pose, &p)).map_err(err)
    }

    // ------------------------------------------------------------------ distances

    /// Whether the surfaces come within distance ``c`` (closed: exactly ``c`` counts), exactly.
    fn within_distance(&self, py: Python<'_>, other: &Collider, c: f64) -> bool {
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.within_distance(b, c))
    }

    /// ``within_distance`` under poses.
    fn within_distance_at(
        &self,
        py: Python<'_>,
        pose_a: &Bound<'_, PyAny>,
        other: &Collider,
        pose_b: &Bound<'_, PyAny>,
        c: f64,
    ) -> PyResult<bool> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.within_distance_at(&pa, b, &pb, c))
            .map_err(err)
    }

    /// ``within_distance_at`` for every pose pair: a ``(k,)`` bool array.
    fn within_distance_batch<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
        poses_a: &Bound<'py, PyAny>,
        poses_b: &Bound<'py, PyAny>,
        c: f64,
    ) -> PyResult<Bound<'py, PyArray1<bool>>> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        let (a, b) = (&self.inner, &other.inner);
        let hits = py
            .detach(|| a.within_distance_batch(b, &poses, c))
            .map_err(err)?;
        Ok(bools(py, hits))
    }

    /// Every triangle pair whose triangles come within ``c``, sorted, ``(p, 2)`` int64.
    fn pairs_within_distance<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
        c: f64,
    ) -> Bound<'py, PyArray2<i64>> {
        let (a, b) = (&self.inner, &other.inner);
        let p = py.detach(|| a.pairs_within_distance(b, c));
        convert::pairs(py, &p)
    }

    /// ``pairs_within_distance`` under poses.
    fn pairs_within_distance_at<'py>(
        &self,
        py: Python<'py>,
        pose_a: &Bound<'py, PyAny>,
        other: &Collider,
        pose_b: &Bound<'py, PyAny>,
        c: f64,
    ) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        let p = py
            .detach(|| a.pairs_within_distance_at(&pa, b, &pb, c))
            .map_err(err)?;
        Ok(convert::pairs(py, &p))
    }

    /// The certified minimum distance between the surfaces (a ``Distance``), in one frame.
    fn distance(&self, py: Python<'_>, other: &Collider) -> PyResult<Distance> {
        let (a, b) = (&self.inner, &other.inner);
        let d = py.detach(|| a.distance(b)).map_err(err)?;
        Ok(Distance::from(&d))
    }

    /// ``distance`` under poses (witnesses in world coordinates).
    fn distance_at(
        &self,
        py: Python<'_>,
        pose_a: &Bound<'_, PyAny>,
        other: &Collider,
        pose_b: &Bound<'_, PyAny>,
    ) -> PyResult<Distance> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        let d = py.detach(|| a.distance_at(&pa, b, &pb)).map_err(err)?;
        Ok(Distance::from(&d))
    }

    /// ``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays.
    fn distance_batch(
        &self,
        py: Python<'_>,
        other: &Collider,
        poses_a: &Bound<'_, PyAny>,
        poses_b: &Bound<'_, PyAny>,
    ) -> PyResult<DistanceBatch> {
        let poses = convert::pose_pairs(poses_a, poses_b)?;
        let (a, b) = (&self.inner, &other.inner);
        let ds = py.detach(|| a.distance_batch(b, &poses)).map_err(err)?;
        Ok(distance_batch(py, &ds))
    }

    /// The exact minimum distance: ``(distance2, witness_a, witness_b, triangles)`` with the
    /// squared distance and the witnesses' coordinates as ``fractions.Fraction``.
    fn exact_distance<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let (a, b) = (&self.inner, &other.inner);
        let d = py.detach(|| a.exact_distance(b)).map_err(err)?;
        let fraction = py.import("fractions")?.getattr("Fraction")?;
        let q = |x: &cga_collide::ga_core::scalar::Rational| -> PyResult<Bound<'py, PyAny>> {
            fraction
                .call1((x.numer().to_string(),))?
                .call_method1("__truediv__", (fraction.call1((x.denom().to_string(),))?,))
        };
        let point =
            |p: &[cga_collide::ga_core::scalar::Rational; 3]| -> PyResult<Bound<'py, PyTuple>> {
                PyTuple::new(py, [q(&p[0])?, q(&p[1])?, q(&p[2])?])
            };
        PyTuple::new(
            py,
            [
                q(&d.distance2)?,
                point(&d.witness_a)?.into_any(),
                point(&d.witness_b)?.into_any(),
                d.triangles.into_pyobject(py)?.into_any(),
            ],
        )
    }

    // ------------------------------------------------------------------ contacts

    /// How two closed meshes touch: ``"disjoint"``, ``"touching"``, ``"penetrating"``,
    /// ``"a_inside_b"`` or ``"b_inside_a"``.
    fn contact_class(&self, py: Python<'_>, other: &Collider) -> &'static str {
        let (a, b) = (&self.inner, &other.inner);
        py.detach(|| a.contact_class(b)).name()
    }

    /// ``contact_class`` under poses.
    fn contact_class_at(
        &self,
        py: Python<'_>,
        pose_a: &Bound<'_, PyAny>,
        other: &Collider,
        pose_b: &Bound<'_, PyAny>,
    ) -> PyResult<&'static str> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        Ok(py
            .detach(|| a.contact_class_at(&pa, b, &pb))
            .map_err(err)?
            .name())
    }

    /// Every intersecting triangle pair with its exact intersection: a list of
    /// ``((i, j), kind, points)`` with ``kind`` ``"point"``, ``"segment"`` or ``"polygon"`` and
    /// ``points`` a ``(c, 3)`` float64 array of its corners (nearest values of the exact ones).
    fn contacts<'py>(
        &self,
        py: Python<'py>,
        other: &Collider,
    ) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let (a, b) = (&self.inner, &other.inner);
        let cs = py.detach(|| a.contacts(b));
        cs.iter().map(|(ij, g)| contact_tuple(py, *ij, g)).collect()
    }

    /// ``contacts`` under poses (world coordinates).
    fn contacts_at<'py>(
        &self,
        py: Python<'py>,
        pose_a: &Bound<'py, PyAny>,
        other: &Collider,
        pose_b: &Bound<'py, PyAny>,
    ) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let (pa, pb) = (
            convert::pose(pose_a, "pose_a")?,
            convert::pose(pose_b, "pose_b")?,
        );
        let (a, b) = (&self.inner, &other.inner);
        let cs = py.detach(|| a.contacts_at(&pa, b, &pb)).map_err(err)?;
        cs.iter().map(|(ij, g)| contact_tuple(py, *ij, g)).collect()
    }

    // ------------------------------------------------------------------ motion

    /// Every vertex–face and edge–edge pair of ``self`` and ``other`` that touches while
    /// ``self`` moves from ``poses[0]`` to ``poses[1]`` and ``other`` from ``other_poses[0]`` to
    /// ``other_poses[1]`` (``(2, 4, 4)`` float64 arrays; each vertex moves linearly between its
    /// two placed positions), exactly, with the first contact time bounded to ``tolerance``.
    /// Returns a ``cga_collide.motion.MotionContacts``; a refused pose raises ``CgaError``.
    #[pyo3(signature = (poses, other, other_poses, tolerance = 1e-9))]
    fn contacts_during(
        &self,
        py: Python<'_>,
        poses: &Bound<'_, PyAny>,
        other: &Collider,
        other_poses: &Bound<'_, PyAny>,
        tolerance: f64,
    ) -> PyResult<crate::motion::MotionContacts> {
        crate::motion::contacts_during(py, &self.inner, poses, &other.inner, other_poses, tolerance)
    }

    // ------------------------------------------------------------------ self-intersection

    /// Every pair of non-adjacent triangles of the mesh that intersect, ``(p, 2)`` int64.
    fn self_intersections<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        let a = &self.inner;
        let p = py.detach(|| a.self_intersections());
        convert::pairs(py, &p)
    }

    /// Whether the mesh cuts itself.
    fn self_intersects(&self, py: Python<'_>) -> bool {
        let a = &self.inner;
        py.detach(|| a.self_intersects())
    }

    // ------------------------------------------------------------------ shapes

    /// The triangles the closed segment ``p``–``q`` meets, an int64 array of indices.
    fn segment_hits<'py>(
        &self,
        py: Python<'py>,
        p: &Bound<'py, PyAny>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let s = segment(p, q)?;
        let a = &self.inner;
        let hits = py.detach(|| a.segment_hits(&s));
        Ok(convert::indices(py, &hits))
    }

    /// ``segment_hits`` with the mesh at ``pose`` and the segment in world coordinates.
    fn segment_hits_at<'py>(
        &self,
        py: Python<'py>,
        pose: &Bound<'py, PyAny>,
        p: &Bound<'py, PyAny>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let pose = convert::pose(pose, "pose")?;
        let s = segment(p, q)?;
        let a = &self.inner;
        let hits = py.detach(|| a.segment_hits_at(&pose, &s)).map_err(err)?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles a triangle (``(3, 3)`` float64, one corner per row) meets.
    fn triangle_hits<'py>(
        &self,
        py: Python<'py>,
        triangle_corners: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let t = triangle(triangle_corners)?;
        let a = &self.inner;
        let hits = py.detach(|| a.triangle_hits(&t));
        Ok(convert::indices(py, &hits))
    }

    /// ``triangle_hits`` with the mesh at ``pose``.
    fn triangle_hits_at<'py>(
        &self,
        py: Python<'py>,
        pose: &Bound<'py, PyAny>,
        triangle_corners: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let pose = convert::pose(pose, "pose")?;
        let t = triangle(triangle_corners)?;
        let a = &self.inner;
        let hits = py.detach(|| a.triangle_hits_at(&pose, &t)).map_err(err)?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles the sphere surface (``centre`` ``(3,)``, ``radius``) meets.
    fn sphere_hits<'py>(
        &self,
        py: Python<'py>,
        centre: &Bound<'py, PyAny>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let s = Sphere::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let a = &self.inner;
        let hits = py.detach(|| a.sphere_hits(&s));
        Ok(convert::indices(py, &hits))
    }

    /// ``sphere_hits`` with the mesh at ``pose``.
    fn sphere_hits_at<'py>(
        &self,
        py: Python<'py>,
        pose: &Bound<'py, PyAny>,
        centre: &Bound<'py, PyAny>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let pose = convert::pose(pose, "pose")?;
        let s = Sphere::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let a = &self.inner;
        let hits = py.detach(|| a.sphere_hits_at(&pose, &s)).map_err(err)?;
        Ok(convert::indices(py, &hits))
    }

    /// The triangles the solid ball (``centre`` ``(3,)``, ``radius``) meets.
    fn ball_hits<'py>(
        &self,
        py: Python<'py>,
        centre: &Bound<'py, PyAny>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let s = Ball::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let a = &self.inner;
        let hits = py.detach(|| a.ball_hits(&s));
        Ok(convert::indices(py, &hits))
    }

    /// ``ball_hits`` with the mesh at ``pose``.
    fn ball_hits_at<'py>(
        &self,
        py: Python<'py>,
        pose: &Bound<'py, PyAny>,
        centre: &Bound<'py, PyAny>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let pose = convert::pose(pose, "pose")?;
        let s = Ball::new(convert::point(centre, "centre")?, radius).map_err(err)?;
        let a = &self.inner;
        let hits = py.detach(|| a.ball_hits_at(&pose, &s)).map_err(err)?;
        Ok(convert::indices(py, &hits))
    }
}
