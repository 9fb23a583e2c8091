//! The signed distance of two shapes (`cga_collide.signed_distance`): the distance when apart,
//! minus the penetration depth when they overlap, with a proved bound.

use cga_collide::query::{self, SignedDistance as RsSignedDistance, SignedDistanceKind};
use numpy::PyArray1;
use pyo3::prelude::*;

use crate::convert::{self, err, Arg};
use crate::shape_queries::shape;

/// A certified signed distance between two shapes: ``value`` is the distance when they are
/// apart and minus the penetration depth (the shortest translation of ``b`` that separates
/// them) when they overlap; the true value is within ``error_bound`` of it. ``normal`` is the
/// unit direction from ``a`` to ``b``: translating ``b`` by ``-value * normal`` makes them
/// touch. ``witness_a`` and ``witness_b`` are points of each with
/// ``(witness_b - witness_a) @ normal == value`` up to rounding. ``kind`` is ``"separated"``,
/// ``"touching"`` or ``"penetrating"``, decided exactly.
#[pyclass(frozen, module = "cga_collide")]
#[derive(Clone)]
pub struct SignedDistance {
    /// The signed distance (negative when the shapes overlap).
    #[pyo3(get)]
    pub value: f64,
    /// The proved bound on ``|value − true signed distance|``.
    #[pyo3(get)]
    pub error_bound: f64,
    normal: [f64; 3],
    wa: [f64; 3],
    wb: [f64; 3],
    /// ``"separated"``, ``"touching"`` or ``"penetrating"``.
    #[pyo3(get)]
    pub kind: &'static str,
}

impl From<&RsSignedDistance> for SignedDistance {
    fn from(d: &RsSignedDistance) -> Self {
        SignedDistance {
            value: d.value,
            error_bound: d.error_bound,
            normal: [d.normal.x, d.normal.y, d.normal.z],
            wa: [d.witness_a.x, d.witness_a.y, d.witness_a.z],
            wb: [d.witness_b.x, d.witness_b.y, d.witness_b.z],
            kind: match d.kind {
                SignedDistanceKind::Separated => "separated",
                SignedDistanceKind::Touching => "touching",
                SignedDistanceKind::Penetrating => "penetrating",
            },
        }
    }
}

#[pymethods]
impl SignedDistance {
    /// The unit normal from ``a`` to ``b``, a ``(3,)`` float64 array.
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.normal)
    }

    /// The witness point of ``a``, a ``(3,)`` float64 array.
    #[getter]
    fn witness_a<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.wa)
    }

    /// The witness point of ``b``, a ``(3,)`` float64 array.
    #[getter]
    fn witness_b<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.wb)
    }

    fn __float__(&self) -> f64 {
        self.value
    }

    fn __repr__(&self) -> String {
        format!(
            "SignedDistance(value={:?}, error_bound={:?}, kind={:?}, normal={:?})",
            self.value, self.error_bound, self.kind, self.normal
        )
    }
}

/// The certified signed distance of two shapes (``value < 0``: minus the penetration depth).
#[pyfunction]
fn signed_distance(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>) -> PyResult<SignedDistance> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let d = py.detach(|| query::signed_distance(a, b)).map_err(err)?;
    Ok(SignedDistance::from(&d))
}

/// ``signed_distance`` of the shapes placed by their ``(4, 4)`` poses.
#[pyfunction]
fn signed_distance_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
) -> PyResult<SignedDistance> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let (pa, pb) = (convert::pose(pose_a, "pose_a")?, convert::pose(pose_b, "pose_b")?);
    let d = py.detach(|| query::signed_distance_at(a, &pa, b, &pb)).map_err(err)?;
    Ok(SignedDistance::from(&d))
}

/// Adds the class and the functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<SignedDistance>()?;
    m.add_function(wrap_pyfunction!(signed_distance, m)?)?;
    m.add_function(wrap_pyfunction!(signed_distance_at, m)?)?;
    Ok(())
}
