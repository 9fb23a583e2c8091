//! Proved separation of two triangles, the building block of the nearest-pair searches over
//! meshes: a cheap `f64` lower bound on the distance of a triangle pair with every rounding paid,
//! the examination of one pair during a search, and the certification of the pair a search found.

use nalgebra::Point3;

use crate::exact::vector::sub;
use crate::query::closest_points::{triangle_triangle, V};
use crate::query::distance::{certify, scale_of, CertifiedDistance};
use crate::query::within_distance::triangles_within;

// ---------------------------------------------------------------- meshes

/// `2⁻⁵³`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;
/// Absolute allowance for underflow in a few products (far above `2⁻¹⁰⁷⁴` each).
const TINY: f64 = 9.332636185032189e-302; // 2^-1000
/// Below this squared length a direction is too small for a relative error analysis.
const SMALL2: f64 = 1.0e-280;
/// Results below this are treated as no information: far above the subnormal range, where
/// rounding errors are absolute rather than relative.
const NORMAL: f64 = 1.0e-290;

/// The separation of triangles `p` and `q` along a direction `n` (any vector), as a pair
/// `(g, nn)`: the distance is **proved** (for the real numbers the `f64` coordinates denote)
/// to be at least `g / √nn`, from the gap between the projections of the triangles on `n`
/// (projection on a line is 1-Lipschitz, so that gap divided by `|n|` never exceeds the
/// distance).
///
/// Roundings: each dot product `fl(n·v)` is within `γ₃ Σ|nᵢ||vᵢ| < 3.01u·m` of `n·v` (`m` the
/// largest such magnitude sum over the six vertices, itself computed within `γ₃`), and the
/// gap's subtraction adds at most `u·2m`; so `g = fl(gap − (12u·m + TINY))` is at most the true
/// gap times `1 + u` (`TINY` pays for underflowing products). `nn = fl(n·n)` is within `γ₃` of
/// `|n|²`. `None` when the projections overlap, or anything is out of range (non-finite, or `n`
/// so short that `nn` could underflow).
#[inline]
pub(crate) fn separation(n: &V<f64>, p: &[V<f64>; 3], q: &[V<f64>; 3]) -> Option<(f64, f64)> {
    let nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if !(nn >= SMALL2 && nn.is_finite()) {
        return None;
    }
    let proj = |v: &V<f64>| n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    let mag = |v: &V<f64>| (n[0] * v[0]).abs() + (n[1] * v[1]).abs() + (n[2] * v[2]).abs();
    let (mut pmin, mut pmax, mut qmin, mut qmax) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    let mut m = 0.0f64;
    for v in p {
        let s = proj(v);
        pmin = pmin.min(s);
        pmax = pmax.max(s);
        m = m.max(mag(v));
    }
    for v in q {
        let s = proj(v);
        qmin = qmin.min(s);
        qmax = qmax.max(s);
        m = m.max(mag(v));
    }
    let g = (qmin - pmax).max(pmin - qmax) - (12.0 * U * m + TINY);
    (g > 0.0 && g.is_finite()).then_some((g, nn))
}

/// Whether a separation `(g, nn)` proves the distance squared above `best`: `g² > best·nn`
/// with a relative margin `16u` that pays for `g` (`1 + u`), `nn` (`γ₃`) and the two products.
/// `g²` must be far from the subnormal range (where rounding is absolute, not relative); then
/// a subnormal `best·nn` is below it anyway.
#[inline]
pub(crate) fn separated_beyond((g, nn): (f64, f64), best: f64) -> bool {
    let g2 = g * g;
    g2 >= NORMAL && g2 * (1.0 - 16.0 * U) > best * nn
}

/// The proved lower bound `g / √nn` of a separation, rounded down (the square root, the
/// division and `nn` cost under `4u` relative, paid by the factor `1 − 8u`).
#[inline]
pub(crate) fn separation_bound((g, nn): (f64, f64)) -> f64 {
    let b = g / nn.sqrt() * (1.0 - 8.0 * U);
    // A quotient near the subnormal range could be rounded up by an absolute amount.
    if b >= NORMAL {
        b
    } else {
        0.0
    }
}

/// The normal `(b − a) × (c − a)` of a triangle, in `f64` (a test direction for
/// [`separation`]).
#[cfg(test)]
fn normal(t: &[V<f64>; 3]) -> V<f64> {
    crate::exact::vector::cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]))
}

/// Three times the centroid of a triangle, in `f64` (a direction for [`separation`]).
#[inline]
fn centroid3(t: &[V<f64>; 3]) -> V<f64> {
    [
        t[0][0] + t[1][0] + t[2][0],
        t[0][1] + t[1][1] + t[2][1],
        t[0][2] + t[1][2] + t[2][2],
    ]
}

/// The open pairs of a mesh search: `(proved lower bound, i, j)` for every examined pair whose
/// proved bounds did not exceed the best squared distance at the time (see [`examine_pair`]).
pub(crate) type Open = Vec<(f64, u32, u32)>;

