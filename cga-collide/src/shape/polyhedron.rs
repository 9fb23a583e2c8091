//! Convex polyhedra given by their vertices and polygonal faces, with the five solids of the
//! double-sphere paper's Table 1 built in code.
//!
//! A [`ConvexPolyhedron`] stores `f64` vertices and faces as vertex-index polygons ordered
//! counter-clockwise seen from outside. [`ConvexPolyhedron::new`] validates the input (closed
//! two-manifold with consistently oriented faces, Euler's `V - E + F = 2`, every face planar and
//! convex, every vertex on the inner side of every face plane, outward orientation), each within
//! a tolerance relative to the polyhedron's size, and says precisely what is wrong
//! (an [`Error`] whose variant names start with `Polyhedron`).
//!
//! The built-in solids ([`cube`](ConvexPolyhedron::cube),
//! [`octahedron`](ConvexPolyhedron::octahedron),
//! [`truncated_octahedron`](ConvexPolyhedron::truncated_octahedron),
//! [`rh`](ConvexPolyhedron::rh), [`diamond`](ConvexPolyhedron::diamond)) are all centred at the
//! origin, meaning that their smallest enclosing sphere is centred at the origin, and scaled so
//! that this sphere has radius 1 (circumradius 1, up to the rounding of the last bit of the
//! coordinates). The faces are fan-triangulated for the exact triangle tests
//! ([`triangles`](ConvexPolyhedron::triangles), [`to_trimesh`](ConvexPolyhedron::to_trimesh)).
//!
//! ```
//! use cga_collide::shape::polyhedron::ConvexPolyhedron;
//! let d = ConvexPolyhedron::diamond();
//! assert_eq!((d.num_vertices(), d.num_edges(), d.num_faces()), (41, 88, 49));
//! let rh = ConvexPolyhedron::by_name("rh").unwrap();
//! assert_eq!((rh.num_vertices(), rh.num_edges(), rh.num_faces()), (120, 180, 62));
//! assert_eq!(rh.to_trimesh().num_triangles(), rh.triangles().len());
//! ```

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};

use crate::error::Error;
use crate::shape::mesh::TriMesh;

/// A convex polyhedron: `f64` vertices and polygonal faces (vertex indices, counter-clockwise
/// seen from outside), validated on construction, with its fan triangulation.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexPolyhedron {
    vertices: Vec<Point3<f64>>,
    faces: Vec<Vec<usize>>,
    edges: usize,
    triangles: Vec<[u32; 3]>,
    triangle_faces: Vec<usize>,
}

/// Relative tolerance of the validation (times the largest vertex norm).
pub const TOLERANCE: f64 = 1e-9;

