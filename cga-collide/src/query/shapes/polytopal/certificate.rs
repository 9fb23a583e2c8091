//! Certificates checked with rigorous error bounds ([`ErrF64`]): each one, when it holds, proves
//! the answer for the exact real inputs; when none holds the exact search decides.
//!
//! With `S = r_A + r_B + c` (taken exactly) the question is whether the cores are within `S`:
//! * **apart**: a direction `n` with `min_A n·a − max_B n·b > S·|n|` (checked as
//!   `gap > 0` and `gap² > S²·n·n`, with `gap` a proved lower bound), so every pair of
//!   points is farther than `S`;
//! * **close**: weights `λ ≥ 0` over point pairs `(a_k, b_k)` with
//!   `|Σ λ_k (a_k − b_k)|² ≤ S² (Σ λ_k)²`: the convex combinations `x ∈ A`, `y ∈ B` with
//!   these weights are within `S`;
//! * **inside**: four difference points `a_k − b_k` whose tetrahedron holds the origin
//!   (every barycentric coordinate, a ratio of two orientation determinants, `>= 0`): the
//!   cores share a point.

use core::cmp::Ordering;

use ga_core::scalar::Ring;

use super::cores::{Core, P3};
use super::gjk::Found;
use crate::exact::ErrF64;

type E3 = [ErrF64; 3];

fn exact(x: f64) -> ErrF64 {
    ErrF64::exact(x)
}

fn dot(a: &E3, b: &E3) -> ErrF64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: &E3, b: &E3) -> E3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn lifted(core: &Core, i: usize) -> E3 {
    core.point(i).lift(&exact)
}

/// The sum `S` of the radii and the clearance, error-bounded.
fn reach(s: &[f64; 3]) -> ErrF64 {
    exact(s[0]) + exact(s[1]) + exact(s[2])
}

/// Proved bounds `(low, high)` of `min n·x` (or of `max n·x` when `largest`) over the core.
fn extreme_dot(core: &Core, n: &E3, largest: bool) -> (f64, f64) {
    if let Some((centre, axes)) = core.parallelepiped() {
        // Over `c + Σ s_k U_k`, `|s_k| ≤ 1`: `n·c ± Σ |n·U_k|`, each `|n·U_k|` bounded as
        // `n·U_k` is (the absolute value moves a value at most as far as it moves).
        let mut spread = ErrF64::zero();
        for axis in axes {
            let d = dot(&axis.map(exact), n);
            spread = spread
                + ErrF64 {
                    value: d.value.abs(),
                    error: d.error,
                };
        }
        let c = dot(&centre.map(exact), n);
        let d = if largest { c + spread } else { c - spread };
        return (
            (d.value - d.error).next_down(),
            (d.value + d.error).next_up(),
        );
    }
    let mut bounds = (f64::INFINITY, f64::INFINITY);
    if largest {
        bounds = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    }
    for i in 0..core.len() {
        let d = dot(&lifted(core, i), n);
        let lo = (d.value - d.error).next_down();
        let hi = (d.value + d.error).next_up();
        if largest {
            bounds = (bounds.0.max(lo), bounds.1.max(hi));
        } else {
            bounds = (bounds.0.min(lo), bounds.1.min(hi));
        }
    }
    bounds
}

/// `n` with its largest component scaled to about 1 (any direction serves a certificate).
fn unit_direction(v: &P3) -> Option<P3> {
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return None;
    }
    Some(v.map(|x| x / m))
}

/// Proves that the cores are farther apart than `S` along the direction of `v` (a vector of
/// A − B), or returns false.
pub(super) fn apart(a: &Core, b: &Core, v: &P3, s: &[f64; 3]) -> bool {
    let Some(n) = unit_direction(v) else {
        return false;
    };
    let n: E3 = n.map(exact);
    let (low_a, _) = extreme_dot(a, &n, false);
    let (_, high_b) = extreme_dot(b, &n, true);
    let gap = (low_a - high_b).next_down();
    if gap <= 0.0 || !gap.is_finite() {
        return false;
    }
    let g = exact(gap);
    let r = reach(s);
    (g * g - r * r * dot(&n, &n)).sign() == Some(Ordering::Greater)
}

/// Proves that the search's weighted points are within `S` of each other, or returns false.
pub(super) fn close(a: &Core, b: &Core, found: &Found, s: &[f64; 3]) -> bool {
    let mut total = ErrF64::zero();
    let mut gap: E3 = [ErrF64::zero(); 3];
    for (&(ia, ib), &w) in found.pairs().iter().zip(found.weights()) {
        if w < 0.0 || !w.is_finite() {
            return false;
        }
        let wk = exact(w);
        let d = sub(&lifted(a, ia), &lifted(b, ib));
        gap = core::array::from_fn(|k| gap[k] + wk * d[k]);
        total = total + wk;
    }
    if total.value <= 0.0 {
        return false;
    }
    let r = reach(s);
    matches!(
        (r * r * total * total - dot(&gap, &gap)).sign(),
        Some(Ordering::Greater | Ordering::Equal)
    )
}

fn orient(p: [&E3; 4]) -> ErrF64 {
    let (u, v, w) = (sub(p[1], p[0]), sub(p[2], p[0]), sub(p[3], p[0]));
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
}

/// Proves that the search's last tetrahedron of difference points holds the origin, or
/// returns false.
pub(super) fn inside(a: &Core, b: &Core, found: &Found) -> bool {
    if found.pairs().len() != 4 {
        return false;
    }
    let w: Vec<E3> = found
        .pairs()
        .iter()
        .map(|&(ia, ib)| sub(&lifted(a, ia), &lifted(b, ib)))
        .collect();
    let origin: E3 = [ErrF64::zero(); 3];
    let whole = match orient([&w[0], &w[1], &w[2], &w[3]]).sign() {
        Some(s @ (Ordering::Greater | Ordering::Less)) => s,
        _ => return false,
    };
    (0..4).all(|k| {
        let mut p = [&w[0], &w[1], &w[2], &w[3]];
        p[k] = &origin;
        matches!(orient(p).sign(), Some(s) if s == whole || s == Ordering::Equal)
    })
}