/// One examined pair of the `f64` nearest-pair search (triangles `x` of A and `y` of B with
/// corners `p` and `q`; `best` the best squared distance so far): its `f64` squared distance,
/// or `+∞` when it is proved farther than `best`. First a proved lower bound from the
/// separation along the line of the centroids (for small triangles far apart, nearly their
/// distance; the normals were tried too and cost more than they saved); only when that does not
/// beat `best` is the `f64` closest-points routine run, and its witnesses' direction gives a
/// second proved bound. A pair whose proved bounds stay at or below the best is pushed on
/// `open` with the larger bound.
pub(crate) fn examine_pair(
    x: u32,
    p: &[V<f64>; 3],
    y: u32,
    q: &[V<f64>; 3],
    best: f64,
    open: &mut Open,
) -> f64 {
    let centres = separation(&sub(&centroid3(q), &centroid3(p)), p, q);
    if centres.is_some_and(|s| separated_beyond(s, best)) {
        return f64::INFINITY; // proved farther than the best so far
    }

    let (d2, wx, wy) = triangle_triangle(p, q);
    let witnesses = separation(&sub(&wy, &wx), p, q);
    let seps = [centres, witnesses];
    if !seps
        .iter()
        .flatten()
        .any(|&s| separated_beyond(s, best.min(d2)))
    {
        let lb = seps
            .iter()
            .flatten()
            .map(|&s| separation_bound(s))
            .fold(0.0, f64::max);
        open.push((lb, x, y));
    }
    d2
}

/// The certified result of a mesh search that found the pair `(i, j)` and left `open` (see
/// [`examine_pair`]); `tri_a(i)` and `tri_b(j)` give the triangles' corners.
///
/// Every pair not in `open` is proved farther than the best `f64` squared distance, hence than
/// any `c` the certification tries for the lower end (`c < distance`): only `open` can bring
/// the distance down to `c`. So the bound depends on the pair `(i, j)` and on the meshes, not
/// on the order of the search.
pub(crate) fn certified_mesh_distance(
    (i, j): (u32, u32),
    open: &Open,
    tri_a: impl Fn(u32) -> [V<f64>; 3],
    tri_b: impl Fn(u32) -> [V<f64>; 3],
) -> CertifiedDistance {
    let (s, t) = (tri_a(i), tri_b(j));
    let (d2, x, y) = triangle_triangle(&s, &t);
    let distance = d2.sqrt();
    let error_bound = certify(
        distance,
        scale_of(&[&s[0], &s[1], &s[2], &t[0], &t[1], &t[2]]),
        || triangles_within(&s, &t, 0.0),
        |c| triangles_within(&s, &t, c),
        |c| {
            open.iter()
                .any(|&(lb, x, y)| lb <= c && triangles_within(&tri_a(x), &tri_b(y), c))
        },
    );
    CertifiedDistance {
        distance,
        error_bound,
        witness_a: Point3::from(x),
        witness_b: Point3::from(y),
        triangles: Some((i, j)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_core::scalar::{rational_from_f64, Rational, Real};

    fn q(x: f64) -> Rational {
        rational_from_f64(x).expect("finite")
    }

    fn qv(p: &V<f64>) -> V<Rational> {
        p.map(q)
    }
    use proptest::prelude::*;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            2 => (-3i32..=3).prop_map(f64::from),
            3 => -3.0f64..3.0,
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e-9),
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e150),
        ]
    }

    fn point() -> impl Strategy<Value = V<f64>> {
        [coord(), coord(), coord()]
    }

    fn triangle() -> impl Strategy<Value = [V<f64>; 3]> {
        [point(), point(), point()]
    }

    fn exact2(p: &[V<f64>; 3], q: &[V<f64>; 3]) -> Rational {
        triangle_triangle(&p.map(|v| qv(&v)), &q.map(|v| qv(&v))).0
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20))]

        /// The separation along any direction (random, normals, centroids, the `f64` witnesses'
        /// direction) is a proved lower bound: checked against the exact rational distance, for
        /// the bound itself and for the squared comparison used to prune.
        #[test]
        fn separation_never_exceeds_the_exact_distance(
            p in triangle(),
            q in triangle(),
            n in point(),
            shift in point(),
        ) {
            // Also a copy of q moved away, so that separated pairs are frequent.
            let far = q.map(|v| [v[0] + shift[0], v[1] + shift[1], v[2] + shift[2]]);
            for q in [q, far] {
                let exact = exact2(&p, &q);
                let (_, wx, wy) = triangle_triangle(&p, &q);
                for n in [n, normal(&p), normal(&q), sub(&centroid3(&q), &centroid3(&p)), sub(&wy, &wx)] {
                    let Some(s) = separation(&n, &p, &q) else { continue };
                    let lb = separation_bound(s);
                    prop_assert!(lb >= 0.0);
                    prop_assert!(q_sq(lb) <= exact, "bound {lb} above the distance");
                    // Pruning: proved beyond `best` only if the exact distance is.
                    let e = Real::to_f64(&exact);
                    for best in [e, e.next_down(), e.next_up(), e * (1.0 - 1e-15), lb * lb] {
                        if best.is_finite() && separated_beyond(s, best) {
                            prop_assert!(exact > rational_from_f64(best).unwrap());
                        }
                    }
                }
            }
        }
    }

    fn q_sq(x: f64) -> Rational {
        let r = q(x);
        &r * &r
    }

    #[test]
    fn separation_of_far_apart_triangles_is_nearly_their_distance() {
        let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let q = p.map(|v| [v[0], v[1], v[2] + 0.5]);
        let s = separation(&normal(&p), &p, &q).unwrap();
        let lb = separation_bound(s);
        assert!(lb <= 0.5 && lb > 0.5 * (1.0 - 1e-14), "{lb}");
        // Overlapping projections and degenerate directions give nothing.
        assert_eq!(separation(&[1.0, 0.0, 0.0], &p, &q), None);
        assert_eq!(separation(&[0.0, 0.0, 0.0], &p, &q), None);
        assert_eq!(separation(&[f64::NAN, 0.0, 1.0], &p, &q), None);
        assert_eq!(separation(&[0.0, 0.0, 1e300], &p, &q), None);
    }
}
