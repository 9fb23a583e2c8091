//! The generic queries as module functions, over shapes and mesh colliders alike, in the
//! crate's three forms: one frame (`intersects(a, b)`), under poses
//! (`intersects_at(a, pose_a, b, pose_b)`), and many poses at once
//! (`intersects_batch(a, b, poses_a, poses_b)`). Two shapes go to the Rust `query` function of
//! the same name (batches to `query::intersects_batch` and the rest), a shape and a mesh to the
//! collider's shape query (`intersects_shape`, ...), two meshes to the collider's own
//! (`collides`, `collides_batch`, ...).

use cga_collide::collider::{Collider as RsCollider, PosePair};
use cga_collide::nalgebra::Isometry3;
use cga_collide::query::{self, CertifiedDistance};
use cga_collide::shape::Shape;
use cga_collide::Error;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::collider::Collider;
use crate::convert::{self, bools, err, Arg, Bools};
use crate::distance::{distance_batch as distances, Distance, DistanceBatch};
use crate::shapes::PyShape;

type Pose = Isometry3<f64>;

fn type_name(obj: &Arg<'_>) -> String {
    obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "an object".to_owned())
}

/// The library shape of an argument; anything else is a `TypeError` naming the argument.
pub fn shape<'a>(obj: &'a Arg<'_>, name: &str) -> PyResult<&'a Shape> {
    match obj.cast::<PyShape>() {
        Ok(s) => Ok(&s.get().inner),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name}: expected a shape (Ball, Cuboid, Capsule, Cylinder, Cone, HalfSpace, ConvexHull, Triangle or Segment), got {}",
            type_name(obj)
        ))),
    }
}

/// One side of a question: a solid primitive or a mesh (its surface).
#[derive(Clone, Copy)]
enum Operand<'a> {
    Shape(&'a Shape),
    Mesh(&'a RsCollider),
}

fn operand<'a>(obj: &'a Arg<'_>, name: &str) -> PyResult<Operand<'a>> {
    if let Ok(s) = obj.cast::<PyShape>() {
        return Ok(Operand::Shape(&s.get().inner));
    }
    if let Ok(c) = obj.cast::<Collider>() {
        return Ok(Operand::Mesh(&c.get().inner));
    }
    Err(PyTypeError::new_err(format!(
        "{name}: expected a shape (Ball, Cuboid, Capsule, Cylinder, Cone, HalfSpace, ConvexHull, Triangle or Segment) or a Collider, got {}",
        type_name(obj)
    )))
}

/// Whether a question may take long enough to release the GIL for: a mesh's or a hull's cost
/// grows with its size, while every other pair of shapes is answered in about the time that
/// releasing and taking back the GIL costs (a microsecond or less).
fn long(a: Operand<'_>, b: Operand<'_>) -> bool {
    let long =
        |x: Operand<'_>| matches!(x, Operand::Mesh(_) | Operand::Shape(Shape::ConvexHull(_)));
    long(a) || long(b)
}

/// A question asked with the GIL released if it may take long.
fn ask<T: Send>(
    py: Python<'_>, a: Operand<'_>, b: Operand<'_>, q: impl FnOnce() -> Result<T, Error> + Send,
) -> PyResult<T> {
    if long(a, b) {
        py.detach(q).map_err(err)
    } else {
        q().map_err(err)
    }
}

/// The shape's witnesses first: a mesh's answer about a shape has the mesh's first.
fn shape_first(d: CertifiedDistance) -> CertifiedDistance {
    CertifiedDistance {
        witness_a: d.witness_b,
        witness_b: d.witness_a,
        triangles: d.triangles.map(|(i, j)| (j, i)),
        ..d
    }
}

fn intersects_of(a: Operand<'_>, b: Operand<'_>) -> Result<bool, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::intersects(a, b),
        (Operand::Mesh(m), Operand::Shape(s)) | (Operand::Shape(s), Operand::Mesh(m)) => {
            m.intersects_shape(s)
        }
        (Operand::Mesh(a), Operand::Mesh(b)) => Ok(a.collides(b)),
    }
}

fn intersects_at_of(a: Operand<'_>, pa: &Pose, b: Operand<'_>, pb: &Pose) -> Result<bool, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::intersects_at(a, pa, b, pb),
        (Operand::Mesh(m), Operand::Shape(s)) => m.intersects_shape_at(pa, s, pb),
        (Operand::Shape(s), Operand::Mesh(m)) => m.intersects_shape_at(pb, s, pa),
        (Operand::Mesh(a), Operand::Mesh(b)) => a.collides_at(pa, b, pb),
    }
}

