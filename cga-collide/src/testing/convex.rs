//! An exact and fast intersection test for two convex solids given as closed triangle meshes.
//!
//! This is the independent reference of the double-sphere experiment
//! (`cga-experiment double-spheres`, of the unpublished `cga-experiments` package): every answer of the sphere hierarchy is checked against it. It
//! shares nothing with the hierarchy but the exact predicates. It is test support (feature
//! `testing`): the library's own answer for meshes is [`Collider::collides_solid`].
//!
//! The ground truth is the closed solid bounded by the given triangles (touching counts as
//! intersecting), with the vertices exactly as given: after a rigid motion in `f64` the faces
//! of a polyhedron are no longer exactly planar, so "the polyhedron" means these triangles.
//!
//! [`ConvexMeshRef::collides_solid`] runs GJK (Gilbert–Johnson–Keerthi) on the Minkowski difference
//! `A - B` in `f64` and then *certifies* what it found, so that rounding can never make the
//! answer wrong:
//!
//! * **Separated**: a direction `d` with `max_{a∈A} d·a < min_{b∈B} d·b` beyond a rigorous
//!   bound on the rounding of the dot products. Each solid lies in the convex hull of its
//!   vertices, so the solids are disjoint.
//! * **Common point**: a point `x` (built from the terminal GJK simplex) that lies strictly on
//!   the inner side of every triangle of both meshes, by exact `orient3d` signs. Then every
//!   triangle is seen from `x` with a positive solid angle, so the winding number of each closed
//!   surface around `x` is positive: `x` is inside both solids.
//! * **Exhaustive**: when neither certificate is obtained (touching or nearly touching solids,
//!   a degenerate simplex), the exact mesh test [`Collider::collides_solid`] decides: every
//!   triangle pair by the exact triangle test, then containment by exact point-in-mesh.
//!
//! The first two are cheap (about a microsecond for a 120-vertex polyhedron); the fall-back is
//! rare on random placements, and the experiment reports how often it ran.
//!
//! ```
//! use cga_collide::testing::convex::ConvexMeshRef;
//! use nalgebra::Point3;
//!
//! // A unit cube and the same cube moved by (0.5, 0.5, 0.5): they overlap.
//! let corners = |o: f64| -> Vec<Point3<f64>> {
//!     (0..8)
//!         .map(|i| Point3::new(o + (i & 1) as f64, o + ((i >> 1) & 1) as f64, o + ((i >> 2) & 1) as f64))
//!         .collect()
//! };
//! // Outward-facing triangles of the cube with vertices numbered by the bits (x, y, z).
//! let tris: Vec<[u32; 3]> = vec![
//!     [0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
//!     [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5],
//! ];
//! let (a, b, c) = (corners(0.0), corners(0.5), corners(1.5));
//! let (a, b, c) = (
//!     ConvexMeshRef::new(&a, &tris)?,
//!     ConvexMeshRef::new(&b, &tris)?,
//!     ConvexMeshRef::new(&c, &tris)?,
//! );
//! assert!(a.collides_solid(&b).intersect);
//! assert!(!a.collides_solid(&c).intersect);
//! # Ok::<(), cga_collide::Error>(())
//! ```

use crate::exact::vector::{cross, dot, neg, sub};
use std::cmp::Ordering;

use nalgebra::Point3;

use crate::collider::Collider;
use crate::error::Error;
use crate::exact::ExactPlane;
use crate::shape::mesh::TriMesh;
use crate::{Intersects, Triangle};

/// A borrowed closed triangle mesh bounding a convex solid, triangles counter-clockwise seen
/// from outside.
///
/// Convexity and closedness are the caller's promise (they are what makes the certificates of
/// [`ConvexMeshRef::collides_solid`] valid); [`ConvexMeshRef::new`] checks the cheap invariants.
#[derive(Debug, Clone, Copy)]
pub struct ConvexMeshRef<'a> {
    vertices: &'a [Point3<f64>],
    triangles: &'a [[u32; 3]],
}

impl ConvexMeshRef<'_> {
    /// Whether the closed convex solids `self` and `other` share a point (touching counts),
    /// exactly, with the certificate that decided it (see the module docs).
    pub fn collides_solid(&self, other: &ConvexMeshRef<'_>) -> Verdict {
        convex_solids_intersect(self, other)
    }
}

