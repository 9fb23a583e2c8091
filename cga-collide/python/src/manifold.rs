//! The contact manifold of two shapes (`cga_collide.contact_manifold`): a few contact points
//! with one normal, each with its signed distance along the normal and a proved bound.

use cga_collide::query::{self, ContactManifold as RsManifold};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::convert::{self, err, Arg};
use crate::shape_queries::shape;
use crate::signed_distance::SignedDistance;

/// The contact of two shapes (at most 4 points, one region): ``normal`` ``(3,)`` unit from
/// ``a`` to ``b``; ``points`` ``(k, 3)`` halfway between ``points_a`` (on ``a``) and
/// ``points_b`` (on ``b``, over ``points_a`` along the normal); ``distances`` ``(k,)``
/// ``(points_b - points_a) @ normal`` (negative where they overlap); ``error_bounds`` ``(k,)``
/// proved: when the shapes meet each point is within its bound of both shapes (in their
/// intersection when it is 0), when apart ``points_a``/``points_b`` are within it of ``a``/``b``;
/// ``signed_distance`` the pair's certified ``SignedDistance``.
#[pyclass(frozen, module = "cga_collide")]
pub struct ContactManifold {
    normal: Py<PyArray1<f64>>,
    points: Py<PyArray2<f64>>,
    points_a: Py<PyArray2<f64>>,
    points_b: Py<PyArray2<f64>>,
    distances: Py<PyArray1<f64>>,
    error_bounds: Py<PyArray1<f64>>,
    signed_distance: SignedDistance,
    len: usize,
}

fn rows(py: Python<'_>, ps: impl Iterator<Item = [f64; 3]>) -> Py<PyArray2<f64>> {
    let flat: Vec<f64> = ps.flat_map(|p| p.into_iter()).collect();
    let n = flat.len() / 3;
    Array2::from_shape_vec((n, 3), flat)
        .unwrap_or_else(|_| Array2::zeros((0, 3)))
        .into_pyarray(py)
        .unbind()
}

impl ContactManifold {
    fn new(py: Python<'_>, m: &RsManifold, sd: SignedDistance) -> Self {
        let xyz = |p: &cga_collide::nalgebra::Point3<f64>| [p.x, p.y, p.z];
        let col = |f: &dyn Fn(&query::ManifoldPoint) -> f64| {
            Array1::from_iter(m.points.iter().map(f)).into_pyarray(py).unbind()
        };
        ContactManifold {
            normal: PyArray1::from_slice(py, &[m.normal.x, m.normal.y, m.normal.z]).unbind(),
            points: rows(py, m.points.iter().map(|p| xyz(&p.point))),
            points_a: rows(py, m.points.iter().map(|p| xyz(&p.point_a))),
            points_b: rows(py, m.points.iter().map(|p| xyz(&p.point_b))),
            distances: col(&|p| p.distance),
            error_bounds: col(&|p| p.error_bound),
            signed_distance: sd,
            len: m.points.len(),
        }
    }
}

#[pymethods]
impl ContactManifold {
    /// The unit normal from ``a`` to ``b``, ``(3,)`` float64.
    #[getter]
    fn normal(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.normal.clone_ref(py)
    }
    /// The contact points, ``(k, 3)`` float64.
    #[getter]
    fn points(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.points.clone_ref(py)
    }
    /// The points on ``a``, ``(k, 3)`` float64.
    #[getter]
    fn points_a(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.points_a.clone_ref(py)
    }
    /// The points on ``b``, ``(k, 3)`` float64.
    #[getter]
    fn points_b(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.points_b.clone_ref(py)
    }
    /// The signed distance of each point along the normal, ``(k,)`` float64.
    #[getter]
    fn distances(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.distances.clone_ref(py)
    }
    /// The proved bound of each point, ``(k,)`` float64.
    #[getter]
    fn error_bounds(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.error_bounds.clone_ref(py)
    }
    /// The pair's certified signed distance.
    #[getter]
    fn signed_distance(&self) -> SignedDistance {
        self.signed_distance.clone()
    }
    fn __len__(&self) -> usize {
        self.len
    }
    fn __repr__(&self) -> String {
        format!(
            "ContactManifold(points={}, signed_distance={:?})",
            self.len, self.signed_distance.value
        )
    }
}

/// The contact manifold of two shapes, or ``None`` when they are farther apart than
/// ``margin`` (a finite distance ``>= 0``).
#[pyfunction]
#[pyo3(signature = (a, b, margin = 0.0))]
fn contact_manifold(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, margin: f64,
) -> PyResult<Option<ContactManifold>> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let m = py.detach(|| query::contact_manifold(a, b, margin)).map_err(err)?;
    Ok(m.map(|m| {
        let sd = m.signed_distance.as_ref().map(SignedDistance::from);
        ContactManifold::new(py, &m, sd.unwrap_or_else(|| unreachable!("shape pairs have one")))
    }))
}

/// ``contact_manifold`` of the shapes placed by their ``(4, 4)`` poses.
#[pyfunction]
#[pyo3(signature = (a, pose_a, b, pose_b, margin = 0.0))]
fn contact_manifold_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>, margin: f64,
) -> PyResult<Option<ContactManifold>> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let (pa, pb) = (convert::pose(pose_a, "pose_a")?, convert::pose(pose_b, "pose_b")?);
    let m = py.detach(|| query::contact_manifold_at(a, &pa, b, &pb, margin)).map_err(err)?;
    Ok(m.map(|m| {
        let sd = m.signed_distance.as_ref().map(SignedDistance::from);
        ContactManifold::new(py, &m, sd.unwrap_or_else(|| unreachable!("shape pairs have one")))
    }))
}

/// Adds the class and the functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ContactManifold>()?;
    m.add_function(wrap_pyfunction!(contact_manifold, m)?)?;
    m.add_function(wrap_pyfunction!(contact_manifold_at, m)?)?;
    Ok(())
}
