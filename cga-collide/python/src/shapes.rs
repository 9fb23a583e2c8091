//! The solid primitives as Python classes: `Shape`, the base that holds the library's
//! `Shape`, and one subclass per kind (`Ball`, `Cuboid`, ...) with its constructor and
//! read-only properties. The queries over shapes are in `shape_queries.rs`.

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::shape::{
    Capsule as RsCapsule, Cone as RsCone, ConvexHull as RsConvexHull, Cuboid as RsCuboid,
    Cylinder as RsCylinder, HalfSpace as RsHalfSpace, Shape,
};
use cga_collide::{Ball as RsBall, Segment as RsSegment, Triangle as RsTriangle};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::PyClass;

use crate::convert::{self, err, Arg};

type F64s1<'py> = Bound<'py, PyArray1<f64>>;
type F64s2<'py> = Bound<'py, PyArray2<f64>>;

/// A solid primitive, the base class of ``Ball``, ``Cuboid``, ``Capsule``, ``Cylinder``,
/// ``Cone``, ``HalfSpace``, ``ConvexHull``, ``Triangle`` and ``Segment`` (not built itself).
///
/// Every shape is a closed set (touching counts) and is exactly the set that the float64
/// numbers given describe, never rounded: a cuboid's corners are exact sums, a cylinder's rim
/// is a true circle. Constructors take anything numpy reads as numbers that float64 holds
/// exactly; a wrong array shape, a non-finite value, a value beyond ``MAX_MAGNITUDE``, a
/// negative radius or a degenerate input the class refuses raise ``CgaError`` naming the
/// argument.
///
/// The module functions ``intersects``, ``within_distance`` and ``distance`` take any two
/// shapes, in one frame, under poses (``_at``) and for many poses at once (``_batch``).
/// Shapes are immutable, compare equal when built from the same numbers, and pickle.
#[pyclass(frozen, subclass, eq, module = "cga_collide", name = "Shape")]
#[derive(PartialEq)]
pub struct PyShape {
    pub inner: Shape,
}

/// The Python object of a library shape: an instance of its kind's class.
pub fn shape_object(py: Python<'_>, shape: Shape) -> PyResult<Bound<'_, PyAny>> {
    let base = PyClassInitializer::from(PyShape { inner: shape.clone() });
    Ok(match shape {
        Shape::Ball(s) => Bound::new(py, base.add_subclass(Ball { inner: s }))?.into_any(),
        Shape::Cuboid(s) => Bound::new(py, base.add_subclass(Cuboid { inner: s }))?.into_any(),
        Shape::Capsule(s) => Bound::new(py, base.add_subclass(Capsule { inner: s }))?.into_any(),
        Shape::Cylinder(s) => Bound::new(py, base.add_subclass(Cylinder { inner: s }))?.into_any(),
        Shape::Cone(s) => Bound::new(py, base.add_subclass(Cone { inner: s }))?.into_any(),
        Shape::HalfSpace(s) => {
            Bound::new(py, base.add_subclass(HalfSpace { inner: s }))?.into_any()
        }
        Shape::ConvexHull(_) => Bound::new(py, base.add_subclass(ConvexHull))?.into_any(),
        Shape::Triangle(s) => Bound::new(py, base.add_subclass(Triangle { inner: s }))?.into_any(),
        Shape::Segment(s) => Bound::new(py, base.add_subclass(Segment { inner: s }))?.into_any(),
    })
}

/// The constructor's answer: the base holding the library shape, then the subclass.
fn init<S: Into<Shape>, T: PyClass<BaseType = PyShape>>(shape: S, sub: T) -> PyClassInitializer<T> {
    PyClassInitializer::from(PyShape { inner: shape.into() }).add_subclass(sub)
}

fn point3(obj: &Arg<'_>, name: &str) -> PyResult<Point3<f64>> {
    convert::triple(obj, name).map(Point3::from)
}

fn vector(obj: &Arg<'_>, name: &str) -> PyResult<Vector3<f64>> {
    convert::triple(obj, name).map(Vector3::from)
}

fn array1<'py>(py: Python<'py>, v: &[f64]) -> F64s1<'py> {
    PyArray1::from_slice(py, v)
}

fn rows<'py>(py: Python<'py>, rows: &[[f64; 3]]) -> F64s2<'py> {
    Array2::from_shape_fn((rows.len(), 3), |(i, c)| rows[i][c]).into_pyarray(py)
}

