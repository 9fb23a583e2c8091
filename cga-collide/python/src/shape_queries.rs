//! The generic queries over shapes as module functions, in the crate's three forms: one frame
//! (`intersects(a, b)`), under poses (`intersects_at(a, pose_a, b, pose_b)`), and many poses
//! at once (`intersects_batch(a, b, poses_a, poses_b)`), each the Rust `query` function of the
//! same name.

use cga_collide::collider::PosePair;
use cga_collide::nalgebra::Isometry3;
use cga_collide::query::{self, CertifiedDistance};
use cga_collide::shape::Shape;
use cga_collide::Error;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

use crate::convert::{self, bools, err, Arg, Bools};
use crate::distance::{distance_batch as distances, Distance, DistanceBatch};
use crate::shapes::PyShape;

type Pose = Isometry3<f64>;

/// The library shape of an argument; anything else is a `TypeError` naming the argument.
fn shape<'a>(obj: &'a Arg<'_>, name: &str) -> PyResult<&'a Shape> {
    match obj.cast::<PyShape>() {
        Ok(s) => Ok(&s.get().inner),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name}: expected a shape (Ball, Cuboid, Capsule, Cylinder, Cone, HalfSpace, ConvexHull, Triangle or Segment), got {}",
            obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "an object".to_owned())
        ))),
    }
}

/// Whether a question about `a` and `b` may take long enough to release the GIL for: a hull's
/// cost grows with its points, while every other pair is answered in about the time that
/// releasing and taking back the GIL costs (a microsecond or less).
fn long(a: &Shape, b: &Shape) -> bool {
    matches!(a, Shape::ConvexHull(_)) || matches!(b, Shape::ConvexHull(_))
}

/// A question about `a` and `b` (with the GIL released if it may take long).
fn pair<T: Send>(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>,
    q: impl FnOnce(&Shape, &Shape) -> Result<T, Error> + Send,
) -> PyResult<T> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    if long(a, b) {
        py.detach(|| q(a, b)).map_err(err)
    } else {
        q(a, b).map_err(err)
    }
}

/// A question about `a` at `pose_a` and `b` at `pose_b`.
fn at<T: Send>(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
    q: impl FnOnce(&Shape, &Pose, &Shape, &Pose) -> Result<T, Error> + Send,
) -> PyResult<T> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let (pa, pb) = (convert::pose(pose_a, "pose_a")?, convert::pose(pose_b, "pose_b")?);
    if long(a, b) {
        py.detach(|| q(a, &pa, b, &pb)).map_err(err)
    } else {
        q(a, &pa, b, &pb).map_err(err)
    }
}

/// A question for every pose pair of `poses_a` and `poses_b`; the first refused pose pair is
/// the error, with its index (the library's `Error::InBatch`).
fn batch<T: Send>(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
    q: impl Fn(&Shape, &PosePair, &Shape) -> Result<T, Error> + Send + Sync,
) -> PyResult<Vec<T>> {
    let (a, b) = (shape(a, "a")?, shape(b, "b")?);
    let poses = convert::pose_pairs(poses_a, poses_b)?;
    py.detach(|| {
        poses
            .iter()
            .enumerate()
            .map(|(index, p)| q(a, p, b).map_err(|e| Error::InBatch { index, source: Box::new(e) }))
            .collect::<Result<Vec<T>, Error>>()
    })
    .map_err(err)
}

/// Whether the closed shapes ``a`` and ``b`` share a point, exactly (touching counts).
/// ``CgaError`` if the library has no exact test for the pair yet or a value is out of range.
#[pyfunction]
fn intersects(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>) -> PyResult<bool> {
    pair(py, a, b, query::intersects)
}

/// ``intersects`` with ``a`` placed at ``pose_a`` and ``b`` at ``pose_b`` (``(4, 4)`` rigid
/// motions; ``Shape.placed``'s rule).
#[pyfunction]
fn intersects_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
) -> PyResult<bool> {
    at(py, a, pose_a, b, pose_b, query::intersects_at)
}

/// ``intersects_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
/// (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array. The first refused
/// pose raises ``CgaError`` with its index.
#[pyfunction]
fn intersects_batch<'py>(
    py: Python<'py>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
) -> PyResult<Bools<'py>> {
    let hits = batch(py, a, b, poses_a, poses_b, |a, p, b| query::intersects_at(a, &p.a, b, &p.b))?;
    Ok(bools(py, hits))
}

/// Whether the closed shapes ``a`` and ``b`` come within distance ``c`` (closed: exactly
/// ``c`` counts; ``c`` finite and at least 0), exactly.
#[pyfunction]
fn within_distance(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, c: f64) -> PyResult<bool> {
    pair(py, a, b, |a, b| query::within_distance(a, b, c))
}

/// ``within_distance`` under poses.
#[pyfunction]
fn within_distance_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>, c: f64,
) -> PyResult<bool> {
    at(py, a, pose_a, b, pose_b, |a, pa, b, pb| query::within_distance_at(a, pa, b, pb, c))
}

/// ``within_distance_at`` for every pose pair: a ``(k,)`` bool array.
#[pyfunction]
fn within_distance_batch<'py>(
    py: Python<'py>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>, c: f64,
) -> PyResult<Bools<'py>> {
    let hits = batch(py, a, b, poses_a, poses_b, |a, p, b| {
        query::within_distance_at(a, &p.a, b, &p.b, c)
    })?;
    Ok(bools(py, hits))
}

/// The certified minimum distance between the closed shapes ``a`` and ``b`` (``0`` when they
/// meet), a ``Distance`` with witness points on each shape (``triangles`` is ``None``).
#[pyfunction]
fn distance(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>) -> PyResult<Distance> {
    pair(py, a, b, query::distance).map(|d| Distance::from(&d))
}

/// ``distance`` under poses (witnesses in world coordinates).
#[pyfunction]
fn distance_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
) -> PyResult<Distance> {
    at(py, a, pose_a, b, pose_b, query::distance_at).map(|d| Distance::from(&d))
}

/// ``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays.
#[pyfunction]
fn distance_batch(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
) -> PyResult<DistanceBatch> {
    let ds: Vec<CertifiedDistance> =
        batch(py, a, b, poses_a, poses_b, |a, p, b| query::distance_at(a, &p.a, b, &p.b))?;
    Ok(distances(py, &ds))
}

/// Registers the query functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(intersects, m)?)?;
    m.add_function(wrap_pyfunction!(intersects_at, m)?)?;
    m.add_function(wrap_pyfunction!(intersects_batch, m)?)?;
    m.add_function(wrap_pyfunction!(within_distance, m)?)?;
    m.add_function(wrap_pyfunction!(within_distance_at, m)?)?;
    m.add_function(wrap_pyfunction!(within_distance_batch, m)?)?;
    m.add_function(wrap_pyfunction!(distance, m)?)?;
    m.add_function(wrap_pyfunction!(distance_at, m)?)?;
    m.add_function(wrap_pyfunction!(distance_batch, m)?)?;
    Ok(())
}
