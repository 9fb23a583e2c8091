//! Oriented boxes around the nodes of a hierarchy, and the lower bound on the distance of two
//! of them that orders and prunes the mesh distance searches
//! ([`Collider::distance`](crate::collider::Collider::distance) and
//! [`Collider::distance_at`](crate::collider::Collider::distance_at)).
//!
//! Axis-aligned boxes bound the distance of parts that are turned against the axes (or against
//! each other, under a pose) far worse than boxes that follow the geometry: on bunny00 against
//! the armadillo turned by one radian under a pose, the search with oriented boxes visits 2.4
//! times fewer node pairs and 4.7 times fewer leaf pairs. Each node's box has the principal axes
//! of the vertices under it (from their covariance, built bottom-up; for a leaf, the longest
//! edge and the normal of its largest triangle), or the coordinate axes when those give a
//! smaller box, and the interval of the vertices' projections on each axis.
//!
//! # The boxes are proved
//! A box is three `f64` rows `aᵢ` (the matrix `F`; nearly orthonormal: every entry of
//! `F Fᵀ - I` is at most the tree's `η_F`, computed with the rounding of its evaluation) and
//! intervals `[cᵢ - eᵢ, cᵢ + eᵢ]` that hold the real projection `aᵢ · v` of every vertex `v`
//! under the node. The rounded projections `fl(aᵢ · v)` err by at most
//! `γ₃ Σₖ |aᵢₖ vₖ| ≤ 3.01u |aᵢ|₁ ρ` (`u = 2⁻⁵³`, `ρ` bounding every coordinate); their interval
//! is widened by `4u |aᵢ|₁ ρ + 2⁻¹⁰⁰⁰` and one more step each way, then turned into a centre and
//! a half-extent rounded outward. So `|cᵢ| ≤ 1.8ρ` and `eᵢ ≤ 3.7ρ`. A box is convex, so it
//! holds the node's triangles too. The axes only need to be good for pruning: any rows would
//! give correct boxes.
//!
//! # The bound
//! Let `z = D (x - τ_A)` be A's frame, where the pose queries
//! (the pose queries (`collider/poses.rs`, crate-private; its docs are in the source), "The rounding bound") prove that a placed point of A's node lies
//! within `r_A` (per coordinate) of `O_A`, the node's box, and a placed point of B's node
//! within `r_B` of `R̂ O_B + t̂`, with `R̂`, `t̂` the rounded relative motion and
//! `r_A + r_B ≤ r`, the pose margin (for meshes in one frame: `D = R̂ = I`, `t̂ = 0`, `r = 0`).
//! Write `G = R̂ F_Bᵀ` (its column `j` is `nⱼ = R̂ bⱼ`, B's axis `j` in A's frame) and
//! `M = F_A G`.
//! * On A's axis `i`, a point of `O_A` projects into `[c_Aᵢ ± e_Aᵢ]`, and a point `R̂ w + t̂` of
//!   B projects onto `aᵢ` as `Mᵢ · ζ + aᵢ · t̂` with `ζ = F_B w ∈ [c_B ± e_B]`, up to
//!   `|aᵢ| |R̂| |F_B⁻¹ - F_Bᵀ| |ζ| ≤ 8 η_F ρ_B` (as `|F⁻¹ - Fᵀ|₂ ≤ 4η_F`).
//! * On `nⱼ`, B's points project into `[c_Bⱼ ± e_Bⱼ] + nⱼ · t̂` up to
//!   `|R̂ᵀR̂ - I|₂ |w| ≤ 6 η_R ρ_B` (`η_R` bounding the entries of `R̂ᵀR̂ - I`, computed), and
//!   A's points as `(Mᵀ ξ)ⱼ` with `ξ = F_A v ∈ [c_A ± e_A]`, up to `8 η_F ρ_A`.
//! * The neighbourhoods add `(r_A + r_B) |aᵢ|₁` or `(r_A + r_B) |nⱼ|₁`, under `2r`.
//!
//! So on each of the six directions the two projections are apart by at least
//! `gap = |centre difference| - (Σ |Mᵢⱼ| e + e) - μ`, where the allowance `μ` adds to the above
//! `2048u (ρ_A + ρ_B + |t̂|∞)`, more than the rounding of `G`, `M` and the two sides (sums of
//! at most seven terms of magnitude at most `4(ρ_A + ρ_B) + |t̂|∞`). The rows `aᵢ` have
//! `|F_A|₂² ≤ 1 + 3η_F`, the `nⱼ` have `|G|₂² ≤ (1 + 3η_F)(1 + 3η_R)`, and `|D|₂² ≤ 1 + 3η_D`,
//! so `|x - y|² ≥ Σ gap² (1 - 4η_D - 4η_F - 4η_R)` for the three gaps of either box; the code
//! takes the larger sum, times `1 - 4(η_D + η_F + η_R) - 64u` (which also pays for the
//! squares and the sums). Results below `10⁻²⁹⁰` count as 0, and so does everything when some
//! `η` exceeds `10⁻³` (a pose far from a rotation): the analysis above assumes all of them tiny.

