//! The exact decisions: whether linearly moving primitives touch for some `t ∈ [0, 1]`, and
//! the earliest such `t`, by root isolation of polynomials in `t` ([`super::polynomial`]).
//!
//! Points move as `p(t) = p₀ + t·(p₁ − p₀)`; every coordinate is an exact integer polynomial
//! of degree ≤ 1 once all inputs are scaled by one power of two. The decisions:
//! - **vertex–face**: the coplanarity cubic `f = det(b − a, c − a, p − a)`. If `f ≢ 0`, contact
//!   happens only at its roots; at each root (in increasing order) the point is in the closed
//!   triangle iff the three in-plane sides `((b − a) × (p − a))·n, …` with `n = (b − a) × (c − a)`
//!   are `≥ 0`, or, where `n = 0` (a degenerate triangle at that instant), iff the point is on
//!   one of its edges. If `f ≡ 0` (coplanar for all `t`), the set of contact times is closed,
//!   so its first element is `0` or an instant where the point enters the triangle across its
//!   boundary: contact at `t = 0`, or the earliest vertex–edge contact with one of the edges.
//! - **edge–edge**: the cubic `det(a₁ − a₀, b₀ − a₀, b₁ − a₀)`; at a root, with
//!   `n = (a₁ − a₀) × (b₁ − b₀) ≠ 0` the segments meet iff both line parameters
//!   `((b₀ − a₀) × (b₁ − b₀))·n / |n|²` and `((b₀ − a₀) × (a₁ − a₀))·n / |n|²` are in `[0, 1]`; with
//!   `n = 0` (parallel, collinear or zero-length) iff an endpoint of one lies on the other. If
//!   the cubic is `≡ 0`, a first contact after `t = 0` cannot be a proper crossing (those
//!   persist a little earlier), so it is an endpoint reaching the other edge: contact at
//!   `t = 0`, or the earliest of four vertex–edge contacts.
//! - **vertex–edge**: the cross product `e × (q − s₀)` (three quadratics) vanishes and
//!   `0 ≤ (q − s₀)·e ≤ e·e`, or `q = s₀` where `e = 0`; if the cross product is `≡ 0`
//!   (collinear for all `t`), contact at `t = 0` or the earliest time `q` meets an endpoint.
//! - **vertex–vertex**: three linear polynomials vanish together.
//!
//! Every sign is exact ([`Instant::sign_of`]); nothing here rounds.

use core::cmp::Ordering;

use num_bigint::BigInt;

use super::polynomial::{roots_in_unit, Instant, Poly};
use crate::exact::decode;

/// A point moving linearly: its three coordinates as polynomials in `t` of degree ≤ 1.
pub(crate) type Track = [Poly; 3];

/// The tracks of points given at `t = 0` and `t = 1`, all scaled by one power of two.
pub(crate) fn tracks<const N: usize>(points: &[[[f64; 3]; 2]; N]) -> [Track; N] {
    // One common scale for every coordinate of the query (the conditions are homogeneous).
    let flat: Vec<f64> = points
        .iter()
        .flat_map(|p| p.iter().flatten().copied())
        .collect();
    let ints = scaled_integers(&flat);
    core::array::from_fn(|i| {
        core::array::from_fn(|axis| Poly::linear(&ints[6 * i + axis], &ints[6 * i + 3 + axis]))
    })
}

fn scaled_integers(x: &[f64]) -> Vec<BigInt> {
    let parts: Vec<(u64, i16, i8)> = x.iter().map(|&v| decode(v)).collect();
    let min_exp = parts
        .iter()
        .filter(|p| p.0 != 0)
        .map(|p| p.1)
        .min()
        .unwrap_or(0);
    parts
        .iter()
        .map(|&(m, e, sign)| {
            let v = BigInt::from(m) << (e - min_exp) as usize;
            if sign < 0 {
                -v
            } else {
                v
            }
        })
        .collect()
}

fn sub(a: &Track, b: &Track) -> Track {
    core::array::from_fn(|i| a[i].sub(&b[i]))
}

