//! Convex sub-polyhedra of a tree node and their clipping by a plane.
//!
//! A [`SubPolyhedron`] is a convex polyhedron (vertices, counter-clockwise faces) whose faces
//! remember where they come from: a part of an original face, or a cut made by a split plane.
//! [`SubPolyhedron::clip`] keeps the part on one side of a plane (vertices within a tolerance of
//! the plane are kept as they are and belong to both halves, so the two halves cover the
//! parent: their union contains it and they overlap in at most a tolerance-thin slab).

use std::collections::HashMap;

use nalgebra::{Matrix3, Point3, Vector3};

use crate::shape::polyhedron::{newell_normal, order_ccw, ConvexPolyhedron};

/// Where a face of a [`SubPolyhedron`] comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaceOrigin {
    /// A part of this face of the original polyhedron.
    Original(usize),
    /// A cut by a split plane.
    Cut,
}

/// A convex polyhedron obtained from an original one by cuts.
#[derive(Debug, Clone, PartialEq)]
pub struct SubPolyhedron {
    /// Vertices.
    pub vertices: Vec<Point3<f64>>,
    /// Faces as vertex indices, counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
    /// The origin of each face.
    pub origins: Vec<FaceOrigin>,
}

/// Relative tolerance (times the largest coordinate scale) for "on the plane" when clipping.
pub const CLIP_TOLERANCE: f64 = 1e-12;

impl SubPolyhedron {
    /// The whole polyhedron, every face original.
    pub fn from_polyhedron(p: &ConvexPolyhedron) -> Self {
        SubPolyhedron {
            vertices: p.vertices().to_vec(),
            faces: p.faces().to_vec(),
            origins: (0..p.num_faces()).map(FaceOrigin::Original).collect(),
        }
    }

    /// Fan triangulation of the faces.
    pub fn triangles(&self) -> Vec<[Point3<f64>; 3]> {
        let mut out = Vec::new();
        for f in &self.faces {
            for k in 1..f.len() - 1 {
                out.push([
                    self.vertices[f[0]],
                    self.vertices[f[k]],
                    self.vertices[f[k + 1]],
                ]);
            }
        }
        out
    }

    /// The volume (divergence theorem over the fan triangles).
    pub fn volume(&self) -> f64 {
        self.triangles()
            .iter()
            .map(|[a, b, c]| a.coords.dot(&b.coords.cross(&c.coords)))
            .sum::<f64>()
            / 6.0
    }

    /// The paper's centroid and covariance (eqs. 2–3), taken over the triangles of the faces
    /// (Gottschalk's form): with `n` triangles `p_i q_i r_i`, the mean
    /// `μ = (1/3n) Σ (p_i + q_i + r_i)` and `C = (1/3n) Σ (p̄ p̄ᵀ + q̄ q̄ᵀ + r̄ r̄ᵀ)`,
    /// `x̄ = x - μ`.
    pub fn centroid_and_covariance(&self) -> (Point3<f64>, Matrix3<f64>) {
        let tris = self.triangles();
        let n = (3 * tris.len()) as f64;
        let mu = tris
            .iter()
            .flat_map(|t| t.iter())
            .map(|p| p.coords)
            .sum::<Vector3<f64>>()
            / n;
        let mut c = Matrix3::zeros();
        for p in tris.iter().flat_map(|t| t.iter()) {
            let d = p.coords - mu;
            c += d * d.transpose();
        }
        (Point3::from(mu), c / n)
    }

    /// The planes of the faces: outward unit normal `n` and offset `d` (`n·x <= d` inside),
    /// `d` the largest `n·v` over the face's vertices (so that every vertex of the face is
    /// inside within rounding).
    pub fn planes(&self) -> Vec<(Vector3<f64>, f64)> {
        self.faces
            .iter()
            .map(|f| {
                let n = newell_normal(&self.vertices, f).normalize();
                let d = f
                    .iter()
                    .map(|&i| n.dot(&self.vertices[i].coords))
                    .fold(f64::NEG_INFINITY, f64::max);
                (n, d)
            })
            .collect()
    }

