//! The `f64` filter: decides most queries with interval arithmetic over sub-intervals of time,
//! and says when it cannot.
//!
//! On a time interval `T`, the coplanarity polynomial `f` is the determinant of three vectors
//! linear in `t`, so its Bernstein coefficients on `T` are sums of determinants of those
//! vectors taken at the two ends of `T`, and `f(T)` lies within their hull. Every coordinate of
//! a moving point lies between its values at the two ends of `T`; from those boxes,
//! outward-rounded interval arithmetic encloses the in-plane conditions `gᵢ` (the same
//! polynomials the exact decision uses, see [`super::algebraic`]) over all of `T`. Then,
//! exactly for the real inputs:
//! - `0 ∉ f(T)`, or some `gᵢ(T) < 0`: no contact during `T` (at a coplanar instant with every
//!   `gᵢ ≥ 0` violated, the point is outside, or `n ≠ 0` and the edges miss);
//! - `f` has strictly opposite signs at the two ends of `T` and every `gᵢ(T) > 0`: a root of `f`
//!   lies inside `T` and at it the primitives touch (strictly inside, so `n ≠ 0`).
//!
//! Intervals are visited in increasing time, depth first, so the first interval found to hold a
//! contact holds the earliest one, and its ends (where `f ≠ 0`) are not contact times. Anything
//! else is split, up to a budget; a non-finite bound (overflow) or an exhausted budget returns
//! [`Filtered::Unknown`] and the caller decides exactly.

/// An interval of reals with `f64` ends, rounded outward by every operation.
#[derive(Clone, Copy, Debug)]
struct Iv {
    lo: f64,
    hi: f64,
}

/// Widens a rounded-to-nearest result `r` to bounds of the exact value: the rounding error is
/// at most half a unit in the last place, below `|r|·2⁻⁵²`; `TINY` covers results in the
/// subnormal range. Cheaper than stepping to the neighbouring `f64`s, and as safe.
#[inline(always)]
fn down(r: f64) -> f64 {
    r - (r.abs() * EPS + TINY)
}
#[inline(always)]
fn up(r: f64) -> f64 {
    r + (r.abs() * EPS + TINY)
}
const EPS: f64 = f64::EPSILON;
const TINY: f64 = f64::MIN_POSITIVE;

impl Iv {
    fn point(x: f64) -> Iv {
        Iv { lo: x, hi: x }
    }
    fn hull(a: Iv, b: Iv) -> Iv {
        Iv {
            lo: a.lo.min(b.lo),
            hi: a.hi.max(b.hi),
        }
    }
    #[inline(always)]
    fn add(self, o: Iv) -> Iv {
        Iv {
            lo: down(self.lo + o.lo),
            hi: up(self.hi + o.hi),
        }
    }
    #[inline(always)]
    fn sub(self, o: Iv) -> Iv {
        Iv {
            lo: down(self.lo - o.hi),
            hi: up(self.hi - o.lo),
        }
    }
    #[inline(always)]
    fn mul(self, o: Iv) -> Iv {
        let (a, b, c, d) = (
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        );
        Iv {
            lo: down(a.min(b).min(c.min(d))),
            hi: up(a.max(b).max(c.max(d))),
        }
    }
    /// Strictly positive (a NaN bound is never positive).
    fn positive(self) -> bool {
        self.lo > 0.0
    }
    fn negative(self) -> bool {
        self.hi < 0.0
    }
    fn finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }
}

type V = [Iv; 3];

fn sub(a: &V, b: &V) -> V {
    [a[0].sub(b[0]), a[1].sub(b[1]), a[2].sub(b[2])]
}
fn cross(a: &V, b: &V) -> V {
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}
fn dot(a: &V, b: &V) -> Iv {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

/// What the filter found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Filtered {
    /// No contact for any `t ∈ [0, 1]`.
    Never,
    /// The earliest contact is strictly inside `(lo, hi)`.
    Within(f64, f64),
    /// The filter cannot decide.
    Unknown,
}

