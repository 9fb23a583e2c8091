//! Half-spaces against grown polytopes and against each other.
//!
//! For `H = {x : (x − p)·n ≤ 0}` and a core grown by `r`, the distance is
//! `max(0, min_v (v − p)·n / |n| − r)` over the core's points `v` (a linear function is least at
//! a vertex). So the shape is within `c` of `H` exactly when some core point `v` has
//! `h = (v − p)·n ≤ 0` or `h² ≤ (r + c)²·n·n`: two polynomial signs per point, decided
//! exactly ([`super::staged`]). Two half-spaces always meet unless their normals are exactly
//! opposite (`n_A × n_B = 0`, `n_A·n_B < 0`); then their gap is `(p_B − p_A)·n_A / |n_A|`.

use core::cmp::Ordering;

use ga_core::scalar::Ring;

use super::cores::{Core, ExactPoint, P3};
use super::staged::{exact, filtered, signs, Polys};
use crate::exact::ErrF64;
use crate::query::distance::certify;
use crate::query::CertifiedDistance;
use crate::shape::HalfSpace;
use nalgebra::Point3;

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

/// The normal times a power of two that brings its largest component near 1, when that is
/// exact (the questions are homogeneous in the normal); the normal itself otherwise.
fn scaled_normal(h: &HalfSpace) -> P3 {
    let n = h.normal();
    let m = n.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let s = super::gjk::unit_scale(m);
    let scaled = [n.x * s, n.y * s, n.z * s];
    if scaled.iter().zip(n.iter()).all(|(x, y)| x / s == *y) {
        scaled
    } else {
        [n.x, n.y, n.z]
    }
}

/// `[h, h² − (r + c)²·n·n]` with `h = (v − p)·n`, for one core point `v`.
struct PointSide<'a> {
    v: &'a ExactPoint,
    p: P3,
    n: P3,
    r: f64,
    c: f64,
}

impl Polys<2> for PointSide<'_> {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 2] {
        let v = self.v.lift(lift);
        let n = self.n.map(lift);
        let h = (0..3).fold(R::zero(), |acc, k| {
            acc + (v[k].clone() - lift(self.p[k])) * n[k].clone()
        });
        let nn = (0..3).fold(R::zero(), |acc, k| acc + n[k].clone() * n[k].clone());
        let s = lift(self.r) + lift(self.c);
        [h.clone(), h.clone() * h - s.clone() * s * nn]
    }
}

fn near_enough(signs: [Ordering; 2]) -> bool {
    signs[0] != Ordering::Greater || signs[1] != Ordering::Greater
}

/// A parallelepiped's answer from its lowest corner in closed form, when the error-bounded
/// signs are certain: the least `h` over `centre + Σ s_j U_j`, `|s_j| ≤ 1`, is
/// `(centre − p)·n − Σ |U_j·n|`, and some corner has `h ≤ 0` or `h² ≤ (r + c)²·n·n` exactly when
/// the lowest one has (the others' `h` are larger, so are their squares when it is positive).
fn parallelepiped_side(
    centre: &P3,
    axes: &[P3; 3],
    p: &P3,
    n: &P3,
    r: f64,
    c: f64,
) -> Option<bool> {
    let e = ErrF64::exact;
    let dot = |v: &P3| (0..3).fold(ErrF64::zero(), |acc, k| acc + e(v[k]) * e(n[k]));
    let mut low = (0..3).fold(ErrF64::zero(), |acc, k| {
        acc + (e(centre[k]) - e(p[k])) * e(n[k])
    });
    for axis in axes {
        let d = dot(axis);
        // `|x|` is as far from `|exact|` as `x` is from `exact`.
        low = low
            - ErrF64 {
                value: d.value.abs(),
                error: d.error,
            };
    }
    let s = e(r) + e(c);
    let far = low * low - s * s * dot(n);
    Some(near_enough([low.sign()?, far.sign()?]))
}

/// Exact: is the grown core within `c` of the half-space?
pub(super) fn within_core(h: &HalfSpace, core: &Core, c: f64) -> bool {
    let (p, n) = (p3(h.point()), scaled_normal(h));
    if let Some((centre, axes)) = core.parallelepiped() {
        if let Some(answer) = parallelepiped_side(centre, axes, &p, &n, core.radius, c) {
            return answer;
        }
    }
    let mut undecided = Vec::new();
    for i in 0..core.len() {
        let v = core.point(i);
        let side = PointSide {
            v: &v,
            p,
            n,
            r: core.radius,
            c,
        };
        match filtered(&side) {
            Some(s) if near_enough(s) => return true,
            Some(_) => {}
            None => undecided.push(v),
        }
    }
    undecided.iter().any(|v| {
        near_enough(exact(&PointSide {
            v,
            p,
            n,
            r: core.radius,
            c,
        }))
    })
}

