//! The collision test between two [`DoubleSphereTree`]s under rigid motions (the paper's
//! Algorithm 1 and 2, plus an exact containment test): [`DoubleSphereTree::collides_at`], whose
//! docs hold the rounding analysis.

use nalgebra::{Isometry3, Point3};

use super::DoubleSphereTree;
use crate::query::containment::point_in_solid;
use crate::{Intersects, Triangle};

/// How [`DoubleSphereTree::collides_at`] reached its answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Decision {
    /// No collision: every pair of nodes visited was rejected by the outer spheres (or by our
    /// supporting-face-plane test, or held no surface); no pair of external leaves reached
    /// Algorithm 2.
    OuterSpheres,
    /// Collision: two internal nodes' outer spheres meet.
    InternalLabels,
    /// Collision: two inner spheres meet.
    InnerSpheres,
    /// Collision: two original triangles meet (Algorithm 2).
    Faces,
    /// Collision: one solid lies inside the other without surface contact.
    Containment,
    /// No collision: some pair of external leaves reached Algorithm 2 (whose triangle pairs
    /// may all have been skipped by the exact prefilters) and no contact was found.
    NoContact,
}

/// The answer of [`DoubleSphereTree::collides_at`] with how it was reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outcome {
    /// Whether the two solids share a point (exact; touching counts).
    pub collides: bool,
    /// Which test decided.
    pub decided_by: Decision,
    /// Number of sphere–sphere comparisons made.
    pub sphere_tests: u32,
    /// Number of exact triangle–triangle tests made.
    pub triangle_tests: u32,
}

/// Per-tree cache of transformed centres and vertices for one query.
#[derive(Debug, Clone, Default)]
struct Cache {
    /// Per node: the query that last gathered this leaf's triangles into `gathered`.
    leaf_stamp: Vec<u32>,
    /// Transformed leaf triangles, indexed like the tree's leaf-triangle list.
    gathered: Vec<Gathered>,
    node_stamp: Vec<u32>,
    inner_stamp: Vec<u32>,
    outer: Vec<[f64; 3]>,
    inner: Vec<[f64; 3]>,
    vert_stamp: Vec<u32>,
    verts: Vec<[f64; 3]>,
}

impl Cache {
    fn prepare(&mut self, tree: &DoubleSphereTree) {
        let n = tree.nodes.len();
        if self.node_stamp.len() < n {
            self.node_stamp.resize(n, 0);
            self.leaf_stamp.resize(n, 0);
            self.inner_stamp.resize(n, 0);
            self.outer.resize(n, [0.0; 3]);
            self.inner.resize(n, [0.0; 3]);
        }
        let g = tree.leaf_triangles.len();
        if self.gathered.len() < g {
            self.gathered.resize(
                g,
                Gathered {
                    tri: None,
                    lo: [0.0; 3],
                    hi: [0.0; 3],
                },
            );
        }
        let v = tree.polyhedron.num_vertices();
        if self.vert_stamp.len() < v {
            self.vert_stamp.resize(v, 0);
            self.verts.resize(v, [0.0; 3]);
        }
    }
}

/// Reusable buffers for [`collide_with`], so that a query does not allocate.
#[derive(Debug, Clone, Default)]
pub(crate) struct Scratch {
    stamp: u32,
    a: Cache,
    b: Cache,
    stack: Vec<(u32, u32)>,
    tris_a: Vec<u32>,
    tris_b: Vec<u32>,
}

/// A transformed triangle with its bounding box (`None` triangle: a non-finite coordinate,
/// which denotes no point).
#[derive(Debug, Clone, Copy)]
struct Gathered {
    tri: Option<Triangle>,
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Scratch {
    /// Empty buffers (they grow on first use).
    pub(crate) fn new() -> Self {
        Self::default()
    }
}

#[inline(always)]
fn arr(p: &Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}

/// The rounding bound `ε` of [`DoubleSphereTree::collides_at`]'s docs for a pose and a largest
/// vertex norm.
pub(crate) fn transform_error_bound(pose: &Isometry3<f64>, vmax: f64) -> f64 {
    let q = pose.rotation.quaternion();
    let eta = (q.norm_squared() - 1.0).abs() + 1e-15;
    let tau = pose.translation.vector.norm() * 1.01;
    ((2.0 * eta + 1e-14) * vmax + 1e-15 * tau + 1e-290) * 1.01
}

/// One side of a query: the tree, its pose, its bound and its cache.
struct Side<'a> {
    tree: &'a DoubleSphereTree,
    pose: &'a Isometry3<f64>,
    eps: f64,
    cache: &'a mut Cache,
    stamp: u32,
}