/// The in-plane conditions over a time interval.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Side {
    /// Some condition is certainly negative: no contact at any coplanar instant.
    Outside,
    /// Every condition is certainly positive.
    Inside,
    /// Neither.
    Unsure,
}

/// Folds one condition `g ≥ 0` into the side found so far (`None`: overflow).
fn fold(side: Side, g: Iv) -> Option<Side> {
    if !g.finite() {
        return None;
    }
    Some(match side {
        Side::Outside => Side::Outside,
        _ if g.negative() => Side::Outside,
        Side::Inside if g.positive() => Side::Inside,
        _ => Side::Unsure,
    })
}

/// `f` (a cubic) and the in-plane conditions (quartics; unused slots hold the constant 1) in
/// Bernstein form on the current time interval, each scaled by a positive constant. A
/// polynomial's values on the interval lie within the hull of its coefficients, its values at
/// the ends are the first and last coefficients, and halving the interval is de Casteljau's
/// averaging: no positions are recomputed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Forms {
    f: [Iv; 4],
    g: [[Iv; 5]; 4],
}

impl Iv {
    fn half(self) -> Iv {
        Iv {
            lo: down(self.lo * 0.5),
            hi: up(self.hi * 0.5),
        }
    }
    fn times(self, k: f64) -> Iv {
        Iv::point(k).mul(self)
    }
}

/// The product `x(t) × y(t)` of two vectors linear in `t` (given at the two ends), as Bernstein
/// coefficients of a quadratic with the middle one doubled: `[x₀×y₀, x₀×y₁ + x₁×y₀, x₁×y₁]`.
fn quadratic_cross(x: &[V; 2], y: &[V; 2]) -> [V; 3] {
    let m0 = cross(&x[0], &y[1]);
    let m1 = cross(&x[1], &y[0]);
    [
        cross(&x[0], &y[0]),
        [m0[0].add(m1[0]), m0[1].add(m1[1]), m0[2].add(m1[2])],
        cross(&x[1], &y[1]),
    ]
}

/// `n(t)·w(t)` for `n` from [`quadratic_cross`] and `w` linear: the cubic's Bernstein
/// coefficients times 3.
fn cubic_det(n: &[V; 3], w: &[V; 2]) -> [Iv; 4] {
    [
        dot(&n[0], &w[0]).times(3.0),
        dot(&n[1], &w[0]).add(dot(&n[0], &w[1])),
        dot(&n[2], &w[0]).add(dot(&n[1], &w[1])),
        dot(&n[2], &w[1]).times(3.0),
    ]
}

/// `q(t)·n(t)` for two vectors from [`quadratic_cross`]: the quartic's Bernstein coefficients
/// times 12.
fn quartic_dot(q: &[V; 3], n: &[V; 3]) -> [Iv; 5] {
    [
        dot(&q[0], &n[0]).times(12.0),
        dot(&q[0], &n[1]).add(dot(&q[1], &n[0])).times(3.0),
        dot(&q[0], &n[2])
            .add(dot(&q[1], &n[1]))
            .add(dot(&q[2], &n[0]))
            .times(2.0),
        dot(&q[1], &n[2]).add(dot(&q[2], &n[1])).times(3.0),
        dot(&q[2], &n[2]).times(12.0),
    ]
}

/// De Casteljau at the middle: the coefficients on the left and right halves.
fn split<const N: usize>(c: &[Iv; N]) -> ([Iv; N], [Iv; N]) {
    let mut row = *c;
    let mut left = *c;
    let mut right = *c;
    left[0] = row[0];
    right[N - 1] = row[N - 1];
    for r in 1..N {
        for i in 0..N - r {
            row[i] = row[i].add(row[i + 1]).half();
        }
        left[r] = row[0];
        right[N - 1 - r] = row[N - 1 - r];
    }
    (left, right)
}

