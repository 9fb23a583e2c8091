//! Triangle meshes: the [`TriMesh`] type, loaders for OBJ, OFF, PLY and STL, the built-in
//! fixture meshes (feature `builtin-meshes`) and midpoint subdivision.
//!
//! # Coordinates and exactness
//! A mesh is a list of `f64` vertices and a list of index triples. Degenerate triangles
//! (repeated indices, collinear or coincident vertices) are kept: the exact tests answer them as
//! the segment or point they collapse to. Placing a mesh with a rigid transform
//! ([`TriMesh::transformed`]) rounds: the transform is applied **once**, in `f64`, to every
//! vertex, and from then on every test is exact on those transformed `f64` coordinates.
//!
//! # Example
//! ```
//! use cga_collide::shape::mesh::{MeshFormat, TriMesh};
//! let off = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
//! let quad = TriMesh::from_bytes(off.as_bytes(), MeshFormat::Off, "quad.off")?;
//! assert_eq!(quad.triangles(), &[[0, 1, 2], [0, 2, 3]]); // fan triangulation
//! # Ok::<(), cga_collide::Error>(())
//! ```

#[cfg(feature = "builtin-meshes")]
mod builtin;
mod obj;
mod off;
mod ply;
mod stl;
mod text;

use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

use nalgebra::{Isometry3, Point3};

use crate::error::Error;
use crate::Triangle;

pub use crate::error::Location;

/// The file formats the loaders understand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ (read with the `tobj` crate; polygons fan-triangulated).
    Obj,
    /// Object File Format (`OFF`, also `COFF`/`NOFF`/`CNOFF` headers; colours ignored).
    Off,
    /// Stanford PLY, ASCII or binary (little or big endian).
    Ply,
    /// STL, ASCII or binary.
    Stl,
}

impl MeshFormat {
    /// The format named by a file extension (case-insensitive, without the dot).
    pub fn from_extension(extension: &str) -> Option<Self> {
        match extension.to_ascii_lowercase().as_str() {
            "obj" => Some(MeshFormat::Obj),
            "off" => Some(MeshFormat::Off),
            "ply" => Some(MeshFormat::Ply),
            "stl" => Some(MeshFormat::Stl),
            _ => None,
        }
    }

    /// The format of a path from its extension; a trailing `.gz` is looked through
    /// (`bunny.off.gz` is OFF).
    pub fn from_path(path: &Path) -> Option<Self> {
        let name = path.file_name()?.to_str()?;
        let name = name
            .strip_suffix(".gz")
            .or_else(|| name.strip_suffix(".GZ"))
            .unwrap_or(name);
        let (_, ext) = name.rsplit_once('.')?;
        Self::from_extension(ext)
    }
}

/// An indexed triangle mesh with `f64` vertices.
///
/// Invariants (checked by every constructor): at least one triangle, every coordinate finite,
/// every index smaller than the number of vertices.
#[derive(Debug, Clone, PartialEq)]
pub struct TriMesh {
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
}

impl TriMesh {
    /// Builds a mesh, checking the invariants (non-empty, finite, indices in range).
    pub fn new(vertices: Vec<Point3<f64>>, triangles: Vec<[u32; 3]>) -> Result<Self, Error> {
        Self::checked("<memory>", vertices, triangles)
    }

    pub(crate) fn checked(
        file: &str,
        vertices: Vec<Point3<f64>>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Self, Error> {
        if triangles.is_empty() {
            return Err(Error::Empty {
                file: file.to_owned(),
            });
        }
        if vertices.len() > u32::MAX as usize {
            return Err(Error::Syntax {
                at: Location::file(file),
                message: format!(
                    "{} vertices is more than u32 indices address",
                    vertices.len()
                ),
            });
        }
        for (i, v) in vertices.iter().enumerate() {
            if let Some(&value) = v.coords.iter().find(|c| !c.is_finite()) {
                return Err(Error::NonFinite {
                    at: Location::file(file),
                    vertex: i,
                    value,
                });
            }
        }
        for (f, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(Error::IndexOutOfRange {
                    at: Location::file(file),
                    face: f,
                    index: i64::from(index),
                    vertex_count: vertices.len(),
                });
            }
        }
        Ok(TriMesh {
            vertices,
            triangles,
        })
    }

    /// Reads a mesh, choosing the format from the extension (`.obj`, `.off`, `.ply`, `.stl`,
    /// each optionally followed by `.gz`).
    pub fn load(path: impl AsRef<Path>) -> Result<Self, Error> {
        let path = path.as_ref();
        let format = MeshFormat::from_path(path).ok_or_else(|| Error::UnknownFormat {
            file: path.display().to_string(),
            extension: path
                .extension()
                .map(|e| e.to_string_lossy().into_owned())
                .unwrap_or_default(),
        })?;
        Self::load_as(path, format)
    }

