//! Signed distances of many points to a mesh, as Python sees them: a `PointDistances` of arrays.

use cga_collide::collider::PointDistance;
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

/// The signed distances of ``n`` points to a mesh, as arrays: ``signed_distance`` ``(n,)``
/// (negative inside, ``0`` on the surface, which is inside), ``error_bound`` ``(n,)`` (the true
/// distance is within it of ``|signed_distance|``, proved), ``inside`` ``(n,)`` bool (exact),
/// ``nearest`` ``(n, 3)`` (the nearest surface point) and ``triangle`` ``(n,)`` int64 (its
/// triangle).
#[pyclass(frozen, module = "cga_collide")]
pub struct PointDistances {
    /// ``(n,)`` float64: negative inside, ``0`` on the surface.
    #[pyo3(get)]
    signed_distance: Py<PyArray1<f64>>,
    /// ``(n,)`` float64.
    #[pyo3(get)]
    error_bound: Py<PyArray1<f64>>,
    /// ``(n,)`` bool.
    #[pyo3(get)]
    inside: Py<PyArray1<bool>>,
    /// ``(n, 3)`` float64.
    #[pyo3(get)]
    nearest: Py<PyArray2<f64>>,
    /// ``(n,)`` int64.
    #[pyo3(get)]
    triangle: Py<PyArray1<i64>>,
}

#[pymethods]
impl PointDistances {
    fn __len__(&self, py: Python<'_>) -> usize {
        self.signed_distance.bind(py).len().unwrap_or(0)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!("PointDistances(n={})", self.__len__(py))
    }
}

pub fn point_distances(py: Python<'_>, ds: &[PointDistance]) -> PointDistances {
    let mut nearest = Array2::<f64>::zeros((ds.len(), 3));
    for (i, d) in ds.iter().enumerate() {
        for c in 0..3 {
            nearest[[i, c]] = d.nearest[c];
        }
    }
    let column = |f: fn(&PointDistance) -> f64| Array1::from_iter(ds.iter().map(f));
    PointDistances {
        signed_distance: column(|d| d.signed_distance).into_pyarray(py).unbind(),
        error_bound: column(|d| d.error_bound).into_pyarray(py).unbind(),
        inside: Array1::from_iter(ds.iter().map(|d| d.inside)).into_pyarray(py).unbind(),
        nearest: nearest.into_pyarray(py).unbind(),
        triangle: Array1::from_iter(ds.iter().map(|d| i64::from(d.triangle)))
            .into_pyarray(py)
            .unbind(),
    }
}
