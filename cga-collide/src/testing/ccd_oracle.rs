//! An exact decision of continuous collision written independently of [`crate::motion`], for
//! tests: exact rationals throughout (`BigRational`), no floating-point filter, no scaling to
//! integers, no Sturm–Tarski queries.
//!
//! Points move linearly, `p(t) = p₀ + t·(p₁ − p₀)` for `t ∈ [0, 1]`; the inputs are
//! `[[[f64; 3]; 2]; 4]`, four points × (`t = 0`, `t = 1`) × xyz, taken as the exact rationals
//! they denote. Closed sets: touching counts.
//!
//! # Method
//! Contact at time `t` is written as a boolean formula `inside(t)` over the signs of a fixed
//! finite set of polynomials in `t` with rational coefficients:
//! - **vertex `p`, triangle `a, b, c`**: with `n = (b − a) × (c − a)`, `p` is in the closed
//!   triangle iff `f = n·(p − a) = 0` and either `|n|² > 0` and the three barycentric
//!   numerators `((p − a) × (c − a))·n`, `((b − a) × (p − a))·n` and `|n|²` minus both are
//!   `≥ 0` (they are `u·|n|²`, `v·|n|²`, `(1 − u − v)·|n|²` for `p − a = u(b − a) + v(c − a)`),
//!   or `|n|² = 0` (the triangle is a segment or a point, the union of its three edges) and `p`
//!   is on one of the three edges;
//! - **edges `a₀a₁`, `b₀b₁`**: with `n = (a₁ − a₀) × (b₁ − b₀)`, the closed segments meet iff
//!   the four points are coplanar and either `|n|² > 0` (the lines cross at one point) and each
//!   segment's ends are on opposite sides of, or on, the other's line (signs of
//!   `((a₁ − a₀) × (b_i − a₀))·n` and `((b₁ − b₀) × (a_i − b₀))·n`), or `|n|² = 0` (parallel
//!   or zero-length) and an endpoint of one segment is on the other (collinear overlapping
//!   intervals always contain an endpoint of one in the other);
//! - **point `q` on the closed segment `s₀s₁`**: `(q − s₀) × (q − s₁) = 0` and
//!   `(q − s₀)·(q − s₁) ≤ 0` (this covers `s₀ = s₁`: then the dot product is `|q − s₀|²`).
//!
//! The set `C` of contact times is closed (the preimage of a closed set by a continuous map).
//! On every open interval between consecutive points of `Z = {0, 1} ∪` (roots in `[0, 1]` of
//! the polynomials of the formula that are not identically zero), every sign is constant, so
//! `C` contains either all of it or none of it, and in the first case also its left end by
//! closedness. Hence `C` is empty iff no point of `Z` satisfies the formula, and `min C` is the
//! least point of `Z` that does. When the coplanarity polynomial is not identically zero, `C`
//! lies within its roots, and those alone are tested.
//!
//! Points of `Z` are real algebraic numbers ([`Algebraic`]): an exact rational, or a
//! square-free polynomial with an isolating open interval with rational ends (roots isolated
//! by bisection with Sturm sequences; a root met exactly by a bisection point is kept as that
//! rational). The sign of a polynomial `q` at a root of `P` is zero iff `gcd(P, q)` changes
//! sign over the isolating interval; otherwise the interval is bisected until `q` has no root
//! in it, and the sign is that of `q` at an end.

use core::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

type Q = BigRational;

fn q_from_f64(x: f64) -> Q {
    assert!(x.is_finite(), "ccd_oracle: coordinates must be finite");
    BigRational::from_float(x).expect("finite")
}

fn sign(x: &Q) -> Ordering {
    x.cmp(&Q::zero())
}

/// A polynomial in `t` with rational coefficients, constant term first, no trailing zeros.
#[derive(Clone, Debug, PartialEq)]
struct Poly(Vec<Q>);

impl Poly {
    fn new(mut c: Vec<Q>) -> Poly {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        Poly(c)
    }

    fn zero() -> Poly {
        Poly(Vec::new())
    }

