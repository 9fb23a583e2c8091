//! `cga_collide.motion`: continuous collision, with the names of the Rust `motion` module.
//!
//! Every point moves linearly from its start (`t = 0`) to its end (`t = 1`). A moving point is a
//! `(2, 3)` array (start, end), a moving triangle `(3, 2, 3)`, a moving edge `(2, 2, 3)`;
//! batches are `(k, 4, 2, 3)` arrays (the four moving points of each query), answered in one
//! call over the cores.

use cga_collide::collider::Collider as RsCollider;
use cga_collide::motion::{self, ContactTime as RsContactTime, MotionPair, MovingPoint};
use cga_collide::nalgebra::Point3;
use cga_collide::{Error, TriMesh};
use numpy::ndarray::{Array2, Array3, ArrayView2};
use numpy::{IntoPyArray, PyArray2, PyArray3};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rayon::prelude::*;

use crate::convert::{self, bools, err, value_error, Arg, Bools};

/// When two primitives first touch: ``lo <= t <= hi`` for the earliest contact time ``t`` in
/// ``[0, 1]``. Either ``lo == hi == t`` exactly (``is_exact``), or ``lo < t <= hi``, so ``lo``
/// is a time of no contact that a simulation can safely advance to (``safe_time()``).
#[pyclass(frozen, eq, module = "cga_collide.motion")]
#[derive(Clone, Copy, PartialEq)]
pub struct ContactTime {
    inner: RsContactTime,
}

#[pymethods]
impl ContactTime {
    /// A lower bound of the earliest contact time (strictly below it unless exact).
    #[getter]
    fn lo(&self) -> f64 {
        self.inner.lo()
    }

    /// An upper bound of the earliest contact time.
    #[getter]
    fn hi(&self) -> f64 {
        self.inner.hi()
    }

    /// ``hi - lo``.
    #[getter]
    fn width(&self) -> f64 {
        self.inner.width()
    }

    /// Whether the earliest contact time is exactly ``lo`` (``== hi``).
    #[getter]
    fn is_exact(&self) -> bool {
        self.inner.is_exact()
    }

    /// The latest known time strictly before contact: ``lo``, or the float64 just below an
    /// exact contact time; ``None`` when contact is at ``t = 0`` (no time before it in the step).
    fn safe_time(&self) -> Option<f64> {
        self.inner.safe_time()
    }

    fn __repr__(&self) -> String {
        format!("ContactTime(lo={:?}, hi={:?})", self.inner.lo(), self.inner.hi())
    }
}

fn contact_time(t: Option<RsContactTime>) -> Option<ContactTime> {
    t.map(|inner| ContactTime { inner })
}

// ------------------------------------------------------------------ inputs

/// The moving points of a `(c, 2, 3)` view (`c` rows of start and end).
fn moving_points(v: &ArrayView2<'_, f64>, row: usize) -> MovingPoint {
    let p = |r: usize| Point3::new(v[[r, 0]], v[[r, 1]], v[[r, 2]]);
    MovingPoint::new(p(2 * row), p(2 * row + 1))
}

/// The moving points of an array of `shape` (ending in `(2, 3)`), read as rows of
/// `(start, end)`.
fn read_points(
    obj: &Bound<'_, PyAny>, name: &str, shape: &[Option<usize>],
) -> PyResult<Vec<MovingPoint>> {
    convert::read(obj, name, shape, |v| {
        let flat: Vec<f64> = v.iter().copied().collect();
        let count = flat.len() / 6;
        let rows = ArrayView2::from_shape((2 * count, 3), &flat)
            .map_err(|e| value_error(format!("{name}: {e}")))?;
        Ok((0..count).map(|i| moving_points(&rows, i)).collect())
    })
}

/// A moving vertex: `(2, 3)`.
fn vertex(obj: &Bound<'_, PyAny>) -> PyResult<MovingPoint> {
    let p = read_points(obj, "vertex", &[Some(2), Some(3)])?;
    Ok(p[0])
}

/// A moving triangle: `(3, 2, 3)`.
fn face(obj: &Bound<'_, PyAny>) -> PyResult<[MovingPoint; 3]> {
    let p = read_points(obj, "face", &[Some(3), Some(2), Some(3)])?;
    Ok([p[0], p[1], p[2]])
}

