//! The crate's one error type: every way an input can be rejected, saying what was wrong and
//! where (the argument, the file and line, the vertex or face, the pose's place in a batch).

use std::fmt;

use thiserror::Error;

/// Why the crate could not answer: a shape, mesh, file, pose or batch that was rejected.
///
/// Every variant carries what was wrong and where, so the message (`Display`) is enough for a
/// user to fix the input. Variants are grouped by the input they reject: bounded shapes and
/// conformal constructors, meshes and their files, poses of the pose queries, and batches.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    // ------------------------------------------------------------ shapes
    /// A coordinate of a point argument is NaN or infinite.
    #[error("{shape}::new: argument `{argument}` has a non-finite {axis} coordinate ({value}); coordinates must be finite numbers")]
    NonFiniteCoordinate {
        /// The shape being built (`"Segment"`, `"Triangle"`, `"Sphere"`, `"Ball"`).
        shape: &'static str,
        /// The argument name, e.g. `"a"` or `"centre"`.
        argument: &'static str,
        /// `"x"`, `"y"` or `"z"`.
        axis: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A radius is NaN or infinite.
    #[error("{shape}::new: radius is not finite ({value}); give a finite radius >= 0")]
    NonFiniteRadius {
        /// The shape being built.
        shape: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A radius is negative.
    #[error("{shape}::new: radius is negative ({value}); give a finite radius >= 0")]
    NegativeRadius {
        /// The shape being built.
        shape: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// An input of a conformal constructor (a coordinate, a scalar or a blade coefficient) is
    /// NaN or infinite.
    #[error("{constructor}: argument `{argument}` has a non-finite value ({value}); give finite numbers")]
    NonFiniteInput {
        /// The constructor, e.g. `"conformal::Line::from_points"`.
        constructor: &'static str,
        /// The argument name, with the component when it has several (`"a.x"`, `"normal.z"`).
        argument: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// The input of a conformal constructor does not define the requested object (coincident
    /// points for a line, collinear points for a plane, coplanar points for a sphere, a zero
    /// normal, a non-positive scale factor, ...). Decided exactly for the `f64` inputs.
    #[error("{constructor}: degenerate input: {reason}")]
    Degenerate {
        /// The constructor, e.g. `"conformal::Plane::from_points"`.
        constructor: &'static str,
        /// What is degenerate, e.g. `"points a, b, c are collinear"`.
        reason: &'static str,
    },

    // ------------------------------------------------------------ meshes and files
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
    #[error("{file}: cannot read the file: {message} (check the path and its permissions)")]
    Io {
        /// The file.
        file: String,
        /// The operating system's error kind.
        kind: std::io::ErrorKind,
        /// The operating system's message.
        message: String,
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

    /// The end positions of a deforming mesh's step are not one per vertex of the mesh.
    #[error("the step's end positions have {found} vertices but the mesh has {expected}: give one end position per vertex, in the mesh's vertex order")]
    VertexCountMismatch {
        /// Vertices of the mesh.
        expected: usize,
        /// End positions given.
        found: usize,
    },

    // ------------------------------------------------------------ poses
    /// A quaternion or translation component of a pose is NaN or infinite.
    #[error("the pose has a non-finite component: every quaternion and translation component must be a finite number")]
    NonFinitePose,
    /// A pose's quaternion is far from unit length (`|q|²` outside `[1/2, 2]`).
    #[error("the pose's rotation is not a unit quaternion (|q|² = {norm_squared}): normalise it (e.g. UnitQuaternion::new_normalize)")]
    NotUnitRotation {
        /// The squared length of the quaternion.
        norm_squared: f64,
    },
    /// The 3×3 part `R` of a pose given as a matrix is not a rotation: it scales, shears or
    /// reflects (`max |RᵀR − I|` above [`ROTATION_TOLERANCE`](crate::collider::ROTATION_TOLERANCE),
    /// or `det R <= 0`).
    #[error("the pose's 3x3 part is not a rotation (max |RᵀR − I| = {deviation:.3e}, det = {determinant}): a pose is a rotation and a translation, without scale, shear or reflection")]
    NotARotation {
        /// `max |RᵀR − I|` over the entries.
        deviation: f64,
        /// `det R`.
        determinant: f64,
    },
    /// Coordinates or translations so large that a certified answer is out of reach (its
    /// rounding bounds, or the squared distances of a distance query, would overflow `f64`).
    #[error("coordinates too large for a certified answer (|x| up to {magnitude:e}, the limit is {limit:e}): scale the meshes and translations down")]
    OutOfRange {
        /// The largest magnitude involved.
        magnitude: f64,
        /// The largest magnitude this query certifies.
        limit: f64,
    },

    // ------------------------------------------------------------ scenes
    /// A scene was asked about an object it does not hold (never added, or removed).
    #[error("scene object {index} (generation {generation}) is not in the scene: it was removed, or the handle is from another scene")]
    UnknownObject {
        /// The handle's slot.
        index: u32,
        /// The handle's generation (slots are reused after a removal).
        generation: u32,
    },

    // ------------------------------------------------------------ batches
    /// One item of a batch has no answer; `index` is its position in the slice.
    #[error("pose {index} of the batch: {source}")]
    InBatch {
        /// Position of the item in the slice (from 0).
        index: usize,
        /// Why it has no answer.
        source: Box<Error>,
    },
}

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