impl Side<'_> {
    #[inline]
    fn fill(&mut self, i: usize) {
        if self.cache.node_stamp[i] != self.stamp {
            let n = &self.tree.nodes[i];
            self.cache.outer[i] = arr(&(self.pose * n.outer.centre));
            self.cache.node_stamp[i] = self.stamp;
        }
    }
    #[inline]
    fn inner(&mut self, i: usize) -> [f64; 3] {
        if self.cache.inner_stamp[i] != self.stamp {
            let n = &self.tree.nodes[i];
            self.cache.inner[i] = if n.inner.centre == n.outer.centre {
                self.cache.outer[i]
            } else {
                arr(&(self.pose * n.inner.centre))
            };
            self.cache.inner_stamp[i] = self.stamp;
        }
        self.cache.inner[i]
    }
    #[inline]
    fn vertex(&mut self, i: usize) -> [f64; 3] {
        if self.cache.vert_stamp[i] != self.stamp {
            self.cache.verts[i] = arr(&(self.pose * self.tree.polyhedron.vertices()[i]));
            self.cache.vert_stamp[i] = self.stamp;
        }
        self.cache.verts[i]
    }
    #[inline]
    fn triangle(&mut self, t: u32) -> [[f64; 3]; 3] {
        let [a, b, c] = self.tree.polyhedron.triangles()[t as usize];
        [
            self.vertex(a as usize),
            self.vertex(b as usize),
            self.vertex(c as usize),
        ]
    }
}

#[inline(always)]
fn dist2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
}

/// Certainly disjoint balls (`d > s`).
#[inline(always)]
fn certainly_apart(d2: f64, s: f64) -> bool {
    d2 > s * s * (1.0 + 1e-14) + 1e-300
}

/// Certainly meeting balls (`d <= s`, both radii non-negative).
#[inline(always)]
fn certainly_meet(d2: f64, ra: f64, rb: f64) -> bool {
    if ra < 0.0 || rb < 0.0 {
        return false;
    }
    let s = ra + rb;
    d2 * (1.0 + 1e-14) + 1e-300 < s * s
}

fn tri(p: &[[f64; 3]; 3]) -> Option<Triangle> {
    let pt = |a: &[f64; 3]| Point3::new(a[0], a[1], a[2]);
    Triangle::new(pt(&p[0]), pt(&p[1]), pt(&p[2])).ok()
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::new());
}

