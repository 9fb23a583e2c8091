//! The crate's one error type: every way an input can be rejected, saying what was wrong and
//! where (the argument, the file and line, the vertex or face, the tree node, the pose's place
//! in a batch), and every way a device can fail (feature `gpu`).

use std::fmt;

use thiserror::Error;

/// Why the crate could not answer: a shape, mesh, file, pose or batch that was rejected.
///
/// Every variant carries what was wrong and where, so the message (`Display`) is enough for a
/// user to fix the input. Variants are grouped by the input they reject: bounded shapes and
/// conformal constructors, meshes and their files, poses of the pose queries, scenes, convex
/// polyhedra, sphere hierarchies and their files, the GPU, and batches.
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
    /// A coordinate, vector component or radius of a primitive is beyond
    /// [`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE) (`2^500`), where certified answers would overflow.
    #[error("{shape}: argument `{argument}` has the value {value:e}, beyond the limit {limit:e} for primitives; scale the scene down")]
    CoordinateOutOfRange {
        /// The shape, e.g. `"Cuboid"`.
        shape: &'static str,
        /// The argument name, e.g. `"centre"` or `"radius"`.
        argument: &'static str,
        /// The rejected value.
        value: f64,
        /// The limit.
        limit: f64,
    },
    /// One point of a point list (a convex hull's) was rejected; `index` is its position.
    #[error("point {index}: {source}")]
    InShapePoint {
        /// Position of the point in the list (from 0).
        index: usize,
        /// Why it was rejected.
        source: Box<Error>,
    },
    /// A clearance (the `c` of a `within_distance` query) is negative, NaN, infinite or beyond
    /// [`MAX_MAGNITUDE`](crate::shape::MAX_MAGNITUDE).
    #[error("clearance {value} is not a distance: give a finite number >= 0 (at most 2^500)")]
    InvalidClearance {
        /// The rejected value.
        value: f64,
    },
    /// The generic queries cannot yet answer this pair of shape kinds exactly.
    #[error("no exact {query} test for a {a} against a {b} yet")]
    UnsupportedPair {
        /// The query, e.g. `"intersects"`.
        query: &'static str,
        /// The first shape's kind.
        a: &'static str,
        /// The second shape's kind.
        b: &'static str,
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

    /// A scene object was asked for as the other kind: a mesh collider where it holds a
    /// solid primitive, or the reverse.
    #[error("scene object {index} is a {found}, not a {expected}: ask Scene::kind first, or use Scene::{accessor}")]
    WrongObjectKind {
        /// The handle's slot.
        index: u32,
        /// What the call needs (`"mesh"` or `"shape"`).
        expected: &'static str,
        /// What the object is (`"mesh"`, or the shape's kind such as `"ball"`).
        found: &'static str,
        /// The call that takes this object.
        accessor: &'static str,
    },

    // ------------------------------------------------------------ robots
    /// A robot description (URDF) or its semantic file (SRDF) was rejected: `at` names the
    /// file, the line and the element (`panda.urdf:42: <joint name="j1">`).
    #[error("{at}: {reason}")]
    RobotModel {
        /// `FILE:LINE: <element name="...">`.
        at: String,
        /// What is wrong and how to fix it.
        reason: String,
    },
    /// A configuration does not fit the robot: wrong length or a non-finite value.
    #[error("configuration: {reason}")]
    Configuration {
        /// What is wrong (the expected length, the joint whose value is not finite).
        reason: String,
    },
    // ------------------------------------------------------------ convex polyhedra
    /// [`ConvexPolyhedron::new`](crate::shape::polyhedron::ConvexPolyhedron::new) was given
    /// fewer than 4 vertices or 4 faces.
    #[error("ConvexPolyhedron::new: a polyhedron needs at least 4 vertices and 4 faces (got {vertices} vertices, {faces} faces)")]
    PolyhedronTooSmall {
        /// Number of vertices given.
        vertices: usize,
        /// Number of faces given.
        faces: usize,
    },
    /// A polyhedron's vertex coordinate is NaN or infinite.
    #[error("ConvexPolyhedron::new: vertex {vertex} has a non-finite coordinate ({value}); coordinates must be finite numbers")]
    PolyhedronNonFiniteVertex {
        /// Index of the vertex.
        vertex: usize,
        /// The offending value.
        value: f64,
    },
    /// A polyhedron's face has fewer than 3 vertices, repeats a vertex or has zero area.
    #[error("ConvexPolyhedron::new: face {face} is not a polygon: {reason}")]
    PolyhedronBadFace {
        /// Index of the face.
        face: usize,
        /// What is wrong, e.g. `"fewer than 3 vertices"`.
        reason: &'static str,
    },
    /// A polyhedron's face refers to a vertex that does not exist.
    #[error("ConvexPolyhedron::new: face {face} refers to vertex {index}, but there are only {vertex_count} vertices (indices are 0-based)")]
    PolyhedronIndexOutOfRange {
        /// Index of the face.
        face: usize,
        /// The bad vertex index.
        index: usize,
        /// Number of vertices.
        vertex_count: usize,
    },
    /// A polyhedron's vertex is used by no face.
    #[error("ConvexPolyhedron::new: vertex {vertex} belongs to no face; remove it or add the faces that use it")]
    PolyhedronUnusedVertex {
        /// Index of the vertex.
        vertex: usize,
    },
    /// A polyhedron's edge is not shared by exactly two faces traversing it in opposite
    /// directions (the surface is open, non-manifold, or inconsistently oriented).
    #[error("ConvexPolyhedron::new: edge {from}->{to} of face {face} {reason}")]
    PolyhedronBadEdge {
        /// First vertex of the directed edge.
        from: usize,
        /// Second vertex of the directed edge.
        to: usize,
        /// A face using the edge.
        face: usize,
        /// What is wrong.
        reason: &'static str,
    },
    /// A polyhedron's `V - E + F != 2`.
    #[error("ConvexPolyhedron::new: Euler characteristic V - E + F = {vertices} - {edges} + {faces} is not 2: a convex polyhedron is a closed surface without holes or handles")]
    PolyhedronEuler {
        /// Vertices.
        vertices: usize,
        /// Edges.
        edges: usize,
        /// Faces.
        faces: usize,
    },
    /// A polyhedron's face vertices are not in one plane.
    #[error("ConvexPolyhedron::new: face {face} is not planar: vertex {vertex} is {distance:e} from the face plane (tolerance {tolerance:e})")]
    PolyhedronNonPlanarFace {
        /// Index of the face.
        face: usize,
        /// The vertex farthest from the plane.
        vertex: usize,
        /// Its distance.
        distance: f64,
        /// The tolerance.
        tolerance: f64,
    },
    /// A polyhedron's face polygon is not convex (or is degenerate, or is clockwise seen from
    /// outside).
    #[error("ConvexPolyhedron::new: face {face} is not a convex polygon at its corner {corner} (vertex {vertex})")]
    PolyhedronNonConvexFace {
        /// Index of the face.
        face: usize,
        /// Position of the corner in the face's vertex list.
        corner: usize,
        /// The vertex at that corner.
        vertex: usize,
    },
    /// A polyhedron's vertex lies on the outer side of a face plane: the solid is not convex,
    /// or the face is oriented inwards.
    #[error("ConvexPolyhedron::new: vertex {vertex} is {distance:e} outside the plane of face {face} (tolerance {tolerance:e}): not convex, or the face is oriented inwards")]
    PolyhedronNotConvex {
        /// Index of the face.
        face: usize,
        /// The vertex outside.
        vertex: usize,
        /// Its distance from the plane (positive = outside).
        distance: f64,
        /// The tolerance.
        tolerance: f64,
    },
    /// [`ConvexPolyhedron::by_name`](crate::shape::polyhedron::ConvexPolyhedron::by_name) does
    /// not know the name.
    #[error("ConvexPolyhedron::by_name: unknown polyhedron {name:?} (known: cube, octahedron, truncated_octahedron (troctahedron), rh (truncated_icosidodecahedron), diamond)")]
    UnknownPolyhedron {
        /// The name given.
        name: String,
    },

    // ------------------------------------------------------------ hierarchies
    /// A double-sphere tree was asked for a level deeper than it supports.
    #[error("double-sphere tree: level {level} is too deep: choose a level from 0 to {max}")]
    LevelTooDeep {
        /// The requested level.
        level: usize,
        /// The largest supported level.
        max: usize,
    },
    /// A sphere-tree node's centre coordinate or radius is NaN or infinite.
    #[error("sphere tree node {node} (breadth-first index): {what} is not finite ({value})")]
    SphereTreeNonFinite {
        /// Breadth-first index of the node.
        node: usize,
        /// `"centre x"`, `"centre y"`, `"centre z"` or `"radius"`.
        what: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A sphere-tree node's radius is negative.
    #[error("sphere tree node {node} (breadth-first index): radius is negative ({radius})")]
    SphereTreeNegativeRadius {
        /// Breadth-first index of the node.
        node: usize,
        /// The rejected radius.
        radius: f64,
    },
    /// A sphere-tree node has more than 8 children.
    #[error("sphere tree node {node} (breadth-first index) has {count} children; an octree node has at most 8")]
    SphereTreeTooManyChildren {
        /// Breadth-first index of the node.
        node: usize,
        /// Its number of children.
        count: usize,
    },
    /// A sphere tree with more nodes than 32-bit indices address.
    #[error("{count} nodes is more than a sphere tree holds (2^32 - 1): build a shallower tree")]
    SphereTreeTooLarge {
        /// The number of nodes.
        count: usize,
    },
    /// A line of a sphere-tree file is not what the format requires at that point.
    #[error("line {line}: expected {expected}, found `{found}`")]
    SphereTreeSyntax {
        /// The line (1-based).
        line: usize,
        /// What the format requires there.
        expected: String,
        /// The line's content (comment removed, trimmed).
        found: String,
    },
    /// A sphere-tree file ended while a tree was incomplete.
    #[error(
        "input ends after line {line}: expected {expected}; {} of {declared_trees} trees complete{}",
        complete_trees,
        gaps.iter().map(|g| format!("; {g}")).collect::<String>()
    )]
    SphereTreeUnexpectedEnd {
        /// The last line of the input.
        line: usize,
        /// What the format required next.
        expected: String,
        /// The number of trees the first line declares.
        declared_trees: usize,
        /// How many trees were complete.
        complete_trees: usize,
        /// The open nodes of the incomplete tree, outermost first.
        gaps: Vec<Gap>,
    },
    /// Non-blank content after the last tree a sphere-tree file declares.
    #[error("line {line}: the {declared_trees} declared trees are complete, but the input goes on with `{found}`")]
    SphereTreeTrailingContent {
        /// The line.
        line: usize,
        /// The number of trees the first line declares.
        declared_trees: usize,
        /// The line's content.
        found: String,
    },
    /// A tree of a sphere-tree file was read but cannot be stored (one of the `SphereTree…`
    /// variants above says why).
    #[error("tree starting at line {line}: {source}")]
    SphereTreeAtLine {
        /// The line of the tree's root.
        line: usize,
        /// What is wrong.
        source: Box<Error>,
    },
    /// An octree sphere tree was asked for a depth above its maximum.
    #[error("octree sphere tree: depth {depth} is above the maximum {max}: choose a depth from 0 to {max}")]
    OctreeDepthTooLarge {
        /// The requested depth.
        depth: u32,
        /// The largest supported depth.
        max: u32,
    },
    /// An octree sphere tree was asked of a mesh that is not closed, so "inside" is not
    /// defined.
    #[error("octree sphere tree: the mesh is not closed (some edge is used by an odd number of triangles); full and empty cells cannot be told apart: close its holes, or use a closed (watertight) mesh")]
    OctreeMeshNotClosed,
    /// The exact octree grid cannot be represented in `f64` (the mesh is tiny compared to its
    /// distance from the origin, or its coordinates are extreme).
    #[error("octree sphere tree: the grid of depth {depth} cannot be represented exactly in f64 for a mesh of size {extent} at distance {offset} from the origin: move the mesh near the origin (e.g. scale it into the unit box) or choose a smaller depth")]
    OctreePrecision {
        /// The requested depth.
        depth: u32,
        /// The largest side of the mesh's bounding box.
        extent: f64,
        /// The largest absolute coordinate of the box.
        offset: f64,
    },

    // ------------------------------------------------------------ GPU (feature `gpu`)
    /// No GPU adapter (GPU or software driver) was found.
    #[error("no GPU adapter found: wgpu found no Vulkan, Metal, DX12 or GL device (only the backends in WGPU_BACKEND if it is set); install the GPU's driver, or on Linux without a GPU Mesa's software Vulkan driver lavapipe (Debian/Ubuntu package mesa-vulkan-drivers)")]
    NoGpuAdapter,
    /// The GPU adapter refused to create a device.
    #[error("the adapter refused to open a device: {message} (check its driver; WGPU_ADAPTER_NAME or WGPU_BACKEND choose another adapter)")]
    GpuDevice {
        /// The driver's message.
        message: String,
    },
    /// `f64` was asked for but the GPU has no `SHADER_F64`.
    #[error("the device {device} has no 64-bit floats in shaders (SHADER_F64); ask for Precision::F32 or the best available (Device::new), which give the same exact answers with more pairs re-decided on the CPU")]
    GpuNoF64 {
        /// The device's name.
        device: String,
    },
    /// Reading results back from the GPU failed.
    #[error("reading results back from the device failed: {message} (the device was lost or ran out of memory; retry, or split the meshes into smaller parts)")]
    GpuReadback {
        /// The driver's message.
        message: String,
    },
    /// An input does not fit in one storage buffer of the GPU.
    #[error("{what} needs {bytes} bytes, more than the device's storage buffer limit of {limit} bytes; split it into parts that fit, or use the CPU queries (cga_collide::query)")]
    GpuBufferTooLarge {
        /// Which input.
        what: &'static str,
        /// Its size.
        bytes: u64,
        /// The device's limit.
        limit: u64,
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

/// A node of a sphere-tree file whose children had not all been read when the input ended
/// (see [`Error::SphereTreeUnexpectedEnd`] and
/// [`read_lenient`](crate::hierarchy::sphere_tree::format::read_lenient)).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Gap {
    /// Which tree (0-based).
    pub tree: usize,
    /// The line of the node (its `cx cy cz r state` line).
    pub line: usize,
    /// The number of children its `k 8` line declares.
    pub declared: usize,
    /// How many complete children were read.
    pub read: usize,
}

impl fmt::Display for Gap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "tree {} node at line {} declares {} children, {} complete",
            self.tree + 1,
            self.line,
            self.declared,
            self.read
        )
    }
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