fn within_distance_of(a: Operand<'_>, b: Operand<'_>, c: f64) -> Result<bool, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::within_distance(a, b, c),
        (Operand::Mesh(m), Operand::Shape(s)) | (Operand::Shape(s), Operand::Mesh(m)) => {
            m.shape_within_distance(s, c)
        }
        // A collider takes any clearance but NaN (a negative one is never reached).
        (Operand::Mesh(_), Operand::Mesh(_)) if c.is_nan() => {
            Err(Error::InvalidClearance { value: c })
        }
        (Operand::Mesh(a), Operand::Mesh(b)) => Ok(a.within_distance(b, c)),
    }
}

fn within_distance_at_of(
    a: Operand<'_>, pa: &Pose, b: Operand<'_>, pb: &Pose, c: f64,
) -> Result<bool, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::within_distance_at(a, pa, b, pb, c),
        (Operand::Mesh(m), Operand::Shape(s)) => m.shape_within_distance_at(pa, s, pb, c),
        (Operand::Shape(s), Operand::Mesh(m)) => m.shape_within_distance_at(pb, s, pa, c),
        (Operand::Mesh(_), Operand::Mesh(_)) if c.is_nan() => {
            Err(Error::InvalidClearance { value: c })
        }
        (Operand::Mesh(a), Operand::Mesh(b)) => a.within_distance_at(pa, b, pb, c),
    }
}

fn distance_of(a: Operand<'_>, b: Operand<'_>) -> Result<CertifiedDistance, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::distance(a, b),
        (Operand::Mesh(m), Operand::Shape(s)) => m.distance_to_shape(s),
        (Operand::Shape(s), Operand::Mesh(m)) => m.distance_to_shape(s).map(shape_first),
        (Operand::Mesh(a), Operand::Mesh(b)) => a.distance(b),
    }
}

fn distance_at_of(
    a: Operand<'_>, pa: &Pose, b: Operand<'_>, pb: &Pose,
) -> Result<CertifiedDistance, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::distance_at(a, pa, b, pb),
        (Operand::Mesh(m), Operand::Shape(s)) => m.distance_to_shape_at(pa, s, pb),
        (Operand::Shape(s), Operand::Mesh(m)) => m.distance_to_shape_at(pb, s, pa).map(shape_first),
        (Operand::Mesh(a), Operand::Mesh(b)) => a.distance_at(pa, b, pb),
    }
}

/// A question about `a` and `b` in one frame.
fn pair<T: Send>(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>,
    q: impl FnOnce(Operand<'_>, Operand<'_>) -> Result<T, Error> + Send,
) -> PyResult<T> {
    let (a, b) = (operand(a, "a")?, operand(b, "b")?);
    ask(py, a, b, || q(a, b))
}

/// A question about `a` at `pose_a` and `b` at `pose_b`.
fn at<T: Send>(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
    q: impl FnOnce(Operand<'_>, &Pose, Operand<'_>, &Pose) -> Result<T, Error> + Send,
) -> PyResult<T> {
    let (a, b) = (operand(a, "a")?, operand(b, "b")?);
    let (pa, pb) = (convert::pose(pose_a, "pose_a")?, convert::pose(pose_b, "pose_b")?);
    ask(py, a, b, || q(a, &pa, b, &pb))
}

/// A question for every pose pair of `poses_a` and `poses_b`, with the GIL released.
fn batch<T: Send>(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
    q: impl FnOnce(Operand<'_>, Operand<'_>, &[PosePair]) -> Result<Vec<T>, Error> + Send,
) -> PyResult<Vec<T>> {
    let (a, b) = (operand(a, "a")?, operand(b, "b")?);
    let poses = convert::pose_pairs(poses_a, poses_b)?;
    py.detach(|| q(a, b, &poses)).map_err(err)
}

/// The `_at` question for every pose pair of a shape and a mesh, spread over the cores; the
/// first refused pose pair (in order) is the error, with its index (`Error::InBatch`, as the
/// library's own batches report it).
fn each<T: Send>(
    poses: &[PosePair], q: impl Fn(&PosePair) -> Result<T, Error> + Sync,
) -> Result<Vec<T>, Error> {
    let answers: Vec<Result<T, Error>> = poses.par_iter().map(&q).collect();
    answers
        .into_iter()
        .enumerate()
        .map(|(index, r)| r.map_err(|e| Error::InBatch { index, source: Box::new(e) }))
        .collect()
}

fn intersects_batch_of(
    a: Operand<'_>, b: Operand<'_>, poses: &[PosePair],
) -> Result<Vec<bool>, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::intersects_batch(a, b, poses),
        (Operand::Mesh(a), Operand::Mesh(b)) => a.collides_batch(b, poses),
        _ => each(poses, |p| intersects_at_of(a, &p.a, b, &p.b)),
    }
}