    /// `a + b·t`.
    fn linear(a: Q, b: Q) -> Poly {
        Poly::new(vec![a, b])
    }

    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The degree; `None` for the zero polynomial.
    fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    fn add(&self, other: &Poly) -> Poly {
        let n = self.0.len().max(other.0.len());
        Poly::new(
            (0..n)
                .map(|i| {
                    let x = self.0.get(i).cloned().unwrap_or_else(Q::zero);
                    let y = other.0.get(i).cloned().unwrap_or_else(Q::zero);
                    x + y
                })
                .collect(),
        )
    }

    fn neg(&self) -> Poly {
        Poly(self.0.iter().map(|c| -c).collect())
    }

    fn sub(&self, other: &Poly) -> Poly {
        self.add(&other.neg())
    }

    fn mul(&self, other: &Poly) -> Poly {
        if self.is_zero() || other.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![Q::zero(); self.0.len() + other.0.len() - 1];
        for (i, x) in self.0.iter().enumerate() {
            for (j, y) in other.0.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        Poly::new(c)
    }

    fn eval(&self, t: &Q) -> Q {
        self.0.iter().rev().fold(Q::zero(), |acc, c| acc * t + c)
    }

    fn sign_at(&self, t: &Q) -> Ordering {
        sign(&self.eval(t))
    }

    fn derivative(&self) -> Poly {
        Poly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * Q::from_integer(BigInt::from(i)))
                .collect(),
        )
    }

    /// Quotient and remainder by a non-zero divisor.
    fn div_rem(&self, d: &Poly) -> (Poly, Poly) {
        let dd = d.degree().expect("division by the zero polynomial");
        let lead = d.0[dd].clone();
        let mut r = self.0.clone();
        let mut quotient = vec![Q::zero(); r.len().saturating_sub(dd)];
        while r.len() > dd && !r.is_empty() {
            let k = r.len() - 1 - dd;
            let factor = r.last().expect("non-empty") / &lead;
            for (i, c) in d.0.iter().enumerate() {
                r[k + i] -= &factor * c;
            }
            quotient[k] = factor;
            r.pop();
            while r.last().is_some_and(Zero::is_zero) {
                r.pop();
            }
        }
        (Poly::new(quotient), Poly::new(r))
    }

    fn monic(&self) -> Poly {
        match self.0.last() {
            None => Poly::zero(),
            Some(lead) => Poly(self.0.iter().map(|c| c / lead).collect()),
        }
    }

    /// The monic greatest common divisor (zero when both are zero).
    fn gcd(&self, other: &Poly) -> Poly {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let r = a.div_rem(&b).1;
            a = b;
            b = r.monic();
        }
        a.monic()
    }

    /// The product of the distinct irreducible factors (same roots, all simple).
    fn square_free(&self) -> Poly {
        let g = self.gcd(&self.derivative());
        self.div_rem(&g).0.monic()
    }

    /// The Sturm sequence of a square-free polynomial.
    fn sturm(&self) -> Vec<Poly> {
        let mut seq = vec![self.clone(), self.derivative()];
        while !seq.last().expect("two").is_zero() {
            let n = seq.len();
            let r = seq[n - 2].div_rem(&seq[n - 1]).1.neg();
            seq.push(r);
        }
        seq.pop();
        seq
    }
}