/// The outward normal (not normalised) of a polygon by Newell's method.
pub(crate) fn newell_normal(vertices: &[Point3<f64>], face: &[usize]) -> Vector3<f64> {
    let mut n = Vector3::zeros();
    for (k, &i) in face.iter().enumerate() {
        let a = vertices[i];
        let b = vertices[face[(k + 1) % face.len()]];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    n
}

impl ConvexPolyhedron {
    /// Validates and builds a convex polyhedron (see the module docs for the checks; the
    /// tolerance is [`TOLERANCE`] times the largest vertex norm).
    pub fn new(vertices: Vec<Point3<f64>>, faces: Vec<Vec<usize>>) -> Result<Self, Error> {
        if vertices.len() < 4 || faces.len() < 4 {
            return Err(Error::PolyhedronTooSmall {
                vertices: vertices.len(),
                faces: faces.len(),
            });
        }
        for (i, v) in vertices.iter().enumerate() {
            if let Some(&value) = v.coords.iter().find(|c| !c.is_finite()) {
                return Err(Error::PolyhedronNonFiniteVertex { vertex: i, value });
            }
        }
        let mut used = vec![false; vertices.len()];
        for (f, face) in faces.iter().enumerate() {
            if face.len() < 3 {
                return Err(Error::PolyhedronBadFace {
                    face: f,
                    reason: "fewer than 3 vertices",
                });
            }
            for (k, &i) in face.iter().enumerate() {
                if i >= vertices.len() {
                    return Err(Error::PolyhedronIndexOutOfRange {
                        face: f,
                        index: i,
                        vertex_count: vertices.len(),
                    });
                }
                if face[..k].contains(&i) {
                    return Err(Error::PolyhedronBadFace {
                        face: f,
                        reason: "a vertex is repeated",
                    });
                }
                used[i] = true;
            }
        }
        if let Some(vertex) = used.iter().position(|u| !u) {
            return Err(Error::PolyhedronUnusedVertex { vertex });
        }
        // Every directed edge once, and its reverse once.
        let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
        for (f, face) in faces.iter().enumerate() {
            for k in 0..face.len() {
                let e = (face[k], face[(k + 1) % face.len()]);
                if directed.insert(e, f).is_some() {
                    return Err(Error::PolyhedronBadEdge {
                        from: e.0,
                        to: e.1,
                        face: f,
                        reason: "is used twice in the same direction (inconsistent orientation or non-manifold)",
                    });
                }
            }
        }
        for (&(a, b), &f) in &directed {
            if !directed.contains_key(&(b, a)) {
                return Err(Error::PolyhedronBadEdge {
                    from: a,
                    to: b,
                    face: f,
                    reason: "has no opposite face (the surface is open)",
                });
            }
        }
        let edges = directed.len() / 2;
        if vertices.len() + faces.len() != edges + 2 {
            return Err(Error::PolyhedronEuler {
                vertices: vertices.len(),
                edges,
                faces: faces.len(),
            });
        }
        let scale = vertices.iter().map(|v| v.coords.norm()).fold(0.0, f64::max);
        let tolerance = TOLERANCE * scale.max(f64::MIN_POSITIVE);
        for (f, face) in faces.iter().enumerate() {
            let n = newell_normal(&vertices, face);
            let norm = n.norm();
            if norm == 0.0 {
                return Err(Error::PolyhedronBadFace {
                    face: f,
                    reason: "zero area",
                });
            }
            let n = n / norm;
            let c = face
                .iter()
                .map(|&i| vertices[i].coords)
                .sum::<Vector3<f64>>()
                / face.len() as f64;
            // Planarity.
            for &i in face {
                let distance = (vertices[i].coords - c).dot(&n).abs();
                if distance > tolerance {
                    return Err(Error::PolyhedronNonPlanarFace {
                        face: f,
                        vertex: i,
                        distance,
                        tolerance,
                    });
                }
            }
            // Convex and counter-clockwise about the outward normal: every corner turns left.
            for k in 0..face.len() {
                let a = vertices[face[(k + face.len() - 1) % face.len()]];
                let b = vertices[face[k]];
                let d = vertices[face[(k + 1) % face.len()]];
                let turn = (b - a).cross(&(d - b)).dot(&n);
                if turn <= tolerance * (b - a).norm().max(tolerance) {
                    return Err(Error::PolyhedronNonConvexFace {
                        face: f,
                        corner: k,
                        vertex: face[k],
                    });
                }
            }
            // All vertices inside the face's plane (convex solid, outward face).
            for (i, v) in vertices.iter().enumerate() {
                let distance = (v.coords - c).dot(&n);
                if distance > tolerance {
                    return Err(Error::PolyhedronNotConvex {
                        face: f,
                        vertex: i,
                        distance,
                        tolerance,
                    });
                }
            }
        }
        let mut triangles = Vec::new();
        let mut triangle_faces = Vec::new();
        for (f, face) in faces.iter().enumerate() {
            for k in 1..face.len() - 1 {
                triangles.push([face[0] as u32, face[k] as u32, face[k + 1] as u32]);
                triangle_faces.push(f);
            }
        }
        Ok(ConvexPolyhedron {
            vertices,
            faces,
            edges,
            triangles,
            triangle_faces,
        })
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point3<f64>] {
        &self.vertices
    }

    /// The faces: vertex indices, counter-clockwise seen from outside.
    pub fn faces(&self) -> &[Vec<usize>] {
        &self.faces
    }

    /// The fan triangulation of the faces: face `[v0, v1, ..., vk]` gives the triangles
    /// `[v0, vi, vi+1]`, in face order, counter-clockwise seen from outside.
    /// [`triangle_faces`](Self::triangle_faces) maps each triangle to its face.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// For each triangle of [`triangles`](Self::triangles), the index of the face it is part of.
    pub fn triangle_faces(&self) -> &[usize] {
        &self.triangle_faces
    }

    /// The triangle `i` of [`triangles`](Self::triangles) as three points.
    pub fn triangle(&self, i: usize) -> [Point3<f64>; 3] {
        let [a, b, c] = self.triangles[i];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// The fan triangulation as a [`TriMesh`] (same vertices, triangles in the order of
    /// [`triangles`](Self::triangles)).
    pub fn to_trimesh(&self) -> TriMesh {
        // A validated polyhedron has finite vertices, at least 4 triangles and valid indices,
        // which is everything `TriMesh::new` checks.
        TriMesh::new(self.vertices.clone(), self.triangles.clone())
            .expect("a validated polyhedron is a valid mesh")
    }

    /// Number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.vertices.len()
    }

    /// Number of edges.
    pub fn num_edges(&self) -> usize {
        self.edges
    }

    /// Number of faces.
    pub fn num_faces(&self) -> usize {
        self.faces.len()
    }

    /// The outward unit normal of face `f` (Newell's method).
    pub fn face_normal(&self, f: usize) -> Vector3<f64> {
        newell_normal(&self.vertices, &self.faces[f]).normalize()
    }

    /// The volume (divergence theorem over the fan triangles).
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize].coords);
                a.dot(&b.cross(&c))
            })
            .sum::<f64>()
            / 6.0
    }

    /// The largest distance of a vertex from the origin.
    pub fn max_vertex_norm(&self) -> f64 {
        self.vertices
            .iter()
            .map(|v| v.coords.norm())
            .fold(0.0, f64::max)
    }

    /// The cube `[-s, s]³` with circumradius 1 (`s = 1/√3`): 8 vertices, 12 edges, 6 faces.
    pub fn cube() -> Self {
        let mut v = Vec::new();
        for i in 0..8 {
            let s = |bit: usize| if i & bit != 0 { 1.0 } else { -1.0 };
            v.push([s(1), s(2), s(4)]);
        }
        let normals = [
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ];
        from_vertices_and_normals(&v, &normals)
    }

    /// The regular octahedron with vertices `±e_i` (circumradius 1): 6 vertices, 12 edges,
    /// 8 faces.
    pub fn octahedron() -> Self {
        let v = signed_even_permutations([1.0, 0.0, 0.0]);
        let normals = signed_even_permutations([1.0, 1.0, 1.0]);
        from_vertices_and_normals(&v, &normals)
    }

    /// The truncated octahedron ("troctaedro"): the permutations of `(0, ±1, ±2)` scaled by
    /// `1/√5`; 24 vertices, 36 edges, 14 faces (6 squares, 8 regular hexagons).
    pub fn truncated_octahedron() -> Self {
        let mut v = signed_even_permutations([0.0, 1.0, 2.0]);
        v.extend(signed_even_permutations([0.0, 2.0, 1.0]));
        let mut normals = signed_even_permutations([1.0, 0.0, 0.0]);
        normals.extend(signed_even_permutations([1.0, 1.0, 1.0]));
        from_vertices_and_normals(&v, &normals)
    }

    /// The paper's "Rh": the great rhombicosidodecahedron, also called the truncated
    /// icosidodecahedron ([`truncated_icosidodecahedron`](Self::truncated_icosidodecahedron)).
    pub fn rh() -> Self {
        Self::truncated_icosidodecahedron()
    }

    /// The truncated icosidodecahedron (great rhombicosidodecahedron): the even permutations
    /// with all sign changes of `(1/φ, 1/φ, 3+φ)`, `(2/φ, φ, 1+2φ)`, `(1/φ, φ², 3φ-1)`,
    /// `(2φ-1, 2, 2+φ)`, `(φ, 3, 2φ)`, scaled to circumradius 1; 120 vertices, 180 edges,
    /// 62 faces (30 squares, 20 hexagons, 12 decagons).
    pub fn truncated_icosidodecahedron() -> Self {
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        let mut v = Vec::new();
        for base in [
            [1.0 / phi, 1.0 / phi, 3.0 + phi],
            [2.0 / phi, phi, 1.0 + 2.0 * phi],
            [1.0 / phi, phi * phi, 3.0 * phi - 1.0],
            [2.0 * phi - 1.0, 2.0, 2.0 + phi],
            [phi, 3.0, 2.0 * phi],
        ] {
            v.extend(signed_even_permutations(base));
        }
        // Squares: icosidodecahedron directions; hexagons: dodecahedron vertices; decagons:
        // icosahedron vertices.
        let mut normals = signed_even_permutations([0.0, 0.0, phi]);
        normals.extend(signed_even_permutations([0.5, phi / 2.0, phi * phi / 2.0]));
        normals.extend(signed_even_permutations([1.0, 1.0, 1.0]));
        normals.extend(signed_even_permutations([0.0, 1.0 / phi, phi]));
        normals.extend(signed_even_permutations([0.0, phi, 1.0]));
        from_vertices_and_normals(&v, &normals)
    }

    /// A round-brilliant-like gem with the paper's counts (41 vertices, 88 edges, 49 faces).
    ///
    /// Proportions, in units of the girdle radius (then scaled to circumradius 1): a regular
    /// octagonal table of circumradius 0.56 (a 56 % table), a crown 0.30 high (crown angle
    /// ≈ 34.3°, crown height 15 % of the diameter), a girdle band 0.06 thick (3 %), and a pavilion
    /// 0.862 deep ending in a culet vertex (pavilion angle ≈ 40.8°, depth 43 %). Vertices: the
    /// 8 table corners, two 16-vertex girdle rings (above and below the girdle band, at angles
    /// `k·22.5°`), the culet. Faces: the table (1 octagon); the crown's 8 triangles (a table
    /// corner and a girdle edge below it) and 8 isosceles trapezoids (a table edge and the
    /// parallel girdle edge); the girdle band's 16 rectangles; the pavilion's 16 triangles to
    /// the culet. The crown is the convex hull of the table and the upper girdle ring. The
    /// smallest enclosing sphere is centred at the middle of the girdle band (the origin)
    /// and passes through all 32 girdle vertices.
    pub fn diamond() -> Self {
        use std::f64::consts::PI;
        let (table, crown, girdle, pavilion) = (0.56, 0.30, 0.06, 0.862);
        let step = PI / 8.0;
        let mut v = Vec::new();
        // Table corners T_k at the middle angle of girdle vertices 2k, 2k+1.
        for k in 0..8 {
            let a = (2 * k) as f64 * step + step / 2.0;
            v.push([table * a.cos(), table * a.sin(), girdle / 2.0 + crown]);
        }
        for z in [girdle / 2.0, -girdle / 2.0] {
            for j in 0..16 {
                let a = j as f64 * step;
                v.push([a.cos(), a.sin(), z]);
            }
        }
        v.push([0.0, 0.0, -girdle / 2.0 - pavilion]);
        let t = |k: usize| k % 8;
        let up = |j: usize| 8 + j % 16;
        let lo = |j: usize| 24 + j % 16;
        let culet = 40;
        let mut faces = Vec::new();
        // Table, counter-clockwise seen from above.
        faces.push((0..8).collect::<Vec<_>>());
        for k in 0..8 {
            faces.push(vec![t(k), up(2 * k), up(2 * k + 1)]);
            faces.push(vec![t(k), up(2 * k + 1), up(2 * k + 2), t(k + 1)]);
        }
        for j in 0..16 {
            faces.push(vec![up(j), lo(j), lo(j + 1), up(j + 1)]);
            faces.push(vec![lo(j), culet, lo(j + 1)]);
        }
        let r = (1.0 + (girdle / 2.0) * (girdle / 2.0)).sqrt();
        let vertices = v
            .iter()
            .map(|p| Point3::new(p[0] / r, p[1] / r, p[2] / r))
            .collect();
        Self::new(vertices, faces).expect("the diamond is a valid convex polyhedron")
    }

    /// The solid of a name, case-insensitive: `cube`; `octahedron`; `truncated_octahedron`,
    /// `troctahedron`, `troct`; `rh`, `truncated_icosidodecahedron`,
    /// `great_rhombicosidodecahedron`; `diamond` (`-` and `_` are interchangeable).
    pub fn by_name(name: &str) -> Result<Self, Error> {
        match name.to_ascii_lowercase().replace('-', "_").as_str() {
            "cube" => Ok(Self::cube()),
            "octahedron" => Ok(Self::octahedron()),
            "truncated_octahedron" | "troctahedron" | "troct" => Ok(Self::truncated_octahedron()),
            "rh" | "truncated_icosidodecahedron" | "great_rhombicosidodecahedron" => {
                Ok(Self::truncated_icosidodecahedron())
            }
            "diamond" => Ok(Self::diamond()),
            _ => Err(Error::UnknownPolyhedron {
                name: name.to_owned(),
            }),
        }
    }

    /// The names [`by_name`](Self::by_name) knows, one per solid (in Table 1's order: cube,
    /// octahedron, diamond, Rh, truncated octahedron).
    pub const NAMES: [&'static str; 5] = [
        "cube",
        "octahedron",
        "diamond",
        "rh",
        "truncated_octahedron",
    ];
}

