//! The papers' experiments on cga-collide (an unpublished package, as `ga-thesis` is): the
//! double-sphere paper's experiment and SVG bar charts, used by the `cga-experiment` binary,
//! the research examples and the `double_sphere` bench. The collision library itself is
//! `cga-collide` and its command line `cga-cli`; neither depends on this package.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod experiment;
pub mod plot;