/// `[x, y, z]` with Python's spelling of each float (`{:?}` is the shortest round trip, as
/// Python's `repr`).
fn list(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
    format!("[{}]", items.join(", "))
}

fn list_of(rows: &[[f64; 3]]) -> String {
    let items: Vec<String> = rows.iter().map(|r| list(r)).collect();
    format!("[{}]", items.join(", "))
}

/// Hulls of more points than this show their count in `repr`, not every point.
const REPR_POINTS: usize = 8;

/// The constructor arguments of a shape, as `__reduce__` gives them (numpy arrays and floats).
fn arguments<'py>(py: Python<'py>, shape: &Shape) -> PyResult<Bound<'py, PyTuple>> {
    let p = |p: &Point3<f64>| array1(py, p.coords.as_slice()).into_any();
    let r = |r: f64| r.into_pyobject(py).map(Bound::into_any);
    match shape {
        Shape::Ball(s) => PyTuple::new(py, [p(s.centre()), r(s.radius())?]),
        Shape::Cuboid(s) => {
            let axes = s.half_axes().map(|h| [h.x, h.y, h.z]);
            PyTuple::new(py, [p(s.centre()), rows(py, &axes).into_any()])
        }
        Shape::Capsule(s) => PyTuple::new(py, [p(s.a()), p(s.b()), r(s.radius())?]),
        Shape::Cylinder(s) => PyTuple::new(py, [p(s.a()), p(s.b()), r(s.radius())?]),
        Shape::Cone(s) => PyTuple::new(py, [p(s.apex()), p(s.base()), r(s.radius())?]),
        Shape::HalfSpace(s) => {
            PyTuple::new(py, [p(s.point()), array1(py, s.normal().as_slice()).into_any()])
        }
        Shape::ConvexHull(s) => PyTuple::new(py, [rows(py, &hull_rows(s)).into_any()]),
        Shape::Triangle(s) => PyTuple::new(py, s.vertices().iter().map(p)),
        Shape::Segment(s) => PyTuple::new(py, [p(s.a()), p(s.b())]),
    }
}

fn hull_rows(h: &RsConvexHull) -> Vec<[f64; 3]> {
    h.points().iter().map(|p| [p.x, p.y, p.z]).collect()
}

/// What `Shape.__reduce__` returns: the shape's class and its constructor arguments.
type Reduced<'py> = (Bound<'py, PyAny>, Bound<'py, PyTuple>);

#[pymethods]
impl PyShape {
    /// The kind's name, as the ``cga shapes`` command line's JSON spells it: ``"ball"``,
    /// ``"cuboid"``, ``"capsule"``, ``"cylinder"``, ``"cone"``, ``"halfspace"``, ``"convex"``,
    /// ``"triangle"`` or ``"segment"``.
    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.kind()
    }

    /// This shape moved by ``pose`` (a ``(4, 4)`` rigid motion), as a shape of the same class,
    /// by the library's placement rule: each defining point is mapped and each defining vector
    /// rotated in float64, every coordinate rounded once, radii unchanged. Every ``_at`` and
    /// ``_batch`` answer is the answer for the shapes placed so. Raises ``CgaError`` when a
    /// placed value leaves the range or a cylinder's or cone's rounded axis ends coincide.
    fn placed<'py>(&self, py: Python<'py>, pose: &Arg<'py>) -> PyResult<Bound<'py, PyAny>> {
        let pose = convert::pose(pose, "pose")?;
        shape_object(py, self.inner.placed(&pose).map_err(err)?)
    }

    /// Pickling: the class and the constructor's arguments (the shape is rebuilt, and checked,
    /// from the same numbers).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Reduced<'py>> {
        let args = arguments(slf.py(), &slf.get().inner)?;
        Ok((slf.get_type().into_any(), args))
    }

    fn __repr__(&self) -> String {
        let p = |p: &Point3<f64>| list(p.coords.as_slice());
        match &self.inner {
            Shape::Ball(s) => format!("Ball(centre={}, radius={:?})", p(s.centre()), s.radius()),
            Shape::Cuboid(s) => format!(
                "Cuboid(centre={}, half_axes={})",
                p(s.centre()),
                list_of(&s.half_axes().map(|h| [h.x, h.y, h.z]))
            ),
            Shape::Capsule(s) => {
                format!("Capsule(a={}, b={}, radius={:?})", p(s.a()), p(s.b()), s.radius())
            }
            Shape::Cylinder(s) => {
                format!("Cylinder(a={}, b={}, radius={:?})", p(s.a()), p(s.b()), s.radius())
            }
            Shape::Cone(s) => {
                format!("Cone(apex={}, base={}, radius={:?})", p(s.apex()), p(s.base()), s.radius())
            }
            Shape::HalfSpace(s) => {
                format!("HalfSpace(point={}, normal={})", p(s.point()), list(s.normal().as_slice()))
            }
            Shape::ConvexHull(s) if s.points().len() > REPR_POINTS => {
                format!("ConvexHull(<{} points>)", s.points().len())
            }
            Shape::ConvexHull(s) => format!("ConvexHull(points={})", list_of(&hull_rows(s))),
            Shape::Triangle(s) => {
                let [a, b, c] = s.vertices();
                format!("Triangle(a={}, b={}, c={})", p(a), p(b), p(c))
            }
            Shape::Segment(s) => format!("Segment(a={}, b={})", p(s.a()), p(s.b())),
        }
    }
}

