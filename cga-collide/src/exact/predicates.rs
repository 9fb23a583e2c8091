//! The polynomial predicates, each written once as straight-line code generic over
//! [`Ring`] so that the same code runs on `f64`, on the error-bounded
//! [`ErrF64`](crate::exact::ErrF64) and on exact integers / rationals. The conformal vectors
//! are the generated `ga_core::cga::Vector` with its generated scalar product.
//!
//! They are phrased in the conformal model (`docs/conventions.md`): with the thesis's scaling
//! `X = 2·up(x) = 2x + (|x|² - 1) e4 + (|x|² + 1) e5` (no division, so it stays in a ring) and
//! the sphere `S = 2·up(c) - r² n_inf`, the inner product gives `X·S = -2(|x - c|² - r²)`,
//! `S·S = 4r²` and `S1·S2 = 2(r1² + r2² - |c1 - c2|²)`; the plane
//! `up(a) ∧ up(b) ∧ up(c) ∧ up(d) ∧ n_inf` is exactly `orient3d(a, b, c, d)` times the
//! pseudoscalar `e12345` (checked against the generated algebra in
//! `tests/predicates_conformal.rs`). Every predicate first translates its inputs so
//! that one of them is the origin (exact in the rational evaluation, and it keeps the `f64`
//! error bounds small: the conformal embedding is not translation invariant in `f64`).

use crate::exact::vector::{cross, dot, sub};
use ga_core::cga::{self, Vector};
use ga_core::prelude::*;

use crate::exact::Predicate;

type V3<R> = [R; 3];

#[inline(always)]
fn v3<R: Ring>(x: &[R], i: usize) -> V3<R> {
    [x[i].clone(), x[i + 1].clone(), x[i + 2].clone()]
}

/// `2·up(x) = 2x + (|x|² - 1) e4 + (|x|² + 1) e5` as a generated [`cga::Vector`].
#[inline(always)]
fn up2<R: Ring>(x: &V3<R>) -> Vector<R> {
    let two = R::from_i64(2);
    let q = dot(x, x);
    Vector::new(
        two.clone() * x[0].clone(),
        two.clone() * x[1].clone(),
        two * x[2].clone(),
        q.clone() - R::one(),
        q + R::one(),
    )
}

/// The dual sphere `2·up(c) - r² n_inf`.
#[inline(always)]
fn sphere2<R: Ring>(c: &V3<R>, r: &R) -> Vector<R> {
    up2(c) - cga::n_inf::<R>().scale(&(r.clone() * r.clone()))
}

/// The inner product of two conformal vectors (the generated scalar product).
#[inline(always)]
fn inner<R: Ring>(a: &Vector<R>, b: &Vector<R>) -> R {
    a.scalar_product(b)
}

/// `|w × d|² - r2·|d|²` with `d = b - a`, `w = c - a` for the points `a, b, c` at the start of
/// `x`: shared by [`LineDistance`] (`r2 = r²`) and [`LineReach`] (`r2` a squared reach).
#[inline(always)]
fn line_gap<R: Ring>(x: &[R], r2: R) -> R {
    let a = v3(x, 0);
    let d = sub(&v3(x, 3), &a);
    let w = sub(&v3(x, 6), &a);
    let m = cross(&w, &d);
    dot(&m, &m) - r2 * dot(&d, &d)
}

/// `(n·(q - a))² - r2·|n|²` with `n = (b - a) × (c - a)` for the points `a, b, c, q` at the
/// start of `x`: shared by [`PlaneDistance`] and [`PlaneReach`].
#[inline(always)]
fn plane_gap<R: Ring>(x: &[R], r2: R) -> R {
    let a = v3(x, 0);
    let n = cross(&sub(&v3(x, 3), &a), &sub(&v3(x, 6), &a));
    let h = dot(&n, &sub(&v3(x, 9), &a));
    h.clone() * h - r2 * dot(&n, &n)
}

/// For the segments `ab`, `cd` at the start of `x`: `u = b - a`, `v = d - c`, `w = c - a` and
/// `n = u × v` (the line–line predicates).
#[inline(always)]
fn line_line<R: Ring>(x: &[R]) -> (V3<R>, V3<R>, V3<R>, V3<R>) {
    let a = v3(x, 0);
    let u = sub(&v3(x, 3), &a);
    let v = sub(&v3(x, 9), &v3(x, 6));
    let w = sub(&v3(x, 6), &a);
    let n = cross(&u, &v);
    (u, v, w, n)
}