impl<'a> ConvexMeshRef<'a> {
    /// Borrows a mesh, checking that it has triangles, that its coordinates are finite and
    /// that its indices are in range.
    pub fn new(vertices: &'a [Point3<f64>], triangles: &'a [[u32; 3]]) -> Result<Self, Error> {
        // TriMesh's checks, without copying: build a tiny mesh only when something is wrong.
        let bad_vertex = vertices
            .iter()
            .any(|v| v.coords.iter().any(|c| !c.is_finite()));
        let bad_index = triangles
            .iter()
            .any(|t| t.iter().any(|&i| i as usize >= vertices.len()));
        if triangles.is_empty() || bad_vertex || bad_index {
            TriMesh::new(vertices.to_vec(), triangles.to_vec())?;
        }
        Ok(ConvexMeshRef {
            vertices,
            triangles,
        })
    }

    /// The same triangles over other vertices (e.g. the same solid in another pose): only the
    /// vertex count and finiteness are checked, the triangles were checked by `new`.
    pub fn with_vertices<'b>(&self, vertices: &'b [Point3<f64>]) -> Result<ConvexMeshRef<'b>, Error>
    where
        'a: 'b,
    {
        if vertices.len() != self.vertices.len()
            || vertices
                .iter()
                .any(|v| !(v.x.is_finite() && v.y.is_finite() && v.z.is_finite()))
        {
            return ConvexMeshRef::new(vertices, self.triangles).and_then(|m| {
                if vertices.len() == self.vertices.len() {
                    Ok(m)
                } else {
                    Err(Error::Empty {
                        file: format!(
                            "<memory: {} vertices given for a mesh of {}>",
                            vertices.len(),
                            self.vertices.len()
                        ),
                    })
                }
            });
        }
        Ok(ConvexMeshRef {
            vertices,
            triangles: self.triangles,
        })
    }

    /// The vertices.
    pub fn vertices(&self) -> &'a [Point3<f64>] {
        self.vertices
    }

    /// The triangles (indices into [`vertices`](Self::vertices)).
    pub fn triangles(&self) -> &'a [[u32; 3]] {
        self.triangles
    }
}

/// How [`ConvexMeshRef::collides_solid`] reached its answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Certificate {
    /// A certified separating direction was found: disjoint.
    Separated,
    /// A point certified to lie inside both solids was found: intersecting.
    CommonPoint,
    /// Neither certificate was obtained; the exhaustive exact mesh test decided.
    Exhaustive,
}

/// The answer of [`ConvexMeshRef::collides_solid`] and how it was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Verdict {
    /// Whether the closed solids share at least one point.
    pub intersect: bool,
    /// Which certificate decided.
    pub certificate: Certificate,
}

/// Whether two closed convex solids, bounded by the given triangle meshes, intersect (exact;
/// touching counts). See the [module documentation](self) for how it is certified.
fn convex_solids_intersect(a: &ConvexMeshRef<'_>, b: &ConvexMeshRef<'_>) -> Verdict {
    match gjk(a.vertices, b.vertices) {
        Gjk::Separated => Verdict {
            intersect: false,
            certificate: Certificate::Separated,
        },
        Gjk::Overlap(points) => {
            let inside = |x: &[f64; 3]| strictly_inside(a, x) && strictly_inside(b, x);
            let (ca, cb) = (centroid(a.vertices), centroid(b.vertices));
            // Most often the midpoint of the two GJK points is inside both (95 % of the
            // overlaps of the truncated octahedron and Rh); then the relaxation.
            let found = points[2].as_ref().is_some_and(inside)
                || relaxed_candidate(&points, a, b).is_some_and(|x| inside(&x))
                || points[..2].iter().flatten().any(inside)
                || interior_candidates(&points, ca, cb).any(|x| inside(&x))
                || vertex_candidates(a, b, ca).any(|x| inside(&x))
                || vertex_candidates(b, a, cb).any(|x| inside(&x))
                || surfaces_meet_near(&points, a, b);
            if found {
                Verdict {
                    intersect: true,
                    certificate: Certificate::CommonPoint,
                }
            } else {
                exhaustive(a, b)
            }
        }
        Gjk::Undecided => exhaustive(a, b),
    }
}

