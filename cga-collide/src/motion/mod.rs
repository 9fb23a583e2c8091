//! Continuous collision: primitives and meshes moving between two poses, decided exactly.
//!
//! Every point moves linearly, `p(t) = (1 − t)·p₀ + t·p₁` for `t ∈ [0, 1]` (the model of motion
//! of the CCD benchmark of Wang, Ferguson, Schneider, Jiang, Attene and Panozzo, ACM TOG 2021).
//! The questions, for a vertex against a triangle and an edge against an edge, closed sets
//! (touching counts), the `f64` inputs taken as the exact numbers they denote:
//! - **do they touch** for some `t ∈ [0, 1]` ([`vertex_face_touch`], [`edge_edge_touch`]): the
//!   exact answer, with no tolerance, for every input including the degenerate ones (coplanar
//!   motion for all `t`, grazing double roots, contact exactly at `t = 0` or `t = 1`, parallel,
//!   collinear and zero-length edges, degenerate triangles, any finite magnitudes);
//! - **when first** ([`vertex_face_first_contact`], [`edge_edge_first_contact`]): a
//!   [`ContactTime`], an interval with `f64` ends that contains the earliest contact time, as
//!   narrow as the caller asks (down to neighbouring `f64`s, or one exact value), and a time
//!   strictly before contact that a simulation can safely advance to.
//!
//! # How
//! A certified `f64` filter (interval arithmetic over sub-intervals of time) decides the common
//! cases. When it cannot, the exact decision isolates the real roots in `[0, 1]` of the
//! polynomials in `t` that the conditions are made of (the coplanarity cubic and the in-plane
//! sides, integer coefficients after one exact scaling) and decides every sign at those roots
//! exactly with Sturm–Tarski queries, so no root is ever approximated to decide anything. The
//! method and its guarantees are written out in the repository's `docs/ccd.md`.
//!
//! ```
//! use cga_collide::motion::{self, MovingPoint};
//! use cga_collide::nalgebra::Point3;
//! let still = |x, y, z| MovingPoint::still(Point3::new(x, y, z));
//! // A vertex falls from z = 1 to z = −1 through the triangle z = 0.
//! let vertex = MovingPoint::new(Point3::new(0.2, 0.2, 1.0), Point3::new(0.2, 0.2, -1.0));
//! let face = [still(0., 0., 0.), still(1., 0., 0.), still(0., 1., 0.)];
//! assert!(motion::vertex_face_touch(&vertex, &face)?);
//! let time = motion::vertex_face_first_contact(&vertex, &face, 1e-9)?.expect("they touch");
//! assert!(time.lo() <= 0.5 && 0.5 <= time.hi());
//! assert_eq!(time.is_exact(), time.lo() == 0.5 && time.hi() == 0.5);
//! assert!(time.safe_time().is_some_and(|t| t < 0.5));
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod algebraic;
mod filter;
mod polynomial;
mod query_file;
mod rigid;
mod step;

use nalgebra::Point3;

use crate::error::Error;
use filter::Filtered;
use polynomial::Instant;
pub use query_file::{load_queries, parse_queries, MotionQuery, QueryKind};
pub use rigid::{MotionContacts, MotionPair};
pub use step::{mesh_edges, step_self_contacts, StepContacts};

/// A point moving linearly from `start` (at `t = 0`) to `end` (at `t = 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MovingPoint {
    /// The position at `t = 0`.
    pub start: Point3<f64>,
    /// The position at `t = 1`.
    pub end: Point3<f64>,
}

impl MovingPoint {
    /// A point moving from `start` to `end`.
    pub fn new(start: Point3<f64>, end: Point3<f64>) -> MovingPoint {
        MovingPoint { start, end }
    }

    /// A point that does not move.
    pub fn still(at: Point3<f64>) -> MovingPoint {
        MovingPoint { start: at, end: at }
    }

    fn coordinates(&self) -> [[f64; 3]; 2] {
        [
            [self.start.x, self.start.y, self.start.z],
            [self.end.x, self.end.y, self.end.z],
        ]
    }
}

/// When two primitives first touch: `lo <= t <= hi` for the earliest contact time `t`.
///
/// Either `lo == hi == t` exactly ([`ContactTime::is_exact`]), or `lo < t <= hi`, so `lo` is a
/// time of no contact that a simulation can safely advance to ([`ContactTime::safe_time`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactTime {
    lo: f64,
    hi: f64,
}