use nalgebra::{Matrix3, Point3, SymmetricEigen, Vector3};

type Mat = [[f64; 3]; 3];

/// Nodes over this many triangles keep the coordinate axes.
const FIT_LIMIT: usize = 256;

pub(crate) const IDENTITY: Mat = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// `2^-53`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;
/// Absolute allowance for underflow.
const TINY: f64 = 9.332636185032189e-302; // 2^-1000
/// Lower bounds below this are dropped: far above the subnormal range, where rounding is
/// absolute rather than relative.
const NORMAL: f64 = 1.0e-290;

/// Centre and half-extent of an interval holding `[lo, hi]` (module docs).
pub(crate) fn centre_half(lo: f64, hi: f64) -> (f64, f64) {
    let c = (lo + hi) * 0.5;
    let m = (hi - c).max(c - lo);
    (c, m * (1.0 + 8.0 * U) + TINY)
}

/// A node's oriented box in its mesh's frame: every vertex `v` under the node has
/// `aᵢ · v ∈ [cᵢ - eᵢ, cᵢ + eᵢ]` (real numbers) for the rows `aᵢ` of `axes` (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct OrientedBox {
    /// The axes `aᵢ`, one per row, nearly orthonormal.
    pub axes: [[f64; 3]; 3],
    /// Centre of the projections on each axis.
    pub c: [f64; 3],
    /// Half-extent of the projections on each axis.
    pub e: [f64; 3],
}

/// First and second moments of a set of points (scaled by the mesh extent, so that nothing
/// overflows): count, sum and sum of outer products.
#[derive(Debug, Clone, Copy, Default)]
struct Moments {
    n: f64,
    sum: Vector3<f64>,
    outer: Matrix3<f64>,
}

impl Moments {
    fn add_point(&mut self, v: Vector3<f64>) {
        self.n += 1.0;
        self.sum += v;
        self.outer += v * v.transpose();
    }

    fn merge(&self, o: &Moments) -> Moments {
        Moments {
            n: self.n + o.n,
            sum: self.sum + o.sum,
            outer: self.outer + o.outer,
        }
    }

    /// Orthonormal principal axes (rows, largest spread first), or the coordinate axes when
    /// the spread has no usable direction.
    fn axes(&self) -> [[f64; 3]; 3] {
        if self.n < 2.0 {
            return IDENTITY;
        }
        let mean = self.sum / self.n;
        let cov = self.outer / self.n - mean * mean.transpose();
        if !cov.iter().all(|x| x.is_finite()) {
            return IDENTITY;
        }
        let eig = SymmetricEigen::new(cov);
        let mut k = [0usize, 1, 2];
        k.sort_by(|&i, &j| eig.eigenvalues[j].total_cmp(&eig.eigenvalues[i]));
        let first = eig.eigenvectors.column(k[0]).into_owned();
        let second = eig.eigenvectors.column(k[1]).into_owned();
        let Some(x) = first.try_normalize(1e-6) else {
            return IDENTITY;
        };
        let Some(y) = (second - x * x.dot(&second)).try_normalize(1e-6) else {
            return IDENTITY;
        };
        right_handed(&x, &y)
    }
}

