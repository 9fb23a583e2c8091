//! Queries under poses: a [`Collider`] built once in its own frame answers for any rigid pose
//! (`nalgebra::Isometry3<f64>`) with no work proportional to the mesh size, and every answer is
//! **identical** to placing the mesh first ([`Collider::placed`]) and asking the placed copy
//! (for [`Collider::distance_at`], see exactly what is equal in "Clearance and distance").
//!
//! # How
//! * Mesh against mesh: the two hierarchies are descended together under the relative motion.
//!   Each node is read as a centre and half-extents (`pose_tree`: one 64-byte cache line per
//!   node). B's box is carried into A's frame by a rounded relative transform and tested on
//!   A's three axes, then A's box into B's frame on B's three axes (the six face axes of the
//!   separating-axis test of two oriented boxes); each test is widened by a margin that bounds
//!   every rounding on the way (below), so no pair of triangles that meets after placing is
//!   ever pruned.
//! * Mesh against a shape: each box of the hierarchy is carried into the world by the pose,
//!   widened the same way, and tested against the shape.
//! * Clearance and distance: the same descent, with the relative box test widened by the
//!   clearance, or turned into a lower bound on the distance (section "Clearance and
//!   distance").
//! * At the leaves, only the candidate triangles are transformed, with **the very expression
//!   `pose * v` that [`TriMesh::transformed`](crate::TriMesh::transformed) uses**, so they are
//!   bit-identical to the placed mesh's triangles; the placed query's exact box filter and exact
//!   test then decide, on the same numbers. The vertices are read from a copy in leaf order
//!   (contiguous), and each leaf is placed at most once per traversal, in scratch memory each
//!   thread keeps from one query to the next (no allocation per pose once it has grown; 8 bytes
//!   per node of the largest trees the thread has met, 128 per triangle placed in its largest
//!   traversal, and 16 per node pair queued by its largest distance search).
//!
//! # The rounding bound
//! nalgebra evaluates `pose * v` for the unit quaternion `q = (w, u)` and translation `τ` as
//! `t = 2(u × v)`, `r = (w t + u × t) + v`, `r + τ`. In exact arithmetic that is the linear map
//! `M(q) v + τ` with `M(q) = (1 - 2|u|²) I + 2 u uᵀ + 2 w [u]×` (a rotation when `|q| = 1`, and
//! still the map the formula denotes when `|q|` is off by rounding). With `a = max(|w|, |uᵢ|)`,
//! `ρ = max |vᵢ|` and `u = 2⁻⁵³`, a forward error analysis of those 30-odd operations gives
//! `|fl(pose * v) - (M v + τ)|∞ ≤ u (80 a² ρ + 2ρ + |τ|∞) (1 + 4u)`; the code uses
//! `δ = u (96 a² ρ + 4ρ + 2|τ|∞) + 2⁻¹⁰⁰⁰` (the last term covers underflow). So each placed
//! triangle lies within `δ` (per coordinate) of the exact image of its local triangle, hence of
//! the exact image of any local box holding it.
//!
//! `M` itself is evaluated in `f64` as `M̂` with `|M - M̂| ≤ 16u(1 + a²)` per entry.
//! * World boxes (shape queries): the box `[lo, hi]` maps into `τ + Σⱼ [min, max](M̂ᵢⱼ loⱼ,
//!   M̂ᵢⱼ hiⱼ)`, widened by `δ + 3ρ|M - M̂| + 16u(3 m ρ + |τ|∞)` (`m = max |M̂ᵢⱼ|`), which also
//!   pays for the rounding of that sum and of the widening itself.
//! * Relative boxes (mesh against mesh): with `D = M̂_Aᵀ` (any matrix would do; this one makes
//!   `D M_A ≈ I`), a common point `x` of two placed triangles satisfies
//!   `D x - D τ_A ∈ box_A ⊕ r_A` and `D x - D τ_A ∈ R̂ box_B + t̂ ⊕ r_B`, where
//!   `R̂ = fl(D M̂_B)`, `t̂ = fl(D fl(τ_B - τ_A))` and the radii collect `|D M_A - I|`,
//!   `|D M_B - R̂|` (matrix-product rounding `4u|D||M̂|` plus `|D| |M - M̂|`), `|D| δ` and the
//!   rounding of `t̂`. With the boxes as `[c - e, c + e]` (real boxes holding the nodes' exact
//!   boxes, `|c| ≤ ρ`, `e ≤ 2ρ(1 + 10u) + 2⁻¹⁰⁰⁰`), such a point exists only if on each axis
//!   `i` of A, `|(R̂ c_B + t̂ - c_A)ᵢ| ≤ Σⱼ |R̂ᵢⱼ| e_Bⱼ + e_Aᵢ + r_A + r_B`. The code evaluates
//!   both sides in `f64` and adds `16u (9 max|R̂ᵢⱼ| ρ_B + |t̂|∞ + 3ρ_A + r_A + r_B)`, more
//!   than the rounding of either side (each a sum of at most five terms of those magnitudes),
//!   so the test in `f64` rejects a pair only when the real inequality fails: it is
//!   conservative. The same holds with the roles of A and B exchanged.
//!
//! # Clearance and distance
//! [`Collider::pairs_within_distance_at`], [`Collider::within_distance_at`] and
//! [`Collider::distance_at`] run on the same descent, placed leaves and relative boxes; only
//! the node test changes.
//! * **Clearance `c`** (`0 ≤ c < ∞`; other `c` are answered as by
//!   [`mesh_pairs_within_distance`](crate::query::mesh_pairs_within_distance) without a
//!   descent). If placed points `x`, `y` of the two meshes have `|x - y| ≤ c`, then on axis `i`
//!   of A's frame the two points `D x - D τ_A` and `D y - D τ_A` of the boxes above differ by
//!   `|Dᵢ · (x - y)| ≤ |Dᵢ|₂ c`, where `Dᵢ` is row `i` of `D`. As `D = M̂_Aᵀ`,
//!   `|Dᵢ|₂² = (D M̂_A)ᵢᵢ ≤ 1 + η_A` with `η_A` the bound on `|D M̂_A - I|` that `r_A` is built
//!   from (it includes the rounding of the computed product). So each axis test is widened by
//!   `w = fl(fl(c · fl(1 + η_A)) · (1 + 2⁻⁴⁸)) ≥ c (1 + η_A)(1 - u)³(1 + 32u) ≥ c √(1 + η_A)
//!   (1 + 16u)`: the `16u c √(1 + η_A)` beyond the need pays for the rounding that the new term
//!   adds to the sum (as the `16u` allowance does for the others), and an underflow of `w` is
//!   paid by the margin's `2⁻¹⁰⁰⁰`. Likewise in B's frame. At the leaves, the placed triangles
//!   (bit-identical to the placed mesh's) go through the placed query's conservative box
//!   filter and its exact clearance test. So the pairs found are exactly the pairs within `c`,
//!   as the placed query's are: the lists are **identical**, and so are the booleans.
//! * **Distance.** With the same notation, a placed point of A's node lies within `r_A` (per
//!   coordinate of A's frame `D (x - τ_A)`) of any convex set holding the node's local
//!   triangles, and a placed point of B's node within `r_B` of `R̂` times such a set plus `t̂`.
//!   The sets used are the nodes' oriented boxes (fitted to the geometry, so that turned parts
//!   keep tight bounds), and the lower bound on `|x - y|²` from their gaps on the six box axes,
//!   every rounding paid, is proved in the module `oriented_boxes` (crate-private; its docs
//!   are in the source). It orders a best-first search over node pairs, as
//!   [`mesh_distance`](crate::query::mesh_distance) does with the same boxes in one frame;
//!   triangle pairs are examined, pruned and certified by the very code of `mesh_distance`, on
//!   the placed triangles.
//!
//! **What `distance_at` has in common with `mesh_distance` on the placed copies.** Always: the
//! same certified guarantee — the true distance of the placed meshes lies in
//! `[distance - error_bound, distance + error_bound]`, the witnesses are the `f64` nearest
//! points of the triangle pair reported, on the placed mesh's coordinates, and that pair's
//! `f64` distance is `distance`. Both searches keep, among the pairs they examine, the least
//! `f64` squared distance, and among equal ones the smallest pair `(i, j)`; both skip only
//! pairs **proved** farther than the best so far. The error bound is a function of that pair
//! and of the meshes alone (the lower end is decided over all pairs, see
//! [`mesh_distance`](crate::query::mesh_distance)). So the two results are **identical in every
//! field** unless a pair's `f64` squared distance is at or below the result while its true
//! distance is above it (rounding of the `f64` closest-points routine, so a near-tie at the
//! level of the last bits); only then may the two searches, which visit pairs in different
//! orders, report different pairs of that near-tie, each with its own certified bound. No test
//! has met such a case (the agreement tests compare every field, ties of dyadic cubes included).
//!
//! Poses whose quaternion is far from unit (`|q|²` outside `[1/2, 2]`), non-finite poses, and
//! meshes or translations so large that the bounds could overflow (`|coordinate| ≥ 2⁹⁹⁰`) get a
//! [`PoseError`] instead of an answer.
//!
//! ```
//! use cga_collide::query::{Collider, Mode};
//! use cga_collide::{nalgebra::{Isometry3, Vector3}, TriMesh};
//! let a = Collider::new(TriMesh::bunny().unit());
//! let b = Collider::new(TriMesh::bunny().unit());
//! let pa = Isometry3::identity();
//! let pb = Isometry3::new(Vector3::new(0.3, 0.05, 0.0), Vector3::new(0.0, 0.5, 0.0));
//! let pairs = a.intersecting_pairs_at(&pa, &b, &pb)?;
//! // Identical to placing both meshes first:
//! let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
//! assert_eq!(pairs, wa.intersecting_pairs(&wb, Mode::Bvh));
//! assert_eq!(a.collides_at(&pa, &b, &pb)?, !pairs.is_empty());
//! # Ok::<(), cga_collide::query::PoseError>(())
//! ```

