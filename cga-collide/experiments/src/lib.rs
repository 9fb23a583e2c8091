//! Library part of the `cga` command line: the double-sphere paper's experiment and SVG bar
//! charts. The collision library itself is `cga-collide`; nothing there depends on this
//! package.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod experiment;
pub mod plot;
