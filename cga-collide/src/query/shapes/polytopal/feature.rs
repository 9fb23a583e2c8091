//! The exact stage on the floating-point search's last simplex: when no error-bounded
//! certificate holds (touching, a few ulps apart or in, flush faces), the simplex is almost
//! always the nearest feature pair, and a handful of polynomial signs of its exact points
//! decide the pair ([`super::staged`]: an error-bounded `f64` filter, then `f64` expansions,
//! rationals only for the values expansions cannot hold). Only when no sign test below
//! proves the answer does the exact rational search run.
//!
//! With `p_k = a_k − b_k` the exact difference points of a sub-simplex and `S` the reach (the
//! radii plus the clearance), every test is a proof on its own:
//! * **within** (one to three points): the origin's projection on the affine hull of the
//!   `p_k` lies in their convex hull (barycentric numerators `>= 0`) and its squared distance
//!   is at most `S²`. That point is a difference `x − y` with `x ∈ A`, `y ∈ B`, so the cores
//!   are within `S`;
//! * **inside** (four points): the tetrahedron holds the origin (orientation signs), so the
//!   cores share a point;
//! * **apart** (the direction `d` from the origin to that projection): `G = min_A d·a −
//!   max_B d·b > 0` and `G² > S²·d·d`, with the extreme points found by exact comparisons, so
//!   every pair of points is farther than `S` apart.
//!
//! The projection's direction, kept as a polynomial (no division): one point `p`: `d = p`;
//! an edge `e = p_1 − p_0`: `d = (e·e) p_0 − (p_0·e) e`; a face with normal
//! `n = (p_1 − p_0) × (p_2 − p_0)`: `d = ±n`, the sign of `p_0·n`.

use core::array::from_fn;
use core::cmp::Ordering;
use core::cmp::Ordering::{Equal, Greater, Less};

use ga_core::scalar::Ring;

use super::cores::{Core, ExactPoint};
use super::staged::{signs, Polys};
use crate::exact::{ErrF64, Expansion};

type V<R> = [R; 3];

fn sub<R: Ring>(a: &V<R>, b: &V<R>) -> V<R> {
    from_fn(|k| a[k].clone() - b[k].clone())
}

fn dot<R: Ring>(a: &V<R>, b: &V<R>) -> R {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

fn cross<R: Ring>(a: &V<R>, b: &V<R>) -> V<R> {
    let c = |i: usize, j: usize| a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
    [c(1, 2), c(2, 0), c(0, 1)]
}

/// One to four difference points `a_k − b_k` and the reach `S` as its three exact terms.
#[derive(Clone, Copy)]
struct Simplex {
    a: [ExactPoint; 4],
    b: [ExactPoint; 4],
    len: usize,
    reach: [f64; 3],
}

impl Simplex {
    /// The difference points (the first `len`; the rest zero), in fixed storage.
    fn points<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [V<R>; 4] {
        from_fn(|k| {
            if k < self.len {
                sub(&self.a[k].lift(lift), &self.b[k].lift(lift))
            } else {
                from_fn(|_| R::zero())
            }
        })
    }

    fn reach<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> R {
        lift(self.reach[0]) + lift(self.reach[1]) + lift(self.reach[2])
    }

    /// The direction `d` of the module docs (`flip` negates a face normal).
    fn direction<R: Ring>(&self, flip: bool, lift: &dyn Fn(f64) -> R) -> V<R> {
        let p = self.points(lift);
        match self.len {
            1 => p[0].clone(),
            2 => {
                let e = sub(&p[1], &p[0]);
                let (ee, pe) = (dot(&e, &e), dot(&p[0], &e));
                from_fn(|k| ee.clone() * p[0][k].clone() - pe.clone() * e[k].clone())
            }
            _ => {
                let n = cross(&sub(&p[1], &p[0]), &sub(&p[2], &p[0]));
                if flip {
                    n.map(|x| -x)
                } else {
                    n
                }
            }
        }
    }

    /// A sub-simplex: the pairs whose bit is set in `mask`.
    fn subset(&self, mask: u8) -> Simplex {
        let mut out = *self;
        out.len = 0;
        for k in 0..self.len {
            if mask >> k & 1 == 1 {
                out.a[out.len] = self.a[k];
                out.b[out.len] = self.b[k];
                out.len += 1;
            }
        }
        out
    }
}

/// `[|p|² − S²]` for one point (within: `<= 0`).
struct WithinPoint(Simplex);

impl Polys<1> for WithinPoint {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 1] {
        let p = self.0.points(lift);
        let s = self.0.reach(lift);
        [dot(&p[0], &p[0]) - s.clone() * s]
    }
}

