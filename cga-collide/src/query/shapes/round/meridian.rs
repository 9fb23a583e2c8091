//! A point (or a ball) against a cylinder or cone, in the meridian half-plane.
//!
//! Both solids are solids of revolution, so the distance from a point `v` to one is the plane
//! distance, in the half-plane through the axis and `v`, from `(t, ρ)` (axial and radial
//! coordinates of `v`) to the solid's profile: the rectangle `[0, |d|] × [0, r]` for a
//! cylinder, the triangle `(0,0), (|d|,0), (|d|,r)` for a cone with its apex at `0`. Scaled
//! by `|d| = √L` every coordinate lies in `Q(√X, √L)` (`X = |(v − o) × d|²`):
//! `v = (T, √X)`, the rim at `(L, r√L)`, so every comparison is an exact sign in that field.

use core::cmp::Ordering;

use ga_core::scalar::Rational;
use num_traits::{Signed, Zero};

use super::exact3::{cross, dot, norm2, sub, Profile, Round, V3};
use super::surd::{Radicands, Surd};

type P2 = [Surd; 2];

fn diff(a: &P2, b: &P2) -> P2 {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

fn dot2(a: &P2, b: &P2, k: &Radicands) -> Surd {
    &a[0].mul(&b[0], k) + &a[1].mul(&b[1], k)
}

fn cross2(a: &P2, b: &P2, k: &Radicands) -> Surd {
    &a[0].mul(&b[1], k) - &a[1].mul(&b[0], k)
}

/// Is `p` within the squared distance `e2` (rational) of the segment `[u, v]`?
fn segment_within(p: &P2, u: &P2, v: &P2, e2: &Rational, k: &Radicands) -> bool {
    let d = diff(v, u);
    let w = diff(p, u);
    let s = dot2(&w, &d, k);
    let l = dot2(&d, &d, k);
    let limit = Surd::rational(e2.clone());
    if s.sign(k) != Ordering::Greater || l.sign(k) == Ordering::Equal {
        return (&dot2(&w, &w, k) - &limit).sign(k) != Ordering::Greater;
    }
    if (&s - &l).sign(k) != Ordering::Less {
        let wv = diff(p, v);
        return (&dot2(&wv, &wv, k) - &limit).sign(k) != Ordering::Greater;
    }
    // Interior foot: |w|² − s²/l <= e² with l > 0.
    let lhs = &dot2(&w, &w, k).mul(&l, k) - &s.mul(&s, k);
    (&lhs - &limit.mul(&l, k)).sign(k) != Ordering::Greater
}

/// Exact: is the point `v` within distance `e >= 0` (rational) of the cylinder or cone?
pub(crate) fn point_within(round: &Round, v: &V3, e: &Rational) -> bool {
    let rel = sub(v, &round.origin);
    let l = round.length2.clone();
    let k = Radicands {
        x: norm2(&cross(&rel, &round.axis)),
        y: l.clone(),
    };
    let zero = || Surd::rational(Rational::zero());
    let p: P2 = [
        Surd::rational(dot(&rel, &round.axis)),
        Surd::root_x(Rational::from_integer(1.into())),
    ];
    let rim = Surd::root_y(round.radius.clone());
    let profile: Vec<P2> = match round.profile {
        Profile::Cylinder => vec![
            [zero(), zero()],
            [Surd::rational(l.clone()), zero()],
            [Surd::rational(l.clone()), rim.clone()],
            [zero(), rim],
        ],
        Profile::Cone => vec![
            [zero(), zero()],
            [Surd::rational(l.clone()), zero()],
            [Surd::rational(l.clone()), rim],
        ],
    };
    // The profile is counter-clockwise in (t, ρ); with r > 0 it has an interior.
    let edges = || {
        profile
            .iter()
            .zip(profile.iter().cycle().skip(1))
            .take(profile.len())
    };
    if round.radius.is_positive()
        && edges().all(|(u, w)| cross2(&diff(w, u), &diff(&p, u), &k).sign(&k) != Ordering::Less)
    {
        return true;
    }
    let e2 = e * e * &l;
    edges().any(|(u, w)| segment_within(&p, u, w, &e2, &k))
}