use std::ops::ControlFlow;

mod distance;

use nalgebra::{Isometry3, Point3};
use thiserror::Error;

use crate::bvh::{Aabb, Bvh};
use crate::parallel::*;
use crate::query::placed_leaves::{place, with_scratch, Placed, Scratch};
use crate::query::pose_tree::PoseNode;
use crate::query::{ray_crosses_triangle, Collider};
use crate::{Ball, Intersects, Segment, Sphere, Triangle};

/// Why a pose query has no answer.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum PoseError {
    /// A quaternion or translation component of the pose is NaN or infinite.
    #[error("the pose has a non-finite component: every quaternion and translation component must be a finite number")]
    NonFinite,
    /// The pose's quaternion is far from unit length (`|q|²` outside `[1/2, 2]`).
    #[error("the pose's rotation is not a unit quaternion (|q|² = {norm_squared}): normalise it (e.g. UnitQuaternion::new_normalize)")]
    NotUnit {
        /// The squared length of the quaternion.
        norm_squared: f64,
    },
    /// Coordinates or translations so large that the rounding bounds could overflow
    /// (`|coordinate| ≥ 2^990`).
    #[error("coordinates too large for a certified pose query (|x| up to {magnitude:e}, the limit is 2^990): scale the meshes and translations down")]
    OutOfRange {
        /// The largest magnitude involved.
        magnitude: f64,
    },
}