/// `[e·e, −p_0·e, p_1·e, (e·e)|p_0|² − (p_0·e)² − S² e·e]` for an edge (within: `> 0`,
/// `>= 0`, `>= 0`, `<= 0`).
struct WithinEdge(Simplex);

impl Polys<4> for WithinEdge {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 4] {
        let p = self.0.points(lift);
        let s = self.0.reach(lift);
        let e = sub(&p[1], &p[0]);
        let (ee, pe) = (dot(&e, &e), dot(&p[0], &e));
        let far =
            ee.clone() * dot(&p[0], &p[0]) - pe.clone() * pe.clone() - s.clone() * s * ee.clone();
        [ee, -pe, dot(&p[1], &e), far]
    }
}

/// `[n·n, λ_0, λ_1, λ_2, (p_0·n)² − S² n·n, p_0·n]` for a face, `λ_i = (p_j × p_k)·n` the
/// barycentric numerators of the origin's projection (within: `> 0`, three `>= 0`, `<= 0`;
/// the last gives the side for the apart direction).
struct WithinFace(Simplex);

impl Polys<6> for WithinFace {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 6] {
        let p = self.0.points(lift);
        let s = self.0.reach(lift);
        let n = cross(&sub(&p[1], &p[0]), &sub(&p[2], &p[0]));
        let nn = dot(&n, &n);
        let h = dot(&p[0], &n);
        let lambda = |j: usize, k: usize| dot(&cross(&p[j], &p[k]), &n);
        [
            nn.clone(),
            lambda(1, 2),
            lambda(2, 0),
            lambda(0, 1),
            h.clone() * h.clone() - s.clone() * s * nn,
            h,
        ]
    }
}

fn orient<R: Ring>(p: [&V<R>; 4]) -> R {
    dot(&sub(p[1], p[0]), &cross(&sub(p[2], p[0]), &sub(p[3], p[0])))
}

/// The orientation of the tetrahedron, then with each corner in turn replaced by the origin
/// (inside: the first nonzero, the others of its sign or zero).
struct InsideTetra(Simplex);

impl Polys<5> for InsideTetra {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 5] {
        let p = self.0.points(lift);
        let o: V<R> = from_fn(|_| R::zero());
        let with_origin = |k: usize| {
            let mut q = [&p[0], &p[1], &p[2], &p[3]];
            q[k] = &o;
            orient(q)
        };
        [
            orient([&p[0], &p[1], &p[2], &p[3]]),
            with_origin(0),
            with_origin(1),
            with_origin(2),
            with_origin(3),
        ]
    }
}

/// `[d·x − d·y]`: how two points of one core compare along the direction.
struct Compare<'a> {
    simplex: &'a Simplex,
    flip: bool,
    x: ExactPoint,
    y: ExactPoint,
}

impl Polys<1> for Compare<'_> {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 1] {
        let d = self.simplex.direction(self.flip, lift);
        [dot(&d, &sub(&self.x.lift(lift), &self.y.lift(lift)))]
    }
}

/// `[G, G² − S² d·d]` with `G = d·a − d·b` (apart: both `> 0`).
struct Gap<'a> {
    simplex: &'a Simplex,
    flip: bool,
    a: ExactPoint,
    b: ExactPoint,
}