impl DoubleSphereTree {
    /// Whether this solid at `pose` and `other` at `other_pose` share a point (exact; touching
    /// counts), with how the answer was reached ([`Outcome`]). Uses per-thread buffers, so
    /// repeated queries do not allocate once the trees' sizes have been seen.
    ///
    /// ```
    /// use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
    /// use cga_collide::nalgebra::Isometry3;
    /// use cga_collide::shape::polyhedron::ConvexPolyhedron;
    /// let cube = DoubleSphereTree::build(&ConvexPolyhedron::cube(), 3, InnerSphereKind::Chebyshev)?;
    /// let here = Isometry3::identity();
    /// assert!(cube.collides_at(&here, &cube, &Isometry3::translation(0.5, 0.0, 0.0)).collides);
    /// assert!(!cube.collides_at(&here, &cube, &Isometry3::translation(5.0, 0.0, 0.0)).collides);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    ///
    /// The test is the paper's Algorithm 1 (outer spheres reject, labels and inner spheres accept, leaves go to
    /// Algorithm 2's exact face tests), plus an exact containment test.
    ///
    /// # What "exact" means here
    /// The ground truth is the pair of closed solids bounded by the triangles of
    /// [`ConvexPolyhedron::triangles`](crate::shape::polyhedron::ConvexPolyhedron::triangles) with vertices
    /// `pose * v` computed in `f64` by nalgebra (as
    /// [`TriMesh::transformed`](crate::shape::mesh::TriMesh::transformed) does); touching counts. The face
    /// tests run on exactly those triangles with the exact [`Triangle`] test. The spheres are
    /// stored in the body frame and their centres are transformed in `f64` at query time, so the
    /// sphere tests are made conservative:
    ///
    /// **The rounding bound.** nalgebra rotates `v` by the quaternion `q = (w, u)` as
    /// `t = 2 u×v; v' = (w t + u×t) + v`, then adds the translation `τ`. For the exact evaluation
    /// of that formula with a non-unit `q`, `|q|² = 1 + η`, the result is `R v + η (R v - v)` where
    /// `R` is the rotation of `q/|q|`, so it differs from the rigid motion `M v = R v + τ` by at
    /// most `2|η||v|`. The `f64` evaluation adds, per component, at most a few units of roundoff
    /// `u = 2⁻⁵³` times `|v|` (two products and a difference for `t`, the same for `u×t`, one
    /// product and two sums) and one rounding of `|v'| + |τ|` for the translation: with
    /// `|u|, |w| <= 1`, the error vector is below `≈ 35u|v| + 2u|τ|`. We use the generous
    /// `ε = (2|η| + 1e-14)|v|max + 1e-15|τ| + 1e-290` (`1e-14 ≈ 90u`; the last term covers
    /// underflow), where `|v|max` is the solid's largest vertex norm (sphere centres lie inside
    /// the solid, so they obey the same bound). Every transformed vertex and centre is within `ε`
    /// of its image under `M`.
    ///
    /// * **Outer spheres** are used with radius `r + 2ε`: every point of a transformed triangle is
    ///   within `ε` of the `M`-image of the corresponding point of the body-frame triangle, and
    ///   the centre is within `ε` of its image: so a surface contact point lies in the inflated
    ///   outer spheres of every node on its path, and rejection never loses a contact.
    /// * **Inner spheres** (and the outer spheres of internal nodes) are used with radius
    ///   `r - 3ε`: that ball is within the `M`-image of a ball at distance `>= ε` from the solid's
    ///   boundary, and since the transformed surface is an `ε`-perturbation of the `M`-image
    ///   surface (a homotopy moving no point by more than `ε` never crosses the ball), the ball
    ///   lies inside the transformed solid. Two such balls meeting proves that the solids meet.
    /// * **Sphere comparisons** compute `d² = |c₁ - c₂|²` and `s² = (r₁ + r₂)²` in `f64`; both
    ///   have relative errors below `8u`, so "disjoint" is decided only when
    ///   `d² > s² (1 + 1e-14) + 1e-300` and "meet" only when `d² (1 + 1e-14) + 1e-300 < s²`.
    ///   Anything uncertain falls through to the next test (finally to the exact faces).
    ///
    /// # Containment
    /// Algorithm 1 finds surface contacts. When none is found and the outer root spheres met, one
    /// solid may still lie inside the other: a vertex of A is tested against B (and a vertex of B
    /// against A). The vertex is mapped back to the other's body frame and compared with its
    /// triangle planes: beyond a margin that covers `ε` and the inverse transform's rounding the
    /// answer is certain; otherwise the exact even–odd count of the crossings of a segment from
    /// the point to far outside, with exact `orient3d` signs, decides (a direction giving a zero
    /// sign is replaced by another one).
    pub fn collides_at(
        &self,
        pose: &Isometry3<f64>,
        other: &DoubleSphereTree,
        other_pose: &Isometry3<f64>,
    ) -> Outcome {
        SCRATCH.with(|s| match s.try_borrow_mut() {
            Ok(mut scratch) => collide_with(&mut scratch, self, pose, other, other_pose),
            // Re-entered on this thread (not possible through this module): fresh buffers.
            Err(_) => collide_with(&mut Scratch::new(), self, pose, other, other_pose),
        })
    }

