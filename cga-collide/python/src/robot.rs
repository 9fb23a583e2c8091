//! `Robot`: a URDF's kinematic tree and collision geometry, and its self- and environment
//! collisions at configurations given as numpy arrays (the Rust `cga_collide::robot::Robot`).

use std::path::PathBuf;

use cga_collide::robot::{Against, NearestPair, Robot as RsRobot};
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::convert::{self, err, value_error, Arg, Bools};
use crate::distance::Distance;
use crate::robot_motion::{self, RobotMotion};
use crate::scene::Scene;

type Pair = (String, String);

fn against(name: &str) -> PyResult<Against> {
    match name {
        "self" => Ok(Against::Itself),
        "environment" => Ok(Against::Environment),
        "both" => Ok(Against::Both),
        other => Err(value_error(format!(
            "against: expected \"self\", \"environment\" or \"both\", got {other:?}"
        ))),
    }
}

/// One configuration: a ``(dof,)`` array.
fn configuration(q: &Arg, dof: usize) -> PyResult<Vec<f64>> {
    convert::read(q, "q", &[Some(dof)], |v| Ok(v.iter().copied().collect()))
}

/// Many configurations: a ``(k, dof)`` array, one row each.
fn configurations(qs: &Arg, dof: usize) -> PyResult<Vec<Vec<f64>>> {
    convert::read(qs, "qs", &[None, Some(dof)], |v| {
        Ok(v.outer_iter().map(|row| row.iter().copied().collect()).collect())
    })
}

fn nearest_pair(n: Option<NearestPair>) -> Option<(Pair, Distance)> {
    n.map(|n| (n.pair, Distance::from(&n.distance)))
}

/// A robot read from a URDF: links with their collision geometry (meshes in STL, OBJ, PLY
/// or OFF, scaled; boxes, cylinders, spheres, capsules), joints (revolute, continuous,
/// prismatic, fixed). A configuration is one value per movable joint in the order of
/// ``joint_names``. Links joined by fixed joints are one body; adjacent bodies, an SRDF's
/// ``disable_collisions`` and ``exclude_pair`` pairs are not tested. Meshes are surfaces (as
/// in coal and pinocchio) unless ``set_solid(True)``. Pairs are named by link (sorted);
/// environment objects as ``"env:<i>"``. ``against`` is ``"self"``, ``"environment"`` or
/// ``"both"``. Every answer is exact for the placed parts; batches run over the cores with
/// the GIL released.
#[pyclass(module = "cga_collide")]
pub struct Robot {
    inner: RsRobot,
}

#[pymethods]
impl Robot {
    /// Reads the URDF at ``path``; ``package://`` paths are looked up in ``package_dirs``;
    /// an SRDF's ``disable_collisions`` pairs are left out when ``srdf`` is given.
    #[staticmethod]
    #[pyo3(signature = (path, package_dirs = Vec::new(), srdf = None))]
    fn from_urdf(
        py: Python<'_>, path: PathBuf, package_dirs: Vec<PathBuf>, srdf: Option<PathBuf>,
    ) -> PyResult<Robot> {
        let inner =
            py.detach(|| RsRobot::from_urdf(&path, &package_dirs, srdf.as_deref())).map_err(err)?;
        Ok(Robot { inner })
    }

    /// Number of movable joints (the length of a configuration).
    #[getter]
    fn dof(&self) -> usize {
        self.inner.dof()
    }

    /// The movable joints' names, in configuration order.
    #[getter]
    fn joint_names(&self) -> Vec<String> {
        self.inner.joint_names().to_vec()
    }

    /// Every link's name, in URDF order.
    #[getter]
    fn link_names(&self) -> Vec<String> {
        self.inner.link_names().to_vec()
    }