/// A moving edge: `(2, 2, 3)`.
fn edge(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<[MovingPoint; 2]> {
    let p = read_points(obj, name, &[Some(2), Some(2), Some(3)])?;
    Ok([p[0], p[1]])
}

/// The queries of a batch: a `(k, 4, 2, 3)` array, four moving points a query.
fn batch(obj: &Bound<'_, PyAny>) -> PyResult<Vec<[MovingPoint; 4]>> {
    let p = read_points(obj, "points", &[None, Some(4), Some(2), Some(3)])?;
    Ok(p.chunks_exact(4).map(|q| [q[0], q[1], q[2], q[3]]).collect())
}

/// The queries of the batch `points` answered over the cores with the GIL released; the
/// first error names its query.
fn answer_batch<T: Send>(
    py: Python<'_>, points: &Arg, f: impl Fn(&[MovingPoint; 4]) -> Result<T, Error> + Sync + Send,
) -> PyResult<Vec<T>> {
    let queries = batch(points)?;
    py.detach(|| {
        queries
            .par_iter()
            .enumerate()
            .map(|(k, q)| f(q).map_err(|e| (k, e)))
            .collect::<Result<Vec<T>, (usize, Error)>>()
    })
    .map_err(|(k, e)| value_error(format!("points[{k}]: {e}")))
}

fn vf(q: &[MovingPoint; 4]) -> (&MovingPoint, [MovingPoint; 3]) {
    (&q[0], [q[1], q[2], q[3]])
}

fn ee(q: &[MovingPoint; 4]) -> ([MovingPoint; 2], [MovingPoint; 2]) {
    ([q[0], q[1]], [q[2], q[3]])
}

/// First contacts as a `(k, 2)` float64 array of `[lo, hi]`, NaN where none.
fn bounds_array<'py>(
    py: Python<'py>, times: &[Option<RsContactTime>],
) -> Bound<'py, PyArray2<f64>> {
    let mut a = Array2::<f64>::from_elem((times.len(), 2), f64::NAN);
    for (k, t) in times.iter().enumerate() {
        if let Some(t) = t {
            a[[k, 0]] = t.lo();
            a[[k, 1]] = t.hi();
        }
    }
    a.into_pyarray(py)
}

// ------------------------------------------------------------------ primitives

/// Whether the moving vertex (``(2, 3)``: start, end) and the moving closed triangle
/// ``face`` (``(3, 2, 3)``: each corner's start and end) touch at some ``t`` in ``[0, 1]``,
/// exactly (no tolerance; touching counts). A non-finite coordinate raises ``CgaError``.
#[pyfunction]
pub fn vertex_face_touch(
    py: Python<'_>, vertex: &Bound<'_, PyAny>, face: &Bound<'_, PyAny>,
) -> PyResult<bool> {
    let (v, f) = (self::vertex(vertex)?, self::face(face)?);
    py.detach(|| motion::vertex_face_touch(&v, &f)).map_err(err)
}

/// Whether the moving closed edges ``a`` and ``b`` (``(2, 2, 3)`` each: each end's
/// start and end) touch at some ``t`` in ``[0, 1]``, exactly.
#[pyfunction]
pub fn edge_edge_touch(
    py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>,
) -> PyResult<bool> {
    let (a, b) = (edge(a, "a")?, edge(b, "b")?);
    py.detach(|| motion::edge_edge_touch(&a, &b)).map_err(err)
}

/// The earliest time the moving vertex touches the moving triangle, a ``ContactTime`` at most
/// ``tolerance`` wide (or as narrow as float64 allows; ``0.0`` for the narrowest), or ``None``
/// if they never touch in ``[0, 1]``. A tolerance that is NaN or negative raises ``CgaError``.
#[pyfunction]
#[pyo3(signature = (vertex, face, tolerance = 1e-9))]
pub fn vertex_face_first_contact(
    py: Python<'_>, vertex: &Bound<'_, PyAny>, face: &Bound<'_, PyAny>, tolerance: f64,
) -> PyResult<Option<ContactTime>> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let (v, f) = (self::vertex(vertex)?, self::face(face)?);
    let t = py.detach(|| motion::vertex_face_first_contact(&v, &f, tolerance)).map_err(err)?;
    Ok(contact_time(t))
}