/// `2^-53`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;
/// Absolute allowance for underflow (generous: the true figure is a few `2^-1074`).
const TINY: f64 = 9.332636185032189e-302; // 2^-1000
/// Largest magnitude for which no bound below can overflow.
const RANGE: f64 = 9.774714424757689e297; // 2^990

type Mat = [[f64; 3]; 3];

/// A pose analysed once: the `f64` matrix of its rotation, its translation and the constants
/// of its rounding bounds.
#[derive(Debug, Clone, Copy)]
struct PoseMap {
    /// `M̂`, row-major.
    m: Mat,
    t: [f64; 3],
    /// `max(|w|, |x|, |y|, |z|)` of the quaternion.
    a: f64,
    /// `max |M̂ᵢⱼ|`.
    mmax: f64,
    /// `|τ|∞`.
    tmax: f64,
}

impl PoseMap {
    fn new(iso: &Isometry3<f64>) -> Result<PoseMap, PoseError> {
        let q = iso.rotation.quaternion();
        let (w, x, y, z) = (q.w, q.i, q.j, q.k);
        let t = [
            iso.translation.vector.x,
            iso.translation.vector.y,
            iso.translation.vector.z,
        ];
        if ![w, x, y, z].iter().chain(&t).all(|c| c.is_finite()) {
            return Err(PoseError::NonFinite);
        }
        let n2 = w * w + x * x + y * y + z * z;
        if !(0.5..=2.0).contains(&n2) {
            return Err(PoseError::NotUnit { norm_squared: n2 });
        }
        let m = [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ];
        let a = w.abs().max(x.abs()).max(y.abs()).max(z.abs());
        let mmax = m.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
        let tmax = t.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        Ok(PoseMap {
            m,
            t,
            a,
            mmax,
            tmax,
        })
    }

    /// `δ`: bound on `|fl(pose * v) - (M v + τ)|∞` for `|v|∞ ≤ rho`.
    fn delta(&self, rho: f64) -> f64 {
        U * (96.0 * self.a * self.a * rho + 4.0 * rho + 2.0 * self.tmax) + TINY
    }

    /// Bound on `|M - M̂|` per entry.
    fn matrix_error(&self) -> f64 {
        16.0 * U * (1.0 + self.a * self.a) + TINY
    }

    fn check_range(&self, rho: f64) -> Result<(), PoseError> {
        let magnitude = rho.max(self.tmax);
        if magnitude < RANGE {
            Ok(())
        } else {
            Err(PoseError::OutOfRange { magnitude })
        }
    }
}

/// `[min, max]` of `t + Σⱼ mⱼ yⱼ` over `y` in the box, for one row `m` (rounded to nearest).
#[inline(always)]
fn row_range(m: &[f64; 3], t: f64, b: &Aabb) -> (f64, f64) {
    let (mut lo, mut hi) = (t, t);
    for ((&mj, &x), &y) in m.iter().zip(&b.min).zip(&b.max) {
        let p = mj * x;
        let q = mj * y;
        if p <= q {
            lo += p;
            hi += q;
        } else {
            lo += q;
            hi += p;
        }
    }
    (lo, hi)
}

/// Carries boxes of a mesh's own frame into the world under a pose, conservatively.
#[derive(Debug, Clone, Copy)]
struct WorldBoxes {
    m: Mat,
    t: [f64; 3],
    margin: f64,
}

impl WorldBoxes {
    fn new(pose: &PoseMap, rho: f64) -> WorldBoxes {
        let margin = pose.delta(rho)
            + 3.0 * rho * pose.matrix_error()
            + 16.0 * U * (3.0 * pose.mmax * rho + pose.tmax)
            + TINY;
        WorldBoxes {
            m: pose.m,
            t: pose.t,
            margin: margin * (1.0 + 8.0 * U),
        }
    }

    /// A world box holding the placed image of everything inside the local box `b`.
    #[inline]
    fn world(&self, b: &Aabb) -> Aabb {
        let mut out = Aabb::EMPTY;
        for i in 0..3 {
            let (lo, hi) = row_range(&self.m[i], self.t[i], b);
            out.min[i] = lo - self.margin;
            out.max[i] = hi + self.margin;
        }
        out
    }
}

/// The relative motion of B into A's frame, rounded, with the margin that makes box tests in
/// A's frame conservative for the placed meshes (module docs).
#[derive(Debug, Clone, Copy)]
struct Relative {
    r: Mat,
    /// `|r|` entrywise.
    abs_r: Mat,
    t: [f64; 3],
    margin: f64,
    /// `η`: a bound on every entry of `D M̂ - I` (`D = M̂ᵀ` of this frame's pose), so that
    /// every row of `D` has Euclidean length at most `√(1 + η)` and `|D|₂² ≤ 1 + 3η`.
    eta: f64,
}

fn mat_mul(x: &Mat, y: &Mat) -> Mat {
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = x[i][0] * y[0][j] + x[i][1] * y[1][j] + x[i][2] * y[2][j];
        }
    }
    out
}

fn transpose(x: &Mat) -> Mat {
    let mut out = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = x[j][i];
        }
    }
    out
}