fn norm(v: &P3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The distance between the half-space and the grown core, with witnesses on the core (first)
/// and on the half-space (second).
pub(super) fn distance_core(h: &HalfSpace, core: &Core) -> CertifiedDistance {
    let (p, n) = (p3(h.point()), scaled_normal(h));
    let len = norm(&n);
    let u = n.map(|x| x / len);
    let height = |v: &P3| (0..3).map(|k| (v[k] - p[k]) * u[k]).sum::<f64>();
    let (mut low, mut lowest) = (p, f64::INFINITY);
    let mut scale = core.magnitude();
    for i in 0..core.len() {
        let v = core.approx(i);
        let hv = height(&v);
        if hv < lowest {
            (low, lowest) = (v, hv);
        }
    }
    for x in p {
        scale = scale.max(x.abs());
    }
    let r = core.radius;
    let along = |t: f64| -> Point3<f64> {
        Point3::new(low[0] - t * u[0], low[1] - t * u[1], low[2] - t * u[2])
    };
    let (distance, on_core, on_plane) = if lowest > r {
        (lowest - r, along(r), along(lowest))
    } else {
        let common = along(lowest.max(0.0));
        (0.0, common, common)
    };
    let within = |c: f64| !c.is_finite() || within_core(h, core, c);
    CertifiedDistance {
        distance,
        error_bound: certify(distance, scale, || within(0.0), within, within),
        witness_a: on_core,
        witness_b: on_plane,
        triangles: None,
    }
}

/// The signs of `n_A × n_B` and of `n_A·n_B`.
struct Normals(P3, P3);

impl Polys<4> for Normals {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 4] {
        let (a, b) = (self.0.map(lift), self.1.map(lift));
        let c = |i: usize, j: usize| a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
        let d = (0..3).fold(R::zero(), |acc, k| acc + a[k].clone() * b[k].clone());
        [c(1, 2), c(2, 0), c(0, 1), d]
    }
}

/// `[g, g² − c²·n·n]` with `g = (p_B − p_A)·n_A`.
struct PlaneGap {
    pa: P3,
    pb: P3,
    n: P3,
    c: f64,
}

impl Polys<2> for PlaneGap {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 2] {
        let n = self.n.map(lift);
        let g = (0..3).fold(R::zero(), |acc, k| {
            acc + (lift(self.pb[k]) - lift(self.pa[k])) * n[k].clone()
        });
        let nn = (0..3).fold(R::zero(), |acc, k| acc + n[k].clone() * n[k].clone());
        let c = lift(self.c);
        [g.clone(), g.clone() * g - c.clone() * c * nn]
    }
}

fn opposite(a: &HalfSpace, b: &HalfSpace) -> bool {
    let s = signs(&Normals(scaled_normal(a), scaled_normal(b)));
    s[..3].iter().all(|x| *x == Ordering::Equal) && s[3] == Ordering::Less
}

/// Exact: are the two half-spaces within `c`?
pub(super) fn within_half_spaces(a: &HalfSpace, b: &HalfSpace, c: f64) -> bool {
    if !opposite(a, b) {
        return true;
    }
    near_enough(signs(&PlaneGap {
        pa: p3(a.point()),
        pb: p3(b.point()),
        n: scaled_normal(a),
        c,
    }))
}

/// The distance between two half-spaces (zero unless their normals are exactly opposite),
/// witnesses on each.
pub(super) fn distance_half_spaces(a: &HalfSpace, b: &HalfSpace) -> CertifiedDistance {
    let (pa, pb) = (p3(a.point()), p3(b.point()));
    let (na, nb) = (scaled_normal(a), scaled_normal(b));
    let ua = na.map(|x| x / norm(&na));
    let ub = nb.map(|x| x / norm(&nb));
    let side = |x: &P3, p: &P3, u: &P3| (0..3).map(|k| (x[k] - p[k]) * u[k]).sum::<f64>();
    let scale = pa.iter().chain(&pb).fold(0.0f64, |m, x| m.max(x.abs()));
    let (distance, wa, wb) = if opposite(a, b) {
        let gap = side(&pb, &pa, &ua);
        if gap > 0.0 {
            (gap, pa, core_step(&pa, &ua, gap))
        } else {
            (0.0, pa, pa)
        }
    } else if side(&pa, &pb, &ub) <= 0.0 {
        (0.0, pa, pa)
    } else if side(&pb, &pa, &ua) <= 0.0 {
        (0.0, pb, pb)
    } else {
        // Slide from p_A inside A's plane, against n_B, until B's plane is reached.
        let along = (0..3).map(|k| ua[k] * ub[k]).sum::<f64>();
        let dir: P3 = core::array::from_fn(|k| along * ua[k] - ub[k]);
        let rate = -(0..3).map(|k| dir[k] * ub[k]).sum::<f64>();
        let t = if rate > 0.0 {
            side(&pa, &pb, &ub) / rate
        } else {
            0.0
        };
        let x = core_step(&pa, &dir, t);
        (0.0, x, x)
    };
    let within = |c: f64| !c.is_finite() || within_half_spaces(a, b, c);
    let point = |x: P3| Point3::new(x[0], x[1], x[2]);
    CertifiedDistance {
        distance,
        error_bound: certify(distance, scale, || within(0.0), within, within),
        witness_a: point(wa),
        witness_b: point(wb),
        triangles: None,
    }
}

/// `x + t·u`.
fn core_step(x: &P3, u: &P3, t: f64) -> P3 {
    core::array::from_fn(|k| x[k] + t * u[k])
}
