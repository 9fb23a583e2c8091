//! Exact decisions about one real parameter: is there a `t` in a rational interval where
//! every polynomial of a list is `<= 0`?
//!
//! The pairs that sweep a point along a segment (a capsule's axis against a cylinder or cone)
//! reduce to such questions, with polynomials of degree at most 4 and rational coefficients.
//! The set `S = {t : pᵢ(t) <= 0 for all i}` is closed, so if `S ∩ [lo, hi]` is not empty its
//! least element is `lo` or a root of some `pᵢ` in `(lo, hi)` (just left of it some `pᵢ` is
//! positive, and by continuity it vanishes there). The test therefore tries `lo`, `hi` and
//! every such root. Roots are isolated with Sturm sequences of the square-free part and the
//! other polynomials' signs at an irrational root come from a Tarski query (the Sturm–Tarski
//! theorem: for `p` with one root `α` in `(a, b)`, `a` and `b` not roots, the sign variations
//! of the signed remainder sequence of `(p, p'·q)` at `a` minus those at `b` are the sign of
//! `q(α)`). No root is ever approximated to decide a sign.
//!
//! The crate's `motion` layer has the same machinery over integer polynomials in time; this
//! layer sits below it, and its coefficients are rationals of any size.

use core::cmp::Ordering;

use ga_core::scalar::Rational;
use num_traits::{One, Signed, Zero};

use super::surd::sign;

/// `Σ c[i] tⁱ` with rational coefficients and no trailing zeros (zero has none).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Poly(Vec<Rational>);

impl Poly {
    pub(crate) fn new(mut c: Vec<Rational>) -> Poly {
        while c.last().is_some_and(|x| x.is_zero()) {
            c.pop();
        }
        Poly(c)
    }

    pub(crate) fn constant(c: Rational) -> Poly {
        Poly::new(vec![c])
    }

    /// `a + b·t`.
    pub(crate) fn linear(a: Rational, b: Rational) -> Poly {
        Poly::new(vec![a, b])
    }

    /// `a + b·t + c·t²`.
    pub(crate) fn quadratic(a: Rational, b: Rational, c: Rational) -> Poly {
        Poly::new(vec![a, b, c])
    }

    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    fn lead(&self) -> Rational {
        self.0.last().cloned().unwrap_or_else(Rational::zero)
    }

    pub(crate) fn add(&self, o: &Poly) -> Poly {
        let n = self.0.len().max(o.0.len());
        let zero = Rational::zero();
        Poly::new(
            (0..n)
                .map(|i| self.0.get(i).unwrap_or(&zero) + o.0.get(i).unwrap_or(&zero))
                .collect(),
        )
    }

    pub(crate) fn scale(&self, k: &Rational) -> Poly {
        Poly::new(self.0.iter().map(|c| c * k).collect())
    }

    pub(crate) fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.scale(&-Rational::one()))
    }

    pub(crate) fn mul(&self, o: &Poly) -> Poly {
        if self.is_zero() || o.is_zero() {
            return Poly(Vec::new());
        }
        let mut c = vec![Rational::zero(); self.0.len() + o.0.len() - 1];
        for (i, x) in self.0.iter().enumerate() {
            for (j, y) in o.0.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        Poly::new(c)
    }

    pub(crate) fn eval(&self, t: &Rational) -> Rational {
        self.0
            .iter()
            .rev()
            .fold(Rational::zero(), |acc, c| acc * t + c)
    }

    fn derivative(&self) -> Poly {
        Poly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * Rational::from_integer((i as i64).into()))
                .collect(),
        )
    }

    /// Quotient and remainder of the division by `d` (not zero).
    fn div_rem(&self, d: &Poly) -> (Poly, Poly) {
        let mut r = self.0.clone();
        let dl = d.lead();
        let mut quot = vec![Rational::zero(); self.0.len().saturating_sub(d.degree())];
        while r.len() >= d.0.len() && !r.is_empty() {
            let shift = r.len() - d.0.len();
            let k = r.last().cloned().unwrap_or_else(Rational::zero) / &dl;
            for (i, c) in d.0.iter().enumerate() {
                r[shift + i] -= &k * c;
            }
            quot[shift] = k;
            r.pop();
            while r.last().is_some_and(|x| x.is_zero()) {
                r.pop();
            }
        }
        (Poly::new(quot), Poly::new(r))
    }

    /// The square-free part (same distinct roots, each simple).
    fn square_free(&self) -> Poly {
        let mut a = self.clone();
        let mut b = self.derivative();
        while !b.is_zero() {
            let (_, r) = a.div_rem(&b);
            a = b;
            b = r;
        }
        if a.degree() == 0 {
            return self.clone();
        }
        self.div_rem(&a).0
    }
}