/// `orient3d(a, b, c, d) = (b - a) × (c - a) · (d - a)`, inputs `[a, b, c, d]` (12 numbers):
/// the `e12345` coefficient of `up(a) ∧ up(b) ∧ up(c) ∧ up(d) ∧ n_inf`, expanded by hand in the
/// frame translated to `a` (the literal generated-wedge version is [`Orient3dCga`]; the
/// benchmark `orient3d` shows it is about 7x slower, so the kernels use this one).
pub struct Orient3d;
impl Predicate<12> for Orient3d {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let a = v3(x, 0);
        let u = sub(&v3(x, 3), &a);
        let v = sub(&v3(x, 6), &a);
        let w = sub(&v3(x, 9), &a);
        dot(&cross(&u, &v), &w)
    }
    #[inline]
    fn exact_sign_direct(x: &[f64; 12]) -> Option<core::cmp::Ordering> {
        crate::exact::expansion::orient3d_sign(x)
    }
}

macro_rules! normal_component {
    ($name:ident, $i:expr, $doc:expr) => {
        #[doc = $doc]
        pub struct $name;
        impl Predicate<9> for $name {
            #[inline(always)]
            fn eval<R: Ring>(x: &[R; 9]) -> R {
                let a = v3(x, 0);
                let u = sub(&v3(x, 3), &a);
                let v = sub(&v3(x, 6), &a);
                let [n0, n1, n2] = cross(&u, &v);
                [n0, n1, n2][$i].clone()
            }
            /// Component `i` of the normal is `orient2d` of the corners projected on the two
            /// other axes, taken in cyclic order (`j = i + 1`, `k = i + 2`).
            #[inline]
            fn exact_sign_direct(x: &[f64; 9]) -> Option<core::cmp::Ordering> {
                let (j, k) = (($i + 1) % 3, ($i + 2) % 3);
                crate::exact::expansion::orient2d_sign(&[
                    x[j],
                    x[k],
                    x[3 + j],
                    x[3 + k],
                    x[6 + j],
                    x[6 + k],
                ])
            }
        }
    };
}
normal_component!(
    NormalX,
    0,
    "The x component of the normal `(b - a) × (c - a)`, inputs `[a, b, c]`."
);
normal_component!(
    NormalY,
    1,
    "The y component of the normal `(b - a) × (c - a)`, inputs `[a, b, c]`."
);
normal_component!(
    NormalZ,
    2,
    "The z component of the normal `(b - a) × (c - a)`, inputs `[a, b, c]`."
);

/// `orient2d(a, b, c) = (b - a) × (c - a)` in the plane, inputs `[a, b, c]` (6 numbers).
pub struct Orient2d;
impl Predicate<6> for Orient2d {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 6]) -> R {
        let ux = x[2].clone() - x[0].clone();
        let uy = x[3].clone() - x[1].clone();
        let vx = x[4].clone() - x[0].clone();
        let vy = x[5].clone() - x[1].clone();
        ux * vy - uy * vx
    }
    #[inline]
    fn exact_sign_direct(x: &[f64; 6]) -> Option<core::cmp::Ordering> {
        crate::exact::expansion::orient2d_sign(x)
    }
}

/// `(c - a)·(b - a)`, inputs `[a, b, c]`: where the foot of `c` lies along the segment `ab`
/// (the contraction of the points' differences; `up(c)·up(a)`-type products reduce to it).
pub struct SegmentDot;
impl Predicate<9> for SegmentDot {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 9]) -> R {
        let a = v3(x, 0);
        dot(&sub(&v3(x, 6), &a), &sub(&v3(x, 3), &a))
    }
}

/// `2(|p - c|² - r²) = -X·S` for the conformal point `X = 2·up(p - c)` and the dual sphere
/// `S = 2·up(0) - r² n_inf`; inputs `[p, c, r]` (7 numbers). Negative inside the ball, zero on
/// the sphere.
pub struct PointPower;
impl Predicate<7> for PointPower {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 7]) -> R {
        let p = sub(&v3(x, 0), &v3(x, 3));
        let zero = [R::zero(), R::zero(), R::zero()];
        -inner(&up2(&p), &sphere2(&zero, &x[6]))
    }
}

/// `|w × d|² - r²|d|²` with `d = b - a`, `w = c - a`, inputs `[a, b, c, r]` (10 numbers):
/// `|d|²` times (squared distance from `c` to the line `ab` minus `r²`).
pub struct LineDistance;
impl Predicate<10> for LineDistance {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 10]) -> R {
        line_gap(x, x[9].clone() * x[9].clone())
    }
}

