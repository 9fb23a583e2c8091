//! The distance between two cores by the Gilbert–Johnson–Keerthi search over their Minkowski
//! difference: once in `f64` (fast, a guide for the certificates), and exactly in rationals
//! (the fallback, warm-started from the `f64` search's last simplex).
//!
//! In exact arithmetic the search ends with the exact nearest point: each step either proves
//! optimality (`v·v ≤ v·w` for the support point `w` in direction `−v`, so every point `x` of
//! the difference has `v·x ≥ v·v`) or strictly shortens `v`, and `v` is always the nearest
//! point of a sub-simplex of the finitely many difference vertices, so it cannot repeat.

use ga_core::scalar::{rational_from_f64, Rational, Ring};

use super::cores::{Core, P3};
use super::float_simplex::nearest_to_origin;
use super::simplex;

/// What the `f64` search found: the last simplex as pairs of core point indices, its
/// barycentric weights and the nearest point `v` (of the difference A − B, scaled by `scale`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Found {
    pairs: [(usize, usize); 4],
    weights: [f64; 4],
    len: usize,
    pub(super) v: P3,
    /// The power of two the search's coordinates were multiplied by (keeps the products
    /// inside the `f64` range at every scale).
    pub(super) scale: f64,
}

impl Found {
    /// The pairs of the last simplex.
    pub(super) fn pairs(&self) -> &[(usize, usize)] {
        &self.pairs[..self.len]
    }

    /// The weights of the pairs.
    pub(super) fn weights(&self) -> &[f64] {
        &self.weights[..self.len]
    }

    /// The nearest points of A and of B in `f64` (unscaled).
    pub(super) fn witnesses(&self, a: &Core, b: &Core) -> (P3, P3) {
        let total: f64 = self.weights().iter().sum();
        let total = if total > 0.0 { total } else { 1.0 };
        let mut x = [0.0; 3];
        let mut y = [0.0; 3];
        for (&(ia, ib), w) in self.pairs().iter().zip(self.weights()) {
            let (pa, pb) = (a.approx(ia), b.approx(ib));
            for k in 0..3 {
                x[k] += w / total * pa[k];
                y[k] += w / total * pb[k];
            }
        }
        (x, y)
    }
}

const MAX_STEPS: usize = 64;

/// A power of two `s` with `s · magnitude` near 1 (clamped to the normal range).
pub(super) fn unit_scale(magnitude: f64) -> f64 {
    if magnitude == 0.0 || !magnitude.is_finite() {
        return 1.0;
    }
    let e = magnitude.log2().floor() as i32;
    2f64.powi((-e).clamp(-1022, 1022))
}

fn exact_dependent(det: &Rational, _: &Rational) -> bool {
    Ring::is_zero(det)
}

/// The `f64` search: fixed-size arrays, each difference point computed once.
pub(super) fn search(a: &Core, b: &Core) -> Found {
    let scale = unit_scale(a.magnitude().max(b.magnitude()));
    let point = |(ia, ib): (usize, usize)| -> P3 {
        let (pa, pb) = (a.approx(ia), b.approx(ib));
        core::array::from_fn(|k| pa[k] * scale - pb[k] * scale)
    };
    let mut pairs = [(0, 0); 4];
    let mut pts = [point((0, 0)); 4];
    let mut len = 1;
    let mut found = Found {
        pairs,
        weights: [1.0, 0.0, 0.0, 0.0],
        len,
        v: pts[0],
        scale,
    };
    let mut last = f64::INFINITY;
    for _ in 0..MAX_STEPS {
        let near = nearest_to_origin(&pts[..len]);
        // Stop unless strictly nearer (NaN stops too).
        if near.norm2.partial_cmp(&last) != Some(std::cmp::Ordering::Less) {
            break;
        }
        last = near.norm2;
        let mut weights = [0.0; 4];
        let mut kept = 0;
        for i in 0..len {
            if near.used >> i & 1 == 1 {
                pairs[kept] = pairs[i];
                pts[kept] = pts[i];
                weights[kept] = near.weights[i].max(0.0);
                kept += 1;
            }
        }
        len = kept;
        found = Found {
            pairs,
            weights,
            len,
            v: near.point,
            scale,
        };
        if near.norm2 == 0.0 || len == 4 {
            break;
        }
        let v = near.point;
        let next = (a.support(&v.map(|x| -x)), b.support(&v));
        if pairs[..len].contains(&next) {
            break;
        }
        let w = point(next);
        let gap = near.norm2 - (v[0] * w[0] + v[1] * w[1] + v[2] * w[2]);
        if gap <= 1e-14 * near.norm2 {
            break;
        }
        pairs[len] = next;
        pts[len] = w;
        len += 1;
    }
    found
}

fn q(x: f64) -> Rational {
    // Cores hold finite values only.
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn argmax(points: &[[Rational; 3]], d: &[Rational; 3]) -> usize {
    let mut best: Option<(usize, Rational)> = None;
    for (i, p) in points.iter().enumerate() {
        let v = dot(p, d);
        if best.as_ref().is_none_or(|(_, b)| v > *b) {
            best = Some((i, v));
        }
    }
    best.map_or(0, |(i, _)| i)
}

/// The exact squared distance between the two cores, starting from the pairs `start`.
pub(super) fn exact_distance2(a: &Core, b: &Core, start: &[(usize, usize)]) -> Rational {
    let lift =
        |c: &Core| -> Vec<[Rational; 3]> { (0..c.len()).map(|i| c.point(i).lift(&q)).collect() };
    let (pa, pb) = (lift(a), lift(b));
    let point = |(ia, ib): (usize, usize)| -> [Rational; 3] {
        core::array::from_fn(|k| &pa[ia][k] - &pb[ib][k])
    };
    let mut pairs: Vec<(usize, usize)> = start.to_vec();
    if pairs.is_empty() {
        pairs.push((0, 0));
    }
    // Finite by the argument in the module docs; the bound only guards against a defect.
    let steps = 64 + 4 * pa.len() * pb.len();
    let mut best = <Rational as Ring>::zero();
    for _ in 0..steps {
        let pts: Vec<[Rational; 3]> = pairs.iter().map(|&p| point(p)).collect();
        let near = simplex::nearest_to_origin(&pts, &exact_dependent);
        best = near.norm2.clone();
        if Ring::is_zero(&near.norm2) {
            break;
        }
        pairs = (0..pairs.len())
            .filter(|i| near.used >> i & 1 == 1)
            .map(|i| pairs[i])
            .collect();
        let v = near.point;
        let minus_v = [-v[0].clone(), -v[1].clone(), -v[2].clone()];
        let next = (argmax(&pa, &minus_v), argmax(&pb, &v));
        if pairs.contains(&next) {
            break;
        }
        let w = point(next);
        if dot(&v, &w) >= near.norm2 {
            break;
        }
        pairs.push(next);
    }
    best
}
