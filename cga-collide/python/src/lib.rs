//! Python bindings of `cga-collide`: the extension module `cga_collide._native`, re-exported by
//! the Python package `cga_collide` (see `cga_collide/__init__.py` and the `.pyi` stubs).
//!
//! Arrays come in and go out as numpy arrays; dtypes and shapes are checked, never cast
//! silently; every library error becomes a `CgaError` (a `ValueError`) with the library's
//! message; the GIL is released while Rust works.

mod collider;
mod convert;
mod motion;
mod scene;

use pyo3::prelude::*;

/// Exact collision detection: colliders, scenes, numpy in and out.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<collider::Collider>()?;
    m.add_class::<collider::Distance>()?;
    m.add_class::<collider::DistanceBatch>()?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<scene::ObjectId>()?;
    motion::register(m)?;
    m.add("CgaError", m.py().get_type::<convert::CgaError>())?;
    m.add("ROTATION_TOLERANCE", convert::ROTATION_TOLERANCE)?;
    Ok(())
}
