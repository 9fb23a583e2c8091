//! Workspace-level property and cross-crate tests live in `tests/tests/`.
//! This library holds the shared helpers (strategies, comparison utilities) they use.
#![forbid(unsafe_code)]

pub mod shape_oracle;