// ---------------------------------------------------------------------------------- the kinds

/// The closed solid ball of ``centre`` (``(3,)``) and ``radius`` (at least 0; ``0`` is the
/// point).
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Ball")]
pub struct Ball {
    inner: RsBall,
}

#[pymethods]
impl Ball {
    #[new]
    fn py_new(centre: &Arg<'_>, radius: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let s = RsBall::new(point3(centre, "centre")?, convert::number(radius, "radius")?)
            .map_err(err)?;
        Ok(init(s, Ball { inner: s }))
    }

    /// The centre, a ``(3,)`` float64 array.
    #[getter]
    fn centre<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.centre().coords.as_slice())
    }

    /// The radius.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
}

/// The closed solid ``centre + s1 U + s2 V + s3 W`` with ``|si| <= 1``, for ``centre``
/// (``(3,)``) and ``half_axes`` (``(3, 3)``, the half axes ``U``, ``V``, ``W`` as rows): a
/// box when the half axes are orthogonal, the parallelepiped they span otherwise, and the
/// flat parallelogram, segment or point they span when they are dependent.
/// ``Cuboid.axis_aligned(centre, half_extents)`` is the axis-aligned box.
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Cuboid")]
pub struct Cuboid {
    inner: RsCuboid,
}

#[pymethods]
impl Cuboid {
    #[new]
    fn py_new(centre: &Arg<'_>, half_axes: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let axes = convert::triples(half_axes, "half_axes", Some(3))?;
        let axes = [0, 1, 2].map(|i| Vector3::from(axes[i]));
        let s = RsCuboid::new(point3(centre, "centre")?, axes).map_err(err)?;
        Ok(init(s, Cuboid { inner: s }))
    }

    /// The axis-aligned box ``centre ± half_extents`` (``(3,)`` each, every half extent at
    /// least 0).
    #[staticmethod]
    fn axis_aligned<'py>(
        py: Python<'py>, centre: &Arg<'py>, half_extents: &Arg<'py>,
    ) -> PyResult<Bound<'py, PyAny>> {
        // `convert::point` refuses a NaN half extent by this argument's name (the library's
        // check of the half axes it builds would name those).
        let h = convert::point(half_extents, "half_extents")?;
        let s = RsCuboid::axis_aligned(point3(centre, "centre")?, h.coords).map_err(err)?;
        shape_object(py, s.into())
    }

    /// The centre, a ``(3,)`` float64 array.
    #[getter]
    fn centre<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.centre().coords.as_slice())
    }

    /// The half axes, a ``(3, 3)`` float64 array (one per row).
    #[getter]
    fn half_axes<'py>(&self, py: Python<'py>) -> F64s2<'py> {
        rows(py, &self.inner.half_axes().map(|h| [h.x, h.y, h.z]))
    }
}

/// The points within ``radius`` (at least 0) of the closed segment ``a``–``b`` (``(3,)``
/// each): a cylinder with round caps; ``a == b`` gives a ball, radius ``0`` the segment.
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Capsule")]
pub struct Capsule {
    inner: RsCapsule,
}