/// The exact mesh test: surfaces by exact triangle tests, then containment.
fn exhaustive(a: &ConvexMeshRef<'_>, b: &ConvexMeshRef<'_>) -> Verdict {
    let collider = |m: &ConvexMeshRef<'_>| {
        // ConvexMeshRef::new checked exactly what TriMesh::new checks.
        TriMesh::new(m.vertices.to_vec(), m.triangles.to_vec())
            .map(Collider::new)
            .expect("ConvexMeshRef invariants are TriMesh's")
    };
    Verdict {
        intersect: collider(a).collides_solid(&collider(b)),
        certificate: Certificate::Exhaustive,
    }
}

/// Whether `x` is certainly strictly on the inner side of every triangle: the semi-static
/// `orient3d` filter must certify each sign (an uncertain sign counts as "no", which is safe
/// here and avoids exact arithmetic for the many candidates that sit on a face).
fn strictly_inside(m: &ConvexMeshRef<'_>, x: &[f64; 3]) -> bool {
    m.triangles.iter().all(|t| {
        let p = t.map(|i| m.vertices[i as usize].coords.into());
        ExactPlane::new(&p).filtered_side(x) == Some(Ordering::Less)
    })
}

/// The vertex average (an interior point of a non-degenerate convex polytope).
fn centroid(points: &[Point3<f64>]) -> [f64; 3] {
    let n = points.len() as f64;
    let s = points
        .iter()
        .fold([0.0; 3], |s, p| [s[0] + p.x, s[1] + p.y, s[2] + p.z]);
    s.map(|c| c / n)
}

/// Candidate interior points of `A ∩ B`, most likely first. The GJK points lie in both closed
/// solids up to rounding but often on the boundary of one (when its support points repeat a
/// vertex); moving a point of `A ∩ B` a little towards an interior point of either solid keeps
/// it in that solid's interior and, for a small enough step, in the other's. The exact test
/// decides whether a candidate really works, so the list only has to be good, not right.
fn interior_candidates(
    points: &[Option<[f64; 3]>; 3],
    ca: [f64; 3],
    cb: [f64; 3],
) -> impl Iterator<Item = [f64; 3]> + '_ {
    let mid = [
        0.5 * (ca[0] + cb[0]),
        0.5 * (ca[1] + cb[1]),
        0.5 * (ca[2] + cb[2]),
    ];
    const STEPS: [f64; 4] = [1e-6, 1e-3, 0.05, 0.3];
    points.iter().flatten().flat_map(move |x| {
        STEPS.iter().flat_map(move |&t| {
            [ca, cb, mid].into_iter().map(move |c| {
                [
                    x[0] + t * (c[0] - x[0]),
                    x[1] + t * (c[1] - x[1]),
                    x[2] + t * (c[2] - x[2]),
                ]
            })
        })
    })
}

/// A point pushed into both solids by cyclic projections onto their face half-spaces, each
/// moved inwards by a small depth (the relaxation method of Agmon, Motzkin and Schoenberg):
/// from a point near `A ∩ B`, it finds a point at that depth inside both whenever the
/// intersection is thicker than twice the depth. Plain `f64`; the caller checks the result
/// exactly.
fn relaxed_candidate(
    points: &[Option<[f64; 3]>; 3],
    a: &ConvexMeshRef<'_>,
    b: &ConvexMeshRef<'_>,
) -> Option<[f64; 3]> {
    let mut x = points[2]?;
    let half_spaces: Vec<([f64; 3], [f64; 3])> = [a, b]
        .iter()
        .flat_map(|m| {
            m.triangles.iter().filter_map(|t| {
                let [p, q, r] = t.map(|i| -> [f64; 3] { m.vertices[i as usize].coords.into() });
                let n = cross(&sub(&q, &p), &sub(&r, &p));
                let len = dot(&n, &n).sqrt();
                (len > 0.0).then(|| (n.map(|c| c / len), p))
            })
        })
        .collect();
    let scale = magnitude(a.vertices)
        .max(magnitude(b.vertices))
        .max(f64::MIN_POSITIVE);
    let depth = 1e-9 * scale;
    for _ in 0..60 {
        let mut moved = false;
        for (n, p) in &half_spaces {
            let excess = dot(n, &sub(&x, p)) + depth;
            if excess > 0.0 {
                // Project onto the plane at twice the depth so the point does not sit on it.
                let step = excess + depth;
                x = [x[0] - step * n[0], x[1] - step * n[1], x[2] - step * n[2]];
                moved = true;
            }
        }
        if !moved {
            return Some(x);
        }
    }
    None
}