impl Polys<2> for Gap<'_> {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 2] {
        let d = self.simplex.direction(self.flip, lift);
        let g = dot(&d, &sub(&self.a.lift(lift), &self.b.lift(lift)));
        let s = self.simplex.reach(lift);
        [g.clone(), g.clone() * g - s.clone() * s * dot(&d, &d)]
    }
}

/// A sub-simplex's apart direction `d`, error-bounded, and exactly on expansions once an
/// exact sign is needed (`None` inside when they cannot hold it), so that the comparisons of
/// [`extreme`] and the gap of [`apart`] compute it once.
struct Direction<'a> {
    simplex: &'a Simplex,
    flip: bool,
    bounded: V<ErrF64>,
    exact: Option<Option<V<Expansion>>>,
}

impl<'a> Direction<'a> {
    fn new(simplex: &'a Simplex, flip: bool) -> Self {
        Direction {
            simplex,
            flip,
            bounded: simplex.direction(flip, &ErrF64::exact),
            exact: None,
        }
    }

    fn exact(&mut self) -> Option<&V<Expansion>> {
        let (simplex, flip) = (self.simplex, self.flip);
        self.exact
            .get_or_insert_with(|| {
                let d = simplex.direction(flip, &Expansion::from_f64);
                (!d.iter().any(Expansion::is_poisoned)).then_some(d)
            })
            .as_ref()
    }

    /// The exact sign of `d·x − d·y`.
    fn compare(&mut self, x: &ExactPoint, y: &ExactPoint) -> Ordering {
        let bounded = dot(
            &self.bounded,
            &sub(&x.lift(&ErrF64::exact), &y.lift(&ErrF64::exact)),
        );
        if let Some(s) = bounded.sign() {
            return s;
        }
        if let Some(d) = self.exact() {
            let diff = sub(&x.lift(&Expansion::from_f64), &y.lift(&Expansion::from_f64));
            if let Some(s) = dot(d, &diff).sign() {
                return s;
            }
        }
        let [s] = signs(&Compare {
            simplex: self.simplex,
            flip: self.flip,
            x: *x,
            y: *y,
        });
        s
    }

    /// The exact signs of `[G, G² − S² d·d]`, `G = d·a − d·b`.
    fn gap(&mut self, a: &ExactPoint, b: &ExactPoint) -> [Ordering; 2] {
        fn eval<R: Ring>(d: &V<R>, a: &V<R>, b: &V<R>, s: R) -> [R; 2] {
            let g = dot(d, &sub(a, b));
            [g.clone(), g.clone() * g - s.clone() * s * dot(d, d)]
        }
        let simplex = self.simplex;
        let bounded = eval(
            &self.bounded,
            &a.lift(&ErrF64::exact),
            &b.lift(&ErrF64::exact),
            simplex.reach(&ErrF64::exact),
        );
        if let [Some(g), Some(f)] = bounded.map(|x| x.sign()) {
            return [g, f];
        }
        if let Some(d) = self.exact() {
            let e = &Expansion::from_f64;
            let exact = eval(d, &a.lift(e), &b.lift(e), simplex.reach(e));
            if let [Some(g), Some(f)] = exact.map(|x| x.sign()) {
                return [g, f];
            }
        }
        signs(&Gap {
            simplex,
            flip: self.flip,
            a: *a,
            b: *b,
        })
    }
}

/// The point of `core` least along the direction (greatest when `largest`), exactly.
///
/// A first pass bounds every point's `d·x` with the error-bounded direction and takes the
/// point with the best proved bound; a point whose bound is strictly worse than that one's
/// cannot be the extreme, so only the points whose bounds overlap it (ties, flush faces) are
/// compared exactly.
fn extreme(core: &Core, direction: &mut Direction, largest: bool) -> ExactPoint {
    let d = direction.bounded;
    // Bounds of `±d·x` (negated for the least point), so that the extreme is the greatest.
    let bounds = |i: usize| {
        let p = core.point(i).lift(&ErrF64::exact);
        let v = dot(&p, &d);
        let v = if largest { v } else { -v };
        (
            (v.value - v.error).next_down(),
            (v.value + v.error).next_up(),
        )
    };
    let mut best = 0;
    let mut best_low = f64::NEG_INFINITY;
    for i in 0..core.len() {
        let (low, _) = bounds(i);
        if low > best_low {
            (best, best_low) = (i, low);
        }
    }
    let mut point = core.point(best);
    let beyond = if largest {
        Ordering::Greater
    } else {
        Ordering::Less
    };
    for i in 0..core.len() {
        // NaN bounds (overflow) fall through to the exact comparison.
        if i == best || bounds(i).1 < best_low {
            continue;
        }
        let x = core.point(i);
        if direction.compare(&x, &point) == beyond {
            point = x;
        }
    }
    point
}

