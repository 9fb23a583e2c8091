//! Signed distance of a pair with a cylinder or a cone (neither a half-space), bracketed
//! between an inner polytope and a support-function bound.
//!
//! For convex `A`, `B` and `K = A − B`, let `F = min over unit n of h_K(n)` with
//! `h_K(n) = h_A(n) + h_B(−n)`: the signed distance is `−F` (when the origin is outside `K`,
//! `−F` is its distance to `K`; inside, `F` is its depth). So
//! * **lower bound of `F`**: replace each cylinder or cone by the hull of `f64` points proved
//!   inside it ([`super::inner`]). The inner difference `K_in ⊆ K` has `h_{K_in} ≤ h_K`,
//!   hence `F_in ≤ F`, and `F_in` is minus the signed distance of two polytopal shapes, which
//!   the polytope engine gives exactly up to one rounding with its bound;
//! * **upper bound of `F`**: `h_K(n) / |n|` for any `n`, evaluated with outward rounding
//!   ([`super::body`]); the direction taken is the inner pair's normal.
//!
//! The inner hulls are refined where they matter: rim points extreme along the current normal
//! (and turned from it by a shrinking angle) are added, until the bracket is within a few
//! dozen ulps of the pair's scale or the hull would exceed its size cap. The reported value is
//! the midpoint of the bracket of `−F` and `error_bound` its half width (rounded up), so the
//! bound is proved whatever the refinement reached.
//!
//! The kind is decided exactly: `intersects` (exact for these pairs, or the pair is refused as
//! it is there) tells apart from meeting; meeting pairs are penetrating when the lower bound
//! is positive, and touching when `h_K(n) ≤ 0` is proved exactly for a tried direction
//! ([`super::body::gap_is_nonpositive`]). A meeting pair that is neither proved is refused
//! ([`Error::UnsupportedPair`]): its depth is below the bound but its sign is not known.

use nalgebra::{Point3, Vector3};

use super::body::{gap_is_nonpositive, gap_upper, Body, P3};
use super::rounding::midpoint;
use super::{inner, unit, SignedDistance, SignedDistanceKind};
use crate::error::Error;
use crate::shape::{ConvexHull, Shape};

/// Rim points per cap disc at the start.
const START_RIM: usize = 16;
/// The most refinement rounds.
const MAX_ROUNDS: usize = 12;
/// The most points an inner hull may take (below the polytope depth's cap).
const MAX_POINTS: usize = super::MAX_HULL_POINTS - 8;
/// The bracket width, in units of `2^-52 ·` scale, at which refinement stops.
const TARGET_ULPS: f64 = 32.0;

/// A pair member: its body and, for a round one, its inner points.
struct Member {
    body: Body,
    points: Vec<P3>,
}

impl Member {
    fn new(body: Body) -> Member {
        let points = inner::initial(&body, START_RIM);
        Member { body, points }
    }

    /// The polytopal shape the depth search uses in place of this one.
    fn inner(&self) -> Option<Shape> {
        match &self.body {
            Body::Polytopal { shape, .. } => Some(shape.clone()),
            _ => ConvexHull::new(self.points.iter().map(|p| Point3::from(*p)).collect())
                .ok()
                .map(Shape::from),
        }
    }

    /// Adds rim points around the extreme along `n`; `false` when the cap is reached.
    fn refine(&mut self, n: &Vector3<f64>, spread: f64) -> bool {
        if matches!(self.body, Body::Polytopal { .. }) {
            return true;
        }
        let more = inner::around(&self.body, n, spread);
        if self.points.len() + more.len() > MAX_POINTS {
            return false;
        }
        for p in more {
            if !self.points.contains(&p) {
                self.points.push(p);
            }
        }
        true
    }
}

fn unsupported(a: &Shape, b: &Shape) -> Error {
    super::unsupported(a, b)
}

/// The bracket `lo ≤ F ≤ hi` found, with the direction of the best upper bound and every
/// direction tried.
struct Bracket {
    lo: f64,
    hi: f64,
    normal: Vector3<f64>,
    tried: Vec<Vector3<f64>>,
}

fn p3(v: &Vector3<f64>) -> P3 {
    [v.x, v.y, v.z]
}

fn bracket(a: &mut Member, b: &mut Member, whole: (&Shape, &Shape)) -> Result<Bracket, Error> {
    let scale = a.body.scale().max(b.body.scale());
    let target = TARGET_ULPS * f64::EPSILON * scale;
    let mut best = Bracket {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
        normal: Vector3::x(),
        tried: Vec::new(),
    };
    let mut spread = std::f64::consts::PI / START_RIM as f64;
    for _ in 0..MAX_ROUNDS {
        let (Some(ia), Some(ib)) = (a.inner(), b.inner()) else {
            return Err(unsupported(whole.0, whole.1));
        };
        let sd = super::signed_distance(&ia, &ib).map_err(|_| unsupported(whole.0, whole.1))?;
        // F_in = −sd, within sd's bound.
        let lo = (-sd.value - sd.error_bound).next_down();
        best.lo = best.lo.max(lo);
        let n = sd.normal;
        let hi = gap_upper(&a.body, &b.body, &p3(&n));
        if hi < best.hi {
            best.hi = hi;
            best.normal = n;
        }
        best.tried.push(n);
        if best.hi - best.lo <= target {
            break;
        }
        spread *= 0.25;
        if !(a.refine(&n, spread) && b.refine(&-n, spread)) {
            break;
        }
    }
    Ok(best)
}

/// The signed distance of a pair with a cylinder or a cone, neither a half-space, whose
/// certified distance was not available or not positive; `meets` is the exact `intersects`.
pub(super) fn signed_distance(a: &Shape, b: &Shape, meets: bool) -> Result<SignedDistance, Error> {
    let (Some(ba), Some(bb)) = (Body::of(a), Body::of(b)) else {
        return Err(unsupported(a, b));
    };
    let (mut ma, mut mb) = (Member::new(ba), Member::new(bb));
    let br = bracket(&mut ma, &mut mb, (a, b))?;
    // The signed distance −F lies in [−hi, −lo].
    let (mut low, mut high) = (-br.hi, -br.lo);
    let kind = if !meets {
        low = low.max(0.0);
        SignedDistanceKind::Separated
    } else if br.lo > 0.0 {
        high = high.min(0.0);
        SignedDistanceKind::Penetrating
    } else if br
        .tried
        .iter()
        .any(|n| gap_is_nonpositive(&ma.body, &mb.body, &p3(n)))
    {
        SignedDistanceKind::Touching
    } else {
        return Err(unsupported(a, b));
    };
    let normal = unit(&br.normal);
    let witness_a = ma.body.support_point(&normal);
    let witness_b = mb.body.support_point(&-normal);
    if kind == SignedDistanceKind::Touching {
        return Ok(SignedDistance {
            value: 0.0,
            error_bound: 0.0,
            normal,
            witness_a,
            witness_b,
            kind,
        });
    }
    if !(low.is_finite() && high.is_finite() && low <= high) {
        return Err(unsupported(a, b));
    }
    let (value, error_bound) = midpoint(low, high);
    Ok(SignedDistance {
        value,
        error_bound,
        normal,
        witness_a,
        witness_b,
        kind,
    })
}