fn cross(a: &Track, b: &Track) -> Track {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

fn dot(a: &Track, b: &Track) -> Poly {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

fn vanishes_at(v: &Track, t: &Instant) -> bool {
    v.iter().all(|c| t.sign_of(c) == Ordering::Equal)
}

fn non_negative_at(p: &Poly, t: &Instant) -> bool {
    t.sign_of(p) != Ordering::Less
}

/// Collects candidate earliest instants.
fn earliest(parts: impl IntoIterator<Item = Option<Vec<Instant>>>) -> Option<Vec<Instant>> {
    let all: Vec<Instant> = parts.into_iter().flatten().flatten().collect();
    (!all.is_empty()).then_some(all)
}

/// Vertex `q` and vertex `s` coincide at some `t ∈ [0, 1]`: the first such instant.
fn vertex_vertex(q: &Track, s: &Track) -> Option<Vec<Instant>> {
    let d = sub(q, s);
    match d.iter().find(|c| !c.is_zero()) {
        None => Some(vec![Instant::zero()]),
        Some(c) => roots_in_unit(c)
            .into_iter()
            .find(|t| vanishes_at(&d, t))
            .map(|t| vec![t]),
    }
}

/// `q` on the closed segment `[s0, s1]` at instant `t`.
fn on_segment_at(q: &Track, s0: &Track, s1: &Track, t: &Instant) -> bool {
    let e = sub(s1, s0);
    let w = sub(q, s0);
    if vanishes_at(&e, t) {
        return vanishes_at(&w, t);
    }
    if !vanishes_at(&cross(&e, &w), t) {
        return false;
    }
    let along = dot(&w, &e);
    non_negative_at(&along, t) && non_negative_at(&dot(&e, &e).sub(&along), t)
}

/// Vertex `q` meets the closed segment `[s0, s1]` at some `t ∈ [0, 1]`: candidates for the
/// earliest instant.
pub(crate) fn vertex_edge(q: &Track, s0: &Track, s1: &Track) -> Option<Vec<Instant>> {
    let c = cross(&sub(s1, s0), &sub(q, s0));
    match c.iter().find(|p| !p.is_zero()) {
        None => {
            if on_segment_at(q, s0, s1, &Instant::zero()) {
                return Some(vec![Instant::zero()]);
            }
            earliest([vertex_vertex(q, s0), vertex_vertex(q, s1)])
        }
        Some(p) => roots_in_unit(p)
            .into_iter()
            .find(|t| on_segment_at(q, s0, s1, t))
            .map(|t| vec![t]),
    }
}

/// `p` in the closed triangle `abc` at an instant where the four points are coplanar.
fn in_triangle_at(p: &Track, a: &Track, b: &Track, c: &Track, t: &Instant) -> bool {
    let ab = sub(b, a);
    let n = cross(&ab, &sub(c, a));
    if vanishes_at(&n, t) {
        return on_segment_at(p, a, b, t) || on_segment_at(p, b, c, t) || on_segment_at(p, c, a, t);
    }
    [(a, b), (b, c), (c, a)].iter().all(|(u, v)| {
        let side = dot(&cross(&sub(v, u), &sub(p, u)), &n);
        non_negative_at(&side, t)
    })
}

/// Vertex `p` meets the closed triangle `abc`: candidates for the earliest instant.
pub(crate) fn vertex_face(p: &Track, a: &Track, b: &Track, c: &Track) -> Option<Vec<Instant>> {
    let f = dot(&cross(&sub(b, a), &sub(c, a)), &sub(p, a));
    if f.is_zero() {
        if in_triangle_at(p, a, b, c, &Instant::zero()) {
            return Some(vec![Instant::zero()]);
        }
        return earliest([
            vertex_edge(p, a, b),
            vertex_edge(p, b, c),
            vertex_edge(p, c, a),
        ]);
    }
    roots_in_unit(&f)
        .into_iter()
        .find(|t| in_triangle_at(p, a, b, c, t))
        .map(|t| vec![t])
}

/// The closed segments `[a0, a1]` and `[b0, b1]` meet at an instant where they are coplanar.
fn segments_meet_at(a0: &Track, a1: &Track, b0: &Track, b1: &Track, t: &Instant) -> bool {
    let ea = sub(a1, a0);
    let eb = sub(b1, b0);
    let n = cross(&ea, &eb);
    if vanishes_at(&n, t) {
        return on_segment_at(a0, b0, b1, t)
            || on_segment_at(a1, b0, b1, t)
            || on_segment_at(b0, a0, a1, t)
            || on_segment_at(b1, a0, a1, t);
    }
    let d = sub(b0, a0);
    let nn = dot(&n, &n);
    let u = dot(&cross(&d, &eb), &n);
    let v = dot(&cross(&d, &ea), &n);
    non_negative_at(&u, t)
        && non_negative_at(&nn.sub(&u), t)
        && non_negative_at(&v, t)
        && non_negative_at(&nn.sub(&v), t)
}

/// Edges `[a0, a1]` and `[b0, b1]` meet: candidates for the earliest instant.
pub(crate) fn edge_edge(a0: &Track, a1: &Track, b0: &Track, b1: &Track) -> Option<Vec<Instant>> {
    let f = dot(&cross(&sub(a1, a0), &sub(b0, a0)), &sub(b1, a0));
    if f.is_zero() {
        if segments_meet_at(a0, a1, b0, b1, &Instant::zero()) {
            return Some(vec![Instant::zero()]);
        }
        return earliest([
            vertex_edge(a0, b0, b1),
            vertex_edge(a1, b0, b1),
            vertex_edge(b0, a0, a1),
            vertex_edge(b1, a0, a1),
        ]);
    }
    roots_in_unit(&f)
        .into_iter()
        .find(|t| segments_meet_at(a0, a1, b0, b1, t))
        .map(|t| vec![t])
}