/// The box with rows `axes` around the triangles `under` (module docs).
fn boxed(axes: Mat, under: &[[Point3<f64>; 3]], rho: f64) -> OrientedBox {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for v in under.iter().flatten() {
        for (k, a) in axes.iter().enumerate() {
            let p = a[0] * v.x + a[1] * v.y + a[2] * v.z;
            lo[k] = lo[k].min(p);
            hi[k] = hi[k].max(p);
        }
    }
    let mut frame = OrientedBox {
        axes,
        c: [0.0; 3],
        e: [0.0; 3],
    };
    for (k, a) in axes.iter().enumerate() {
        let norm1 = a[0].abs() + a[1].abs() + a[2].abs();
        let slack = 4.0 * U * norm1 * rho + TINY;
        (frame.c[k], frame.e[k]) =
            centre_half((lo[k] - slack).next_down(), (hi[k] + slack).next_up());
    }
    frame
}

/// The oriented boxes of a tree's nodes, given as `(start, count)` (leaves: a range of
/// `vertices`, in leaf order; inner nodes: `count = 0` and the left child at `start`, the
/// right one after it, children after their parent) with their axis-aligned boxes as centre
/// and half-extents. `rho` bounds every vertex coordinate.
pub(crate) fn fit(
    nodes: &[(u32, u32)],
    aligned: impl Fn(usize) -> ([f64; 3], [f64; 3]),
    vertices: &[[Point3<f64>; 3]],
    rho: f64,
) -> OrientedBoxes {
    // Children follow their parent: one backward pass gathers each subtree's leaf-order range
    // and moments.
    let mut range = vec![(0usize, 0usize); nodes.len()];
    let mut moments = vec![Moments::default(); nodes.len()];
    let scale = if rho > 0.0 && rho.is_finite() {
        1.0 / rho
    } else {
        1.0
    };
    for (i, &(start, count)) in nodes.iter().enumerate().rev() {
        if count > 0 {
            let (s, e) = (start as usize, (start + count) as usize);
            range[i] = (s, e);
            for t in &vertices[s..e] {
                for v in t {
                    moments[i].add_point(v.coords * scale);
                }
            }
        } else {
            let (l, r) = (start as usize, start as usize + 1);
            range[i] = (range[l].0, range[r].1);
            moments[i] = moments[l].merge(&moments[r]);
        }
    }
    let mut eta = 0.0f64;
    let frames = (0..nodes.len())
        .map(|i| {
            let (s, e) = range[i];
            let (c, e_aligned) = aligned(i);
            let aligned = OrientedBox {
                axes: IDENTITY,
                c,
                e: e_aligned,
            };
            // The principal axes, unless the coordinate axes give a box no larger (symmetric
            // parts, such as a cube's corners, have no useful principal axes). Nodes near the
            // root keep the coordinate axes: a search meets them a few times only, and fitting
            // them would read every vertex once per level.
            if e - s > FIT_LIMIT {
                return aligned;
            }
            let axes = if nodes[i].1 > 0 {
                triangle_axes(&vertices[s..e])
            } else {
                moments[i].axes()
            };
            let principal = boxed(axes, &vertices[s..e], rho);
            let volume = |b: &OrientedBox| b.e[0] * b.e[1] * b.e[2];
            let frame = if volume(&principal) < volume(&aligned) {
                principal
            } else {
                aligned
            };
            for (i, x) in frame.axes.iter().enumerate() {
                for (j, y) in frame.axes.iter().enumerate() {
                    let dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
                    let id = if i == j { 1.0 } else { 0.0 };
                    // `|x|, |y| ≤ 1.01`: the dot product errs by under `4u`.
                    eta = eta.max((dot - id).abs() + 4.0 * U);
                }
            }
            frame
        })
        .collect();
    OrientedBoxes {
        boxes: frames,
        eta: eta * (1.0 + 4.0 * U) + TINY,
    }
}

/// Axes for a leaf's few triangles, without an eigen-decomposition: the longest edge and the
/// normal of its largest triangle (nearly the principal axes of a flat patch).
fn triangle_axes(under: &[[Point3<f64>; 3]]) -> Mat {
    let area2 = |t: &[Point3<f64>; 3]| (t[1] - t[0]).cross(&(t[2] - t[0])).norm_squared();
    let Some(t) = under.iter().max_by(|a, b| area2(a).total_cmp(&area2(b))) else {
        return IDENTITY;
    };
    let edges = [t[1] - t[0], t[2] - t[1], t[0] - t[2]];
    let longest = edges
        .iter()
        .max_by(|a, b| a.norm_squared().total_cmp(&b.norm_squared()))
        .unwrap_or(&edges[0]);
    let (Some(x), Some(z)) = (
        longest.try_normalize(0.0),
        edges[0].cross(&edges[1]).try_normalize(0.0),
    ) else {
        return IDENTITY;
    };
    let Some(y) = z.cross(&x).try_normalize(0.0) else {
        return IDENTITY;
    };
    right_handed(&x, &y)
}

