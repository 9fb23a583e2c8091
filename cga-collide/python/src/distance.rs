//! Certified distances as Python sees them: one `Distance`, or a `DistanceBatch` of arrays.

use cga_collide::query::CertifiedDistance;
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

/// A certified distance between two meshes (their surfaces) or two shapes (the solids):
/// ``distance`` is within ``error_bound`` of the true minimum distance; ``witness_a`` and
/// ``witness_b`` are points of each (world coordinates) whose distance is ``distance``;
/// ``triangles`` is the pair of triangle indices they lie on (``None`` for shapes, or when not
/// known).
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
    /// The witness point on the first mesh or shape, a ``(3,)`` float64 array.
    #[getter]
    fn witness_a<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.wa)
    }

    /// The witness point on the second mesh or shape, a ``(3,)`` float64 array.
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

pub fn distance_batch(py: Python<'_>, ds: &[CertifiedDistance]) -> DistanceBatch {
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
        distance: Array1::from_iter(ds.iter().map(|d| d.distance)).into_pyarray(py).unbind(),
        error_bound: Array1::from_iter(ds.iter().map(|d| d.error_bound)).into_pyarray(py).unbind(),
        witness_a: wa.into_pyarray(py).unbind(),
        witness_b: wb.into_pyarray(py).unbind(),
        triangles: tr.into_pyarray(py).unbind(),
    }
}