fn within_distance_batch_of(
    a: Operand<'_>, b: Operand<'_>, poses: &[PosePair], c: f64,
) -> Result<Vec<bool>, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::within_distance_batch(a, b, poses, c),
        (Operand::Mesh(_), Operand::Mesh(_)) if c.is_nan() => {
            Err(Error::InvalidClearance { value: c })
        }
        (Operand::Mesh(a), Operand::Mesh(b)) => a.within_distance_batch(b, poses, c),
        _ => each(poses, |p| within_distance_at_of(a, &p.a, b, &p.b, c)),
    }
}

fn distance_batch_of(
    a: Operand<'_>, b: Operand<'_>, poses: &[PosePair],
) -> Result<Vec<CertifiedDistance>, Error> {
    match (a, b) {
        (Operand::Shape(a), Operand::Shape(b)) => query::distance_batch(a, b, poses),
        (Operand::Mesh(a), Operand::Mesh(b)) => a.distance_batch(b, poses),
        _ => each(poses, |p| distance_at_of(a, &p.a, b, &p.b)),
    }
}

/// Whether ``a`` and ``b`` share a point, exactly (touching counts): each a ``Shape`` (a
/// closed solid) or a ``Collider`` (its surface, as in the collider's own questions).
/// ``CgaError`` if a value is out of range or the library has no exact test for the pair.
#[pyfunction]
fn intersects(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>) -> PyResult<bool> {
    pair(py, a, b, intersects_of)
}

/// ``intersects`` with ``a`` placed at ``pose_a`` and ``b`` at ``pose_b`` (``(4, 4)`` rigid
/// motions; ``Shape.placed``'s rule for shapes).
#[pyfunction]
fn intersects_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
) -> PyResult<bool> {
    at(py, a, pose_a, b, pose_b, intersects_at_of)
}

/// ``intersects_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
/// (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array. The first refused
/// pose raises ``CgaError`` with its index.
#[pyfunction]
fn intersects_batch<'py>(
    py: Python<'py>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
) -> PyResult<Bools<'py>> {
    Ok(bools(py, batch(py, a, b, poses_a, poses_b, intersects_batch_of)?))
}

/// Whether ``a`` and ``b`` (shapes or colliders, as for ``intersects``) come within distance
/// ``c`` (closed: exactly ``c`` counts), exactly. With a shape, ``c`` must be finite and at
/// least 0; between two colliders, as ``Collider.within_distance``, only NaN is refused.
#[pyfunction]
fn within_distance(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, c: f64) -> PyResult<bool> {
    pair(py, a, b, |a, b| within_distance_of(a, b, c))
}

/// ``within_distance`` under poses.
#[pyfunction]
fn within_distance_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>, c: f64,
) -> PyResult<bool> {
    at(py, a, pose_a, b, pose_b, |a, pa, b, pb| within_distance_at_of(a, pa, b, pb, c))
}

/// ``within_distance_at`` for every pose pair: a ``(k,)`` bool array.
#[pyfunction]
fn within_distance_batch<'py>(
    py: Python<'py>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>, c: f64,
) -> PyResult<Bools<'py>> {
    let hits = batch(py, a, b, poses_a, poses_b, |a, b, p| within_distance_batch_of(a, b, p, c))?;
    Ok(bools(py, hits))
}

/// The certified minimum distance between ``a`` and ``b`` (shapes or colliders, as for
/// ``intersects``; ``0`` when they meet), a ``Distance`` with a witness point on each.
/// ``triangles`` is ``None`` for two shapes and holds ``0`` for a shape's side.
#[pyfunction]
fn distance(py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>) -> PyResult<Distance> {
    pair(py, a, b, distance_of).map(|d| Distance::from(&d))
}

/// ``distance`` under poses (witnesses in world coordinates).
#[pyfunction]
fn distance_at(
    py: Python<'_>, a: &Arg<'_>, pose_a: &Arg<'_>, b: &Arg<'_>, pose_b: &Arg<'_>,
) -> PyResult<Distance> {
    at(py, a, pose_a, b, pose_b, distance_at_of).map(|d| Distance::from(&d))
}

/// ``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays.
#[pyfunction]
fn distance_batch(
    py: Python<'_>, a: &Arg<'_>, b: &Arg<'_>, poses_a: &Arg<'_>, poses_b: &Arg<'_>,
) -> PyResult<DistanceBatch> {
    let ds = batch(py, a, b, poses_a, poses_b, distance_batch_of)?;
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