/// The earliest time the moving edges ``a`` and ``b`` touch, a ``ContactTime`` (see
/// ``vertex_face_first_contact`` for ``tolerance``), or ``None``.
#[pyfunction]
#[pyo3(signature = (a, b, tolerance = 1e-9))]
pub fn edge_edge_first_contact(
    py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, tolerance: f64,
) -> PyResult<Option<ContactTime>> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let (a, b) = (edge(a, "a")?, edge(b, "b")?);
    let t = py.detach(|| motion::edge_edge_first_contact(&a, &b, tolerance)).map_err(err)?;
    Ok(contact_time(t))
}

/// ``vertex_face_touch`` for many queries in one call: ``points`` is ``(k, 4, 2, 3)``, each
/// query the moving vertex then the triangle's three moving corners; returns a ``(k,)`` bool
/// array. Answered over the cores with the GIL released.
#[pyfunction]
pub fn vertex_face_touch_batch<'py>(py: Python<'py>, points: &Arg) -> PyResult<Bools<'py>> {
    let hits = answer_batch(py, points, |q| {
        let (v, f) = vf(q);
        motion::vertex_face_touch(v, &f)
    })?;
    Ok(bools(py, hits))
}

/// ``edge_edge_touch`` for many queries in one call: ``points`` is ``(k, 4, 2, 3)``, each
/// query the two ends of edge ``a`` then those of edge ``b``; returns a ``(k,)`` bool array.
#[pyfunction]
pub fn edge_edge_touch_batch<'py>(py: Python<'py>, points: &Arg) -> PyResult<Bools<'py>> {
    let hits = answer_batch(py, points, |q| {
        let (a, b) = ee(q);
        motion::edge_edge_touch(&a, &b)
    })?;
    Ok(bools(py, hits))
}

/// ``vertex_face_first_contact`` for many queries (``points`` as in
/// ``vertex_face_touch_batch``): a ``(k, 2)`` float64 array of ``[lo, hi]``, NaN where the
/// query never touches.
#[pyfunction]
#[pyo3(signature = (points, tolerance = 1e-9))]
pub fn vertex_face_first_contact_batch<'py>(
    py: Python<'py>, points: &Arg, tolerance: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let times = answer_batch(py, points, |q| {
        let (v, f) = vf(q);
        motion::vertex_face_first_contact(v, &f, tolerance)
    })?;
    Ok(bounds_array(py, &times))
}

/// ``edge_edge_first_contact`` for many queries (``points`` as in ``edge_edge_touch_batch``):
/// a ``(k, 2)`` float64 array of ``[lo, hi]``, NaN where the query never touches.
#[pyfunction]
#[pyo3(signature = (points, tolerance = 1e-9))]
pub fn edge_edge_first_contact_batch<'py>(
    py: Python<'py>, points: &Arg, tolerance: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let times = answer_batch(py, points, |q| {
        let (a, b) = ee(q);
        motion::edge_edge_first_contact(&a, &b, tolerance)
    })?;
    Ok(bounds_array(py, &times))
}

// ------------------------------------------------------------------ two moving colliders

fn pair_tuple<'py>(py: Python<'py>, p: &MotionPair) -> PyResult<Bound<'py, PyTuple>> {
    match *p {
        MotionPair::VertexFace(v, f) => ("vertex_face", v, f).into_pyobject(py),
        MotionPair::FaceVertex(f, v) => ("face_vertex", f, v).into_pyobject(py),
        MotionPair::EdgeEdge(a, b) => ("edge_edge", (a[0], a[1]), (b[0], b[1])).into_pyobject(py),
    }
}

/// What touches while two colliders move (``Collider.contacts_during``).
///
/// ``pairs`` and ``first_pairs`` are lists of tuples, sorted as in Rust:
/// ``("vertex_face", v, f)`` (a vertex of the first collider, a face of the second),
/// ``("face_vertex", f, v)`` (a face of the first, a vertex of the second) and
/// ``("edge_edge", (a0, a1), (b0, b1))`` (an edge of each, as its two vertices, smaller first).
/// The same pairs as arrays: ``vertex_face`` and ``face_vertex`` ``(p, 2)`` int64,
/// ``edge_edge`` ``(q, 2, 2)`` int64.
#[pyclass(frozen, module = "cga_collide.motion")]
pub struct MotionContacts {
    inner: motion::MotionContacts,
}

/// `[v, f]` of a vertex–face pair.
fn vertex_face_of(p: &MotionPair) -> Option<(u32, u32)> {
    match *p {
        MotionPair::VertexFace(v, f) => Some((v, f)),
        _ => None,
    }
}