/// The rows `x`, `y`, `x × y` (unit `x` and `y` at right angles), or the coordinate axes if
/// anything is not finite.
fn right_handed(x: &Vector3<f64>, y: &Vector3<f64>) -> Mat {
    let rows = [*x, *y, x.cross(y)].map(|r| [r.x, r.y, r.z]);
    if rows.iter().flatten().all(|v| v.is_finite()) {
        rows
    } else {
        IDENTITY
    }
}

/// The oriented boxes of a tree's nodes and the bound `η_F` on their axes (module docs).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct OrientedBoxes {
    /// One box per node, indexed like the nodes.
    pub boxes: Vec<OrientedBox>,
    /// Bound on every entry of `F Fᵀ - I` over the boxes' axes `F`.
    pub eta: f64,
}

/// The part of the bound that depends on B's node only (see [`OrientedGaps::carry`]).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Carried {
    g: Mat,
    gt: [f64; 3],
}

/// The distance bound of two oriented boxes under a relative motion (module docs).
#[derive(Debug, Clone, Copy)]
pub(crate) struct OrientedGaps {
    /// `R̂`, B's frame into A's.
    r: Mat,
    /// `t̂`.
    t: [f64; 3],
    /// `μ`, subtracted from every gap.
    mu: f64,
    /// The factor taking the larger sum of squared gaps to a lower bound on the squared
    /// distance; 0 turns the bound off.
    shrink: f64,
}

impl OrientedGaps {
    /// The bound for B's boxes carried into A's frame by `r`, `t` (rounded), where placed
    /// points lie within `margin` of the carried boxes and `eta_d` bounds the entries of
    /// `D M̂_A - I` (module docs); `rho_a`, `rho_b` bound the meshes' coordinates and `eta_f`
    /// the boxes' axes.
    pub fn new(
        (r, t): (Mat, [f64; 3]),
        margin: f64,
        eta_d: f64,
        (rho_a, rho_b): (f64, f64),
        eta_f: f64,
    ) -> OrientedGaps {
        // η_R, with the rounding of `R̂ᵀR̂` (`|R̂ᵢⱼ| ≤ rmax`).
        let rmax = r.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut dev = 0.0f64;
        for i in 0..3 {
            for j in 0..3 {
                let g = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
                let id = if i == j { 1.0 } else { 0.0 };
                dev = dev.max((g - id).abs());
            }
        }
        let eta_r = dev * (1.0 + 4.0 * U) + 10.0 * U * rmax * rmax + TINY;
        let tmax = t.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let rho = rho_a + rho_b;
        let mu = 2.0 * (1.0 + 2.0 * eta_r) * (1.0 + 2.0 * eta_f) * margin
            + (16.0 * (1.0 + eta_r) * eta_f + 8.0 * eta_r) * rho
            + 2048.0 * U * (rho + tmax)
            + TINY;
        let usable = eta_d.max(eta_r).max(eta_f) <= 1e-3 && mu.is_finite();
        OrientedGaps {
            r,
            t,
            mu: mu * (1.0 + 64.0 * U),
            shrink: if usable {
                1.0 - 4.0 * (eta_d + eta_r + eta_f) - 64.0 * U
            } else {
                0.0
            },
        }
    }

    /// The bound for two meshes in the same frame, coordinates at most `rho_a` and `rho_b`.
    pub fn same_frame(rho: (f64, f64), eta_f: f64) -> OrientedGaps {
        Self::new((IDENTITY, [0.0; 3]), 0.0, 0.0, rho, eta_f)
    }

    /// The same bound without the rounding allowance `μ` (wrong: to show that `μ` matters).
    #[cfg(test)]
    pub fn without_allowance(mut self) -> OrientedGaps {
        self.mu = 0.0;
        self
    }