fn split_forms(x: &Forms) -> (Forms, Forms) {
    let (fl, fr) = split(&x.f);
    let halves: [([Iv; 5], [Iv; 5]); 4] = core::array::from_fn(|k| split(&x.g[k]));
    (
        Forms {
            f: fl,
            g: core::array::from_fn(|k| halves[k].0),
        },
        Forms {
            f: fr,
            g: core::array::from_fn(|k| halves[k].1),
        },
    )
}

fn signed(c: &[Iv]) -> bool {
    c.iter().all(|b| b.positive()) || c.iter().all(|b| b.negative())
}

/// What a query is, for the filter: the coplanarity polynomial and the in-plane conditions on
/// boxes of positions.
trait Conditions<const N: usize> {
    /// The three vectors whose determinant is `f`, each linear in `t`.
    fn factors(x: &[V; N]) -> [V; 3];
    /// The conditions `gᵢ ≥ 0` on the boxes.
    fn side(x: &[V; N]) -> Option<Side>;
    /// `f` in Bernstein form on `[0, 1]` from the points at both ends, and the normal `n` (a
    /// quadratic, from [`quadratic_cross`]) the conditions are made of.
    fn coplanarity_form(start: &[V; N], end: &[V; N]) -> ([Iv; 4], [V; 3]);
    /// The conditions in Bernstein form on `[0, 1]`.
    fn condition_forms(start: &[V; N], end: &[V; N], n: &[V; 3]) -> [[Iv; 5]; 4];
}

/// Vertex `p` against triangle `abc`.
pub(crate) struct VertexFace;

impl Conditions<4> for VertexFace {
    fn coplanarity_form(s: &[V; 4], e: &[V; 4]) -> ([Iv; 4], [V; 3]) {
        let e1 = [sub(&s[2], &s[1]), sub(&e[2], &e[1])];
        let e2 = [sub(&s[3], &s[1]), sub(&e[3], &e[1])];
        let w = [sub(&s[0], &s[1]), sub(&e[0], &e[1])];
        let n = quadratic_cross(&e1, &e2);
        (cubic_det(&n, &w), n)
    }
    fn condition_forms(s: &[V; 4], e: &[V; 4], n: &[V; 3]) -> [[Iv; 5]; 4] {
        let side = |u: usize, v: usize| {
            let d = [sub(&s[v], &s[u]), sub(&e[v], &e[u])];
            let r = [sub(&s[0], &s[u]), sub(&e[0], &e[u])];
            quartic_dot(&quadratic_cross(&d, &r), n)
        };
        [side(1, 2), side(2, 3), side(3, 1), [Iv::point(1.0); 5]]
    }
    fn factors(x: &[V; 4]) -> [V; 3] {
        let [p, a, b, c] = x;
        [sub(b, a), sub(c, a), sub(p, a)]
    }
    fn side(x: &[V; 4]) -> Option<Side> {
        let [p, a, b, c] = x;
        let n = cross(&sub(b, a), &sub(c, a));
        [(a, b), (b, c), (c, a)]
            .iter()
            .try_fold(Side::Inside, |side, (u, v)| {
                fold(side, dot(&cross(&sub(v, u), &sub(p, u)), &n))
            })
    }
}

/// Edge `a0 a1` against edge `b0 b1`.
pub(crate) struct EdgeEdge;