    /// [`collides_at`](Self::collides_at) with both solids where they were built (the identity
    /// pose for both).
    ///
    /// ```
    /// use cga_collide::hierarchy::double_sphere::{Decision, DoubleSphereTree, InnerSphereKind};
    /// use cga_collide::shape::polyhedron::ConvexPolyhedron;
    /// let a = DoubleSphereTree::build(&ConvexPolyhedron::octahedron(), 3, InnerSphereKind::Centroid)?;
    /// let b = DoubleSphereTree::build(&ConvexPolyhedron::diamond(), 3, InnerSphereKind::Centroid)?;
    /// let out = a.collides(&b); // both centred at the origin
    /// assert!(out.collides);
    /// assert_eq!(out.decided_by, Decision::InnerSpheres);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn collides(&self, other: &DoubleSphereTree) -> Outcome {
        let id = Isometry3::identity();
        self.collides_at(&id, other, &id)
    }
}

/// [`DoubleSphereTree::collides_at`] with explicit buffers: after the first query with trees of
/// a given size, no heap allocation happens.
pub(crate) fn collide_with(
    scratch: &mut Scratch,
    a: &DoubleSphereTree,
    pose_a: &Isometry3<f64>,
    b: &DoubleSphereTree,
    pose_b: &Isometry3<f64>,
) -> Outcome {
    scratch.stamp = scratch.stamp.wrapping_add(1);
    if scratch.stamp == 0 {
        // Wrapped: invalidate everything.
        scratch.a.node_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.a.inner_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.a.leaf_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.b.leaf_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.b.inner_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.a.vert_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.b.node_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.b.vert_stamp.iter_mut().for_each(|s| *s = u32::MAX);
        scratch.stamp = 1;
    }
    scratch.a.prepare(a);
    scratch.b.prepare(b);
    let stamp = scratch.stamp;
    let mut sa = Side {
        tree: a,
        pose: pose_a,
        eps: transform_error_bound(pose_a, a.vmax),
        cache: &mut scratch.a,
        stamp,
    };
    let mut sb = Side {
        tree: b,
        pose: pose_b,
        eps: transform_error_bound(pose_b, b.vmax),
        cache: &mut scratch.b,
        stamp,
    };
    scratch.stack.clear();
    let mut out = Outcome {
        collides: false,
        decided_by: Decision::OuterSpheres,
        sphere_tests: 0,
        triangle_tests: 0,
    };
    if !(sa.eps.is_finite() && sb.eps.is_finite()) {
        // A non-finite pose places no point anywhere.
        return out;
    }
    let mut roots_meet = false;
    let mut reached_faces = false;
    scratch.stack.push((0, 0));
    while let Some((i, j)) = scratch.stack.pop() {
        let (i, j) = (i as usize, j as usize);
        sa.fill(i);
        sb.fill(j);
        let (na, nb) = (&a.nodes[i], &b.nodes[j]);
        let d2 = dist2(&sa.cache.outer[i], &sb.cache.outer[j]);
        out.sphere_tests += 1;
        if certainly_apart(
            d2,
            na.outer.radius + 2.0 * sa.eps + nb.outer.radius + 2.0 * sb.eps,
        ) {
            continue;
        }
        if i == 0 && j == 0 {
            roots_meet = true;
        }
        if na.internal && nb.internal {
            out.sphere_tests += 1;
            if certainly_meet(
                d2,
                na.outer.radius - 3.0 * sa.eps,
                nb.outer.radius - 3.0 * sb.eps,
            ) {
                out.collides = true;
                out.decided_by = Decision::InternalLabels;
                return out;
            }
        }
        out.sphere_tests += 1;
        if certainly_meet(
            dist2(&sa.inner(i), &sb.inner(j)),
            na.inner.radius - 3.0 * sa.eps,
            nb.inner.radius - 3.0 * sb.eps,
        ) {
            out.collides = true;
            out.decided_by = Decision::InnerSpheres;
            return out;
        }
        let (ca, cb) = (sa.cache.outer[i], sb.cache.outer[j]);
        // Ours: a node whose inflated outer sphere is certainly beyond a supporting face plane
        // of the other solid holds no point of it, so no pair below can meet (neither by
        // faces nor by inner spheres inside these regions): the pair is dropped.
        if beyond_faces(&sa, i, &cb, nb.outer.radius + 2.0 * sb.eps)
            || beyond_faces(&sb, j, &ca, na.outer.radius + 2.0 * sa.eps)
        {
            continue;
        }
        let (i32_, j32) = (i as u32, j as u32);
        match (na.internal, nb.internal, na.children, nb.children) {
            // Internal regions hold no surface: only acceptance can come from below.
            (true, true, _, _) => {}
            (true, false, _, Some(c)) | (false, false, None, Some(c)) => {
                let [near, far] = nearer_first(&mut sb, c, &ca);
                scratch.stack.push((i32_, far));
                scratch.stack.push((i32_, near));
            }
            (false, true, Some(c), _) | (false, false, Some(c), None) => {
                let [near, far] = nearer_first(&mut sa, c, &cb);
                scratch.stack.push((far, j32));
                scratch.stack.push((near, j32));
            }
            (true, false, _, None) | (false, true, None, _) => {}
            (false, false, None, None) => {
                reached_faces = true;
                if leaf_faces(
                    &mut sa,
                    i,
                    &mut sb,
                    j,
                    &mut out,
                    &mut scratch.tris_a,
                    &mut scratch.tris_b,
                ) {
                    out.collides = true;
                    out.decided_by = Decision::Faces;
                    return out;
                }
            }
            (false, false, Some(a2), Some(b2)) => {
                if na.outer.radius >= nb.outer.radius {
                    let [near, far] = nearer_first(&mut sa, a2, &cb);
                    scratch.stack.push((far, j32));
                    scratch.stack.push((near, j32));
                } else {
                    let [near, far] = nearer_first(&mut sb, b2, &ca);
                    scratch.stack.push((i32_, far));
                    scratch.stack.push((i32_, near));
                }
            }
        }
    }
    if reached_faces {
        out.decided_by = Decision::NoContact;
    }
    if roots_meet {
        let pa = sa.vertex(0);
        let pb = sb.vertex(0);
        if contains_point(&mut sb, &pa) || contains_point(&mut sa, &pb) {
            out.collides = true;
            out.decided_by = Decision::Containment;
        }
    }
    out
}