impl ContactTime {
    /// A lower bound of the earliest contact time (strictly below it unless exact).
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// An upper bound of the earliest contact time.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// `hi − lo`.
    pub fn width(&self) -> f64 {
        self.hi - self.lo
    }

    /// Whether the earliest contact time is exactly `lo` (`== hi`).
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }

    /// The latest known time strictly before contact: `lo`, or the `f64` just below an exact
    /// contact time; `None` when contact is at `t = 0` (there is no time before it in the step).
    pub fn safe_time(&self) -> Option<f64> {
        if self.lo < self.hi {
            Some(self.lo)
        } else if self.lo > 0.0 {
            Some(self.lo.next_down().max(0.0))
        } else {
            None
        }
    }

    /// The earliest of several contact times of the same motion (the union of their bounds).
    pub fn earliest(times: impl IntoIterator<Item = ContactTime>) -> Option<ContactTime> {
        let times: Vec<ContactTime> = times.into_iter().collect();
        let lo = times.iter().map(|t| t.lo).fold(f64::INFINITY, f64::min);
        if lo == f64::INFINITY {
            return None;
        }
        // An exact time at the least lower bound is the earliest: every other time is above
        // its own lower bound, which is at least `lo`.
        if times.iter().any(|t| t.is_exact() && t.lo == lo) {
            return Some(ContactTime { lo, hi: lo });
        }
        let hi = times.iter().map(|t| t.hi).fold(f64::INFINITY, f64::min);
        Some(ContactTime { lo, hi })
    }
}

/// The names of the coordinates, for errors.
const VERTEX_FACE_NAMES: [[&str; 2]; 4] = [
    ["vertex.start", "vertex.end"],
    ["face[0].start", "face[0].end"],
    ["face[1].start", "face[1].end"],
    ["face[2].start", "face[2].end"],
];
const EDGE_EDGE_NAMES: [[&str; 2]; 4] = [
    ["a[0].start", "a[0].end"],
    ["a[1].start", "a[1].end"],
    ["b[0].start", "b[0].end"],
    ["b[1].start", "b[1].end"],
];

fn checked(
    query: &'static str,
    names: &[[&'static str; 2]; 4],
    points: [&MovingPoint; 4],
) -> Result<[[[f64; 3]; 2]; 4], Error> {
    let coords: [[[f64; 3]; 2]; 4] = core::array::from_fn(|i| points[i].coordinates());
    for (i, point) in coords.iter().enumerate() {
        for (j, position) in point.iter().enumerate() {
            for (axis, &value) in ["x", "y", "z"].iter().zip(position) {
                if !value.is_finite() {
                    return Err(Error::NonFiniteCoordinate {
                        shape: query,
                        argument: names[i][j],
                        axis,
                        value,
                    });
                }
            }
        }
    }
    Ok(coords)
}

/// Whether vertex `vertex` and the closed triangle `face` touch at some `t ∈ [0, 1]`, exactly.
///
/// # Errors
/// [`Error::NonFiniteCoordinate`] when a coordinate is NaN or infinite.
pub fn vertex_face_touch(vertex: &MovingPoint, face: &[MovingPoint; 3]) -> Result<bool, Error> {
    let points = checked(
        "motion::vertex_face",
        &VERTEX_FACE_NAMES,
        [vertex, &face[0], &face[1], &face[2]],
    )?;
    Ok(points_vertex_face_touch(&points))
}

/// Whether the closed edges `a` and `b` touch at some `t ∈ [0, 1]`, exactly.
///
/// # Errors
/// [`Error::NonFiniteCoordinate`] when a coordinate is NaN or infinite.
pub fn edge_edge_touch(a: &[MovingPoint; 2], b: &[MovingPoint; 2]) -> Result<bool, Error> {
    let points = checked(
        "motion::edge_edge",
        &EDGE_EDGE_NAMES,
        [&a[0], &a[1], &b[0], &b[1]],
    )?;
    Ok(points_edge_edge_touch(&points))
}

/// The earliest time vertex `vertex` touches the closed triangle `face`, `None` if never in
/// `[0, 1]`; the interval is at most `tolerance` wide, or as narrow as `f64` allows (pass `0.0`
/// for the narrowest).
///
/// # Errors
/// [`Error::NonFiniteCoordinate`] when a coordinate is NaN or infinite.
pub fn vertex_face_first_contact(
    vertex: &MovingPoint,
    face: &[MovingPoint; 3],
    tolerance: f64,
) -> Result<Option<ContactTime>, Error> {
    let points = checked(
        "motion::vertex_face",
        &VERTEX_FACE_NAMES,
        [vertex, &face[0], &face[1], &face[2]],
    )?;
    Ok(points_vertex_face_first_contact(&points, tolerance))
}

/// The earliest time the closed edges `a` and `b` touch, `None` if never in `[0, 1]`; see
/// [`vertex_face_first_contact`] for `tolerance`.
///
/// # Errors
/// [`Error::NonFiniteCoordinate`] when a coordinate is NaN or infinite.
pub fn edge_edge_first_contact(
    a: &[MovingPoint; 2],
    b: &[MovingPoint; 2],
    tolerance: f64,
) -> Result<Option<ContactTime>, Error> {
    let points = checked(
        "motion::edge_edge",
        &EDGE_EDGE_NAMES,
        [&a[0], &a[1], &b[0], &b[1]],
    )?;
    Ok(points_edge_edge_first_contact(&points, tolerance))
}

/// [`vertex_face_touch`] on checked coordinates.
pub(crate) fn points_vertex_face_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
    match filter::vertex_face(points, f64::INFINITY) {
        Filtered::Never => false,
        Filtered::Within(..) => true,
        Filtered::Unknown => exact_vertex_face(points).is_some(),
    }
}

/// [`edge_edge_touch`] on checked coordinates.
pub(crate) fn points_edge_edge_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
    match filter::edge_edge(points, f64::INFINITY) {
        Filtered::Never => false,
        Filtered::Within(..) => true,
        Filtered::Unknown => exact_edge_edge(points).is_some(),
    }
}