impl Conditions<4> for EdgeEdge {
    fn coplanarity_form(s: &[V; 4], e: &[V; 4]) -> ([Iv; 4], [V; 3]) {
        let ea = [sub(&s[1], &s[0]), sub(&e[1], &e[0])];
        let eb = [sub(&s[3], &s[2]), sub(&e[3], &e[2])];
        let d = [sub(&s[2], &s[0]), sub(&e[2], &e[0])];
        let n = quadratic_cross(&ea, &eb);
        (cubic_det(&n, &d), n)
    }
    fn condition_forms(s: &[V; 4], e: &[V; 4], n: &[V; 3]) -> [[Iv; 5]; 4] {
        let ea = [sub(&s[1], &s[0]), sub(&e[1], &e[0])];
        let eb = [sub(&s[3], &s[2]), sub(&e[3], &e[2])];
        let d = [sub(&s[2], &s[0]), sub(&e[2], &e[0])];
        let nn = quartic_dot(n, n);
        let u = quartic_dot(&quadratic_cross(&d, &eb), n);
        let v = quartic_dot(&quadratic_cross(&d, &ea), n);
        [
            u,
            v,
            core::array::from_fn(|k| nn[k].sub(u[k])),
            core::array::from_fn(|k| nn[k].sub(v[k])),
        ]
    }
    fn factors(x: &[V; 4]) -> [V; 3] {
        let [a0, a1, b0, b1] = x;
        [sub(a1, a0), sub(b1, b0), sub(b0, a0)]
    }
    fn side(x: &[V; 4]) -> Option<Side> {
        let [a0, a1, b0, b1] = x;
        let (ea, eb, d) = (sub(a1, a0), sub(b1, b0), sub(b0, a0));
        let n = cross(&ea, &eb);
        let nn = dot(&n, &n);
        let u = dot(&cross(&d, &eb), &n);
        let v = dot(&cross(&d, &ea), &n);
        [u, nn.sub(u), v, nn.sub(v)]
            .into_iter()
            .try_fold(Side::Inside, fold)
    }
}

/// Whether the swept boxes of the first point and of the other three are disjoint (exact:
/// only comparisons of the inputs).
fn boxes_apart(points: &[[[f64; 3]; 2]; 4]) -> bool {
    (0..3).any(|i| {
        let lo = |p: &[[f64; 3]; 2]| p[0][i].min(p[1][i]);
        let hi = |p: &[[f64; 3]; 2]| p[0][i].max(p[1][i]);
        let (first, rest) = points.split_first().expect("four points");
        let rest_lo = rest.iter().map(lo).fold(f64::INFINITY, f64::min);
        let rest_hi = rest.iter().map(hi).fold(f64::NEG_INFINITY, f64::max);
        hi(first) < rest_lo || lo(first) > rest_hi
    })
}

/// Whether the swept boxes of the two edges are disjoint.
fn edge_boxes_apart(points: &[[[f64; 3]; 2]; 4]) -> bool {
    (0..3).any(|i| {
        let lo = |p: &[[f64; 3]; 2]| p[0][i].min(p[1][i]);
        let hi = |p: &[[f64; 3]; 2]| p[0][i].max(p[1][i]);
        let a_lo = lo(&points[0]).min(lo(&points[1]));
        let a_hi = hi(&points[0]).max(hi(&points[1]));
        let b_lo = lo(&points[2]).min(lo(&points[3]));
        let b_hi = hi(&points[2]).max(hi(&points[3]));
        a_hi < b_lo || a_lo > b_hi
    })
}

/// How many time intervals the filter may look at before giving up.
const BUDGET: usize = 64;

/// The narrowest time interval the filter splits when it cannot decide on it (contact at an
/// end of the step, or an exact zero, is left to the exact decision early).
const NARROWEST: f64 = 1.0 / 65536.0;