/// Whether a triangle of `A` and a triangle of `B` that both pass near the GJK point meet
/// (exact triangle test). This certifies the thin overlaps where no interior point is found
/// quickly: there the GJK point lies on both surfaces, and the faces through it intersect.
fn surfaces_meet_near(
    points: &[Option<[f64; 3]>; 3],
    a: &ConvexMeshRef<'_>,
    b: &ConvexMeshRef<'_>,
) -> bool {
    let Some(x) = points[2] else {
        return false;
    };
    let scale = magnitude(a.vertices).max(magnitude(b.vertices));
    let tol = 1e-6 * scale.max(f64::MIN_POSITIVE);
    let near = |m: &ConvexMeshRef<'_>| -> Vec<Triangle> {
        m.triangles
            .iter()
            .filter_map(|t| {
                let p = t.map(|i| m.vertices[i as usize]);
                let lo = p[0].coords.inf(&p[1].coords).inf(&p[2].coords);
                let hi = p[0].coords.sup(&p[1].coords).sup(&p[2].coords);
                let in_box = (0..3).all(|k| lo[k] - tol <= x[k] && x[k] <= hi[k] + tol);
                let n = (p[1] - p[0]).cross(&(p[2] - p[0]));
                let len = n.norm();
                let close = len > 0.0 && (n.dot(&(Point3::from(x) - p[0])) / len).abs() <= tol;
                if in_box && close {
                    Triangle::new(p[0], p[1], p[2]).ok()
                } else {
                    None
                }
            })
            .collect()
    };
    let (ta, tb) = (near(a), near(b));
    ta.iter().any(|s| tb.iter().any(|t| s.intersects(t)))
}

/// The vertices of one solid that lie strictly inside the other (given by its `planes`),
/// moved slightly towards their own solid's interior point `c` so that they leave their own
/// boundary. This catches the overlaps where the GJK points sit on both boundaries.
fn vertex_candidates<'p>(
    own: &'p ConvexMeshRef<'p>,
    other: &'p ConvexMeshRef<'p>,
    c: [f64; 3],
) -> impl Iterator<Item = [f64; 3]> + 'p {
    own.vertices
        .iter()
        .map(|v| -> [f64; 3] { v.coords.into() })
        .filter(move |v| strictly_inside(other, v))
        .flat_map(move |v| {
            [1e-9, 1e-6, 1e-3].map(|t| {
                [
                    v[0] + t * (c[0] - v[0]),
                    v[1] + t * (c[1] - v[1]),
                    v[2] + t * (c[2] - v[2]),
                ]
            })
        })
}

/// A vertex of the Minkowski difference `A - B` and the vertices it came from.
#[derive(Debug, Clone, Copy)]
struct SupportPoint {
    w: [f64; 3],
    a: [f64; 3],
    b: [f64; 3],
}

enum Gjk {
    Separated,
    /// The origin is inside a tetrahedron of `A - B`: candidate common points.
    Overlap([Option<[f64; 3]>; 3]),
    Undecided,
}

const MAX_ITERATIONS: usize = 64;

/// Unit roundoff of `f64`.
const U: f64 = f64::EPSILON / 2.0;

/// `(u × v) × u`: the component of `v` orthogonal to `u`, scaled.
fn triple(u: &[f64; 3], v: &[f64; 3]) -> [f64; 3] {
    cross(&cross(u, v), u)
}

/// The vertex of `points` with the largest `d·p`, and that value.
fn extreme(points: &[Point3<f64>], d: &[f64; 3]) -> ([f64; 3], f64) {
    let mut best = (points[0].coords.into(), f64::NEG_INFINITY);
    for p in points {
        let p: [f64; 3] = p.coords.into();
        let s = dot(d, &p);
        if s > best.1 {
            best = (p, s);
        }
    }
    best
}