impl Relative {
    fn new(pa: &PoseMap, rho_a: f64, pb: &PoseMap, rho_b: f64) -> Relative {
        let d = transpose(&pa.m);
        // |D| row sums.
        let dsum = 3.0 * pa.mmax;
        let g = mat_mul(&d, &pa.m);
        let mut dev = 0.0f64;
        for (i, row) in g.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                let id = if i == j { 1.0 } else { 0.0 };
                dev = dev.max((v - id).abs());
            }
        }
        let eta_a = dev * (1.0 + 4.0 * U)
            + 4.0 * U * 3.0 * pa.mmax * pa.mmax
            + dsum * pa.matrix_error()
            + TINY;
        let r = mat_mul(&d, &pb.m);
        let eta_b = 4.0 * U * 3.0 * pa.mmax * pb.mmax + dsum * pb.matrix_error() + TINY;
        let dt = [pb.t[0] - pa.t[0], pb.t[1] - pa.t[1], pb.t[2] - pa.t[2]];
        let dtmax = dt.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        let t = [
            d[0][0] * dt[0] + d[0][1] * dt[1] + d[0][2] * dt[2],
            d[1][0] * dt[0] + d[1][1] * dt[1] + d[1][2] * dt[2],
            d[2][0] * dt[0] + d[2][1] * dt[1] + d[2][2] * dt[2],
        ];
        let e_t = 16.0 * U * dsum * dtmax + TINY;
        let rmax = r.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
        let tmax = t.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        let radius = 3.0 * eta_a * rho_a
            + dsum * pa.delta(rho_a)
            + 3.0 * eta_b * rho_b
            + dsum * pb.delta(rho_b)
            + e_t;
        // Node boxes are centres `|c| ≤ ρ` and half-extents `e ≤ 2ρ(1 + 10u) + 2⁻¹⁰⁰⁰`
        // (`pose_tree`): `16u` times these magnitudes pays for the rounding of the test.
        let margin = radius + 16.0 * U * (9.0 * rmax * rho_b + tmax + 3.0 * rho_a + radius) + TINY;
        Relative {
            r,
            abs_r: r.map(|row| row.map(f64::abs)),
            t,
            margin: margin * (1.0 + 8.0 * U),
            eta: eta_a,
        }
    }

    /// `false` only if no placed triangle under node `a` of A meets a placed triangle under
    /// node `b` of B: `b`'s box carried into A's frame, against `a`'s box on A's three axes
    /// (`|r c_b + t - c_a| > |r| e_b + e_a + margin` on an axis separates them).
    #[inline(always)]
    fn may_overlap(&self, a: &PoseNode, b: &PoseNode) -> bool {
        self.may_be_within(a, b, 0.0)
    }

    /// The reach `w` to add on every axis of this frame for a clearance `c ≥ 0`:
    /// `w ≥ c √(1 + η) (1 + 16u)` (module docs, clearance), `+∞` if that overflows.
    #[inline]
    fn widen(&self, c: f64) -> f64 {
        c * (1.0 + self.eta) * (1.0 + 32.0 * U)
    }

    /// [`may_overlap`](Self::may_overlap) with every axis test widened by `w` (from
    /// [`widen`](Self::widen)): `false` only if no placed triangle under `a` comes within `c`
    /// of a placed triangle under `b`.
    #[inline(always)]
    fn may_be_within(&self, a: &PoseNode, b: &PoseNode, w: f64) -> bool {
        let (r, ar) = (&self.r, &self.abs_r);
        let mut apart = false;
        for i in 0..3 {
            let d = r[i][0] * b.c[0] + r[i][1] * b.c[1] + r[i][2] * b.c[2] + self.t[i] - a.c[i];
            let reach = ar[i][0] * b.e[0]
                + ar[i][1] * b.e[1]
                + ar[i][2] * b.e[2]
                + a.e[i]
                + self.margin
                + w;
            apart |= d.abs() > reach;
        }
        !apart
    }
}

/// Two colliders under their poses, ready to be traversed together.
struct PosedPair<'a> {
    a: &'a Collider,
    b: &'a Collider,
    pose_a: Isometry3<f64>,
    pose_b: Isometry3<f64>,
    /// B's boxes in A's frame.
    rel: Relative,
    /// A's boxes in B's frame (the other three face axes of the separating-axis test).
    inv: Relative,
}