/// `n·((b - a) × (q - a))` with `n = (b - a) × (c - a)`, inputs `[a, b, c, q]`: non-negative
/// exactly when the projection of `q` on the plane lies on the inner side of edge `ab`.
pub struct EdgeSide;
impl Predicate<12> for EdgeSide {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let a = v3(x, 0);
        let u = sub(&v3(x, 3), &a);
        let v = sub(&v3(x, 6), &a);
        let w = sub(&v3(x, 9), &a);
        dot(&cross(&u, &v), &cross(&u, &w))
    }
}

/// `(n·(q - a))² - r²|n|²` with `n = (b - a) × (c - a)`, inputs `[a, b, c, q, r]`: `|n|²` times
/// (squared distance from `q` to the plane minus `r²`).
pub struct PlaneDistance;
impl Predicate<13> for PlaneDistance {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 13]) -> R {
        plane_gap(x, x[12].clone() * x[12].clone())
    }
}

/// The thesis's `B²` for two spheres: `(S1·S2)² - (S1·S1)(S2·S2)` with the dual spheres
/// `S1 = 2·up(0) - r1² n_inf`, `S2 = 2·up(c2 - c1) - r2² n_inf`; inputs `[c1, r1, c2, r2]`.
/// The surfaces meet exactly when it is `<= 0` (`= 0`: tangent or coincident).
pub struct SphereSphere;
impl Predicate<8> for SphereSphere {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 8]) -> R {
        let zero = [R::zero(), R::zero(), R::zero()];
        let d = sub(&v3(x, 4), &v3(x, 0));
        let s1 = sphere2(&zero, &x[3]);
        let s2 = sphere2(&d, &x[7]);
        let s12 = inner(&s1, &s2);
        s12.clone() * s12 - inner(&s1, &s1) * inner(&s2, &s2)
    }
}

/// `S1·S2 + 4 r1 r2 = 2((r1 + r2)² - |c1 - c2|²)` with the dual spheres of [`SphereSphere`];
/// inputs `[c1, r1, c2, r2]`. The balls meet exactly when it is `>= 0`.
pub struct BallBall;
impl Predicate<8> for BallBall {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 8]) -> R {
        let zero = [R::zero(), R::zero(), R::zero()];
        let d = sub(&v3(x, 4), &v3(x, 0));
        let s1 = sphere2(&zero, &x[3]);
        let s2 = sphere2(&d, &x[7]);
        inner(&s1, &s2) + R::from_i64(4) * x[3].clone() * x[7].clone()
    }
}

/// `orient3d` computed with the generated outer product: the pseudoscalar coefficient of
/// `2up(0) ∧ 2up(b - a) ∧ 2up(c - a) ∧ 2up(d - a) ∧ n_inf`, which is `-16·orient3d(a, b, c, d)`
/// (see the tests). Inputs as [`Orient3d`]. Kept as the literal conformal formulation and
/// benchmarked against the expanded [`Orient3d`], which the kernels use.
pub struct Orient3dCga;
impl Predicate<12> for Orient3dCga {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let a = v3(x, 0);
        let zero = [R::zero(), R::zero(), R::zero()];
        let o = up2(&zero);
        let b = up2(&sub(&v3(x, 3), &a));
        let c = up2(&sub(&v3(x, 6), &a));
        let d = up2(&sub(&v3(x, 9), &a));
        let plane = o.wedge(&b).wedge(&c).wedge(&cga::n_inf::<R>());
        -plane.wedge(&d).e12345
    }
}

// ---------------------------------------------------------------- clearance (distance <= reach)
//
// The clearance predicates compare squared distances with the square of a *reach*
// `r0 + r1 + r2` summed inside the ring (exact in the exact evaluation), so that "within `c`
// of a ball of radius `r`" is decided without rounding `r + c` in `f64`.

#[inline(always)]
fn reach2<R: Ring>(x: &[R], i: usize) -> R {
    let r = x[i].clone() + x[i + 1].clone() + x[i + 2].clone();
    r.clone() * r
}

/// `|p - q|² - (r0 + r1 + r2)²`, inputs `[p, q, r0, r1, r2]` (9 numbers): negative or zero
/// exactly when `p` is within the reach of `q` (for a non-negative reach).
pub struct CentreDistance;
impl Predicate<9> for CentreDistance {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 9]) -> R {
        let d = sub(&v3(x, 0), &v3(x, 3));
        dot(&d, &d) - reach2(x, 6)
    }
}