/// [`vertex_face_first_contact`] on checked coordinates.
pub(crate) fn points_vertex_face_first_contact(
    points: &[[[f64; 3]; 2]; 4],
    tolerance: f64,
) -> Option<ContactTime> {
    let tolerance = tolerance.max(0.0);
    match filter::vertex_face(points, tolerance) {
        Filtered::Never => None,
        Filtered::Within(lo, hi) => Some(ContactTime { lo, hi }),
        Filtered::Unknown => exact_vertex_face(points).and_then(|c| bounded(&c, tolerance)),
    }
}

/// [`edge_edge_first_contact`] on checked coordinates.
pub(crate) fn points_edge_edge_first_contact(
    points: &[[[f64; 3]; 2]; 4],
    tolerance: f64,
) -> Option<ContactTime> {
    let tolerance = tolerance.max(0.0);
    match filter::edge_edge(points, tolerance) {
        Filtered::Never => None,
        Filtered::Within(lo, hi) => Some(ContactTime { lo, hi }),
        Filtered::Unknown => exact_edge_edge(points).and_then(|c| bounded(&c, tolerance)),
    }
}

fn bounded(candidates: &[Instant], tolerance: f64) -> Option<ContactTime> {
    ContactTime::earliest(candidates.iter().map(|c| {
        let (lo, hi) = c.bounds(tolerance);
        ContactTime { lo, hi }
    }))
}

fn exact_vertex_face(points: &[[[f64; 3]; 2]; 4]) -> Option<Vec<Instant>> {
    let [p, a, b, c] = algebraic::tracks(points);
    algebraic::vertex_face(&p, &a, &b, &c)
}

fn exact_edge_edge(points: &[[[f64; 3]; 2]; 4]) -> Option<Vec<Instant>> {
    let [a0, a1, b0, b1] = algebraic::tracks(points);
    algebraic::edge_edge(&a0, &a1, &b0, &b1)
}

/// The exact decisions without the filter (for tests and benchmarks that compare the two).
#[cfg(feature = "testing")]
pub mod unfiltered {
    use super::*;

    /// [`vertex_face_touch`] decided exactly, without the `f64` filter.
    pub fn vertex_face_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
        exact_vertex_face(points).is_some()
    }

    /// [`edge_edge_touch`] decided exactly, without the `f64` filter.
    pub fn edge_edge_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
        exact_edge_edge(points).is_some()
    }
}
