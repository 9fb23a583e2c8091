//! Test support (feature `testing`): an exact brute-force oracle independent of the code under
//! test, deterministic adversarial input sets, and the research hooks that the tests and the
//! papers' experiments use but that are not part of the library proper (brute-force and
//! as-published variants, filter statistics, internal steps of the hierarchies). No library
//! code depends on it.

pub mod adversarial;
pub mod baseline;
pub mod conformal;
pub mod double_sphere;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod oracle;
pub mod sphere_tree;