#[pymethods]
impl Capsule {
    #[new]
    fn py_new(a: &Arg<'_>, b: &Arg<'_>, radius: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let r = convert::number(radius, "radius")?;
        let s = RsCapsule::new(point3(a, "a")?, point3(b, "b")?, r).map_err(err)?;
        Ok(init(s, Capsule { inner: s }))
    }

    /// The first end of the axis, a ``(3,)`` float64 array.
    #[getter]
    fn a<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.a().coords.as_slice())
    }

    /// The second end of the axis, a ``(3,)`` float64 array.
    #[getter]
    fn b<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.b().coords.as_slice())
    }

    /// The radius.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
}

/// The closed solid cylinder of axis segment ``a``–``b`` (``(3,)`` each, distinct) and
/// ``radius`` (at least 0), with flat caps: the discs at ``a`` and ``b`` perpendicular to
/// ``b - a``. Radius ``0`` gives the segment.
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Cylinder")]
pub struct Cylinder {
    inner: RsCylinder,
}

#[pymethods]
impl Cylinder {
    #[new]
    fn py_new(a: &Arg<'_>, b: &Arg<'_>, radius: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let r = convert::number(radius, "radius")?;
        let s = RsCylinder::new(point3(a, "a")?, point3(b, "b")?, r).map_err(err)?;
        Ok(init(s, Cylinder { inner: s }))
    }

    /// The centre of the first cap, a ``(3,)`` float64 array.
    #[getter]
    fn a<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.a().coords.as_slice())
    }

    /// The centre of the second cap, a ``(3,)`` float64 array.
    #[getter]
    fn b<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.b().coords.as_slice())
    }

    /// The radius.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
}

/// The closed solid cone of ``apex`` and the base disc of centre ``base`` (``(3,)`` each,
/// distinct) and ``radius`` (at least 0), perpendicular to ``base - apex``: the convex hull
/// of the apex and the disc. Radius ``0`` gives the segment ``apex``–``base``.
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Cone")]
pub struct Cone {
    inner: RsCone,
}

#[pymethods]
impl Cone {
    #[new]
    fn py_new(
        apex: &Arg<'_>, base: &Arg<'_>, radius: &Arg<'_>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let r = convert::number(radius, "radius")?;
        let s = RsCone::new(point3(apex, "apex")?, point3(base, "base")?, r).map_err(err)?;
        Ok(init(s, Cone { inner: s }))
    }

    /// The apex, a ``(3,)`` float64 array.
    #[getter]
    fn apex<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.apex().coords.as_slice())
    }

    /// The centre of the base disc, a ``(3,)`` float64 array.
    #[getter]
    fn base<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.base().coords.as_slice())
    }

    /// The radius of the base disc.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
}

/// The closed half-space ``{x : (x - point)·normal <= 0}`` of ``point`` (``(3,)``, on the
/// boundary plane) and ``normal`` (``(3,)``, outward, not zero; used as given, not
/// normalised).
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "HalfSpace")]
pub struct HalfSpace {
    inner: RsHalfSpace,
}

#[pymethods]
impl HalfSpace {
    #[new]
    fn py_new(point: &Arg<'_>, normal: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let s =
            RsHalfSpace::new(point3(point, "point")?, vector(normal, "normal")?).map_err(err)?;
        Ok(init(s, HalfSpace { inner: s }))
    }

    /// A point of the boundary plane, a ``(3,)`` float64 array.
    #[getter]
    fn point<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.point().coords.as_slice())
    }

    /// The outward normal as given, a ``(3,)`` float64 array.
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.normal().as_slice())
    }
}

/// The closed convex hull of ``points`` (``(n, 3)``, at least one), exactly: points inside
/// change nothing; one point, collinear or coplanar points give the point, segment or flat
/// polygon they span.
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "ConvexHull")]
pub struct ConvexHull;

#[pymethods]
impl ConvexHull {
    #[new]
    fn py_new(py: Python<'_>, points: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let p = convert::triples(points, "points", None)?;
        let p: Vec<Point3<f64>> = p.into_iter().map(Point3::from).collect();
        let s = py.detach(|| RsConvexHull::new(p)).map_err(err)?;
        Ok(init(s, ConvexHull))
    }

