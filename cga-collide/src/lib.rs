//! Exact collision tests in the 5D conformal model of Euclidean space.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub use ga_core;
pub use nalgebra;
