//! Test support (feature `testing`): an exact brute-force oracle independent of the code under
//! test, and deterministic adversarial input sets. Not part of the library proper: no library
//! code depends on it.

pub mod adversarial;
pub mod baseline;
pub mod oracle;