/// The triangles of leaf `i` of `side` that may meet the ball `(c, r)` (their bounding box
/// is not certainly farther than `r` from `c`), as indices into the cache's transformed
/// triangles (each leaf is transformed at most once per query).
fn gather(side: &mut Side, i: usize, c: &[f64; 3], r: f64, buf: &mut Vec<u32>) {
    buf.clear();
    let range = side.tree.nodes[i].triangles.clone();
    if side.cache.leaf_stamp[i] != side.stamp {
        for k in range.clone() {
            let p = side.triangle(side.tree.leaf_triangles[k as usize]);
            let lo = [
                p[0][0].min(p[1][0]).min(p[2][0]),
                p[0][1].min(p[1][1]).min(p[2][1]),
                p[0][2].min(p[1][2]).min(p[2][2]),
            ];
            let hi = [
                p[0][0].max(p[1][0]).max(p[2][0]),
                p[0][1].max(p[1][1]).max(p[2][1]),
                p[0][2].max(p[1][2]).max(p[2][2]),
            ];
            side.cache.gathered[k as usize] = Gathered {
                tri: tri(&p),
                lo,
                hi,
            };
        }
        side.cache.leaf_stamp[i] = side.stamp;
    }
    let r2 = r * r * (1.0 + 1e-14) + 1e-300;
    for k in range {
        let g = &side.cache.gathered[k as usize];
        if g.tri.is_none() {
            continue;
        }
        let d2: f64 = (0..3)
            .map(|a| {
                let e = (g.lo[a] - c[a]).max(c[a] - g.hi[a]).max(0.0);
                e * e
            })
            .sum();
        if d2 <= r2 {
            buf.push(k);
        }
    }
}

/// The inverse-transform rounding bound for a world point `p` (the rounding analysis of
/// [`DoubleSphereTree::collides_at`]: `|p| + |τ|` in
/// the role of `|v|`).
fn inverse_error_bound(pose: &Isometry3<f64>, p: &Point3<f64>) -> f64 {
    let q = pose.rotation.quaternion();
    let eta = (q.norm_squared() - 1.0).abs() + 1e-15;
    let reach = p.coords.norm() + pose.translation.vector.norm();
    ((2.0 * eta + 1e-14) * reach * 1.01 + 1e-290) * 1.01
}