    /// A lower bound on the squared distance between anything (placed) in A's box `fa` and
    /// anything in B's box `fb`.
    #[cfg(test)]
    pub fn gap2(&self, fa: &OrientedBox, fb: &OrientedBox) -> f64 {
        self.gap2_carried(fa, &self.offset(fa), fb, &self.carry(fb), f64::INFINITY)
    }

    /// B's box axes carried into A's frame (`G = R̂ F_Bᵀ`, column `j` is `nⱼ`) and `Gᵀ t̂`: the
    /// part of the bound that depends on B's node only, worth keeping for the node's pairs.
    #[inline(always)]
    pub fn carry(&self, fb: &OrientedBox) -> Carried {
        let (r, t, b) = (&self.r, &self.t, &fb.axes);
        let g: Mat = std::array::from_fn(|i| {
            std::array::from_fn(|j| r[i][0] * b[j][0] + r[i][1] * b[j][1] + r[i][2] * b[j][2])
        });
        let gt = std::array::from_fn(|j| g[0][j] * t[0] + g[1][j] * t[1] + g[2][j] * t[2]);
        Carried { g, gt }
    }

    /// [`gap2_carried`](Self::gap2_carried) for a bound made by
    /// [`same_frame`](Self::same_frame): the same numbers, without multiplying by `I` and `0`.
    #[inline(always)]
    pub fn gap2_same_frame(&self, fa: &OrientedBox, fb: &OrientedBox, best: f64) -> f64 {
        let b = &fb.axes;
        let carried = Carried {
            g: std::array::from_fn(|i| std::array::from_fn(|j| b[j][i])),
            gt: [0.0; 3],
        };
        self.gap2_carried(fa, &[0.0; 3], fb, &carried, best)
    }

    /// `F_A t̂`: the part of the bound that depends on A's node only.
    #[inline(always)]
    pub fn offset(&self, fa: &OrientedBox) -> [f64; 3] {
        let (t, a) = (&self.t, &fa.axes);
        std::array::from_fn(|i| a[i][0] * t[0] + a[i][1] * t[1] + a[i][2] * t[2])
    }

    /// The bound from the parts [`offset`](Self::offset) of `fa` and [`carry`](Self::carry)
    /// of `fb`: that of [`gap2`](Self::gap2), or only the bound from A's three axes when that
    /// already exceeds `best` (the caller then prunes the pair, and B's axes are not worth
    /// computing).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // B's axes are the columns of `m`
    pub fn gap2_carried(
        &self,
        fa: &OrientedBox,
        at: &[f64; 3],
        fb: &OrientedBox,
        carried: &Carried,
        best: f64,
    ) -> f64 {
        let (a, g) = (&fa.axes, &carried.g);
        let m: Mat = std::array::from_fn(|i| {
            std::array::from_fn(|j| a[i][0] * g[0][j] + a[i][1] * g[1][j] + a[i][2] * g[2][j])
        });
        let (mut on_a, mut on_b) = (0.0, 0.0);
        for i in 0..3 {
            let d = m[i][0] * fb.c[0] + m[i][1] * fb.c[1] + m[i][2] * fb.c[2] + at[i] - fa.c[i];
            let reach = m[i][0].abs() * fb.e[0]
                + m[i][1].abs() * fb.e[1]
                + m[i][2].abs() * fb.e[2]
                + fa.e[i]
                + self.mu;
            let gap = (d.abs() - reach).max(0.0);
            on_a += gap * gap;
        }
        let lb_a = self.lower(on_a);
        if lb_a > best {
            return lb_a;
        }
        for j in 0..3 {
            let d =
                m[0][j] * fa.c[0] + m[1][j] * fa.c[1] + m[2][j] * fa.c[2] - fb.c[j] - carried.gt[j];
            let reach = m[0][j].abs() * fa.e[0]
                + m[1][j].abs() * fa.e[1]
                + m[2][j].abs() * fa.e[2]
                + fb.e[j]
                + self.mu;
            let gap = (d.abs() - reach).max(0.0);
            on_b += gap * gap;
        }
        lb_a.max(self.lower(on_b))
    }

    /// A sum of squared gaps as a lower bound on the squared distance.
    #[inline(always)]
    fn lower(&self, sum: f64) -> f64 {
        let lb = sum * self.shrink;
        if lb >= NORMAL {
            lb
        } else {
            0.0
        }
    }
}