/// The signed remainder sequence of `(p, q)`.
fn remainders(p: &Poly, q: &Poly) -> Vec<Poly> {
    let mut seq = vec![p.clone()];
    let mut next = q.clone();
    while !next.is_zero() {
        let r = seq[seq.len() - 1].div_rem(&next).1;
        seq.push(next);
        next = r.scale(&-Rational::one());
    }
    seq
}

fn variations(seq: &[Poly], x: &Rational) -> i64 {
    let mut last = Ordering::Equal;
    let mut n = 0;
    for p in seq {
        let s = sign(&p.eval(x));
        if s == Ordering::Equal {
            continue;
        }
        if last != Ordering::Equal && s != last {
            n += 1;
        }
        last = s;
    }
    n
}

/// A root of a square-free polynomial: exact, or the only one in an open interval whose ends
/// are not roots.
enum Root {
    Exact(Rational),
    Between(Rational, Rational),
}

/// The roots of the square-free `p` in `(a, b)`, where `p(a) != 0 != p(b)`.
fn isolate(p: &Poly, sturm: &[Poly], a: Rational, b: Rational, out: &mut Vec<Root>) {
    let n = variations(sturm, &a) - variations(sturm, &b);
    if n <= 0 {
        return;
    }
    if n == 1 {
        out.push(Root::Between(a, b));
        return;
    }
    let two = Rational::from_integer(2.into());
    let m = (&a + &b) / &two;
    if !p.eval(&m).is_zero() {
        isolate(p, sturm, a, m.clone(), out);
        isolate(p, sturm, m, b, out);
        return;
    }
    // `m` is a root: step off it to points that are not, close enough to hold no other.
    out.push(Root::Exact(m.clone()));
    let mut delta = (&b - &a) / Rational::from_integer(4.into());
    loop {
        let (lo, hi) = (&m - &delta, &m + &delta);
        if !p.eval(&lo).is_zero()
            && !p.eval(&hi).is_zero()
            && variations(sturm, &lo) - variations(sturm, &hi) == 1
        {
            isolate(p, sturm, a, lo, out);
            isolate(p, sturm, hi, b, out);
            return;
        }
        delta /= &two;
    }
}

/// The sign of `q` at the only root of `p` in `(a, b)` (`p(a)`, `p(b)` not zero).
fn sign_at_root(p: &Poly, q: &Poly, a: &Rational, b: &Rational) -> Ordering {
    let seq = remainders(p, &p.derivative().mul(q));
    (variations(&seq, a) - variations(&seq, b)).cmp(&0)
}