fn apart(a: &Core, b: &Core, simplex: &Simplex, flip: bool) -> bool {
    let mut direction = Direction::new(simplex, flip);
    let low_a = extreme(a, &mut direction, false);
    let high_b = extreme(b, &mut direction, true);
    direction.gap(&low_a, &high_b) == [Ordering::Greater; 2]
}

/// What one sub-simplex proves alone.
enum Verdict {
    /// The cores are within `S`.
    Within,
    /// Not proved within; the apart test may try this direction (`flip` negates a face's
    /// normal).
    Try { flip: bool },
    /// Nothing (a degenerate sub-simplex, or the origin on a face's plane outside the face).
    Nothing,
}

fn at_least_zero(s: &Ordering) -> bool {
    *s != Less
}

fn verdict(simplex: &Simplex) -> Verdict {
    let within = |yes: bool| {
        if yes {
            Verdict::Within
        } else {
            Verdict::Try { flip: false }
        }
    };
    match simplex.len {
        1 => within(signs(&WithinPoint(*simplex))[0] != Greater),
        2 => match signs(&WithinEdge(*simplex)) {
            [Greater, t0, t1, far] => {
                within(at_least_zero(&t0) && at_least_zero(&t1) && far != Greater)
            }
            _ => Verdict::Nothing,
        },
        3 => match signs(&WithinFace(*simplex)) {
            [Greater, l0, l1, l2, far, side] => {
                if [l0, l1, l2].iter().all(at_least_zero) && far != Greater {
                    Verdict::Within
                } else if side == Equal {
                    Verdict::Nothing
                } else {
                    Verdict::Try { flip: side == Less }
                }
            }
            _ => Verdict::Nothing,
        },
        _ => match signs(&InsideTetra(*simplex)) {
            [whole @ (Greater | Less), rest @ ..]
                if rest.iter().all(|&s| s == whole || s == Equal) =>
            {
                Verdict::Within
            }
            _ => Verdict::Nothing,
        },
    }
}

/// The exact answer (are the grown cores within `S = reach[0] + reach[1] + reach[2]`?) from the
/// pairs of the search's last simplex, or `None` when these signs prove neither answer.
pub(super) fn decide(
    a: &Core,
    b: &Core,
    pairs: &[(usize, usize)],
    reach: [f64; 3],
) -> Option<bool> {
    let len = pairs.len().min(4);
    if len == 0 {
        return None;
    }
    let mut simplex = Simplex {
        a: [a.point(pairs[0].0); 4],
        b: [b.point(pairs[0].1); 4],
        len,
        reach,
    };
    for (k, &(ia, ib)) in pairs.iter().take(len).enumerate() {
        simplex.a[k] = a.point(ia);
        simplex.b[k] = b.point(ib);
    }
    // The whole simplex first (almost always the nearest feature pair), then its faces,
    // edges and points.
    let mut masks: Vec<u8> = (1..1u8 << len).collect();
    masks.sort_by_key(|m| core::cmp::Reverse(m.count_ones()));
    for mask in masks {
        let sub = simplex.subset(mask);
        match verdict(&sub) {
            Verdict::Within => return Some(true),
            Verdict::Try { flip } if apart(a, b, &sub, flip) => return Some(false),
            Verdict::Try { .. } | Verdict::Nothing => {}
        }
    }
    None
}
