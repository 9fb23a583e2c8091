//! Cores apart, in closed form: the distance between a point, segment or cuboid core and
//! another, certified from one candidate pair of nearest points.
//!
//! The candidate pair `x̃` (near the core `P`) and `ỹ` (near `Q`) comes from alternating
//! projections (exact nearest points for points and segments, the clamp in the box's frame for
//! cuboids: only a candidate, never trusted). Two proved bounds bracket the core distance `d`:
//! * from above, `d ≤ dist(x̃, P) + dist(x̃, Q)`, each term the manifold's proved `f64` point
//!   bound (the distance to a point of the shape built from clamped exact parameters);
//! * from below, along `n = ỹ − x̃`, `d ≥ (min over Q of n·y − max over P of n·x) / |n|`, both
//!   support values rounded with the bound of [`Prepared::support`] (the same `ñ` on both sides,
//!   so no direction error enters).
//!
//! At the true nearest pair the two meet. The bracket is kept only when its lower end is
//! positive (the cores are proved apart) and its width is within `1024 u` of the coordinates'
//! size (the projections settled); otherwise the certified `f64` search decides.

use super::{Core, Prepared};
use crate::query::shapes::manifold::point_bound;
use crate::query::shapes::rounded_f64::{dot, tame, P3, U};

/// The most projection rounds before the candidate pair is taken as it is.
const ROUNDS: usize = 16;
/// The widest bracket kept, relative to the pair's coordinates: a few hundred roundings.
const TIGHT: f64 = 1024.0 * U;

/// A proved bracket `[low, high]` of the distance between two apart cores and the candidate
/// nearest points `x` (near `a`) and `y` (near `b`).
pub(super) struct Bracket {
    pub(super) low: f64,
    pub(super) high: f64,
    pub(super) x: P3,
    pub(super) y: P3,
}