/// `r0 + r1 + r2`, inputs `[r0, r1, r2]`: the sign of a sum of radii and clearances.
pub struct ReachSign;
impl Predicate<3> for ReachSign {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 3]) -> R {
        x[0].clone() + x[1].clone() + x[2].clone()
    }
}

/// [`LineDistance`] with the reach `r0 + r1 + r2`: `|w × d|² - (Σr)²|d|²`, inputs
/// `[a, b, c, r0, r1, r2]` (12 numbers).
pub struct LineReach;
impl Predicate<12> for LineReach {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        line_gap(x, reach2(x, 9))
    }
}

/// [`PlaneDistance`] with the reach `r0 + r1 + r2`: `(n·(q - a))² - (Σr)²|n|²`, inputs
/// `[a, b, c, q, r0, r1, r2]` (15 numbers).
pub struct PlaneReach;
impl Predicate<15> for PlaneReach {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 15]) -> R {
        plane_gap(x, reach2(x, 12))
    }
}

/// `|n|²` with `n = (b - a) × (d - c)`, inputs `[a, b, c, d]`: zero exactly when the segments
/// `ab` and `cd` are parallel (or one is a point).
pub struct CrossNorm2;
impl Predicate<12> for CrossNorm2 {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let (_, _, _, n) = line_line(x);
        dot(&n, &n)
    }
}

/// `((c - a) × (d - c))·n` with `n = (b - a) × (d - c)`, inputs `[a, b, c, d]`: `|n|²` times the
/// parameter `s` of the point `a + s(b - a)` of line `ab` nearest to line `cd`.
pub struct LineLineParam;
impl Predicate<12> for LineLineParam {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let (_, v, w, n) = line_line(x);
        dot(&cross(&w, &v), &n)
    }
}

/// `|n|² - ((c - a) × (d - c))·n`: `|n|²` times `1 - s` for the `s` of [`LineLineParam`].
pub struct LineLineParamRest;
impl Predicate<12> for LineLineParamRest {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let (_, v, w, n) = line_line(x);
        dot(&n, &n) - dot(&cross(&w, &v), &n)
    }
}

/// `(n·(c - a))² - r²|n|²` with `n = (b - a) × (d - c)`, inputs `[a, b, c, d, r]` (13 numbers):
/// `|n|²` times (squared distance between the lines `ab` and `cd` minus `r²`).
pub struct LineLineReach;
impl Predicate<13> for LineLineReach {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 13]) -> R {
        let (_, _, w, n) = line_line(x);
        let h = dot(&n, &w);
        h.clone() * h - x[12].clone() * x[12].clone() * dot(&n, &n)
    }
}

/// `(r2 - r1)^2 - |c1 - c2|^2`, inputs `[c1, r1, c2, r2]`: with `r2 >= r1` the ball 1 lies in
/// ball 2 exactly when it is `>= 0`.
pub struct BallInBall;
impl Predicate<8> for BallInBall {
    fn eval<R: Ring>(x: &[R; 8]) -> R {
        let d0 = x[4].clone() - x[0].clone();
        let d1 = x[5].clone() - x[1].clone();
        let d2 = x[6].clone() - x[2].clone();
        let dr = x[7].clone() - x[3].clone();
        dr.clone() * dr - (d0.clone() * d0 + d1.clone() * d1 + d2.clone() * d2)
    }
}

/// `(b_j - a_j)(p_k - q_k) - (b_k - a_k)(p_j - q_j)`, inputs `[a_j, a_k, b_j, b_k, p_j, p_k,
/// q_j, q_k]`: the component of `(e_i × (b - a))·(p - q)` for the axis `i` completing `j, k`.
pub struct EdgeAxis;
impl Predicate<8> for EdgeAxis {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 8]) -> R {
        let dj = x[2].clone() - x[0].clone();
        let dk = x[3].clone() - x[1].clone();
        let wj = x[4].clone() - x[6].clone();
        let wk = x[5].clone() - x[7].clone();
        dj * wk - dk * wj
    }
}

