//! `RobotMotion`: the answer about a straight joint-space motion of a `Robot` (the Rust
//! `cga_collide::robot::MotionAnswer`).

use cga_collide::robot::{MotionAnswer, MotionLimit, MotionOptions};
use numpy::ndarray::Array1;
use numpy::{IntoPyArray, PyArray1};
use pyo3::prelude::*;

use crate::convert::value_error;

/// The answer about the straight motion ``q(t) = (1 - t) q0 + t q1``, ``t`` in ``[0, 1]``:
/// ``status`` is ``"free"`` (certified for every configuration of the motion, not only
/// samples), ``"collides"`` (``configuration`` at ``time`` collides, exactly, with every
/// touching pair in ``pairs``; the motion is certified free up to ``free_until``, so the first
/// contact lies in ``[free_until, time]``) or ``"undecided"`` (``limit``, ``"resolution"`` or
/// ``"configurations"``, ran out first; certified free up to ``free_until``).
#[pyclass(frozen, module = "cga_collide")]
pub struct RobotMotion {
    inner: MotionAnswer,
}

impl From<MotionAnswer> for RobotMotion {
    fn from(inner: MotionAnswer) -> Self {
        RobotMotion { inner }
    }
}

#[pymethods]
impl RobotMotion {
    /// ``"free"``, ``"collides"`` or ``"undecided"``.
    #[getter]
    fn status(&self) -> &'static str {
        match self.inner {
            MotionAnswer::Free => "free",
            MotionAnswer::Collides { .. } => "collides",
            MotionAnswer::Undecided { .. } => "undecided",
        }
    }

    /// Whether the motion is certified free.
    #[getter]
    fn is_free(&self) -> bool {
        self.inner.is_free()
    }

    /// The time of the colliding configuration, or ``None``.
    #[getter]
    fn time(&self) -> Option<f64> {
        match self.inner {
            MotionAnswer::Collides { time, .. } => Some(time),
            _ => None,
        }
    }

    /// The colliding configuration, a ``(dof,)`` float64 array, or ``None``.
    #[getter]
    fn configuration<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        match &self.inner {
            MotionAnswer::Collides { configuration, .. } => {
                Some(Array1::from(configuration.clone()).into_pyarray(py))
            }
            _ => None,
        }
    }

    /// Every touching pair at the colliding configuration (sorted), else ``[]``.
    #[getter]
    fn pairs(&self) -> Vec<(String, String)> {
        match &self.inner {
            MotionAnswer::Collides { pairs, .. } => pairs.clone(),
            _ => Vec::new(),
        }
    }

    /// The motion is certified free on ``[0, free_until]`` (``1.0`` when free).
    #[getter]
    fn free_until(&self) -> f64 {
        match self.inner {
            MotionAnswer::Free => 1.0,
            MotionAnswer::Collides { free_until, .. }
            | MotionAnswer::Undecided { free_until, .. } => free_until,
        }
    }

    /// Which budget left the motion undecided (``"resolution"`` or ``"configurations"``), or
    /// ``None``.
    #[getter]
    fn limit(&self) -> Option<&'static str> {
        match self.inner {
            MotionAnswer::Undecided { limit, .. } => Some(match limit {
                MotionLimit::Resolution => "resolution",
                MotionLimit::Configurations => "configurations",
            }),
            _ => None,
        }
    }

    fn __repr__(&self) -> String {
        match &self.inner {
            MotionAnswer::Free => "RobotMotion(free)".to_string(),
            MotionAnswer::Collides { time, pairs, free_until, .. } => format!(
                "RobotMotion(collides, time={time}, free_until={free_until}, pairs={pairs:?})"
            ),
            MotionAnswer::Undecided { free_until, .. } => format!(
                "RobotMotion(undecided, limit={:?}, free_until={free_until})",
                self.limit().unwrap_or("")
            ),
        }
    }
}

/// The motion options from the Python keywords.
pub fn options(
    against: cga_collide::robot::Against, resolution: f64, max_configurations: i64,
) -> PyResult<MotionOptions> {
    let max_configurations =
        usize::try_from(max_configurations).ok().filter(|&n| n > 0).ok_or_else(|| {
            value_error(format!(
                "max_configurations: expected a whole number >= 1, got {max_configurations}"
            ))
        })?;
    Ok(MotionOptions { against, resolution, max_configurations })
}