    /// The points as given, a fresh ``(n, 3)`` float64 array.
    #[getter]
    fn points<'py>(slf: &Bound<'py, Self>) -> F64s2<'py> {
        let rows_of = match &slf.as_super().get().inner {
            Shape::ConvexHull(h) => hull_rows(h),
            // The base of a `ConvexHull` always holds a hull (`init`).
            _ => Vec::new(),
        };
        rows(slf.py(), &rows_of)
    }

    /// The hull's corners, exactly (a point one ulp outside a face is a corner, one inside is
    /// not), a fresh ``(k, 3)`` float64 array: a flat polygon's in boundary order.
    #[getter]
    fn corners<'py>(slf: &Bound<'py, Self>) -> F64s2<'py> {
        let rows_of: Vec<[f64; 3]> = hull_of(slf)
            .map(|h| h.corners().iter().map(|p| [p.x, p.y, p.z]).collect())
            .unwrap_or_default();
        rows(slf.py(), &rows_of)
    }

    /// For a solid hull, its boundary as triangles of row indices into ``corners``,
    /// counter-clockwise seen from outside, an ``(m, 3)`` int64 array; ``(0, 3)`` for a point,
    /// segment or flat polygon.
    #[getter]
    fn triangles<'py>(slf: &Bound<'py, Self>) -> Bound<'py, PyArray2<i64>> {
        let t: Vec<[u32; 3]> = hull_of(slf).map(|h| h.triangles().to_vec()).unwrap_or_default();
        Array2::from_shape_fn((t.len(), 3), |(i, c)| i64::from(t[i][c])).into_pyarray(slf.py())
    }

    /// 0 for a point, 1 for a segment, 2 for a flat polygon, 3 for a solid.
    #[getter]
    fn dimension(slf: &Bound<'_, Self>) -> u8 {
        hull_of(slf).map_or(0, |h| h.dimension())
    }
}

/// The library hull a Python `ConvexHull` holds.
fn hull_of<'a>(slf: &'a Bound<'_, ConvexHull>) -> Option<&'a RsConvexHull> {
    match &slf.as_super().get().inner {
        Shape::ConvexHull(h) => Some(h),
        // The base of a `ConvexHull` always holds a hull (`init`).
        _ => None,
    }
}

/// The closed triangle ``abc`` (``(3,)`` each; collinear corners give the segment or point
/// they span).
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Triangle")]
pub struct Triangle {
    inner: RsTriangle,
}

#[pymethods]
impl Triangle {
    #[new]
    fn py_new(a: &Arg<'_>, b: &Arg<'_>, c: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let s = RsTriangle::new(point3(a, "a")?, point3(b, "b")?, point3(c, "c")?).map_err(err)?;
        Ok(init(s, Triangle { inner: s }))
    }

    /// The corners ``a``, ``b``, ``c`` as rows, a ``(3, 3)`` float64 array.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> F64s2<'py> {
        rows(py, &self.inner.vertices().map(|p| [p.x, p.y, p.z]))
    }
}

/// The closed segment ``a``–``b`` (``(3,)`` each; the point when they coincide).
#[pyclass(frozen, extends = PyShape, module = "cga_collide", name = "Segment")]
pub struct Segment {
    inner: RsSegment,
}

#[pymethods]
impl Segment {
    #[new]
    fn py_new(a: &Arg<'_>, b: &Arg<'_>) -> PyResult<PyClassInitializer<Self>> {
        let s = RsSegment::new(point3(a, "a")?, point3(b, "b")?).map_err(err)?;
        Ok(init(s, Segment { inner: s }))
    }

    /// The first end, a ``(3,)`` float64 array.
    #[getter]
    fn a<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.a().coords.as_slice())
    }

    /// The second end, a ``(3,)`` float64 array.
    #[getter]
    fn b<'py>(&self, py: Python<'py>) -> F64s1<'py> {
        array1(py, self.inner.b().coords.as_slice())
    }
}

/// Registers the shape classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyShape>()?;
    m.add_class::<Ball>()?;
    m.add_class::<Cuboid>()?;
    m.add_class::<Capsule>()?;
    m.add_class::<Cylinder>()?;
    m.add_class::<Cone>()?;
    m.add_class::<HalfSpace>()?;
    m.add_class::<ConvexHull>()?;
    m.add_class::<Triangle>()?;
    m.add_class::<Segment>()?;
    m.add("MAX_MAGNITUDE", cga_collide::shape::MAX_MAGNITUDE)?;
    Ok(())
}