/// Exact: is there a `t ∈ [lo, hi]` (with `lo <= hi`) where every polynomial of `all` is `<= 0`?
pub(crate) fn exists_all_non_positive(all: &[Poly], lo: &Rational, hi: &Rational) -> bool {
    let holds_at = |t: &Rational| all.iter().all(|p| !p.eval(t).is_positive());
    if holds_at(lo) || holds_at(hi) {
        return true;
    }
    for p in all.iter().filter(|p| p.degree() > 0) {
        let mut s = p.square_free();
        // Take the ends out, so that neither is a root.
        for end in [lo, hi] {
            if s.eval(end).is_zero() {
                s = s.div_rem(&Poly::linear(-end.clone(), Rational::one())).0;
            }
        }
        if s.degree() == 0 {
            continue;
        }
        let sturm = remainders(&s, &s.derivative());
        let mut roots = Vec::new();
        isolate(&s, &sturm, lo.clone(), hi.clone(), &mut roots);
        for root in roots {
            let ok = match &root {
                Root::Exact(t) => holds_at(t),
                Root::Between(a, b) => all
                    .iter()
                    .all(|q| sign_at_root(&s, q, a, b) != Ordering::Greater),
            };
            if ok {
                return true;
            }
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64) -> Rational {
        Rational::from_integer(n.into())
    }

    fn poly(c: &[i64]) -> Poly {
        Poly::new(c.iter().map(|&x| r(x)).collect())
    }

    #[test]
    fn a_tangent_parabola_touches_at_one_irrational_point() {
        // (t² − 2)² <= 0 only at t = √2; with t <= √2 as t² − 2 <= 0 the set is {√2}.
        let p = poly(&[-2, 0, 1]);
        let sq = p.mul(&p);
        assert!(exists_all_non_positive(
            std::slice::from_ref(&sq),
            &r(0),
            &r(2)
        ));
        assert!(exists_all_non_positive(
            &[sq.clone(), p.clone()],
            &r(0),
            &r(2)
        ));
        // Also t >= 3/2 (3/2 − t <= 0): √2 ≈ 1.414 is not, so nothing.
        let right = poly(&[0, -2]).add(&Poly::constant(r(3)));
        assert!(!exists_all_non_positive(&[sq.clone(), right], &r(0), &r(2)));
        // t >= 7/5 = 1.4: √2 is.
        let right = poly(&[7, -5]);
        assert!(exists_all_non_positive(&[sq, right], &r(0), &r(2)));
    }

    #[test]
    fn rational_roots_at_midpoints_and_ends() {
        // (t − 1)² <= 0 on [0, 2]: the root 1 is the first midpoint.
        let p = poly(&[1, -2, 1]);
        assert!(exists_all_non_positive(
            std::slice::from_ref(&p),
            &r(0),
            &r(2)
        ));
        // On [1, 3] the root is the end.
        assert!(exists_all_non_positive(
            std::slice::from_ref(&p),
            &r(1),
            &r(3)
        ));
        // On [2, 3] it is outside.
        assert!(!exists_all_non_positive(&[p], &r(2), &r(3)));
        // (t − 1)(t − 3/2)(t − 2) <= 0 together with t(…) : several roots, one a midpoint.
        let q = poly(&[-1, 1]).mul(&poly(&[-3, 2])).mul(&poly(&[-2, 1]));
        let neg = q.scale(&r(-1));
        // q <= 0 and −q <= 0 only at the roots 1, 3/2, 2.
        assert!(exists_all_non_positive(
            &[q.clone(), neg.clone()],
            &r(0),
            &r(4)
        ));
        // Excluding them with t <= 1/2:
        let left = poly(&[-1, 2]);
        assert!(!exists_all_non_positive(&[q, neg, left], &r(0), &r(4)));
    }

    #[test]
    fn positive_constants_and_zero_polynomials() {
        assert!(!exists_all_non_positive(
            &[Poly::constant(r(1))],
            &r(0),
            &r(1)
        ));
        assert!(exists_all_non_positive(&[Poly::new(vec![])], &r(0), &r(1)));
        assert!(exists_all_non_positive(&[], &r(0), &r(1)));
    }

    #[test]
    fn square_free_parts() {
        let p = poly(&[-1, 1]).mul(&poly(&[-1, 1])).mul(&poly(&[2, 1]));
        let s = p.square_free();
        assert_eq!(s.degree(), 2);
        assert!(s.eval(&r(1)).is_zero() && s.eval(&r(-2)).is_zero());
    }
}