impl<'a> PosedPair<'a> {
    fn new(
        a: &'a Collider,
        pose_a: &Isometry3<f64>,
        b: &'a Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<PosedPair<'a>, PoseError> {
        let pa = PoseMap::new(pose_a)?;
        let pb = PoseMap::new(pose_b)?;
        pa.check_range(a.extent())?;
        pb.check_range(b.extent())?;
        let rel = Relative::new(&pa, a.extent(), &pb, b.extent());
        let inv = Relative::new(&pb, b.extent(), &pa, a.extent());
        Ok(PosedPair {
            a,
            b,
            pose_a: *pose_a,
            pose_b: *pose_b,
            rel,
            inv,
        })
    }

    /// `false` only if nothing placed under node `x` of A meets anything placed under node
    /// `y` of B: B's box tested in A's frame, then A's box in B's frame (the six face axes of
    /// the separating-axis test).
    #[inline(always)]
    fn may_overlap(&self, x: &PoseNode, y: &PoseNode) -> bool {
        self.rel.may_overlap(x, y) && self.inv.may_overlap(y, x)
    }

    /// Whether two placed triangles meet (exact), behind a test of their exact boxes.
    #[inline(always)]
    fn meet(p: &Placed, q: &Placed) -> bool {
        p.bounds.overlaps(&q.bounds) && p.tri.intersects(&q.tri)
    }

    /// The descent below the node pairs on `scratch.stack`: node pairs failing `near` are
    /// pruned, and `visit(i, j)` gets every pair of placed triangles passing `keep`; stops
    /// when `visit` breaks. `near` must be conservative for `keep` (module docs).
    fn traverse_where<B>(
        &self,
        scratch: &mut Scratch,
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
        mut visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let (ta, tb) = (self.a.pose_tree(), self.b.pose_tree());
        let (na, nb) = (ta.nodes(), tb.nodes());
        while let Some((i, j)) = scratch.stack.pop() {
            let (x, y) = (&na[i as usize], &nb[j as usize]);
            if !near(x, y) {
                continue;
            }
            match (x.is_leaf(), y.is_leaf()) {
                (true, true) => {
                    // Leaves meet many leaves of the other tree: each is placed once per
                    // traversal.
                    let la = scratch.leaf(0, i, x, ta, &self.pose_a);
                    let lb = scratch.leaf(1, j, y, tb, &self.pose_b);
                    let (pa, pb) = (scratch.placed(la), scratch.placed(lb));
                    for p in pa {
                        for q in pb {
                            if keep(p, q) {
                                visit(p.index, q.index)?;
                            }
                        }
                    }
                }
                (false, true) => push_children(&mut scratch.stack, x.start, j, true),
                (true, false) => push_children(&mut scratch.stack, i, y.start, false),
                (false, false) => {
                    if x.size >= y.size {
                        push_children(&mut scratch.stack, x.start, j, true);
                    } else {
                        push_children(&mut scratch.stack, i, y.start, false);
                    }
                }
            }
        }
        ControlFlow::Continue(())
    }

    /// Runs the traversal from the node pairs `start` with this thread's scratch memory.
    fn run<B>(
        &self,
        start: &[(u32, u32)],
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        self.run_where(start, |x, y| self.may_overlap(x, y), Self::meet, visit)
    }

    /// [`traverse_where`](Self::traverse_where) from the node pairs `start` with this
    /// thread's scratch memory.
    fn run_where<B>(
        &self,
        start: &[(u32, u32)],
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
        visit: impl FnMut(u32, u32) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let (na, nb) = (self.a.pose_tree().nodes(), self.b.pose_tree().nodes());
        with_scratch(na.len(), nb.len(), |scratch| {
            scratch.stack.extend_from_slice(start);
            self.traverse_where(scratch, near, keep, visit)
        })
    }

    /// Every intersecting pair below the node pairs `start`, unsorted.
    fn collect_pairs(&self, start: &[(u32, u32)]) -> Vec<(u32, u32)> {
        self.collect_pairs_where(start, |x, y| self.may_overlap(x, y), Self::meet)
    }

    /// Every pair passing `keep` below the node pairs `start` (pruned by `near`), unsorted.
    fn collect_pairs_where(
        &self,
        start: &[(u32, u32)],
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
        keep: impl Fn(&Placed, &Placed) -> bool,
    ) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        let _ = self.run_where::<()>(start, near, keep, |i, j| {
            out.push((i, j));
            ControlFlow::Continue(())
        });
        out
    }

    /// Every pair passing `keep` (pruned by `near`), sorted, the traversal split over the
    /// cores (rayon, feature `parallel`).
    fn all_pairs_where(
        &self,
        near: impl Fn(&PoseNode, &PoseNode) -> bool + Sync,
        keep: impl Fn(&Placed, &Placed) -> bool + Sync,
    ) -> Vec<(u32, u32)> {
        let threads = cores();
        let mut out = if threads <= 1 {
            self.collect_pairs_where(&[(0, 0)], &near, &keep)
        } else {
            let tasks = self.split_where(threads * TASKS_PER_CORE, &near);
            tasks
                .par_iter()
                .flat_map_iter(|&task| self.collect_pairs_where(&[task], &near, &keep))
                .collect()
        };
        out.sort_unstable();
        out
    }

    /// Node pairs covering the whole traversal pruned by `near`, at least `want` of them when
    /// the trees allow (breadth-first split of the root pair), for spreading over the cores.
    fn split_where(
        &self,
        want: usize,
        near: impl Fn(&PoseNode, &PoseNode) -> bool,
    ) -> Vec<(u32, u32)> {
        let (na, nb) = (self.a.pose_tree().nodes(), self.b.pose_tree().nodes());
        let mut level = vec![(0u32, 0u32)];
        for _ in 0..64 {
            if level.len() >= want {
                break;
            }
            let mut next = Vec::with_capacity(level.len() * 2);
            let mut grew = false;
            for &(i, j) in &level {
                let (x, y) = (&na[i as usize], &nb[j as usize]);
                if !near(x, y) {
                    continue;
                }
                let split_a = match (x.is_leaf(), y.is_leaf()) {
                    (true, true) => {
                        next.push((i, j));
                        continue;
                    }
                    (false, true) => true,
                    (true, false) => false,
                    (false, false) => x.size >= y.size,
                };
                grew = true;
                if split_a {
                    let s = x.start;
                    next.extend([(s, j), (s + 1, j)]);
                } else {
                    let s = y.start;
                    next.extend([(i, s), (i, s + 1)]);
                }
            }
            level = next;
            if !grew {
                break;
            }
        }
        level
    }
}

#[inline(always)]
fn push_children(stack: &mut Vec<(u32, u32)>, i: u32, j: u32, split_a: bool) {
    if split_a {
        stack.push((i + 1, j));
        stack.push((i, j));
    } else {
        stack.push((i, j + 1));
        stack.push((i, j));
    }
}

/// Node pairs per core in the parallel all-pairs traversal.
const TASKS_PER_CORE: usize = 16;