    /// Reads a mesh in the given format (gzip-compressed data is recognised by its magic bytes).
    pub fn load_as(path: impl AsRef<Path>, format: MeshFormat) -> Result<Self, Error> {
        let path = path.as_ref();
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|error| Error::Io {
            kind: error.kind(),
            message: error.to_string(),
            file: name.clone(),
        })?;
        Self::from_bytes(&bytes, format, &name)
    }

    /// Parses a mesh from bytes in memory; `name` is used in error messages.
    /// Gzip-compressed data (magic bytes `1f 8b`) is decompressed first.
    pub fn from_bytes(bytes: &[u8], format: MeshFormat, name: &str) -> Result<Self, Error> {
        if bytes.starts_with(&[0x1f, 0x8b]) {
            let mut plain = Vec::new();
            flate2::read::MultiGzDecoder::new(bytes)
                .read_to_end(&mut plain)
                .map_err(|error| Error::Io {
                    kind: error.kind(),
                    message: error.to_string(),
                    file: name.to_owned(),
                })?;
            return Self::from_bytes(&plain, format, name);
        }
        let (vertices, triangles) = match format {
            MeshFormat::Obj => obj::parse(bytes, name)?,
            MeshFormat::Off => off::parse(bytes, name)?,
            MeshFormat::Ply => ply::parse(bytes, name)?,
            MeshFormat::Stl => stl::parse(bytes, name)?,
        };
        Self::checked(name, vertices, triangles)
    }

    /// The closed axis-aligned box `[min, max]` as 12 outward-oriented triangles (two per face).
    ///
    /// Errors when a coordinate is not finite or `min > max` on some axis (a flat box, with
    /// `min == max` on an axis, is allowed).
    ///
    /// ```
    /// use cga_collide::{nalgebra::Point3, TriMesh};
    /// let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))?;
    /// assert_eq!((cube.vertices().len(), cube.num_triangles()), (8, 12));
    /// assert!(cube.is_closed());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn cuboid(min: Point3<f64>, max: Point3<f64>) -> Result<Self, Error> {
        if let Some(axis) = (0..3).find(|&k| min[k].partial_cmp(&max[k]).is_none_or(|o| o.is_gt()))
        {
            return Err(Error::InvalidBox {
                axis,
                min: min[axis],
                max: max[axis],
            });
        }
        let corner = |m: usize| {
            Point3::new(
                if m & 1 == 0 { min.x } else { max.x },
                if m & 2 == 0 { min.y } else { max.y },
                if m & 4 == 0 { min.z } else { max.z },
            )
        };
        let vertices = (0..8).map(corner).collect();
        // Each face as a quad, counter-clockwise seen from outside.
        const QUADS: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let triangles = QUADS
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        TriMesh::new(vertices, triangles)
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point3<f64>] {
        &self.vertices
    }

    /// The triangles, as indices into [`vertices`](Self::vertices).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Number of triangles.
    pub fn num_triangles(&self) -> usize {
        self.triangles.len()
    }

    /// The three corners of triangle `i`. Panics if `i` is out of range (like slice indexing).
    #[inline]
    pub fn corners(&self, i: u32) -> [Point3<f64>; 3] {
        let [a, b, c] = self.triangles[i as usize];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// Triangle `i` as an exact-test shape. Panics if `i` is out of range (like slice
    /// indexing).
    #[inline]
    pub fn triangle(&self, i: u32) -> Triangle {
        // A mesh's vertices are finite (checked when it was built).
        Triangle::from_finite(self.corners(i))
    }

    /// Corner-wise minimum and maximum of all vertices.
    pub fn bounds(&self) -> (Point3<f64>, Point3<f64>) {
        bounds_of(&self.vertices)
    }

    /// The mesh with `iso` applied once, in `f64`, to every vertex. The exact tests are then
    /// exact on the rounded, transformed coordinates (see the module docs).
    ///
    /// Returns an error only if a coordinate overflows to infinity.
    pub fn transformed(&self, iso: &Isometry3<f64>) -> Result<TriMesh, Error> {
        let vertices = self.vertices.iter().map(|v| iso * v).collect();
        Self::checked("<transformed>", vertices, self.triangles.clone())
    }

    /// The mesh scaled uniformly and translated so that its bounding box is centred at the
    /// origin with largest side 1 (the CLI's `--unit`). A mesh whose vertices all coincide is
    /// only translated. Works for every finite mesh, from subnormal sizes (`1e-320` across) to
    /// `±1e308`: the result is always finite.
    ///
    /// ```
    /// use cga_collide::{nalgebra::Point3, TriMesh};
    /// let tiny = TriMesh::cuboid(Point3::origin(), Point3::new(1e-320, 1e-320, 1e-320))?;
    /// let (lo, hi) = tiny.unit().bounds();
    /// assert_eq!((hi - lo).max(), 1.0);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn unit(&self) -> TriMesh {
        let (lo, hi) = self.bounds();
        let centre = nalgebra::center(&lo, &hi);
        let side = (hi - lo).max();
        let scale = if side > 0.0 { 1.0 / side } else { 1.0 };
        let vertices: Vec<Point3<f64>> = self
            .vertices
            .iter()
            .map(|v| Point3::from((v - centre) * scale))
            .collect();
        let vertices =
            if side.is_normal() && vertices.iter().all(|v| v.iter().all(|x| x.is_finite())) {
                vertices
            } else {
                self.unit_by_powers_of_two()
            };
        TriMesh {
            vertices,
            triangles: self.triangles.clone(),
        }
    }

    /// [`unit`](Self::unit) for meshes where the direct formula over- or underflows (sides
    /// beyond `f64`'s range, or subnormal): exact power-of-two scalings first bring the
    /// coordinates, then their offsets from the centre, near 1, where the same formula is safe.
    fn unit_by_powers_of_two(&self) -> Vec<Point3<f64>> {
        let magnitude = |vs: &[Point3<f64>]| {
            vs.iter()
                .flat_map(|v| v.iter().map(|x| x.abs()))
                .fold(0.0f64, f64::max)
        };
        let near_one = |vs: Vec<Point3<f64>>| {
            let m = magnitude(&vs);
            if m == 0.0 {
                return vs;
            }
            let e = -(m.log2().floor() as i32);
            vs.into_iter()
                .map(|v| v.map(|x| times_power_of_two(x, e)))
                .collect()
        };
        let scaled = near_one(self.vertices.clone());
        let (lo, hi) = bounds_of(&scaled);
        let centre = nalgebra::center(&lo, &hi);
        let offsets = near_one(scaled.iter().map(|v| Point3::from(v - centre)).collect());
        let (lo, hi) = bounds_of(&offsets);
        let side = (hi - lo).max();
        // Divided, not multiplied by `1 / side`: the rounded reciprocal would leave a symmetric
        // mesh (offsets `±side / 2`) with largest side `1 - 2⁻⁵³` instead of exactly 1.
        if side > 0.0 {
            offsets.into_iter().map(|v| v / side).collect()
        } else {
            offsets
        }
    }

    /// One step of 1→4 midpoint subdivision: every triangle is split at its edge midpoints
    /// into four. Midpoints are shared between the triangles of an edge, so a closed mesh stays
    /// closed; the geometry (the surface as a point set) is unchanged up to the rounding of the
    /// midpoints.
    pub fn subdivided(&self) -> TriMesh {
        let mut vertices = self.vertices.clone();
        let mut midpoints: HashMap<(u32, u32), u32> =
            HashMap::with_capacity(self.triangles.len() * 2);
        let mut triangles = Vec::with_capacity(self.triangles.len() * 4);
        let mut mid = |a: u32, b: u32, vertices: &mut Vec<Point3<f64>>| -> u32 {
            let key = (a.min(b), a.max(b));
            *midpoints.entry(key).or_insert_with(|| {
                let (p, q) = (vertices[a as usize], vertices[b as usize]);
                vertices.push(Point3::from(p.coords * 0.5 + q.coords * 0.5));
                (vertices.len() - 1) as u32
            })
        };
        for &[a, b, c] in &self.triangles {
            let ab = mid(a, b, &mut vertices);
            let bc = mid(b, c, &mut vertices);
            let ca = mid(c, a, &mut vertices);
            triangles.extend_from_slice(&[[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        TriMesh {
            vertices,
            triangles,
        }
    }

    /// Whether every undirected edge is used by an even number of triangles (edges of
    /// degenerate triangles included): the condition under which the mesh bounds a solid
    /// for the even–odd rule (`Collider::contains_point`).
    pub fn is_closed(&self) -> bool {
        let mut edges: HashMap<(u32, u32), u32> = HashMap::with_capacity(self.triangles.len() * 3);
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if a != b {
                    *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
                }
            }
        }
        edges.values().all(|n| n % 2 == 0)
    }

    /// The mesh subdivided ([`subdivided`](Self::subdivided)) until it has at least
    /// `min_triangles` triangles (×4 per step).
    pub fn subdivided_to(&self, min_triangles: usize) -> TriMesh {
        let mut mesh = self.clone();
        while mesh.triangles.len() < min_triangles {
            mesh = mesh.subdivided();
        }
        mesh
    }
}

/// `x · 2^e`, exact unless the result leaves `f64`'s range (the steps keep each factor finite).
fn times_power_of_two(mut x: f64, mut e: i32) -> f64 {
    while e != 0 {
        let step = e.clamp(-1000, 1000);
        x *= 2f64.powi(step);
        e -= step;
    }
    x
}

/// Corner-wise minimum and maximum of points.
fn bounds_of(points: &[Point3<f64>]) -> (Point3<f64>, Point3<f64>) {
    let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for v in points {
        for k in 0..3 {
            lo[k] = lo[k].min(v[k]);
            hi[k] = hi[k].max(v[k]);
        }
    }
    (lo, hi)
}
