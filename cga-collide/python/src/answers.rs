//! The Rust answers that have no class of their own, as Python values: contacts as tuples,
//! exact distances as `fractions.Fraction`.

use cga_collide::ga_core::scalar::Rational;
use cga_collide::query::{ContactGeometry, ExactDistance};
use numpy::ndarray::Array2;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// One contact of `Collider.contacts`: the triangle pair, the kind of intersection and its
/// corners (nearest float64 values of the exact rationals).
fn contact_tuple<'py>(
    py: Python<'py>, (i, j): (u32, u32), g: &ContactGeometry,
) -> PyResult<Bound<'py, PyTuple>> {
    let kind = match g {
        ContactGeometry::Point(_) => "point",
        ContactGeometry::Segment(..) => "segment",
        ContactGeometry::Polygon(_) => "polygon",
    };
    let pts = g.points_f64();
    let a = Array2::from_shape_fn((pts.len(), 3), |(k, c)| pts[k][c]);
    PyTuple::new(
        py,
        [
            (i, j).into_pyobject(py)?.into_any(),
            kind.into_pyobject(py)?.into_any(),
            a.into_pyarray(py).into_any(),
        ],
    )
}

/// Every contact of `Collider.contacts` as a tuple.
pub fn contact_tuples<'py>(
    py: Python<'py>, cs: &[((u32, u32), ContactGeometry)],
) -> PyResult<Vec<Bound<'py, PyTuple>>> {
    cs.iter().map(|(ij, g)| contact_tuple(py, *ij, g)).collect()
}

/// `Collider.exact_distance`'s answer: `(distance2, witness_a, witness_b, triangles)` with
/// every rational a `fractions.Fraction`.
pub fn exact_distance_tuple<'py>(
    py: Python<'py>, d: &ExactDistance,
) -> PyResult<Bound<'py, PyTuple>> {
    let fraction = py.import("fractions")?.getattr("Fraction")?;
    let q = |x: &Rational| -> PyResult<Bound<'py, PyAny>> {
        fraction
            .call1((x.numer().to_string(),))?
            .call_method1("__truediv__", (fraction.call1((x.denom().to_string(),))?,))
    };
    let point = |p: &[Rational; 3]| -> PyResult<Bound<'py, PyTuple>> {
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