fn variations(seq: &[Poly], x: &Q) -> usize {
    let signs: Vec<Ordering> = seq
        .iter()
        .map(|p| p.sign_at(x))
        .filter(|s| *s != Ordering::Equal)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The number of distinct roots in `(lo, hi)` of the square-free polynomial whose Sturm
/// sequence is `seq`, neither `lo` nor `hi` being a root.
fn count_roots(seq: &[Poly], lo: &Q, hi: &Q) -> usize {
    variations(seq, lo) - variations(seq, hi)
}

/// A real algebraic number: an exact rational, or the only root of a square-free polynomial in
/// an open interval with rational ends at which the polynomial does not vanish.
#[derive(Clone, Debug)]
pub struct Algebraic(Repr);

#[derive(Clone, Debug)]
enum Repr {
    Exact(Q),
    Root { poly: Poly, lo: Q, hi: Q },
}

impl Algebraic {
    fn exact(q: Q) -> Algebraic {
        Algebraic(Repr::Exact(q))
    }

    /// Bounds `lo <= x <= hi` (equal iff the number is that rational; else `lo < x < hi`).
    pub fn bounds(&self) -> (BigRational, BigRational) {
        match &self.0 {
            Repr::Exact(q) => (q.clone(), q.clone()),
            Repr::Root { lo, hi, .. } => (lo.clone(), hi.clone()),
        }
    }

    /// The number, when it is rational and known to be (every rational contact time that a
    /// bisection meets exactly, `0` and `1` among them).
    pub fn as_exact(&self) -> Option<&BigRational> {
        match &self.0 {
            Repr::Exact(q) => Some(q),
            Repr::Root { .. } => None,
        }
    }

    /// The bounds rounded outwards to `f64` (for messages).
    pub fn approx(&self) -> (f64, f64) {
        let (lo, hi) = self.bounds();
        let f = |q: &Q| {
            let n = q.numer().to_string().parse::<f64>().unwrap_or(f64::NAN);
            let d = q.denom().to_string().parse::<f64>().unwrap_or(f64::NAN);
            n / d
        };
        (f(&lo), f(&hi))
    }

    /// Halves the isolating interval (or finds the number exactly).
    fn bisect(&mut self) {
        if let Repr::Root { poly, lo, hi } = &mut self.0 {
            let mid = (&*lo + &*hi) / Q::from_integer(BigInt::from(2));
            let s = poly.sign_at(&mid);
            if s == Ordering::Equal {
                self.0 = Repr::Exact(mid);
            } else if s == poly.sign_at(lo) {
                *lo = mid;
            } else {
                *hi = mid;
            }
        }
    }

    /// Narrows the isolating interval to at most `width`.
    pub fn refine(&mut self, width: &BigRational) {
        while let Repr::Root { lo, hi, .. } = &self.0 {
            if &(hi - lo) <= width {
                break;
            }
            self.bisect();
        }
    }

    /// Compares the number with the rational `q`.
    pub fn cmp_rational(&mut self, q: &BigRational) -> Ordering {
        match &mut self.0 {
            Repr::Exact(x) => (*x).cmp(q),
            Repr::Root { poly, lo, hi } => {
                if q <= lo {
                    Ordering::Greater
                } else if q >= hi {
                    Ordering::Less
                } else {
                    let s = poly.sign_at(q);
                    if s == Ordering::Equal {
                        self.0 = Repr::Exact(q.clone());
                        Ordering::Equal
                    } else if s == poly.sign_at(lo) {
                        // The root is above `q`.
                        *lo = q.clone();
                        Ordering::Greater
                    } else {
                        *hi = q.clone();
                        Ordering::Less
                    }
                }
            }
        }
    }

    /// Compares the number with the exact value of the finite `x`.
    pub fn cmp_f64(&mut self, x: f64) -> Ordering {
        self.cmp_rational(&q_from_f64(x))
    }

    /// The sign of `q` at the number.
    fn sign_of(&mut self, q: &Poly) -> Ordering {
        if q.is_zero() {
            return Ordering::Equal;
        }
        let (poly, lo, hi) = match &self.0 {
            Repr::Exact(x) => return q.sign_at(x),
            Repr::Root { poly, lo, hi } => (poly.clone(), lo.clone(), hi.clone()),
        };
        // A common root: `g` divides the square-free `poly`, which has one simple root in
        // `(lo, hi)` and none at the ends, so `g` vanishes there iff it changes sign.
        let g = poly.gcd(q);
        if g.degree().is_some_and(|d| d >= 1) && g.sign_at(&lo) != g.sign_at(&hi) {
            return Ordering::Equal;
        }
        // Otherwise `q` is not zero at the number: narrow until `q` has no root in the interval.
        let seq = q.square_free().sturm();
        loop {
            match &self.0 {
                Repr::Exact(x) => return q.sign_at(x),
                Repr::Root { lo, hi, .. } => {
                    // Equal non-zero end signs first (cheap), then no root in between.
                    let s_lo = q.sign_at(lo);
                    if s_lo != Ordering::Equal
                        && q.sign_at(hi) == s_lo
                        && count_roots(&seq, lo, hi) == 0
                    {
                        return s_lo;
                    }
                }
            }
            self.bisect();
        }
    }
}

/// Compares two algebraic numbers exactly.
fn compare(a: &mut Algebraic, b: &mut Algebraic) -> Ordering {
    loop {
        if let Repr::Exact(q) = &a.0 {
            let q = q.clone();
            return b.cmp_rational(&q).reverse();
        }
        if let Repr::Exact(q) = &b.0 {
            let q = q.clone();
            return a.cmp_rational(&q);
        }
        let (
            Repr::Root {
                poly: pa,
                lo: la,
                hi: ha,
            },
            Repr::Root {
                poly: pb,
                lo: lb,
                hi: hb,
            },
        ) = (&a.0, &b.0)
        else {
            unreachable!("both are roots here");
        };
        if ha <= lb {
            return Ordering::Less;
        }
        if hb <= la {
            return Ordering::Greater;
        }
        // Overlapping: equal iff their common factor has a root in the overlap (it divides both
        // square-free polynomials, so it has at most one root there and is non-zero at the ends).
        let g = pa.gcd(pb);
        if g.degree().is_some_and(|d| d >= 1) {
            let lo = la.max(lb);
            let hi = ha.min(hb);
            if g.sign_at(lo) != g.sign_at(hi) {
                return Ordering::Equal;
            }
        }
        a.bisect();
        b.bisect();
    }
}

/// The real roots in `[0, 1]` of a polynomial that is not identically zero, ascending.
fn roots_in_unit(p: &Poly) -> Vec<Algebraic> {
    let mut out = Vec::new();
    if p.degree().is_none_or(|d| d == 0) {
        return out;
    }
    let mut s = p.square_free();
    let (zero, one) = (Q::zero(), Q::one());
    if s.sign_at(&zero) == Ordering::Equal {
        out.push(Algebraic::exact(zero.clone()));
        s = s.div_rem(&Poly::linear(Q::zero(), Q::one())).0;
    }
    let at_one = s.sign_at(&one) == Ordering::Equal;
    if at_one {
        s = s.div_rem(&Poly::linear(-Q::one(), Q::one())).0;
    }
    isolate(s, zero, one.clone(), &mut out);
    if at_one {
        out.push(Algebraic::exact(one));
    }
    out
}

/// Appends the roots in `(lo, hi)` of the square-free `p` (not zero at `lo` nor `hi`), ascending.
fn isolate(p: Poly, lo: Q, hi: Q, out: &mut Vec<Algebraic>) {
    if p.degree().is_none_or(|d| d == 0) {
        return;
    }
    let seq = p.sturm();
    match count_roots(&seq, &lo, &hi) {
        0 => {}
        1 => out.push(Algebraic(Repr::Root { poly: p, lo, hi })),
        _ => {
            let mid = (&lo + &hi) / Q::from_integer(BigInt::from(2));
            if p.sign_at(&mid) == Ordering::Equal {
                // Deflate: the quotient keeps the other roots, none at `mid`.
                let rest = p.div_rem(&Poly::linear(-mid.clone(), Q::one())).0;
                isolate(rest.clone(), lo, mid.clone(), out);
                out.push(Algebraic::exact(mid.clone()));
                isolate(rest, mid, hi, out);
            } else {
                isolate(p.clone(), lo, mid.clone(), out);
                isolate(p, mid, hi, out);
            }
        }
    }
}

type Vector = [Poly; 3];

fn track(point: &[[f64; 3]; 2]) -> Vector {
    core::array::from_fn(|axis| {
        let start = q_from_f64(point[0][axis]);
        let end = q_from_f64(point[1][axis]);
        let velocity = &end - &start;
        Poly::linear(start, velocity)
    })
}

fn sub(a: &Vector, b: &Vector) -> Vector {
    core::array::from_fn(|i| a[i].sub(&b[i]))
}

fn cross(a: &Vector, b: &Vector) -> Vector {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

fn dot(a: &Vector, b: &Vector) -> Poly {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

/// Point `q` on the closed segment `s₀s₁`: `(q − s₀) × (q − s₁) = 0`, `(q − s₀)·(q − s₁) ≤ 0`.
struct OnSegment {
    cross: Vector,
    dot: Poly,
}

impl OnSegment {
    fn new(q: &Vector, s0: &Vector, s1: &Vector) -> OnSegment {
        let (u, v) = (sub(q, s0), sub(q, s1));
        OnSegment {
            cross: cross(&u, &v),
            dot: dot(&u, &v),
        }
    }

    fn holds(&self, t: &mut Algebraic) -> bool {
        self.cross.iter().all(|c| t.sign_of(c) == Ordering::Equal)
            && t.sign_of(&self.dot) != Ordering::Greater
    }

    fn polys(&self) -> impl Iterator<Item = &Poly> {
        self.cross.iter().chain(core::iter::once(&self.dot))
    }
}

/// The least point of `Z` (see the module docs) at which `inside` holds.
fn first(
    coplanar: &Poly,
    others: &[&Poly],
    mut inside: impl FnMut(&mut Algebraic) -> bool,
) -> Option<Algebraic> {
    let candidates: Vec<Algebraic> = if coplanar.is_zero() {
        let mut all = vec![Algebraic::exact(Q::zero()), Algebraic::exact(Q::one())];
        for p in others {
            if !p.is_zero() {
                all.extend(roots_in_unit(p));
            }
        }
        all
    } else {
        roots_in_unit(coplanar)
    };
    let mut best: Option<Algebraic> = None;
    for mut t in candidates {
        if !inside(&mut t) {
            continue;
        }
        best = Some(match best {
            None => t,
            Some(mut b) => {
                if compare(&mut t, &mut b) == Ordering::Less {
                    t
                } else {
                    b
                }
            }
        });
    }
    best
}

fn product_sign(a: Ordering, b: Ordering) -> Ordering {
    match (a, b) {
        (Ordering::Equal, _) | (_, Ordering::Equal) => Ordering::Equal,
        (x, y) if x == y => Ordering::Greater,
        _ => Ordering::Less,
    }
}

/// The earliest `t ∈ [0, 1]` at which vertex `points[0]` is in the closed triangle
/// `points[1..4]`, `None` if never.
pub fn vertex_face_first_contact(points: &[[[f64; 3]; 2]; 4]) -> Option<Algebraic> {
    let [p, a, b, c] = core::array::from_fn(|i| track(&points[i]));
    let (e1, e2, pa) = (sub(&b, &a), sub(&c, &a), sub(&p, &a));
    let n = cross(&e1, &e2);
    let nn = dot(&n, &n);
    let f = dot(&n, &pa);
    let u = dot(&cross(&pa, &e2), &n);
    let v = dot(&cross(&e1, &pa), &n);
    let w = nn.sub(&u).sub(&v);
    let edges = [
        OnSegment::new(&p, &a, &b),
        OnSegment::new(&p, &b, &c),
        OnSegment::new(&p, &c, &a),
    ];
    let mut others: Vec<&Poly> = vec![&nn, &u, &v, &w];
    others.extend(edges.iter().flat_map(OnSegment::polys));
    first(&f, &others, |t| {
        if t.sign_of(&f) != Ordering::Equal {
            return false;
        }
        if t.sign_of(&nn) == Ordering::Greater {
            [&u, &v, &w].iter().all(|s| t.sign_of(s) != Ordering::Less)
        } else {
            edges.iter().any(|e| e.holds(t))
        }
    })
}

/// The earliest `t ∈ [0, 1]` at which the closed edges `points[0..2]` and `points[2..4]`
/// touch, `None` if never.
pub fn edge_edge_first_contact(points: &[[[f64; 3]; 2]; 4]) -> Option<Algebraic> {
    let [a0, a1, b0, b1] = core::array::from_fn(|i| track(&points[i]));
    let (ea, eb) = (sub(&a1, &a0), sub(&b1, &b0));
    let n = cross(&ea, &eb);
    let nn = dot(&n, &n);
    let g = dot(&ea, &cross(&sub(&b0, &a0), &sub(&b1, &a0)));
    let side_a = [
        dot(&cross(&ea, &sub(&b0, &a0)), &n),
        dot(&cross(&ea, &sub(&b1, &a0)), &n),
    ];
    let side_b = [
        dot(&cross(&eb, &sub(&a0, &b0)), &n),
        dot(&cross(&eb, &sub(&a1, &b0)), &n),
    ];
    let ends = [
        OnSegment::new(&a0, &b0, &b1),
        OnSegment::new(&a1, &b0, &b1),
        OnSegment::new(&b0, &a0, &a1),
        OnSegment::new(&b1, &a0, &a1),
    ];
    let mut others: Vec<&Poly> = vec![&nn];
    others.extend(side_a.iter().chain(&side_b));
    others.extend(ends.iter().flat_map(OnSegment::polys));
    first(&g, &others, |t| {
        if t.sign_of(&g) != Ordering::Equal {
            return false;
        }
        if t.sign_of(&nn) == Ordering::Greater {
            product_sign(t.sign_of(&side_a[0]), t.sign_of(&side_a[1])) != Ordering::Greater
                && product_sign(t.sign_of(&side_b[0]), t.sign_of(&side_b[1])) != Ordering::Greater
        } else {
            ends.iter().any(|e| e.holds(t))
        }
    })
}

/// Whether the vertex and the triangle touch for some `t ∈ [0, 1]`.
pub fn vertex_face_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
    vertex_face_first_contact(points).is_some()
}

/// Whether the edges touch for some `t ∈ [0, 1]`.
pub fn edge_edge_touch(points: &[[[f64; 3]; 2]; 4]) -> bool {
    edge_edge_first_contact(points).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn roots_are_isolated_and_sorted() {
        // (t − 1/4)(t − 1/3)²(t − 1)(t² − 1/2)
        let p = Poly::linear(-q(1, 4), Q::one())
            .mul(&Poly::linear(-q(1, 3), Q::one()))
            .mul(&Poly::linear(-q(1, 3), Q::one()))
            .mul(&Poly::linear(-Q::one(), Q::one()))
            .mul(&Poly::new(vec![-q(1, 2), Q::zero(), Q::one()]));
        let mut roots = roots_in_unit(&p);
        assert_eq!(roots.len(), 4);
        assert_eq!(roots[0].as_exact(), Some(&q(1, 4)));
        assert_eq!(roots[1].cmp_rational(&q(1, 3)), Ordering::Equal);
        assert_eq!(roots[2].cmp_rational(&q(7071, 10000)), Ordering::Greater);
        assert_eq!(roots[2].cmp_rational(&q(7072, 10000)), Ordering::Less);
        assert_eq!(roots[3].as_exact(), Some(&Q::one()));
    }

    #[test]
    fn signs_at_roots() {
        let mut r = roots_in_unit(&Poly::new(vec![-q(1, 2), Q::zero(), Q::one()])).remove(0);
        // t² − 1/2 shares the root; 2t² − 1 too; t − 7/10 is positive there.
        assert_eq!(
            r.sign_of(&Poly::new(vec![-Q::one(), Q::zero(), q(2, 1)])),
            Ordering::Equal
        );
        assert_eq!(
            r.sign_of(&Poly::linear(-q(7, 10), Q::one())),
            Ordering::Greater
        );
        assert_eq!(
            r.sign_of(&Poly::linear(-q(71, 100), Q::one())),
            Ordering::Less
        );
    }

    #[test]
    fn falling_vertex() {
        let still = |x: f64, y: f64, z: f64| [[x, y, z], [x, y, z]];
        let points = [
            [[0.2, 0.2, 1.0], [0.2, 0.2, -1.0]],
            still(0., 0., 0.),
            still(1., 0., 0.),
            still(0., 1., 0.),
        ];
        let mut t = vertex_face_first_contact(&points).expect("contact");
        assert_eq!(t.cmp_rational(&q(1, 2)), Ordering::Equal);
        // Coplanar sliding into a still triangle: contact when reaching the edge x = 0.
        let points = [
            [[-1.0, 0.25, 0.0], [1.0, 0.25, 0.0]],
            still(0., 0., 0.),
            still(1., 0., 0.),
            still(0., 1., 0.),
        ];
        let mut t = vertex_face_first_contact(&points).expect("contact");
        assert_eq!(t.cmp_rational(&q(1, 2)), Ordering::Equal);
        // Crossing edges, and the same but passing beside.
        let e = [
            [[0., 0., 0.], [0., 0., 0.]],
            [[1., 0., 0.], [1., 0., 0.]],
            [[0.5, -1., 1.], [0.5, -1., -1.]],
            [[0.5, 1., 1.], [0.5, 1., -1.]],
        ];
        assert!(edge_edge_touch(&e));
        let mut beside = e;
        beside[2][0][0] = 1.5;
        beside[2][1][0] = 1.5;
        beside[3][0][0] = 1.5;
        beside[3][1][0] = 1.5;
        assert!(!edge_edge_touch(&beside));
    }
}