    fn scale(&self) -> f64 {
        self.vertices
            .iter()
            .map(|v| v.coords.amax())
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE)
    }

    /// The part with `n·x <= d` (`n` need not be unit), or `None` if no vertex is strictly
    /// (beyond the tolerance) on that side.
    pub fn clip(&self, n: &Vector3<f64>, d: f64) -> Option<SubPolyhedron> {
        let tol = CLIP_TOLERANCE * self.scale() * n.norm();
        let s: Vec<f64> = self.vertices.iter().map(|v| n.dot(&v.coords) - d).collect();
        if s.iter().all(|&x| x >= -tol) {
            return None;
        }
        let mut vertices = Vec::new();
        let mut map = vec![usize::MAX; self.vertices.len()];
        let mut on_plane = Vec::new();
        for (i, v) in self.vertices.iter().enumerate() {
            if s[i] <= tol {
                map[i] = vertices.len();
                if s[i] >= -tol {
                    on_plane.push(vertices.len());
                }
                vertices.push(*v);
            }
        }
        let mut cuts: HashMap<(usize, usize), usize> = HashMap::new();
        let mut faces = Vec::new();
        let mut origins = Vec::new();
        let mut coplanar_face = false;
        for (f, face) in self.faces.iter().enumerate() {
            let mut poly = Vec::new();
            for k in 0..face.len() {
                let (a, b) = (face[k], face[(k + 1) % face.len()]);
                if s[a] <= tol {
                    poly.push(map[a]);
                }
                let crosses = (s[a] < -tol && s[b] > tol) || (s[a] > tol && s[b] < -tol);
                if crosses {
                    let key = (a.min(b), a.max(b));
                    let idx = *cuts.entry(key).or_insert_with(|| {
                        let (p, q) = (self.vertices[key.0], self.vertices[key.1]);
                        let (sp, sq) = (s[key.0], s[key.1]);
                        let t = sp / (sp - sq);
                        vertices.push(p + (q - p) * t);
                        on_plane.push(vertices.len() - 1);
                        vertices.len() - 1
                    });
                    poly.push(idx);
                }
            }
            if poly.len() >= 3 {
                if face.iter().all(|&i| s[i].abs() <= tol) {
                    coplanar_face = true;
                }
                faces.push(poly);
                origins.push(self.origins[f]);
            }
        }
        if !coplanar_face && on_plane.len() >= 3 {
            faces.push(order_ccw(&vertices, on_plane, &n.normalize()));
            origins.push(FaceOrigin::Cut);
        }
        // Drop vertices no face uses (possible when only a tolerance-thin sliver was cut off).
        let mut used = vec![false; vertices.len()];
        for f in &faces {
            for &i in f {
                used[i] = true;
            }
        }
        if used.iter().all(|&u| u) {
            return Some(SubPolyhedron {
                vertices,
                faces,
                origins,
            });
        }
        let mut remap = vec![usize::MAX; vertices.len()];
        let mut kept = Vec::new();
        for (i, v) in vertices.iter().enumerate() {
            if used[i] {
                remap[i] = kept.len();
                kept.push(*v);
            }
        }
        for f in &mut faces {
            for i in f.iter_mut() {
                *i = remap[*i];
            }
        }
        Some(SubPolyhedron {
            vertices: kept,
            faces,
            origins,
        })
    }
}

/// Whether the convex polygon `poly` (e.g. a triangle) has a point with `n·x <= d + tol` for
/// every half-space `(n, d)` of `halfspaces` (Sutherland–Hodgman clipping with a tolerance:
/// a conservative "touches the region" test).
pub fn polygon_meets_halfspaces(
    poly: &[Point3<f64>],
    halfspaces: &[(Vector3<f64>, f64)],
    tol: f64,
) -> bool {
    let mut cur: Vec<Point3<f64>> = poly.to_vec();
    for (n, d) in halfspaces {
        if cur.is_empty() {
            return false;
        }
        let t = tol * n.norm();
        let s: Vec<f64> = cur.iter().map(|p| n.dot(&p.coords) - d).collect();
        if s.iter().all(|&x| x <= t) {
            continue;
        }
        let mut next = Vec::new();
        for k in 0..cur.len() {
            let j = (k + 1) % cur.len();
            if s[k] <= t {
                next.push(cur[k]);
            }
            if (s[k] <= t) != (s[j] <= t) {
                let r = (s[k] - t) / (s[k] - s[j]);
                next.push(cur[k] + (cur[j] - cur[k]) * r);
            }
        }
        cur = next;
    }
    !cur.is_empty()
}