/// `[f, v]` of a face–vertex pair.
fn face_vertex_of(p: &MotionPair) -> Option<(u32, u32)> {
    match *p {
        MotionPair::FaceVertex(f, v) => Some((f, v)),
        _ => None,
    }
}

/// The two edges of an edge–edge pair.
fn edge_edge_of(p: &MotionPair) -> Option<([u32; 2], [u32; 2])> {
    match *p {
        MotionPair::EdgeEdge(a, b) => Some((a, b)),
        _ => None,
    }
}

impl MotionContacts {
    /// The touching pairs of one kind, in `pairs` order.
    fn pairs_of<T>(&self, pick: impl Fn(&MotionPair) -> Option<T>) -> Vec<T> {
        self.inner.pairs.iter().filter_map(pick).collect()
    }
}

#[pymethods]
impl MotionContacts {
    /// Every pair that touches at some ``t`` in ``[0, 1]``, sorted: a list of tuples.
    #[getter]
    fn pairs<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        self.inner.pairs.iter().map(|p| pair_tuple(py, p)).collect()
    }

    /// The earliest contact of all (a ``ContactTime``, to the tolerance asked for); ``None``
    /// when nothing touches.
    #[getter]
    fn first_contact(&self) -> Option<ContactTime> {
        contact_time(self.inner.first_contact)
    }

    /// The pairs whose own first contact may be the earliest (those whose contact interval
    /// meets ``first_contact``'s), as tuples like ``pairs``.
    #[getter]
    fn first_pairs<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        self.inner.first_pairs.iter().map(|p| pair_tuple(py, p)).collect()
    }

    /// The ``("vertex_face", v, f)`` pairs as a ``(p, 2)`` int64 array of ``[v, f]``.
    #[getter]
    fn vertex_face<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        convert::pairs(py, &self.pairs_of(vertex_face_of))
    }

    /// The ``("face_vertex", f, v)`` pairs as a ``(p, 2)`` int64 array of ``[f, v]``.
    #[getter]
    fn face_vertex<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        convert::pairs(py, &self.pairs_of(face_vertex_of))
    }

    /// The ``("edge_edge", a, b)`` pairs as a ``(q, 2, 2)`` int64 array of ``[a, b]``.
    #[getter]
    fn edge_edge<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<i64>> {
        edge_pairs(py, &self.pairs_of(edge_edge_of))
    }

    /// Number of touching pairs.
    fn __len__(&self) -> usize {
        self.inner.pairs.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "MotionContacts(pairs={}, first_contact={}, first_pairs={})",
            self.inner.pairs.len(),
            match self.inner.first_contact {
                Some(t) => format!("ContactTime(lo={:?}, hi={:?})", t.lo(), t.hi()),
                None => "None".to_owned(),
            },
            self.inner.first_pairs.len()
        )
    }
}

/// Edge pairs as a `(q, 2, 2)` int64 array.
fn edge_pairs<'py>(py: Python<'py>, p: &[([u32; 2], [u32; 2])]) -> Bound<'py, PyArray3<i64>> {
    let mut a = Array3::<i64>::zeros((p.len(), 2, 2));
    for (k, (x, y)) in p.iter().enumerate() {
        for i in 0..2 {
            a[[k, 0, i]] = i64::from(x[i]);
            a[[k, 1, i]] = i64::from(y[i]);
        }
    }
    a.into_pyarray(py)
}

/// The Rust `Collider::contacts_during`, called from `Collider.contacts_during`.
pub fn contacts_during(
    py: Python<'_>, a: &RsCollider, poses: &Bound<'_, PyAny>, b: &RsCollider,
    other_poses: &Bound<'_, PyAny>, tolerance: f64,
) -> PyResult<MotionContacts> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let pa = convert::pose_motion(poses, "poses")?;
    let pb = convert::pose_motion(other_poses, "other_poses")?;
    let inner = py
        .detach(|| a.contacts_during([&pa[0], &pa[1]], b, [&pb[0], &pb[1]], tolerance))
        .map_err(err)?;
    Ok(MotionContacts { inner })
}

// ------------------------------------------------------------------ a deforming mesh

