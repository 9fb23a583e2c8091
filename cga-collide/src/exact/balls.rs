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
pub(crate) fn balls_meet(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
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
/// crate's [`ExactKernel`].
fn balls_meet_exact(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
    // `(r1 + r2)² − |c2 − c1|²` on expansions first (no allocation); the kernel decides what
    // they cannot hold.
    let e = super::Expansion::from_f64;
    let d: [super::Expansion; 3] = core::array::from_fn(|k| e(c2[k]) - e(c1[k]));
    let s = e(r1) + e(r2);
    let room = s * s - (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if let Some(sign) = room.sign() {
        return sign != Ordering::Less;
    }
    ExactKernel::sign::<BallBall, 8>(&[c1[0], c1[1], c1[2], r1, c2[0], c2[1], c2[2], r2])
        != Ordering::Less
}

/// Whether the ball `(c1, r1)` lies inside the ball `(c2, r2)`, exactly.
pub(crate) fn ball_inside(c1: &[f64; 3], r1: f64, c2: &[f64; 3], r2: f64) -> bool {
    if r1 > r2 {
        return false;
    }
    ExactKernel::sign::<BallInBall, 8>(&[c1[0], c1[1], c1[2], r1, c2[0], c2[1], c2[2], r2])
        != Ordering::Less
}

#[cfg(test)]
mod tests {
    use super::{balls_meet, balls_meet_exact};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        /// The `f64` filter of `balls_meet` never disagrees with the exact predicate, on random
        /// balls, on near-tangent ones and at extreme scales.
        #[test]
        fn ball_filter_agrees_with_the_exact_predicate(
            c1 in prop::array::uniform3(-10.0f64..10.0),
            dir in prop::array::uniform3(-1.0f64..1.0),
            r1 in 0.0f64..5.0,
            r2 in 0.0f64..5.0,
            wiggle in -4i64..=4,
            scale in prop::sample::select(vec![1e-300, 1e-160, 1e-10, 1.0, 1e10, 1e150, 1e300]),
        ) {
            let n = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt().max(1e-3);
            // Centre 2 at distance r1 + r2 (tangent up to rounding), nudged by a few ulps.
            let d = (r1 + r2) * (1.0 + wiggle as f64 * f64::EPSILON);
            let c2 = [c1[0] + dir[0] / n * d, c1[1] + dir[1] / n * d, c1[2] + dir[2] / n * d];
            let sc = |v: [f64; 3]| v.map(|x| x * scale);
            for (a, ra, b, rb) in [
                (sc(c1), r1 * scale, sc(c2), r2 * scale),
                (sc(c1), r1 * scale, sc(c1.map(|x| x + 3.0)), r2 * scale),
                (c1, 0.0, c1, 0.0),
                (c1, 0.0, c2, 0.0),
            ] {
                prop_assert_eq!(balls_meet(&a, ra, &b, rb), balls_meet_exact(&a, ra, &b, rb));
            }
        }
    }

    #[test]
    fn ball_filter_exact_cases() {
        // Integer tangency (3-4-5), just apart, just overlapping, coincident points.
        let cases = [
            ([0.0, 0.0, 0.0], 2.0, [3.0, 4.0, 0.0], 3.0, true),
            (
                [0.0, 0.0, 0.0],
                2.0,
                [3.0, 4.0, 0.0],
                2.999_999_999_999_999_6,
                false,
            ),
            (
                [0.0, 0.0, 0.0],
                2.0,
                [3.0, 4.0, 0.0],
                3.000_000_000_000_000_4,
                true,
            ),
            ([1.0, 1.0, 1.0], 0.0, [1.0, 1.0, 1.0], 0.0, true),
            ([1.0, 1.0, 1.0], 0.0, [1.0, 1.0, 2.0], 0.0, false),
            ([1e300, 0.0, 0.0], 1e300, [-1e300, 0.0, 0.0], 1e300, true),
        ];
        for (c1, r1, c2, r2, want) in cases {
            assert_eq!(
                balls_meet_exact(&c1, r1, &c2, r2),
                want,
                "{c1:?} {r1} {c2:?} {r2}"
            );
            assert_eq!(
                balls_meet(&c1, r1, &c2, r2),
                want,
                "{c1:?} {r1} {c2:?} {r2}"
            );
        }
    }
}
