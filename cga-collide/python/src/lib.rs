//! Python bindings of `cga-collide`: the extension module `cga_collide._native`, re-exported by
//! the Python package `cga_collide` (see `cga_collide/__init__.py` and the `.pyi` stubs).
//!
//! Arrays come in as anything numpy reads as numbers that float64 holds exactly (never a
//! rounding cast) and go out as numpy arrays; shapes are checked; every refused input and
//! every library error is a `CgaError` (a `ValueError`) naming the argument; the GIL is
//! released while Rust works (but for single shape-pair questions, shorter than releasing it).

mod answers;
mod collider;
mod convert;
mod distance;
mod manifold;
mod motion;
mod points;
mod robot;
mod robot_motion;
mod scene;
mod shape_queries;
mod shapes;
mod signed_distance;

use numpy::PyArray2;
use pyo3::prelude::*;

/// The ``(4, 4)`` float64 pose that rotates by ``degrees[0]`` about the x axis, then by
/// ``degrees[1]`` about the y axis, then by ``degrees[2]`` about the z axis (fixed axes,
/// right-handed, counter-clockwise looking down the axis), then translates by ``translation``
/// (``None`` for none): ``x -> Rz Ry Rx x + t``. The convention of the ``cga`` command line's
/// ``--rotate`` and ``--translate`` and of the Rust ``pose_from_degrees``, so a pose written
/// for one is the same pose in the other.
#[pyfunction]
#[pyo3(signature = (degrees, translation = None))]
fn pose_from_degrees<'py>(
    py: Python<'py>, degrees: &convert::Arg<'_>, translation: Option<&convert::Arg<'_>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    Ok(convert::matrix(py, &convert::degrees_pose(degrees, translation)?))
}

/// Exact collision detection: colliders, shapes, scenes, numpy in and out.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<collider::Collider>()?;
    m.add_class::<distance::Distance>()?;
    m.add_class::<distance::DistanceBatch>()?;
    m.add_class::<points::PointDistances>()?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<scene::ObjectId>()?;
    m.add_class::<robot::Robot>()?;
    m.add_class::<robot_motion::RobotMotion>()?;
    motion::register(m)?;
    shapes::register(m)?;
    shape_queries::register(m)?;
    signed_distance::register(m)?;
    manifold::register(m)?;
    m.add_function(wrap_pyfunction!(pose_from_degrees, m)?)?;
    m.add("CgaError", m.py().get_type::<convert::CgaError>())?;
    m.add("ROTATION_TOLERANCE", convert::ROTATION_TOLERANCE)?;
    Ok(())
}