/// The filter for a query of kind `C`. `tolerance`: the width at which a contact interval is
/// accepted (`f64::INFINITY` when only whether they touch is asked).
fn search<C: Conditions<4>>(points: &[[[f64; 3]; 2]; 4], tolerance: f64) -> Filtered {
    let start: [V; 4] = core::array::from_fn(|i| points[i][0].map(Iv::point));
    let end: [V; 4] = core::array::from_fn(|i| points[i][1].map(Iv::point));
    // Cheap first, on the boxes the points sweep: often enough to rule the whole step out.
    let boxes: [V; 4] =
        core::array::from_fn(|i| core::array::from_fn(|k| Iv::hull(start[i][k], end[i][k])));
    let [u, v, w] = C::factors(&boxes);
    let rough = dot(&cross(&u, &v), &w);
    if rough.positive() || rough.negative() {
        return Filtered::Never;
    }
    // Then the coplanarity cubic's Bernstein bounds (no root in the step: no contact), then
    // the conditions on the boxes, and only then the conditions' own Bernstein forms.
    let (f, n) = C::coplanarity_form(&start, &end);
    if signed(&f) {
        return Filtered::Never;
    }
    if C::side(&boxes) == Some(Side::Outside) {
        return Filtered::Never;
    }
    let forms = Forms {
        f,
        g: C::condition_forms(&start, &end, &n),
    };
    if forms
        .f
        .iter()
        .chain(forms.g.iter().flatten())
        .any(|c| !c.finite())
    {
        return Filtered::Unknown;
    }
    let mut stack = vec![(0.0f64, 1.0f64, forms)];
    let mut visited = 0;
    while let Some((t0, t1, forms)) = stack.pop() {
        visited += 1;
        if visited > BUDGET {
            return Filtered::Unknown;
        }
        let f = &forms.f;
        if signed(f) {
            continue;
        }
        if forms.g.iter().any(|g| g.iter().all(|c| c.negative())) {
            continue; // a condition fails throughout
        }
        let inside = forms.g.iter().all(|g| g.iter().all(|c| c.positive()));
        let crossing = (f[0].positive() && f[3].negative()) || (f[0].negative() && f[3].positive());
        if inside && crossing && t1 - t0 <= tolerance {
            return Filtered::Within(t0, t1);
        }
        // Where `f` may vanish at an end of the interval (an exact root there, typically a
        // contact at the start of the step), no sub-interval touching that end can be proved
        // either way unless a condition rules that end out: leave it to the exact decision
        // rather than split towards it.
        let ruled_out = |k: usize| forms.g.iter().any(|g| g[k].negative());
        let open = |c: Iv| !c.positive() && !c.negative();
        if (open(f[0]) && !ruled_out(0)) || (open(f[3]) && !ruled_out(4)) {
            return Filtered::Unknown;
        }
        let mid = 0.5 * (t0 + t1);
        if !inside && t1 - t0 < NARROWEST {
            return Filtered::Unknown;
        }
        if !(t0 < mid && mid < t1) {
            return Filtered::Unknown;
        }
        let (left, right) = split_forms(&forms);
        stack.push((mid, t1, right));
        stack.push((t0, mid, left));
    }
    Filtered::Never
}

/// The largest coordinate magnitude the filter takes: the conditions are of degree at most 4
/// in differences of coordinates, so nothing overflows below it (an overflow could turn into a
/// NaN that `min`/`max` would silently drop). Larger inputs go to the exact decision.
const LARGEST: f64 = 1e60;

fn too_large(points: &[[[f64; 3]; 2]; 4]) -> bool {
    points.iter().flatten().flatten().any(|x| x.abs() > LARGEST)
}

/// The filter for vertex `points[0]` against triangle `points[1..4]`.
pub(crate) fn vertex_face(points: &[[[f64; 3]; 2]; 4], tolerance: f64) -> Filtered {
    if boxes_apart(points) {
        return Filtered::Never;
    }
    if too_large(points) {
        return Filtered::Unknown;
    }
    search::<VertexFace>(points, tolerance)
}

/// The filter for edge `points[0..2]` against edge `points[2..4]`.
pub(crate) fn edge_edge(points: &[[[f64; 3]; 2]; 4], tolerance: f64) -> Filtered {
    if edge_boxes_apart(points) {
        return Filtered::Never;
    }
    if too_large(points) {
        return Filtered::Unknown;
    }
    search::<EdgeEdge>(points, tolerance)
}