fn cores() -> usize {
    #[cfg(feature = "parallel")]
    {
        rayon::current_num_threads()
    }
    #[cfg(not(feature = "parallel"))]
    {
        1
    }
}

/// Pose queries: `self` at `pose`, the other mesh (if any) at its own pose. Each answer equals
/// the answer of the same query on [`Collider::placed`] copies (see [`crate::query::posed`]).
impl Collider {
    /// Whether any triangle of `self` placed at `pose_a` meets any triangle of `other` placed
    /// at `pose_b` (stops at the first hit; single-threaded). Equal to
    /// `self.placed(pose_a)?.collides(&other.placed(pose_b)?, mode)`.
    pub fn collides_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<bool, PoseError> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        Ok(pair
            .run(&[(0, 0)], |_, _| ControlFlow::Break(()))
            .is_break())
    }

    /// Every intersecting pair `(i, j)` (triangle `i` of `self` at `pose_a`, `j` of `other` at
    /// `pose_b`), sorted; the traversal is split over the cores (rayon, feature `parallel`).
    /// Equal to `self.placed(pose_a)?.intersecting_pairs(&other.placed(pose_b)?, mode)`.
    pub fn intersecting_pairs_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Vec<(u32, u32)>, PoseError> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        Ok(pair.all_pairs_where(|x, y| pair.may_overlap(x, y), PosedPair::meet))
    }

    /// Like [`intersecting_pairs_at`](Self::intersecting_pairs_at) on the calling thread only
    /// (what the batch queries run per pose).
    pub fn intersecting_pairs_at_sequential(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Vec<(u32, u32)>, PoseError> {
        let pair = PosedPair::new(self, pose_a, other, pose_b)?;
        let mut out = pair.collect_pairs(&[(0, 0)]);
        out.sort_unstable();
        Ok(out)
    }

    /// Whether the solids bounded by the two closed meshes, at their poses, share a point
    /// (surfaces meet, or one lies wholly inside the other). Equal to
    /// [`collides_solid`](Self::collides_solid) on the placed copies.
    pub fn collides_solid_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<bool, PoseError> {
        if self.collides_at(pose_a, other, pose_b)? {
            return Ok(true);
        }
        // The first placed vertex of each, placed by the same expression as `placed()`.
        let first =
            |c: &Collider, pose: &Isometry3<f64>| c.mesh().vertices().first().map(|v| pose * v);
        if let Some(v) = first(self, pose_a) {
            if other.contains_point_at(pose_b, &v)? {
                return Ok(true);
            }
        }
        if let Some(v) = first(other, pose_b) {
            if self.contains_point_at(pose_a, &v)? {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// Whether the world point `p` lies in the closed solid bounded by this mesh placed at
    /// `pose`. Equal to [`contains_point`](Self::contains_point) on the placed copy.
    pub fn contains_point_at(
        &self,
        pose: &Isometry3<f64>,
        p: &Point3<f64>,
    ) -> Result<bool, PoseError> {
        let world = self.world_boxes(pose)?;
        let Ok(point) = Segment::new(*p, *p) else {
            return Ok(false);
        };
        let on_ray = |b: &Aabb| {
            b.min[1] <= p.y
                && p.y <= b.max[1]
                && b.min[2] <= p.z
                && p.z <= b.max[2]
                && b.max[0] >= p.x
        };
        let mut crossings = 0usize;
        let on = self
            .posed_candidates(&world, pose, on_ray, |t| {
                if t.tri.intersects(&point) {
                    return ControlFlow::Break(());
                }
                crossings += usize::from(ray_crosses_triangle(t.tri.vertices(), p));
                ControlFlow::Continue(())
            })
            .is_break();
        Ok(on || crossings % 2 == 1)
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the world segment meets.
    pub fn segment_hits_at(
        &self,
        pose: &Isometry3<f64>,
        s: &Segment,
    ) -> Result<Vec<u32>, PoseError> {
        let (p, q) = (*s.a(), *s.b());
        self.hits_at(pose, |b| b.may_meet_segment(&p, &q), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the world triangle meets.
    pub fn triangle_hits_at(
        &self,
        pose: &Isometry3<f64>,
        t: &Triangle,
    ) -> Result<Vec<u32>, PoseError> {
        let tb = Aabb::of_points(t.vertices());
        self.hits_at(pose, |b| b.overlaps(&tb), |u| u.intersects(t))
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the sphere surface meets.
    pub fn sphere_hits_at(&self, pose: &Isometry3<f64>, s: &Sphere) -> Result<Vec<u32>, PoseError> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits_at(pose, |b| b.may_meet_sphere(&c, r), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles of this mesh at `pose` that the solid ball meets.
    pub fn ball_hits_at(&self, pose: &Isometry3<f64>, s: &Ball) -> Result<Vec<u32>, PoseError> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits_at(pose, |b| b.may_meet_ball(&c, r), |t| t.intersects(s))
    }

    fn world_boxes(&self, pose: &Isometry3<f64>) -> Result<WorldBoxes, PoseError> {
        let map = PoseMap::new(pose)?;
        map.check_range(self.extent())?;
        Ok(WorldBoxes::new(&map, self.extent()))
    }

    fn hits_at(
        &self,
        pose: &Isometry3<f64>,
        test: impl Fn(&Aabb) -> bool,
        hit: impl Fn(&Triangle) -> bool,
    ) -> Result<Vec<u32>, PoseError> {
        let world = self.world_boxes(pose)?;
        let mut out = Vec::new();
        let _ = self.posed_candidates::<()>(&world, pose, test, |t| {
            if hit(&t.tri) {
                out.push(t.index);
            }
            ControlFlow::Continue(())
        });
        out.sort_unstable();
        Ok(out)
    }

    /// Calls `visit` with every placed triangle whose (exact, placed) box passes `test`,
    /// reached through nodes whose conservative world boxes pass `test`.
    fn posed_candidates<B>(
        &self,
        world: &WorldBoxes,
        pose: &Isometry3<f64>,
        test: impl Fn(&Aabb) -> bool,
        mut visit: impl FnMut(&Placed) -> ControlFlow<B>,
    ) -> ControlFlow<B> {
        let bvh: &Bvh = self.bvh();
        let nodes = bvh.nodes();
        let mut stack = Vec::with_capacity(64);
        stack.push(0usize);
        while let Some(i) = stack.pop() {
            let node = &nodes[i];
            if !test(&world.world(&node.bounds)) {
                continue;
            }
            let s = node.start as usize;
            if node.is_leaf() {
                for k in s..s + node.count as usize {
                    let placed = place(self.pose_tree(), k, pose);
                    if test(&placed.bounds) {
                        visit(&placed)?;
                    }
                }
            } else {
                stack.push(s + 1);
                stack.push(s);
            }
        }
        ControlFlow::Continue(())
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use nalgebra::{UnitQuaternion, Vector3};
    use proptest::prelude::*;

    fn pose(r: [f64; 3], t: [f64; 3]) -> Isometry3<f64> {
        Isometry3::from_parts(
            nalgebra::Translation3::new(t[0], t[1], t[2]),
            UnitQuaternion::from_euler_angles(r[0], r[1], r[2]),
        )
    }

    proptest! {
        /// The analysed matrix and the rounding bound `δ` cover nalgebra's `pose * v`.
        #[test]
        fn rounding_bound_covers_the_transform(
            r in prop::array::uniform3(-4.0f64..4.0),
            t in prop::array::uniform3(-100.0f64..100.0),
            v in prop::array::uniform3(-1000.0f64..1000.0),
        ) {
            let iso = pose(r, t);
            let map = PoseMap::new(&iso).unwrap();
            let p = iso * Point3::new(v[0], v[1], v[2]);
            let rho = v.iter().fold(0.0f64, |s, x| s.max(x.abs()));
            for i in 0..3 {
                let exactish = map.m[i][0] * v[0] + map.m[i][1] * v[1] + map.m[i][2] * v[2] + t[i];
                // M̂ is within a few ulps of M; the bound must hold with room to spare.
                let slack = map.delta(rho) + 3.0 * rho * map.matrix_error() + 8.0 * U * (3.0 * rho + 100.0);
                prop_assert!((p[i] - exactish).abs() <= slack, "{} vs {}", p[i], exactish);
            }
        }

        /// World boxes of a box hold the placed images of its corners.
        #[test]
        fn world_boxes_hold_placed_points(
            r in prop::array::uniform3(-4.0f64..4.0),
            t in prop::array::uniform3(-10.0f64..10.0),
            lo in prop::array::uniform3(-2.0f64..0.0),
            hi in prop::array::uniform3(0.0f64..2.0),
        ) {
            let iso = pose(r, t);
            let map = PoseMap::new(&iso).unwrap();
            let w = WorldBoxes::new(&map, 2.0);
            let b = Aabb { min: lo, max: hi };
            let wb = w.world(&b);
            for k in 0..8 {
                let c = Point3::new(
                    if k & 1 == 0 { lo[0] } else { hi[0] },
                    if k & 2 == 0 { lo[1] } else { hi[1] },
                    if k & 4 == 0 { lo[2] } else { hi[2] },
                );
                let p = iso * c;
                let point = Aabb { min: p.coords.into(), max: p.coords.into() };
                prop_assert!(wb.overlaps(&point));
            }
        }
    }

    /// Nodes from the leaf of triangle `t` (leaf position in the tree's order) up to the root.
    fn ancestors(c: &Collider, t: u32) -> Vec<usize> {
        let nodes = c.pose_tree().nodes();
        let mut parent = vec![usize::MAX; nodes.len()];
        for (i, n) in nodes.iter().enumerate() {
            if !n.is_leaf() {
                parent[n.start as usize] = i;
                parent[n.start as usize + 1] = i;
            }
        }
        let k = c.bvh().order().iter().position(|&u| u == t).unwrap();
        let mut at = nodes
            .iter()
            .position(|n| n.is_leaf() && (n.start..n.start + n.count).contains(&(k as u32)))
            .unwrap();
        let mut out = vec![at];
        while parent[at] != usize::MAX {
            at = parent[at];
            out.push(at);
        }
        out
    }

    /// Every pair of nodes holding two placed triangles that meet passes the box test under
    /// the poses (not only the pairs the traversal happens to visit), and the traversal finds
    /// exactly the pairs brute force finds. Returns the number of meeting pairs.
    fn box_test_keeps_meeting_pairs(
        a: &Collider,
        pa: &Isometry3<f64>,
        b: &Collider,
        pb: &Isometry3<f64>,
    ) -> Result<usize, TestCaseError> {
        let (wa, wb) = (a.placed(pa).unwrap(), b.placed(pb).unwrap());
        let want = wa.intersecting_pairs(&wb, crate::query::Mode::Brute);
        let pair = PosedPair::new(a, pa, b, pb).unwrap();
        let (na, nb) = (a.pose_tree().nodes(), b.pose_tree().nodes());
        for &(i, j) in &want {
            for &x in &ancestors(a, i) {
                for &y in &ancestors(b, j) {
                    prop_assert!(pair.may_overlap(&na[x], &nb[y]), "{i} {j}: nodes {x} {y}");
                }
            }
        }
        let mut got = pair.collect_pairs(&[(0, 0)]);
        got.sort_unstable();
        prop_assert_eq!(got, want.clone());
        Ok(want.len())
    }

    /// `n` random triangles: centres in `[-spread, spread]³`, corners within `jitter` of them
    /// per coordinate; with `degenerate`, every 5th has a repeated corner. Also used by the
    /// tests of [`super::distance`].
    pub(crate) fn soup(
        seed: u64,
        n: usize,
        spread: f64,
        jitter: f64,
        degenerate: bool,
    ) -> crate::TriMesh {
        // A small local generator (query sits above the `testing` module).
        let mut state = seed;
        let mut float = |lo: f64, hi: f64| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
        };
        let mut v = Vec::new();
        let mut t = Vec::new();
        for k in 0..n as u32 {
            let c = Vector3::new(
                float(-spread, spread),
                float(-spread, spread),
                float(-spread, spread),
            );
            for _ in 0..3 {
                v.push(Point3::from(
                    c + Vector3::new(
                        float(-jitter, jitter),
                        float(-jitter, jitter),
                        float(-jitter, jitter),
                    ),
                ));
            }
            t.push(if degenerate && k % 5 == 0 {
                [3 * k, 3 * k + 1, 3 * k + 1]
            } else {
                [3 * k, 3 * k + 1, 3 * k + 2]
            });
        }
        crate::TriMesh::new(v, t).unwrap()
    }

    /// Exact rotations (identity, half turns about the axes) and rounded quarter turns.
    fn lattice_rotation(k: usize) -> UnitQuaternion<f64> {
        let q = |w, x, y, z| UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(w, x, y, z));
        match k {
            0 => UnitQuaternion::identity(),
            1 => q(0.0, 1.0, 0.0, 0.0),
            2 => q(0.0, 0.0, 1.0, 0.0),
            3 => q(0.0, 0.0, 0.0, 1.0),
            4 => UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
            _ => UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -std::f64::consts::FRAC_PI_2),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Random soups (with degenerate triangles) at random poses, both meshes moved.
        #[test]
        fn box_test_never_rejects_meeting_triangles(
            seed in any::<u64>(),
            ra in prop::array::uniform3(-4.0f64..4.0), ta in prop::array::uniform3(-1.0f64..1.0),
            rb in prop::array::uniform3(-4.0f64..4.0), tb in prop::array::uniform3(-1.0f64..1.0),
        ) {
            let a = Collider::new(soup(seed, 60, 1.0, 0.5, true));
            let b = Collider::new(soup(seed ^ 0x5555, 40, 1.0, 0.5, true));
            box_test_keeps_meeting_pairs(&a, &pose(ra, ta), &b, &pose(rb, tb))?;
        }

        /// Integer cubes in face, edge and corner contact (and coplanar faces) at exact and
        /// quarter-turn rotations: every contact survives the box test.
        #[test]
        fn box_test_keeps_touching_cubes(
            lo in prop::array::uniform3(-2i32..2), size in prop::array::uniform3(1i32..3),
            k in 0usize..6, l in 0usize..6, t in prop::array::uniform3(-3i32..4),
        ) {
            let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
            let f = |p: [i32; 3]| Point3::from(p.map(f64::from));
            let a = Collider::new(crate::TriMesh::cuboid(f(lo), f(hi)).unwrap());
            let b = Collider::new(crate::TriMesh::cuboid(f([0, 0, 0]), f(size)).unwrap());
            let pa = Isometry3::from_parts(nalgebra::Translation3::identity(), lattice_rotation(k));
            let pb = Isometry3::from_parts(
                nalgebra::Translation3::new(t[0] as f64, t[1] as f64, t[2] as f64),
                lattice_rotation(l),
            );
            box_test_keeps_meeting_pairs(&a, &pa, &b, &pb)?;
        }
    }

    /// The cube tests above are not vacuous: exact face contact after a half turn is kept.
    #[test]
    fn touching_after_a_half_turn_is_kept() {
        let f = |x, y, z| Point3::new(x, y, z);
        let a = Collider::new(crate::TriMesh::cuboid(f(0.0, 0.0, 0.0), f(1.0, 1.0, 1.0)).unwrap());
        let pb = Isometry3::from_parts(
            nalgebra::Translation3::new(2.0, 1.0, 0.0),
            lattice_rotation(3),
        );
        let n = box_test_keeps_meeting_pairs(&a, &Isometry3::identity(), &a, &pb).unwrap();
        assert!(n > 0);
    }

    #[test]
    fn bad_poses_are_typed_errors() {
        let c = Collider::new(
            crate::TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap(),
        );
        let id = Isometry3::identity();
        let mut nan = id;
        nan.translation.vector.x = f64::NAN;
        assert_eq!(c.collides_at(&id, &c, &nan), Err(PoseError::NonFinite));
        let q = nalgebra::Quaternion::new(3.0, 0.0, 0.0, 0.0);
        let big = Isometry3::from_parts(
            nalgebra::Translation3::identity(),
            UnitQuaternion::new_unchecked(q),
        );
        assert!(matches!(
            c.collides_at(&id, &c, &big),
            Err(PoseError::NotUnit { .. })
        ));
        let far = Isometry3::translation(1e300, 0.0, 0.0);
        assert!(matches!(
            c.segment_hits_at(
                &far,
                &Segment::new(Point3::origin(), Point3::origin()).unwrap()
            ),
            Err(PoseError::OutOfRange { .. })
        ));
        let _ = Vector3::<f64>::x();
    }
}
