//! Exact tests on closed balls given as raw centres and radii, with a semi-static `f64`
//! filter in front of the exact conformal predicates (the hot path of sphere hierarchies).

use core::cmp::Ordering;

use super::predicates::{BallBall, BallInBall};
use super::{ExactKernel, Kernel};

/// Whether the closed balls `(c1, r1)` and `(c2, r2)` share a point, decided exactly:
/// `|c1 - c2| <= r1 + r2` (touching counts, as the paper's `>=`).
///
/// A semi-static filter decides almost every case in plain `f64`: with `u = 2^-53`, the
/// computed `d² = Σ fl(fl(Δ)²)` is within a factor `1 ± γ5` of `|c1 - c2|²` (three rounded
/// differences, squares and two sums of non-negative terms), and the computed
/// `s² = fl(fl(r1 + r2)²)` within `1 ± γ3` of `(r1 + r2)²`, as long as nothing underflows or
/// overflows; so `d² > s²·(1 + 16u)` (product rounded too) proves the balls apart and
/// `d² < s²·(1 - 16u)` proves them meeting. Anything else (near-tangent balls, values below
/// `1e-290` or infinite) goes to the crate's exact conformal
/// [`BallBall`] predicate (certified filter, then exact arithmetic).
#[inline]
pub fn balls_meet(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
    const TINY: f64 = 1e-290;
    const K: f64 = 16.0 * f64::EPSILON / 2.0; // 16u
    let (dx, dy, dz) = (c2[0] - c1[0], c2[1] - c1[1], c2[2] - c1[2]);
    let d2 = dx * dx + dy * dy + dz * dz;
    let s = r1 + r2;
    let s2 = s * s;
    if d2.is_finite() && s2.is_finite() {
        if d2 == 0.0 && dx == 0.0 && dy == 0.0 && dz == 0.0 {
            return true; // same centre, radii non-negative
        }
        if d2 >= TINY && s2 >= TINY {
            if d2 > s2 * (1.0 + K) {
                return false;
            }
            if d2 < s2 * (1.0 - K) {
                return true;
            }
        } else if d2 >= TINY && s2 == 0.0 {
            return false; // two points at distinct places
        }
    }
    balls_meet_exact(c1, r1, c2, r2)
}

/// [`balls_meet`] without the `f64` filter: the conformal [`BallBall`] predicate through the
/// crate's [`ExactKernel`] (reference for the tests).
pub fn balls_meet_exact(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
    ExactKernel::sign::<BallBall, 8>(&[c1[0], c1[1], c1[2], r1, c2[0], c2[1], c2[2], r2])
        != Ordering::Less
}

/// Whether the ball `(c1, r1)` lies inside the ball `(c2, r2)`, exactly.
pub fn ball_inside(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
    if r1 > r2 {
        return false;
    }
    ExactKernel::sign::<BallInBall, 8>(&[c1[0], c1[1], c1[2], r1, c2[0], c2[1], c2[2], r2])
        != Ordering::Less
}
