//! Test support (feature `testing`): an exact brute-force oracle independent of the code under
//! test, deterministic adversarial input sets, and the research hooks that the tests and the
//! papers' experiments use but that are not part of the library proper (brute-force and
//! as-published variants, filter statistics, internal steps of the hierarchies). No library
//! code depends on it.
//!
//! - [`ccd_oracle`]: continuous collision (vertex–face, edge–edge) decided with exact rationals
//!   by a method independent of [`crate::motion`] (no filter, no Sturm–Tarski), with the
//!   earliest contact time as an isolating interval.
//! - [`convex`]: the certified GJK test of two convex solids, the double-sphere experiment's
//!   independent reference.
//! - [`FloatKernel`] and [`IntersectsWith`]: the exact algorithms with plain `f64` signs, to
//!   measure what rounding costs.
//! - [`rational_exact_sign`]: exact signs by rational arithmetic, the reference of the staged
//!   exact signs.
//! - [`stage_counts`], [`reset_stage_counts`]: process-wide counts of the signs each exact
//!   stage after the first `f64` filter decided.

pub mod adversarial;
pub mod baseline;
pub mod ccd_oracle;
pub mod conformal;
pub mod convex;
pub mod double_sphere;
mod float_kernel;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod oracle;
pub mod sphere_tree;

pub use crate::exact::counters::{reset_stage_counts, stage_counts, StageCounts};
pub use crate::exact::sign::rational_exact_sign;
pub use crate::query::intersects::IntersectsWith;
pub use float_kernel::{FloatKernel, FloatPlane};