/// All even (cyclic) permutations of `p` with every sign change, without duplicates.
fn signed_even_permutations(p: [f64; 3]) -> Vec<[f64; 3]> {
    let mut out: Vec<[f64; 3]> = Vec::new();
    for shift in 0..3 {
        let q = [p[shift], p[(shift + 1) % 3], p[(shift + 2) % 3]];
        for signs in 0..8 {
            let s = |k: usize| if signs & (1 << k) != 0 { -q[k] } else { q[k] };
            let r = [s(0), s(1), s(2)];
            if !out.contains(&r) {
                out.push(r);
            }
        }
    }
    out
}

/// The convex polyhedron with the given vertices whose faces have the given outward normals:
/// each face is the set of vertices maximising `n·v`, ordered counter-clockwise about `n`;
/// then scaled to circumradius 1 (the vertex sets used are symmetric about the origin, so the
/// smallest enclosing sphere is centred there).
fn from_vertices_and_normals(v: &[[f64; 3]], normals: &[[f64; 3]]) -> ConvexPolyhedron {
    let r = v
        .iter()
        .map(|p| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt())
        .fold(0.0, f64::max);
    let vertices: Vec<Point3<f64>> = v
        .iter()
        .map(|p| Point3::new(p[0] / r, p[1] / r, p[2] / r))
        .collect();
    let faces = normals
        .iter()
        .map(|n| {
            let n = Vector3::new(n[0], n[1], n[2]).normalize();
            let top = vertices
                .iter()
                .map(|p| p.coords.dot(&n))
                .fold(f64::NEG_INFINITY, f64::max);
            let members: Vec<usize> = (0..vertices.len())
                .filter(|&i| vertices[i].coords.dot(&n) > top - 1e-9)
                .collect();
            order_ccw(&vertices, members, &n)
        })
        .collect();
    ConvexPolyhedron::new(vertices, faces).expect("built-in polyhedron is valid")
}

/// Orders the vertices of a convex planar polygon counter-clockwise about `n`.
pub(crate) fn order_ccw(
    vertices: &[Point3<f64>],
    mut members: Vec<usize>,
    n: &Vector3<f64>,
) -> Vec<usize> {
    let c = members
        .iter()
        .map(|&i| vertices[i].coords)
        .sum::<Vector3<f64>>()
        / members.len() as f64;
    let e1 = {
        let a = if n.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::y()
        };
        (a - n * a.dot(n)).normalize()
    };
    let e2 = n.cross(&e1);
    let angle = |i: usize| {
        let d = vertices[i].coords - c;
        d.dot(&e2).atan2(d.dot(&e1))
    };
    members.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
    members
}
