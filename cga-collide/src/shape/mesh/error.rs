//! Typed errors of the mesh loaders.

use std::fmt;

/// Where in an input something went wrong: the file (or the name given to in-memory data), and
/// the 1-based line for text formats or the byte offset for binary ones, when known.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// File name (or the name given to in-memory data).
    pub file: String,
    /// 1-based line number (text formats).
    pub line: Option<usize>,
    /// 0-based byte offset (binary formats).
    pub byte: Option<usize>,
}

impl Location {
    /// A location naming only the file.
    pub fn file(file: &str) -> Self {
        Location {
            file: file.to_owned(),
            line: None,
            byte: None,
        }
    }

    /// A location naming a file and a 1-based line.
    pub fn line(file: &str, line: usize) -> Self {
        Location {
            file: file.to_owned(),
            line: Some(line),
            byte: None,
        }
    }

    /// A location naming a file and a 0-based byte offset.
    pub fn byte(file: &str, byte: usize) -> Self {
        Location {
            file: file.to_owned(),
            line: None,
            byte: Some(byte),
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(byte) = self.byte {
            write!(f, " (byte {byte})")?;
        }
        Ok(())
    }
}

/// Everything that can go wrong when reading or building a [`TriMesh`](super::TriMesh).
///
/// Every variant says where: the file, and the line (text formats) or byte offset (binary
/// formats) and the vertex or face index where that applies.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// [`TriMesh::cuboid`](super::TriMesh::cuboid) was given a corner that is not finite or
    /// lies beyond the other corner.
    #[error("TriMesh::cuboid: on axis {axis}, min {min} and max {max} do not make an interval (both must be finite, min <= max)")]
    InvalidBox {
        /// The axis (0 = x, 1 = y, 2 = z).
        axis: usize,
        /// The minimum corner's coordinate on that axis.
        min: f64,
        /// The maximum corner's coordinate on that axis.
        max: f64,
    },
    /// The file could not be opened or read.
    #[error("{file}: cannot read the file: {error} (check the path and its permissions)")]
    Io {
        /// The file.
        file: String,
        /// The operating system's error (in the message, so not repeated as a source).
        error: std::io::Error,
    },
    /// The format could not be told from the file name.
    #[error("{file}: unknown mesh format {extension:?} (expected .obj, .off, .ply or .stl, optionally followed by .gz)")]
    UnknownFormat {
        /// The file.
        file: String,
        /// The extension that was not recognised.
        extension: String,
    },
    /// A token that should be a number is not one.
    #[error("{at}: bad number {token:?} (expected {expected})")]
    BadNumber {
        /// Where.
        at: Location,
        /// The offending token (shortened if long).
        token: String,
        /// What kind of number was expected.
        expected: &'static str,
    },
    /// Structure that does not follow the format.
    #[error("{at}: {message}")]
    Syntax {
        /// Where.
        at: Location,
        /// What is wrong.
        message: String,
    },
    /// A face refers to a vertex that does not exist.
    #[error("{at}: face {face}: vertex index {index} out of range (the mesh has {vertex_count} vertices; check the face's indices and the vertex count in the header)")]
    IndexOutOfRange {
        /// Where.
        at: Location,
        /// 0-based index of the face (polygon) in the file.
        face: usize,
        /// The offending index as written (after resolving the format's base).
        index: i64,
        /// Number of vertices.
        vertex_count: usize,
    },
    /// A vertex coordinate is infinite or NaN.
    #[error("{at}: vertex {vertex}: non-finite coordinate {value} (every coordinate must be a finite number)")]
    NonFinite {
        /// Where.
        at: Location,
        /// 0-based vertex index.
        vertex: usize,
        /// The coordinate.
        value: f64,
    },
    /// The mesh has no triangles.
    #[error("{file}: the mesh is empty (no triangles): check that the file has faces, not only vertices or points")]
    Empty {
        /// The file.
        file: String,
    },
    /// The file ends before the data its header or structure promises.
    #[error("{at}: file is truncated: expected {expected}")]
    Truncated {
        /// Where the data ran out.
        at: Location,
        /// What was still expected.
        expected: String,
    },
}

/// Shortens a token for an error message.
pub(crate) fn shorten(token: &str) -> String {
    const MAX: usize = 40;
    if token.chars().count() <= MAX {
        token.to_owned()
    } else {
        let mut s: String = token.chars().take(MAX).collect();
        s.push('…');
        s
    }
}