/// The largest absolute coordinate.
fn magnitude(points: &[Point3<f64>]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.coords.iter())
        .fold(0.0f64, |m, c| m.max(c.abs()))
}

/// Runs boolean GJK. `Separated` is certified; `Overlap` still needs its common point checked.
fn gjk(a: &[Point3<f64>], b: &[Point3<f64>]) -> Gjk {
    if a.is_empty() || b.is_empty() {
        return Gjk::Undecided;
    }
    let scale = magnitude(a).max(magnitude(b));
    if scale.is_nan() || scale >= 1e100 {
        // The barycentric determinants (cubes of coordinates) could overflow: leave it to the
        // exact test.
        return Gjk::Undecided;
    }
    let support = |d: &[f64; 3]| -> (SupportPoint, f64, f64) {
        let (pa, sa) = extreme(a, d);
        let (pb, sb) = extreme(b, &neg(d));
        (
            SupportPoint {
                w: sub(&pa, &pb),
                a: pa,
                b: pb,
            },
            sa,
            -sb,
        )
    };
    // `d` always points from the current simplex towards the origin; the support point of
    // `A - B` along `d` is `s_A(d) - s_B(-d)`. Start along the line between the vertex
    // averages: most separated pairs are certified by this first direction.
    let mut d = sub(&centroid(b), &centroid(a));
    if d == [0.0; 3] || d.iter().any(|c| !c.is_finite()) {
        d = [1.0, 0.0, 0.0];
    }
    let mut simplex: Vec<SupportPoint> = Vec::with_capacity(4);
    for _ in 0..MAX_ITERATIONS {
        let (s, max_a, min_b) = support(&d);
        // Separation along d: max_A d·a < min_B d·b. Each computed dot product errs by at most
        // γ₃ Σ|d_i||p_i| ≤ 4u |d|₁ scale (plus an underflow allowance).
        let err = 4.0 * U * (d[0].abs() + d[1].abs() + d[2].abs()) * scale + 1e-300;
        if max_a + err < min_b - err {
            return Gjk::Separated;
        }
        if dot(&s.w, &d) <= 0.0 {
            // GJK would stop (the origin is beyond the support plane) but the separation is
            // within rounding: the solids nearly touch.
            return Gjk::Undecided;
        }
        simplex.push(s);
        match step(&mut simplex) {
            Step::Continue(next) => {
                if next == [0.0; 3] || next.iter().any(|c| !c.is_finite()) {
                    return Gjk::Undecided;
                }
                d = next;
            }
            Step::ContainsOrigin => return Gjk::Overlap(common_points(&simplex)),
        }
    }
    Gjk::Undecided
}

enum Step {
    /// Search on in this direction (from the kept sub-simplex towards the origin).
    Continue([f64; 3]),
    /// The tetrahedron contains the origin.
    ContainsOrigin,
}

/// The classic boolean GJK simplex update (the newest point last): keeps the sub-simplex
/// nearest the origin and returns the direction from it towards the origin. The direction is
/// rescaled so that its largest component is 1 (any positive multiple is as good, and this
/// keeps the triple products from overflowing or underflowing).
fn step(simplex: &mut Vec<SupportPoint>) -> Step {
    let towards = match simplex.len() {
        1 => neg(&simplex[0].w),
        2 => line(simplex),
        3 => triangle(simplex),
        _ => match tetrahedron(simplex) {
            Some(dir) => dir,
            None => return Step::ContainsOrigin,
        },
    };
    let m = towards.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if m > 0.0 && m.is_finite() {
        Step::Continue(towards.map(|c| c / m))
    } else {
        Step::Continue([0.0; 3])
    }
}

/// Simplex `[B, A]`, A newest: the direction towards the origin.
fn line(s: &mut Vec<SupportPoint>) -> [f64; 3] {
    let (a, b) = (s[1].w, s[0].w);
    let ab = sub(&b, &a);
    let ao = neg(&a);
    if dot(&ab, &ao) > 0.0 {
        triple(&ab, &ao)
    } else {
        s.remove(0);
        ao
    }
}

