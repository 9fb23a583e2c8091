//! Test support (feature `testing`): an exact brute-force oracle independent of the code under
//! test, deterministic adversarial input sets, and the research hooks that the tests and the
//! papers' experiments use but that are not part of the library proper (brute-force and
//! as-published variants, filter statistics, internal steps of the hierarchies). No library
//! code depends on it.
//!
//! - [`ccd_oracle`]: continuous collision (vertex–face, edge–edge) decided with exact rationals
//!   by a method independent of [`crate::motion`] (no filter, no Sturm–Tarski), with the
//!   earliest contact time as an isolating interval.

pub mod adversarial;
pub mod baseline;
pub mod ccd_oracle;
pub mod conformal;
pub mod double_sphere;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod oracle;
pub mod sphere_tree;