/// What touches during a step of a deforming mesh (``step_self_contacts``): ``vertex_face``
/// ``(p, 2)`` int64 ``[vertex, face]`` pairs, ``edge_edge`` ``(q, 2, 2)`` int64 pairs of edges
/// (each edge as its two vertices, smaller first; the smaller edge first), both sorted;
/// ``first_contact`` (a ``ContactTime`` or ``None``); and how many pairs the swept boxes let
/// through to the exact test (``vertex_face_candidates``, ``edge_edge_candidates``).
#[pyclass(frozen, module = "cga_collide.motion")]
pub struct StepContacts {
    /// ``(p, 2)`` int64: ``[vertex, face]`` pairs that touch during the step, sorted.
    #[pyo3(get)]
    vertex_face: Py<PyArray2<i64>>,
    /// ``(q, 2, 2)`` int64: pairs of edges that touch, sorted.
    #[pyo3(get)]
    edge_edge: Py<PyArray3<i64>>,
    first: Option<RsContactTime>,
    /// How many vertex–face pairs the swept boxes let through to the exact test.
    #[pyo3(get)]
    vertex_face_candidates: usize,
    /// How many edge–edge pairs the swept boxes let through to the exact test.
    #[pyo3(get)]
    edge_edge_candidates: usize,
}

#[pymethods]
impl StepContacts {
    /// The earliest contact of all (a ``ContactTime``, to the tolerance asked for); ``None``
    /// when nothing touches.
    #[getter]
    fn first_contact(&self) -> Option<ContactTime> {
        contact_time(self.first)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "StepContacts(vertex_face={}, edge_edge={}, first_contact={}, vertex_face_candidates={}, edge_edge_candidates={})",
            self.vertex_face.bind(py).len().unwrap_or(0),
            self.edge_edge.bind(py).len().unwrap_or(0),
            match self.first {
                Some(t) => format!("ContactTime(lo={:?}, hi={:?})", t.lo(), t.hi()),
                None => "None".to_owned(),
            },
            self.vertex_face_candidates,
            self.edge_edge_candidates
        )
    }
}

/// Every vertex–face and edge–edge contact of a mesh deforming over one step, exactly: the
/// mesh is ``vertices_start`` (``(n, 3)``) and ``faces`` (``(m, 3)`` integers) at
/// ``t = 0``, each vertex moving linearly to its row of ``vertices_end`` (``(n, 3)``)
/// at ``t = 1``. Pairs that share a vertex are excluded. The first contact time is bounded to
/// ``tolerance``. Returns a ``StepContacts``.
#[pyfunction]
#[pyo3(signature = (vertices_start, faces, vertices_end, tolerance = 1e-9))]
pub fn step_self_contacts(
    py: Python<'_>, vertices_start: &Bound<'_, PyAny>, faces: &Bound<'_, PyAny>,
    vertices_end: &Bound<'_, PyAny>, tolerance: f64,
) -> PyResult<StepContacts> {
    let tolerance = convert::tolerance(tolerance, "tolerance")?;
    let start = convert::points(vertices_start, "vertices_start")?;
    let f = convert::faces(faces, start.len())?;
    let end = convert::points(vertices_end, "vertices_end")?;
    let c = py
        .detach(|| {
            let mesh = TriMesh::new(start, f)?;
            motion::step_self_contacts(&mesh, &end, tolerance)
        })
        .map_err(err)?;
    Ok(StepContacts {
        vertex_face: convert::pairs(py, &c.vertex_face).unbind(),
        edge_edge: edge_pairs(py, &c.edge_edge).unbind(),
        first: c.first_contact,
        vertex_face_candidates: c.vertex_face_candidates,
        edge_edge_candidates: c.edge_edge_candidates,
    })
}

/// Registers the classes and functions of `cga_collide.motion` on the extension module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ContactTime>()?;
    m.add_class::<MotionContacts>()?;
    m.add_class::<StepContacts>()?;
    m.add_function(wrap_pyfunction!(vertex_face_touch, m)?)?;
    m.add_function(wrap_pyfunction!(edge_edge_touch, m)?)?;
    m.add_function(wrap_pyfunction!(vertex_face_first_contact, m)?)?;
    m.add_function(wrap_pyfunction!(edge_edge_first_contact, m)?)?;
    m.add_function(wrap_pyfunction!(vertex_face_touch_batch, m)?)?;
    m.add_function(wrap_pyfunction!(edge_edge_touch_batch, m)?)?;
    m.add_function(wrap_pyfunction!(vertex_face_first_contact_batch, m)?)?;
    m.add_function(wrap_pyfunction!(edge_edge_first_contact_batch, m)?)?;
    m.add_function(wrap_pyfunction!(step_self_contacts, m)?)?;
    Ok(())
}