fn sub(a: &P3, b: &P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The point of `core` nearest `p` (cuboids: the clamp in their frame, nearest when the axes
/// are orthogonal); `None` for cores of more than two points.
fn project(core: &Core, p: &P3) -> Option<P3> {
    match core {
        Core::Points(points) => match points.as_slice() {
            [c] => Some(*c),
            [a, b] => {
                let d = sub(b, a);
                let dd = dot(&d, &d);
                let t = if dd > 0.0 {
                    (dot(&sub(p, a), &d) / dd).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                Some(core::array::from_fn(|k| a[k] + t * d[k]))
            }
            _ => None,
        },
        Core::Cuboid { centre, axes } => {
            let r = sub(p, centre);
            let mut q = *centre;
            for axis in axes {
                let aa = dot(axis, axis);
                let t = if aa > 0.0 {
                    (dot(&r, axis) / aa).clamp(-1.0, 1.0)
                } else {
                    0.0
                };
                for k in 0..3 {
                    q[k] += t * axis[k];
                }
            }
            Some(q)
        }
    }
}

/// A point of `core` (its first point or centre).
fn some_point(core: &Core) -> P3 {
    match core {
        Core::Points(points) => points[0],
        Core::Cuboid { centre, .. } => *centre,
    }
}

/// A proved upper bound of the distance from `p` to `core`.
fn upper(p: &P3, core: &Core) -> Option<f64> {
    match core {
        Core::Points(points) => match points.as_slice() {
            [c] => point_bound::segment(p, c, c, 0.0),
            [a, b] => point_bound::segment(p, a, b, 0.0),
            _ => None,
        },
        Core::Cuboid { centre, axes } => point_bound::cuboid(p, centre, axes),
    }
}

/// `|v|` rounded up.
fn norm_up(v: &P3) -> f64 {
    (dot(v, v).sqrt() * (1.0 + 8.0 * U)).next_up()
}

/// The bracket of the distance between the cores of `a` and `b` (point, segment or cuboid
/// cores only), or `None` when they are not proved apart.
pub(super) fn bracket(a: &Prepared, b: &Prepared) -> Option<Bracket> {
    let mut y = some_point(&b.core);
    let mut x = project(&a.core, &y)?;
    for _ in 0..ROUNDS {
        let y2 = project(&b.core, &x)?;
        let x2 = project(&a.core, &y2)?;
        let settled = x2 == x && y2 == y;
        (x, y) = (x2, y2);
        if settled {
            break;
        }
    }
    if !tame(&x) || !tame(&y) {
        return None;
    }
    let n = sub(&y, &x);
    // Lower end: the separation of the two cores along `ñ`, every rounding paid.
    let (ha, _) = a.support(&n);
    let (hb, _) = b.support(&n.map(|v| -v));
    let gap = -hb - ha;
    let support_error: f64 = (0..3)
        .map(|k| n[k].abs() * (a.extent[k] + b.extent[k]))
        .sum::<f64>()
        * 8.0
        * U;
    let gap_low = (gap - support_error - U * gap.abs()) * (1.0 - 4.0 * U);
    if gap_low <= 0.0 {
        return None;
    }
    let low = gap_low / norm_up(&n) * (1.0 - 2.0 * U);
    // Upper end: through the candidate point `x̃`.
    let high = (upper(&x, &a.core)? + upper(&x, &b.core)?).next_up();
    // Kept only when tight to rounding: alternating projections that have not settled (a
    // segment across a box's edge, say) leave the pair to the `f64` search.
    let scale: f64 = (0..3).map(|k| a.extent[k] + b.extent[k]).sum::<f64>() + high;
    let tight = high - low <= TIGHT * scale;
    (low > 0.0 && high.is_finite() && tight).then_some(Bracket { low, high, x, y })
}

#[cfg(test)]
mod tests {
    use nalgebra::{Isometry3, Point3, Vector3};
    use proptest::prelude::*;

    use super::super::super::{exact_cores, SignedDistanceKind};
    use super::super::{signed_distance as fast, Prepared};
    use super::bracket;
    use crate::shape::{Ball, Capsule, Cuboid, Segment, Shape};

    fn turned_box(half: [f64; 3], centre: [f64; 3], turn: [f64; 3]) -> Shape {
        Cuboid::axis_aligned(Point3::origin(), Vector3::from(half))
            .unwrap()
            .placed(&Isometry3::new(Vector3::from(centre), Vector3::from(turn)))
            .unwrap()
            .into()
    }

    fn rounded(kind: usize, centre: [f64; 3], axis: [f64; 3], r: f64) -> Shape {
        let (c, w) = (Point3::from(centre), Vector3::from(axis));
        match kind {
            0 => Ball::new(c, r).unwrap().into(),
            1 => Capsule::new(c - w, c + w, r).unwrap().into(),
            _ => Segment::new(c - w, c + w).unwrap().into(),
        }
    }

    #[test]
    fn a_capsule_lying_on_a_box_is_bracketed_to_rounding() {
        let ground = turned_box([5.0, 5.0, 0.5], [0.0; 3], [0.0; 3]);
        let capsule = rounded(1, [0.3, -0.2, 0.74], [0.46, 0.19, 0.0], 0.25);
        let core = rounded(2, [0.3, -0.2, 0.74], [0.46, 0.19, 0.0], 0.0);
        let (pa, pb) = (Prepared::of(&ground).unwrap(), Prepared::of(&core).unwrap());
        let br = bracket(&pa, &pb).expect("apart cores");
        let gap = 0.74 - 0.5; // exact
        assert!(br.low <= gap && gap <= br.high && br.high - br.low < 1e-14);
        let got = fast(&ground, &capsule).expect("the closed form answers");
        assert_eq!(got.kind, SignedDistanceKind::Penetrating);
        assert!((got.value - (gap - 0.25)).abs() <= got.error_bound);
        assert!((got.normal - Vector3::z()).norm() <= 1e-15);
    }

    #[test]
    fn meeting_cores_get_no_bracket() {
        let cube = turned_box([0.5; 3], [0.0; 3], [0.1, 0.2, 0.3]);
        let through = rounded(2, [0.0; 3], [2.0, 0.0, 0.0], 0.0);
        let (pa, pb) = (
            Prepared::of(&cube).unwrap(),
            Prepared::of(&through).unwrap(),
        );
        assert!(bracket(&pa, &pb).is_none());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// Balls, capsules and segments against turned boxes: every answer of the fast path
        /// (the closed form whenever the cores are apart) agrees with the exact path within
        /// the two bounds, with the same kind, and its normal with the exact nearest-point
        /// direction.
        #[test]
        fn closed_form_agrees_with_the_exact_path(
            kind in 0usize..3,
            centre in proptest::array::uniform3(-3.0f64..3.0),
            axis in proptest::array::uniform3(-1.0f64..1.0),
            r in 0.01f64..1.5,
            half in proptest::array::uniform3(0.1f64..2.0),
            box_centre in proptest::array::uniform3(-0.5f64..0.5),
            turn in proptest::array::uniform3(-3.0f64..3.0),
        ) {
            let cube = turned_box(half, box_centre, turn);
            let other = rounded(kind, centre, axis, r);
            for (a, b) in [(&cube, &other), (&other, &cube)] {
                let Some(got) = fast(a, b) else { continue };
                let exact = exact_cores(a, b).unwrap();
                prop_assert_eq!(got.kind, exact.kind);
                prop_assert!(
                    (got.value - exact.value).abs() <= got.error_bound + exact.error_bound,
                    "fast {:?} exact {:?}", got, exact
                );
                prop_assert!(got.error_bound <= 1e-13 * (got.value.abs() + 10.0), "{:?}", got);
                prop_assert!((got.normal.norm() - 1.0).abs() <= 1e-15);
                if got.value.abs() > 1e-2 {
                    prop_assert!((got.normal - exact.normal).norm() <= 1e-6, "{:?} {:?}", got, exact);
                }
            }
        }
    }
}
