//! A rigid pose analysed once, and the proved bounds that make box tests under poses
//! conservative: [`PoseMap`] (a pose's rounded matrix and the constants of its rounding bounds),
//! [`WorldBoxes`] (boxes of a mesh's own frame carried into the world) and [`Relative`] (the
//! motion of one mesh into the other's frame, with its margin).
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

use nalgebra::Isometry3;

use crate::bounding::pose_tree::PoseNode;
use crate::bounding::Aabb;
use crate::error::Error;

/// `2^-53`, the unit roundoff.
pub(crate) const U: f64 = f64::EPSILON / 2.0;
/// Absolute allowance for underflow (generous: the true figure is a few `2^-1074`).
pub(crate) const TINY: f64 = 9.332636185032189e-302; // 2^-1000
/// Largest magnitude for which no bound below can overflow.
pub(crate) const RANGE: f64 = 9.774714424757689e297; // 2^990

pub(crate) type Mat = [[f64; 3]; 3];

/// A pose analysed once: the `f64` matrix of its rotation, its translation and the constants
/// of its rounding bounds.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PoseMap {
    /// `M̂`, row-major.
    pub(crate) m: Mat,
    pub(crate) t: [f64; 3],
    /// `max(|w|, |x|, |y|, |z|)` of the quaternion.
    pub(crate) a: f64,
    /// `max |M̂ᵢⱼ|`.
    pub(crate) mmax: f64,
    /// `|τ|∞`.
    pub(crate) tmax: f64,
}

impl PoseMap {
    pub(crate) fn new(iso: &Isometry3<f64>) -> Result<PoseMap, Error> {
        let q = iso.rotation.quaternion();
        let (w, x, y, z) = (q.w, q.i, q.j, q.k);
        let t = [
            iso.translation.vector.x,
            iso.translation.vector.y,
            iso.translation.vector.z,
        ];
        if ![w, x, y, z].iter().chain(&t).all(|c| c.is_finite()) {
            return Err(Error::NonFinitePose);
        }
        let n2 = w * w + x * x + y * y + z * z;
        if !(0.5..=2.0).contains(&n2) {
            return Err(Error::NotUnitRotation { norm_squared: n2 });
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
    pub(crate) fn delta(&self, rho: f64) -> f64 {
        U * (96.0 * self.a * self.a * rho + 4.0 * rho + 2.0 * self.tmax) + TINY
    }

    /// Bound on `|M - M̂|` per entry.
    pub(crate) fn matrix_error(&self) -> f64 {
        16.0 * U * (1.0 + self.a * self.a) + TINY
    }

    pub(crate) fn check_range(&self, rho: f64) -> Result<(), Error> {
        let magnitude = rho.max(self.tmax);
        if magnitude < RANGE {
            Ok(())
        } else {
            Err(Error::OutOfRange {
                magnitude,
                limit: RANGE,
            })
        }
    }
}

/// `[min, max]` of `t + Σⱼ mⱼ yⱼ` over `y` in the box, for one row `m` (rounded to nearest).
#[inline(always)]
pub(crate) fn row_range(m: &[f64; 3], t: f64, b: &Aabb) -> (f64, f64) {
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
pub(crate) struct WorldBoxes {
    pub(crate) m: Mat,
    pub(crate) t: [f64; 3],
    pub(crate) margin: f64,
}

impl WorldBoxes {
    pub(crate) fn new(pose: &PoseMap, rho: f64) -> WorldBoxes {
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
    pub(crate) fn world(&self, b: &Aabb) -> Aabb {
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
pub(crate) struct Relative {
    pub(crate) r: Mat,
    /// `|r|` entrywise.
    pub(crate) abs_r: Mat,
    pub(crate) t: [f64; 3],
    pub(crate) margin: f64,
    /// `η`: a bound on every entry of `D M̂ - I` (`D = M̂ᵀ` of this frame's pose), so that
    /// every row of `D` has Euclidean length at most `√(1 + η)` and `|D|₂² ≤ 1 + 3η`.
    pub(crate) eta: f64,
}

pub(crate) fn mat_mul(x: &Mat, y: &Mat) -> Mat {
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = x[i][0] * y[0][j] + x[i][1] * y[1][j] + x[i][2] * y[2][j];
        }
    }
    out
}

pub(crate) fn transpose(x: &Mat) -> Mat {
    let mut out = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = x[j][i];
        }
    }
    out
}

impl Relative {
    pub(crate) fn new(pa: &PoseMap, rho_a: f64, pb: &PoseMap, rho_b: f64) -> Relative {
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
    pub(crate) fn may_overlap(&self, a: &PoseNode, b: &PoseNode) -> bool {
        self.may_be_within(a, b, 0.0)
    }

    /// How deeply `b`'s box carried into this frame overlaps `a`'s box: the least of
    /// `reach - |d|` over the three axes of [`may_overlap`](Self::may_overlap), margin left
    /// out (larger is deeper, negative is apart). A heuristic that orders a descent; it
    /// decides nothing, so its rounding does not matter.
    #[inline(always)]
    pub(crate) fn depth(&self, a: &PoseNode, b: &PoseNode) -> f64 {
        let (r, ar) = (&self.r, &self.abs_r);
        let mut least = f64::INFINITY;
        for i in 0..3 {
            let d = r[i][0] * b.c[0] + r[i][1] * b.c[1] + r[i][2] * b.c[2] + self.t[i] - a.c[i];
            let reach = ar[i][0] * b.e[0] + ar[i][1] * b.e[1] + ar[i][2] * b.e[2] + a.e[i];
            least = least.min(reach - d.abs());
        }
        least
    }

    /// The reach `w` to add on every axis of this frame for a clearance `c ≥ 0`:
    /// `w ≥ c √(1 + η) (1 + 16u)` (module docs, clearance), `+∞` if that overflows.
    #[inline]
    pub(crate) fn widen(&self, c: f64) -> f64 {
        c * (1.0 + self.eta) * (1.0 + 32.0 * U)
    }

    /// [`may_overlap`](Self::may_overlap) with every axis test widened by `w` (from
    /// [`widen`](Self::widen)): `false` only if no placed triangle under `a` comes within `c`
    /// of a placed triangle under `b`.
    #[inline(always)]
    pub(crate) fn may_be_within(&self, a: &PoseNode, b: &PoseNode, w: f64) -> bool {
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