    /// A ``(dof, 2)`` float64 array of lower and upper limits (``-inf, inf`` for a continuous
    /// joint). Limits are not enforced by the questions.
    #[getter]
    fn joint_limits<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let limits = self.inner.joint_limits();
        let mut a = Array2::from_elem((limits.len(), 2), 0.0);
        for (k, l) in limits.iter().enumerate() {
            let (lo, hi) = l.unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            a[[k, 0]] = lo;
            a[[k, 1]] = hi;
        }
        a.into_pyarray(py)
    }

    /// The link pairs the self questions test.
    fn allowed_pairs(&self) -> Vec<Pair> {
        self.inner.allowed_pairs().into_iter().map(|(a, b)| (a.to_owned(), b.to_owned())).collect()
    }

    /// How many pairs a question with ``against`` tests.
    #[pyo3(signature = (against = "self"))]
    fn pairs_checked(&self, against: &str) -> PyResult<usize> {
        Ok(self.inner.pairs_checked(self::against(against)?))
    }

    /// Never tests links ``a`` and ``b`` against each other.
    fn exclude_pair(&mut self, a: &str, b: &str) -> PyResult<()> {
        self.inner.exclude_pair(a, b).map_err(err)
    }

    /// Meshes are solids (``True``: a part inside a closed mesh touches it) or surfaces.
    fn set_solid(&mut self, solid: bool) {
        self.inner.set_solid(solid);
    }

    /// Takes the scene's objects, as placed now, as the environment (a snapshot).
    fn set_environment(&mut self, scene: &Scene) -> PyResult<()> {
        self.inner.set_environment(&scene.inner).map_err(err)
    }

    /// Every link's world pose at ``q``: a ``(links, 4, 4)`` float64 array.
    fn link_poses<'py>(&self, py: Python<'py>, q: &Arg) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let q = configuration(q, self.inner.dof())?;
        let poses = self.inner.link_poses(&q).map_err(err)?;
        let mut a = Array3::from_elem((poses.len(), 4, 4), 0.0);
        for (k, p) in poses.iter().enumerate() {
            let m = p.to_homogeneous();
            for i in 0..4 {
                for j in 0..4 {
                    a[[k, i, j]] = m[(i, j)];
                }
            }
        }
        Ok(a.into_pyarray(py))
    }

    /// Whether any tested pair touches at ``q`` (a ``(dof,)`` array; stops at the first).
    #[pyo3(signature = (q, against = "self"))]
    fn collides(&self, py: Python<'_>, q: &Arg, against: &str) -> PyResult<bool> {
        let (q, w) = (configuration(q, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        py.detach(|| r.collides(&q, w)).map_err(err)
    }

    /// ``collides`` for each row of a ``(k, dof)`` array: a ``(k,)`` bool array.
    #[pyo3(signature = (qs, against = "self"))]
    fn collides_batch<'py>(
        &self, py: Python<'py>, qs: &Arg, against: &str,
    ) -> PyResult<Bools<'py>> {
        let (qs, w) = (configurations(qs, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        let out = py.detach(|| r.collides_batch(&qs, w)).map_err(err)?;
        Ok(convert::bools(py, out))
    }

    /// Every touching pair at ``q``: a sorted list of ``(name_a, name_b)``, names sorted.
    #[pyo3(signature = (q, against = "self"))]
    fn colliding_pairs(&self, py: Python<'_>, q: &Arg, against: &str) -> PyResult<Vec<Pair>> {
        let (q, w) = (configuration(q, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        py.detach(|| r.colliding_pairs(&q, w)).map_err(err)
    }

    /// ``colliding_pairs`` for each row of a ``(k, dof)`` array.
    #[pyo3(signature = (qs, against = "self"))]
    fn colliding_pairs_batch(
        &self, py: Python<'_>, qs: &Arg, against: &str,
    ) -> PyResult<Vec<Vec<Pair>>> {
        let (qs, w) = (configurations(qs, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        py.detach(|| r.colliding_pairs_batch(&qs, w)).map_err(err)
    }

    /// Every pair within distance ``c`` at ``q`` (exact, closed), sorted.
    #[pyo3(signature = (q, c, against = "self"))]
    fn pairs_within_distance(
        &self, py: Python<'_>, q: &Arg, c: f64, against: &str,
    ) -> PyResult<Vec<Pair>> {
        let (q, w) = (configuration(q, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        py.detach(|| r.pairs_within_distance(&q, c, w)).map_err(err)
    }

    /// ``pairs_within_distance`` for each row of a ``(k, dof)`` array.
    #[pyo3(signature = (qs, c, against = "self"))]
    fn pairs_within_distance_batch(
        &self, py: Python<'_>, qs: &Arg, c: f64, against: &str,
    ) -> PyResult<Vec<Vec<Pair>>> {
        let (qs, w) = (configurations(qs, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        py.detach(|| r.pairs_within_distance_batch(&qs, c, w)).map_err(err)
    }

    /// The nearest tested pair at ``q``: ``((name_a, name_b), Distance)`` (certified, the
    /// witnesses in world coordinates, ``witness_a`` on ``name_a``), or ``None`` when nothing
    /// is tested.
    #[pyo3(signature = (q, against = "self"))]
    fn nearest(
        &self, py: Python<'_>, q: &Arg, against: &str,
    ) -> PyResult<Option<(Pair, Distance)>> {
        let (q, w) = (configuration(q, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        Ok(nearest_pair(py.detach(|| r.nearest(&q, w)).map_err(err)?))
    }

    /// ``nearest`` for each row of a ``(k, dof)`` array.
    #[pyo3(signature = (qs, against = "self"))]
    fn nearest_batch(
        &self, py: Python<'_>, qs: &Arg, against: &str,
    ) -> PyResult<Vec<Option<(Pair, Distance)>>> {
        let (qs, w) = (configurations(qs, self.inner.dof())?, self::against(against)?);
        let r = &self.inner;
        let out = py.detach(|| r.nearest_batch(&qs, w)).map_err(err)?;
        Ok(out.into_iter().map(nearest_pair).collect())
    }

    /// The straight motion from ``q0`` to ``q1`` (``(dof,)`` arrays): certified free, the
    /// earliest colliding configuration found, or undecided when ``resolution`` (the shortest
    /// stretch split, a fraction of the motion) or ``max_configurations`` runs out first: a
    /// ``RobotMotion``. Never misses a contact between samples.
    #[pyo3(signature = (q0, q1, against = "self", resolution = 1e-6, max_configurations = 100_000))]
    fn motion_collision(
        &self, py: Python<'_>, q0: &Arg, q1: &Arg, against: &str, resolution: f64,
        max_configurations: i64,
    ) -> PyResult<RobotMotion> {
        let dof = self.inner.dof();
        let q0 =
            convert::read(q0, "q0", &[Some(dof)], |v| Ok(v.iter().copied().collect::<Vec<f64>>()))?;
        let q1 =
            convert::read(q1, "q1", &[Some(dof)], |v| Ok(v.iter().copied().collect::<Vec<f64>>()))?;
        let o = robot_motion::options(self::against(against)?, resolution, max_configurations)?;
        let r = &self.inner;
        let answer = py.detach(|| r.motion_collision(&q0, &q1, &o)).map_err(err)?;
        Ok(answer.into())
    }

    /// ``motion_collision`` for each row pair of two ``(k, dof)`` arrays, over the cores.
    #[pyo3(signature = (q0s, q1s, against = "self", resolution = 1e-6, max_configurations = 100_000))]
    fn motion_collision_batch(
        &self, py: Python<'_>, q0s: &Arg, q1s: &Arg, against: &str, resolution: f64,
        max_configurations: i64,
    ) -> PyResult<Vec<RobotMotion>> {
        let dof = self.inner.dof();
        let rows = |a: &Arg, name: &str| {
            convert::read(a, name, &[None, Some(dof)], |v| {
                Ok(v.outer_iter()
                    .map(|row| row.iter().copied().collect::<Vec<f64>>())
                    .collect::<Vec<_>>())
            })
        };
        let (q0s, q1s) = (rows(q0s, "q0s")?, rows(q1s, "q1s")?);
        if q0s.len() != q1s.len() {
            return Err(value_error(format!(
                "q0s and q1s: expected as many rows, got {} and {}",
                q0s.len(),
                q1s.len()
            )));
        }
        let motions: Vec<(Vec<f64>, Vec<f64>)> = q0s.into_iter().zip(q1s).collect();
        let o = robot_motion::options(self::against(against)?, resolution, max_configurations)?;
        let r = &self.inner;
        let out = py.detach(|| r.motion_collision_batch(&motions, &o)).map_err(err)?;
        Ok(out.into_iter().map(RobotMotion::from).collect())
    }

    fn __repr__(&self) -> String {
        format!(
            "Robot(links={}, dof={}, pairs={})",
            self.inner.link_names().len(),
            self.inner.dof(),
            self.inner.allowed_pairs().len()
        )
    }
}