/// The hand-written expansion signs ([`orient3d_sign`](crate::exact::expansion::orient3d_sign),
/// the direct normal components) against the big-integer signs of the same predicates.
#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::expansion::{orient2d_sign, orient3d_sign, Expansion};
    use crate::exact::sign::exact_sign;

    fn e(x: f64) -> Expansion {
        Expansion::from_f64(x)
    }

    /// A homogeneous degree-6 polynomial: `orient3d(x)^2 - 3 orient3d(x')^2` (`x'` with two
    /// coordinates swapped).
    struct Sextic;
    impl Predicate<12> for Sextic {
        fn eval<R: Ring>(x: &[R; 12]) -> R {
            let o = crate::exact::predicates::Orient3d::eval(x);
            let mut y = x.clone();
            y.swap(0, 3);
            let p = crate::exact::predicates::Orient3d::eval(&y);
            o.clone() * o - p.clone() * p * R::from_i64(3)
        }
    }

    #[test]
    fn orientations_agree_with_big_integers_on_inexact_differences() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for round in 0..20_000 {
            let scale = [1.0, 3.1e-40, 7.9e45, 1e-3][round % 4];
            // Four points, the last on the plane of the first three up to rounding (so the
            // exact sign is often decided far below the filter's reach), or exactly coplanar
            // with axis-parallel structure.
            let a = [next(), next(), next()];
            let u = [next(), next(), next()];
            let v = [next(), next(), next()];
            let (s, t) = (next(), next());
            let x: [f64; 12] = core::array::from_fn(|i| {
                let k = i % 3;
                let value = match i / 3 {
                    0 => a[k],
                    1 => a[k] + u[k],
                    2 => a[k] + v[k],
                    _ => a[k] + s * u[k] + t * v[k],
                };
                value * scale
            });
            if let Some(direct) = orient3d_sign(&x) {
                let want = exact_sign::<crate::exact::predicates::Orient3d, 12>(&x);
                assert_eq!(direct, want, "{x:?}");
            }
            // The normal components are orientations of projections.
            let corners: [f64; 9] = core::array::from_fn(|i| x[i]);
            for (direct, want) in [
                (
                    crate::exact::predicates::NormalX::exact_sign_direct(&corners),
                    exact_sign::<crate::exact::predicates::NormalX, 9>(&corners),
                ),
                (
                    crate::exact::predicates::NormalY::exact_sign_direct(&corners),
                    exact_sign::<crate::exact::predicates::NormalY, 9>(&corners),
                ),
                (
                    crate::exact::predicates::NormalZ::exact_sign_direct(&corners),
                    exact_sign::<crate::exact::predicates::NormalZ, 9>(&corners),
                ),
            ] {
                if let Some(direct) = direct {
                    assert_eq!(direct, want, "{corners:?}");
                }
            }
            let y: [f64; 6] = [x[0], x[1], x[3], x[4], x[9], x[10]];
            if let Some(direct) = orient2d_sign(&y) {
                let want = exact_sign::<crate::exact::predicates::Orient2d, 6>(&y);
                assert_eq!(direct, want, "{y:?}");
            }
        }
    }

    #[test]
    fn signs_agree_with_big_integers() {
        // A small xorshift generator (no dependency on the crate's test support).
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next_f64 = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for round in 0..4000 {
            let scale = [1.0, 1e-30, 1e30, 3.7e5][round % 4];
            // Coplanar-ish inputs on a coarse grid, then a few random low bits.
            let x: [f64; 12] = core::array::from_fn(|i| {
                let g = (next_f64() * 8.0).floor() - 4.0;
                let jitter = if round % 3 == 0 && i == 11 {
                    next_f64() * 1e-12
                } else {
                    0.0
                };
                (g + jitter) * scale
            });
            let ex: [Expansion; 12] = core::array::from_fn(|i| e(x[i]));
            // The hand-written orientations, wherever they answer.
            let o3 = exact_sign::<crate::exact::predicates::Orient3d, 12>(&x);
            if let Some(direct) = orient3d_sign(&x) {
                assert_eq!(direct, o3, "{x:?}");
            }
            let x2: [f64; 6] = core::array::from_fn(|i| x[i + 3]);
            if let Some(direct) = orient2d_sign(&x2) {
                assert_eq!(
                    direct,
                    exact_sign::<crate::exact::predicates::Orient2d, 6>(&x2),
                    "{x2:?}"
                );
            }
            for (got, want) in [
                (
                    crate::exact::predicates::Orient3d::eval(&ex).sign(),
                    exact_sign::<crate::exact::predicates::Orient3d, 12>(&x),
                ),
                (Sextic::eval(&ex).sign(), exact_sign::<Sextic, 12>(&x)),
            ] {
                if let Some(got) = got {
                    assert_eq!(got, want, "{x:?}");
                }
            }
        }
    }
}