/// Whether the world ball `(c, r)` lies certainly outside one of the supporting planes of the
/// original faces of node `i` of `side` (every face plane supports the whole convex solid):
/// then no point of the ball is in that solid.
fn beyond_faces(side: &Side, i: usize, c: &[f64; 3], r: f64) -> bool {
    let range = side.tree.nodes[i].planes.clone();
    if range.is_empty() {
        return false;
    }
    let cw = Point3::new(c[0], c[1], c[2]);
    let body = side.pose.inverse_transform_point(&cw);
    let reach = r + side.eps + inverse_error_bound(side.pose, &cw);
    side.tree.leaf_planes[range.start as usize..range.end as usize]
        .iter()
        .any(|(n, d)| n.dot(&body.coords) - d > reach * (1.0 + 1e-12) + 1e-12 * side.tree.vmax)
}

/// The two children ordered by the distance of their outer centres to `other` (nearer first:
/// it is explored first, which finds contacts sooner).
#[inline]
fn nearer_first(side: &mut Side, c: [u32; 2], other: &[f64; 3]) -> [u32; 2] {
    side.fill(c[0] as usize);
    side.fill(c[1] as usize);
    let d0 = dist2(&side.cache.outer[c[0] as usize], other);
    let d1 = dist2(&side.cache.outer[c[1] as usize], other);
    if d1 < d0 {
        [c[1], c[0]]
    } else {
        c
    }
}

/// Algorithm 2 on the original triangles of two leaves: every pair of their triangles that
/// can meet (each triangle's box reaches the other leaf's inflated outer sphere, and the two
/// boxes overlap; both filters are exact comparisons or certified) is tested exactly.
#[allow(clippy::too_many_arguments)]
fn leaf_faces(
    sa: &mut Side,
    i: usize,
    sb: &mut Side,
    j: usize,
    out: &mut Outcome,
    bufa: &mut Vec<u32>,
    bufb: &mut Vec<u32>,
) -> bool {
    let (ca, ra) = (
        sa.cache.outer[i],
        sa.tree.nodes[i].outer.radius + 2.0 * sa.eps,
    );
    let (cb, rb) = (
        sb.cache.outer[j],
        sb.tree.nodes[j].outer.radius + 2.0 * sb.eps,
    );
    gather(sa, i, &cb, rb, bufa);
    if bufa.is_empty() {
        return false;
    }
    gather(sb, j, &ca, ra, bufb);
    for &kx in bufa.iter() {
        let x = &sa.cache.gathered[kx as usize];
        for &ky in bufb.iter() {
            let y = &sb.cache.gathered[ky as usize];
            if (0..3).any(|k| x.hi[k] < y.lo[k] || y.hi[k] < x.lo[k]) {
                continue;
            }
            out.triangle_tests += 1;
            if let (Some(p), Some(q)) = (&x.tri, &y.tri) {
                if p.intersects(q) {
                    return true;
                }
            }
        }
    }
    false
}

/// Whether the world point `p` lies in the closed solid of `side` (exact; see
/// [`DoubleSphereTree::collides_at`]).
fn contains_point(side: &mut Side, p: &[f64; 3]) -> bool {
    let pw = Point3::new(p[0], p[1], p[2]);
    let body = side.pose.inverse_transform_point(&pw);
    let eps_inv = inverse_error_bound(side.pose, &pw);
    let margin = side.eps + eps_inv + super::BUILD_MARGIN * side.tree.vmax;
    let s = side
        .tree
        .planes
        .iter()
        .map(|(n, d)| n.dot(&body.coords) - d)
        .fold(f64::NEG_INFINITY, f64::max);
    if s > margin {
        return false;
    }
    if s < -margin {
        return true;
    }
    ray_parity(side, p)
}

/// Exact containment by ray parity over the solid's transformed triangles (see
/// [`crate::query::point_in_solid`]).
fn ray_parity(side: &mut Side, p: &[f64; 3]) -> bool {
    let n = side.tree.polyhedron.triangles().len() as u32;
    let triangles = (0..n).map(|t| side.triangle(t).map(Point3::from));
    point_in_solid(triangles, &Point3::new(p[0], p[1], p[2]))
}