/// Simplex `[C, B, A]`, A newest.
fn triangle(s: &mut Vec<SupportPoint>) -> [f64; 3] {
    let (a, b, c) = (s[2].w, s[1].w, s[0].w);
    let ab = sub(&b, &a);
    let ac = sub(&c, &a);
    let ao = neg(&a);
    let abc = cross(&ab, &ac);
    if dot(&cross(&abc, &ac), &ao) > 0.0 {
        if dot(&ac, &ao) > 0.0 {
            // Keep [C, A].
            s.remove(1);
            triple(&ac, &ao)
        } else {
            // Keep [B, A] and treat it as a line.
            s.remove(0);
            line(s)
        }
    } else if dot(&cross(&ab, &abc), &ao) > 0.0 {
        s.remove(0);
        line(s)
    } else if dot(&abc, &ao) > 0.0 {
        abc
    } else {
        // The origin is below: flip the winding so the normal faces it.
        s.swap(0, 1);
        neg(&abc)
    }
}

/// Simplex `[D, C, B, A]`, A newest: `None` when the origin is inside.
fn tetrahedron(s: &mut Vec<SupportPoint>) -> Option<[f64; 3]> {
    let (a, b, c, d) = (s[3].w, s[2].w, s[1].w, s[0].w);
    let ao = neg(&a);
    let ab = sub(&b, &a);
    let ac = sub(&c, &a);
    let ad = sub(&d, &a);
    // Outward normals of the three faces through A (the face BCD was tested last step).
    let faces = [
        (cross(&ab, &ac), ad, [2, 1]), // ABC, away from D: keep [C, B, A]
        (cross(&ac, &ad), ab, [1, 0]), // ACD, away from B: keep [D, C, A]
        (cross(&ad, &ab), ac, [0, 2]), // ADB, away from C: keep [B, D, A]
    ];
    for (normal, other, keep) in faces {
        let normal = if dot(&normal, &other) > 0.0 {
            neg(&normal)
        } else {
            normal
        };
        if dot(&normal, &ao) > 0.0 {
            let newest = s[3];
            let kept = [s[keep[0]], s[keep[1]]];
            s.clear();
            s.extend_from_slice(&kept);
            s.push(newest);
            return Some(triangle(s));
        }
    }
    None
}

/// Points that should lie in both solids when the tetrahedron `s` of `A - B` contains the
/// origin: with the barycentric coordinates `λ` of the origin, `Σ λ_k a_k` (in A) equals
/// `Σ λ_k b_k` (in B) up to rounding; their midpoint is the third candidate.
fn common_points(s: &[SupportPoint]) -> [Option<[f64; 3]>; 3] {
    let w = |k: usize| s[k].w;
    let det = |p: [f64; 3], q: [f64; 3], r: [f64; 3], t: [f64; 3]| {
        dot(&cross(&sub(&q, &p), &sub(&r, &p)), &sub(&t, &p))
    };
    let o = [0.0; 3];
    let total = det(w(0), w(1), w(2), w(3));
    if total == 0.0 || !total.is_finite() {
        return [None; 3];
    }
    let lambda = [
        det(o, w(1), w(2), w(3)) / total,
        det(w(0), o, w(2), w(3)) / total,
        det(w(0), w(1), o, w(3)) / total,
        det(w(0), w(1), w(2), o) / total,
    ];
    let combine = |pick: fn(&SupportPoint) -> [f64; 3]| {
        let mut x = [0.0; 3];
        for (k, l) in lambda.iter().enumerate() {
            let p = pick(&s[k]);
            for i in 0..3 {
                x[i] += l * p[i];
            }
        }
        x
    };
    let xa = combine(|p| p.a);
    let xb = combine(|p| p.b);
    let mid = [
        0.5 * (xa[0] + xb[0]),
        0.5 * (xa[1] + xb[1]),
        0.5 * (xa[2] + xb[2]),
    ];
    [Some(xa), Some(xb), Some(mid)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_and_bad_indices_are_rejected() {
        let v = vec![Point3::new(0.0, 0.0, 0.0); 3];
        assert!(ConvexMeshRef::new(&v, &[[0, 1, 3]]).is_err());
        assert!(ConvexMeshRef::new(&v, &[]).is_err());
        let nan = vec![Point3::new(f64::NAN, 0.0, 0.0); 3];
        assert!(ConvexMeshRef::new(&nan, &[[0, 1, 2]]).is_err());
    }
}
