//! Exact univariate polynomials in the time `t`, with integer coefficients, and their real
//! roots in `[0, 1]`.
//!
//! Every condition of continuous collision between linearly moving points is the sign of a
//! polynomial in `t` of degree at most 6 whose coefficients are exact integers (the `f64`
//! inputs scaled by one common power of two). This module answers the two questions the
//! decisions need, exactly and without any tolerance:
//! - the roots of a polynomial in `[0, 1]`, in increasing order, each either an exact dyadic
//!   rational or an isolating interval with dyadic ends that are not roots ([`Instant`]);
//! - the sign of another polynomial at such a root ([`Instant::sign_of`]), by a Tarski query
//!   (the Sturm–Tarski theorem): for `h` with a single root `α` in `(a, b)` and `a`, `b` not
//!   roots, the sign variations of the signed remainder sequence of `(h, h'·g)` at `a` minus
//!   those at `b` equal the sign of `g(α)`. No root is ever approximated to decide a sign, so
//!   a double root (grazing contact) or a condition that vanishes exactly at the root (touching
//!   an edge at the instant of coplanarity) is decided like any other.
//!
//! Roots are counted with Sturm sequences of the square-free part; remainders are computed
//! up to positive factors (pseudo-division by `|lc|`), which keeps signs and integers.

use core::cmp::Ordering;
use std::rc::Rc;

use num_bigint::{BigInt, Sign};
use num_traits::{Signed, ToPrimitive, Zero};

/// A polynomial `Σ c[i] tⁱ` with integer coefficients, without trailing zero coefficients
/// (the zero polynomial has none).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Poly(Vec<BigInt>);

impl Poly {
    pub(crate) fn new(mut c: Vec<BigInt>) -> Poly {
        while c.last().is_some_and(|x| x.is_zero()) {
            c.pop();
        }
        Poly(c)
    }

    pub(crate) fn zero() -> Poly {
        Poly(Vec::new())
    }

    /// `start + t·(end − start)`.
    pub(crate) fn linear(start: &BigInt, end: &BigInt) -> Poly {
        Poly::new(vec![start.clone(), end - start])
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// Degree; 0 for constants and for the zero polynomial.
    pub(crate) fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    fn lead(&self) -> &BigInt {
        self.0.last().expect("non-zero polynomial")
    }

    pub(crate) fn add(&self, other: &Poly) -> Poly {
        let n = self.0.len().max(other.0.len());
        Poly::new(
            (0..n)
                .map(|i| match (self.0.get(i), other.0.get(i)) {
                    (Some(a), Some(b)) => a + b,
                    (Some(a), None) => a.clone(),
                    (None, Some(b)) => b.clone(),
                    (None, None) => BigInt::zero(),
                })
                .collect(),
        )
    }

    pub(crate) fn neg(&self) -> Poly {
        Poly(self.0.iter().map(|c| -c).collect())
    }

    pub(crate) fn sub(&self, other: &Poly) -> Poly {
        self.add(&other.neg())
    }

    pub(crate) fn mul(&self, other: &Poly) -> Poly {
        if self.is_zero() || other.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![BigInt::zero(); self.0.len() + other.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in other.0.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        Poly::new(c)
    }

    fn derivative(&self) -> Poly {
        Poly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * BigInt::from(i))
                .collect(),
        )
    }

    /// The polynomial divided by the largest power of two dividing every coefficient (a
    /// positive factor; a full gcd costs more than the smaller numbers save at these degrees).
    fn primitive(self) -> Poly {
        let shift = self
            .0
            .iter()
            .filter_map(|c| c.trailing_zeros())
            .min()
            .unwrap_or(0);
        if shift == 0 {
            self
        } else {
            Poly(self.0.into_iter().map(|c| c >> shift as usize).collect())
        }
    }

    /// Pseudo-division by `d` (non-zero) up to a positive factor: `(q, r)` with
    /// `|lc(d)|^k · self = q·d + r` and `deg r < deg d`.
    fn pseudo_divide(&self, d: &Poly) -> (Poly, Poly) {
        let dd = d.degree();
        let l = d.lead().abs();
        let s = d.lead().sign();
        let mut r = self.clone();
        let mut q = vec![BigInt::zero(); self.degree().saturating_sub(dd) + 1];
        while !r.is_zero() && r.degree() >= dd {
            let shift = r.degree() - dd;
            let lr = r.lead().clone();
            for x in q.iter_mut() {
                *x *= &l;
            }
            q[shift] += if s == Sign::Minus { -&lr } else { lr.clone() };
            let mut c: Vec<BigInt> = r.0.iter().map(|x| x * &l).collect();
            for (j, dj) in d.0.iter().enumerate() {
                let term = &lr * dj;
                if s == Sign::Minus {
                    c[j + shift] += term;
                } else {
                    c[j + shift] -= term;
                }
            }
            r = Poly::new(c);
        }
        (Poly::new(q), r)
    }

    /// A positive multiple of the remainder of `self` divided by `d` (`d` non-zero).
    fn positive_remainder(&self, d: &Poly) -> Poly {
        self.pseudo_divide(d).1.primitive()
    }

    /// `self / d` when `d` divides `self` exactly over the rationals, up to a positive factor.
    fn divided_by(&self, d: &Poly) -> Poly {
        self.pseudo_divide(d).0.primitive()
    }

    /// The signed remainder sequence `self, other, −rem, …` up to positive factors (for
    /// Sturm and Tarski queries).
    fn signed_remainders(&self, other: &Poly) -> Vec<Poly> {
        let mut seq = vec![self.clone().primitive()];
        if other.is_zero() {
            return seq;
        }
        seq.push(other.clone().primitive());
        loop {
            let n = seq.len();
            let r = seq[n - 2].positive_remainder(&seq[n - 1]);
            if r.is_zero() {
                return seq;
            }
            seq.push(r.neg());
        }
    }

    /// The square-free part: the same roots, each simple (up to a constant factor).
    fn square_free(&self) -> Poly {
        let seq = self.signed_remainders(&self.derivative());
        let gcd = seq.last().expect("non-empty sequence");
        if gcd.degree() == 0 {
            self.clone().primitive()
        } else {
            self.divided_by(gcd)
        }
    }

    /// The sign of the polynomial at the dyadic `x`: by `f64` interval arithmetic when that
    /// decides, else exactly.
    pub(crate) fn sign_at(&self, x: &Dyadic) -> Ordering {
        let point = x.f64_bounds();
        if let Some(s) = self.interval_sign(point) {
            return s;
        }
        self.exact_sign_at(x)
    }

    /// The sign on all of `[lo, hi]` when `f64` interval arithmetic proves it (`None`: not
    /// proved, or a coefficient beyond the `f64` range).
    pub(crate) fn interval_sign(&self, (lo, hi): (f64, f64)) -> Option<Ordering> {
        let Some((last, rest)) = self.0.split_last() else {
            return Some(Ordering::Equal);
        };
        let coefficient = |c: &BigInt| {
            let v = c.to_f64()?;
            v.is_finite().then(|| (v.next_down(), v.next_up()))
        };
        let mut acc = coefficient(last)?;
        for c in rest.iter().rev() {
            let products = [acc.0 * lo, acc.0 * hi, acc.1 * lo, acc.1 * hi];
            let (c_lo, c_hi) = coefficient(c)?;
            let p_lo = products.iter().copied().fold(f64::INFINITY, f64::min);
            let p_hi = products.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            acc = (
                (p_lo.next_down() + c_lo).next_down(),
                (p_hi.next_up() + c_hi).next_up(),
            );
        }
        if acc.0 > 0.0 && acc.0.is_finite() && acc.1.is_finite() {
            Some(Ordering::Greater)
        } else if acc.1 < 0.0 && acc.0.is_finite() && acc.1.is_finite() {
            Some(Ordering::Less)
        } else {
            None
        }
    }

    /// The sign of the polynomial at the dyadic `x`, exactly.
    fn exact_sign_at(&self, x: &Dyadic) -> Ordering {
        // Σ c_i nⁱ 2^{k(d−i)} has the sign of Σ c_i (n/2^k)ⁱ.
        let Some((last, rest)) = self.0.split_last() else {
            return Ordering::Equal;
        };
        let mut acc = last.clone();
        for (steps, c) in rest.iter().rev().enumerate() {
            acc = acc * &x.num + (c << (x.exp as usize * (steps + 1)));
        }
        sign_of(&acc)
    }
}

fn sign_of(x: &BigInt) -> Ordering {
    match x.sign() {
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
        Sign::Plus => Ordering::Greater,
    }
}

/// The exact rational `num / 2^exp`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Dyadic {
    pub(crate) num: BigInt,
    pub(crate) exp: u32,
}

impl Dyadic {
    pub(crate) fn integer(n: i64) -> Dyadic {
        Dyadic {
            num: BigInt::from(n),
            exp: 0,
        }
    }

    fn midpoint(&self, other: &Dyadic) -> Dyadic {
        let exp = self.exp.max(other.exp);
        let num =
            (&self.num << (exp - self.exp) as usize) + (&other.num << (exp - other.exp) as usize);
        Dyadic { num, exp: exp + 1 }.reduced()
    }

    fn reduced(mut self) -> Dyadic {
        if self.num.is_zero() {
            self.exp = 0;
            return self;
        }
        let tz = self
            .num
            .trailing_zeros()
            .unwrap_or(0)
            .min(u64::from(self.exp));
        self.num >>= tz as usize;
        self.exp -= tz as u32;
        self
    }

    /// `f64` bounds `lo <= self <= hi` (equal when `self` is an `f64`).
    pub(crate) fn f64_bounds(&self) -> (f64, f64) {
        if self.num.bits() <= 53 && self.exp < 1000 {
            let v = self.num.to_f64().unwrap_or(0.0) * 2f64.powi(-(self.exp as i32));
            return (v, v);
        }
        (self.to_f64_directed(false), self.to_f64_directed(true))
    }

    /// The nearest `f64` at or below (`up == false`) or at or above (`up == true`).
    pub(crate) fn to_f64_directed(&self, up: bool) -> f64 {
        // The approximation is within a few units in the last place (double rounding near
        // the subnormal range); step until it is on the requested side.
        let mut x = dyadic_to_f64(&self.num, self.exp);
        loop {
            match compare_f64(x, self) {
                Ordering::Less if up => x = x.next_up(),
                Ordering::Greater if !up => x = x.next_down(),
                _ => return x,
            }
        }
    }
}

/// A close `f64` to `num / 2^exp` (exact when representable).
fn dyadic_to_f64(num: &BigInt, exp: u32) -> f64 {
    // Keep 64 significant bits, then scale.
    let bits = num.bits();
    let drop = bits.saturating_sub(64);
    let top = (num >> drop as usize).to_f64().unwrap_or(0.0);
    let mut e = drop as i64 - i64::from(exp);
    let mut v = top;
    while e > 0 {
        let step = e.min(1000);
        v *= 2f64.powi(step as i32);
        e -= step;
    }
    while e < 0 {
        let step = (-e).min(1000);
        v *= 2f64.powi(-(step as i32));
        e += step;
    }
    v
}

/// `x` compared with the dyadic `d`, exactly.
fn compare_f64(x: f64, d: &Dyadic) -> Ordering {
    let (num, exp) = f64_to_dyadic(x);
    // num / 2^exp  vs  d.num / 2^d.exp, exponents may be negative for x.
    let (l, r) = align(&num, exp, &d.num, i64::from(d.exp));
    l.cmp(&r)
}

fn align(a: &BigInt, ea: i64, b: &BigInt, eb: i64) -> (BigInt, BigInt) {
    let e = ea.max(eb);
    (a << (e - ea) as usize, b << (e - eb) as usize)
}

/// `x = num / 2^exp` exactly (exp may be negative for large `x`).
fn f64_to_dyadic(x: f64) -> (BigInt, i64) {
    if x == 0.0 {
        return (BigInt::zero(), 0);
    }
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i64;
    let m = if e == 0 {
        (bits & 0xf_ffff_ffff_ffff) << 1
    } else {
        (bits & 0xf_ffff_ffff_ffff) | (1 << 52)
    };
    let m = BigInt::from(m);
    let m = if x < 0.0 { -m } else { m };
    (m, 1075 - e)
}

/// A square-free polynomial with its Sturm sequence, shared by the instants that are its roots.
#[derive(Debug)]
pub(crate) struct RootSystem {
    h: Poly,
    dh: Poly,
    sturm: Vec<Poly>,
}

impl RootSystem {
    fn variations(&self, x: &Dyadic) -> usize {
        variations(&self.sturm, x)
    }
}

fn variations(seq: &[Poly], x: &Dyadic) -> usize {
    let mut last = Ordering::Equal;
    let mut count = 0;
    for p in seq {
        let s = p.sign_at(x);
        if s == Ordering::Equal {
            continue;
        }
        if last != Ordering::Equal && s != last {
            count += 1;
        }
        last = s;
    }
    count
}

/// A real number in `[0, 1]`: an exact dyadic rational, or the one root of a square-free
/// polynomial strictly between two dyadic rationals that are not roots.
#[derive(Clone, Debug)]
pub(crate) enum Instant {
    /// Exactly this dyadic rational.
    Exact(Dyadic),
    /// The root of `system.h` in `(lo, hi)`.
    Isolated {
        system: Rc<RootSystem>,
        lo: Dyadic,
        hi: Dyadic,
    },
}

impl Instant {
    pub(crate) fn zero() -> Instant {
        Instant::Exact(Dyadic::integer(0))
    }

    /// The exact sign of `g` at this instant.
    pub(crate) fn sign_of(&self, g: &Poly) -> Ordering {
        match self {
            Instant::Exact(x) => g.sign_at(x),
            Instant::Isolated { system, lo, hi } => {
                if g.is_zero() {
                    return Ordering::Equal;
                }
                // Cheap first: g's sign on a few bisections of the isolating interval (the
                // root is simple, so `h` changes sign across it).
                let (mut lo, mut hi) = (lo.clone(), hi.clone());
                let h_lo = system.h.sign_at(&lo);
                for _ in 0..6 {
                    let bounds = (lo.f64_bounds().0, hi.f64_bounds().1);
                    if let Some(s) = g.interval_sign(bounds) {
                        return s;
                    }
                    let mid = lo.midpoint(&hi);
                    match system.h.sign_at(&mid) {
                        Ordering::Equal => return g.sign_at(&mid),
                        s if s == h_lo => lo = mid,
                        _ => hi = mid,
                    }
                }
                let seq = system.h.signed_remainders(&system.dh.mul(g));
                let v = variations(&seq, &lo) as i64 - variations(&seq, &hi) as i64;
                v.cmp(&0)
            }
        }
    }

    /// Bounds in `f64`: `lo <= t <= hi`, with `lo == hi` only when that is `t` exactly, and
    /// otherwise `lo < t`. The interval is refined until `hi − lo <= tolerance` or the two ends
    /// are neighbouring `f64`s.
    pub(crate) fn bounds(&self, tolerance: f64) -> (f64, f64) {
        match self {
            Instant::Exact(x) => (x.to_f64_directed(false), x.to_f64_directed(true)),
            Instant::Isolated { system, lo, hi } => {
                let (mut lo, mut hi) = (lo.clone(), hi.clone());
                loop {
                    let (l, h) = (lo.to_f64_directed(false), hi.to_f64_directed(true));
                    if h - l <= tolerance || l.next_up() >= h {
                        return (l, h);
                    }
                    let mid = lo.midpoint(&hi);
                    if system.h.sign_at(&mid) == Ordering::Equal {
                        return Instant::Exact(mid).bounds(tolerance);
                    }
                    if system.variations(&lo) - system.variations(&mid) == 1 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
            }
        }
    }
}

/// The distinct roots of `p` in `[0, 1]`, in increasing order (`p` must not be the zero
/// polynomial; a non-zero constant has none).
pub(crate) fn roots_in_unit(p: &Poly) -> Vec<Instant> {
    debug_assert!(!p.is_zero());
    if p.degree() == 0 {
        return Vec::new();
    }
    let h = p.square_free();
    let dh = h.derivative();
    let sturm = h.signed_remainders(&dh);
    let system = Rc::new(RootSystem { h, dh, sturm });
    let zero = Dyadic::integer(0);
    let one = Dyadic::integer(1);
    let mut out = Vec::new();
    if system.h.sign_at(&zero) == Ordering::Equal {
        out.push(Instant::Exact(zero.clone()));
    }
    let (v0, v1) = (system.variations(&zero), system.variations(&one));
    isolate(&system, zero, one, v0, v1, &mut out);
    out
}

/// Pushes the roots in `(a, b]` (there are `va − vb` of them), in increasing order.
fn isolate(
    system: &Rc<RootSystem>,
    a: Dyadic,
    b: Dyadic,
    va: usize,
    vb: usize,
    out: &mut Vec<Instant>,
) {
    let count = va.saturating_sub(vb);
    if count == 0 {
        return;
    }
    if count == 1 {
        if system.h.sign_at(&b) == Ordering::Equal {
            out.push(Instant::Exact(b));
            return;
        }
        if system.h.sign_at(&a) != Ordering::Equal {
            out.push(Instant::Isolated {
                system: system.clone(),
                lo: a,
                hi: b,
            });
            return;
        }
    }
    let m = a.midpoint(&b);
    let vm = system.variations(&m);
    isolate(system, a, m.clone(), va, vm, out);
    isolate(system, m, b, vm, vb, out);
}

/// A dyadic from an integer numerator and a power-of-two denominator exponent.
#[cfg(test)]
pub(crate) fn dyadic(num: i64, exp: u32) -> Dyadic {
    Dyadic {
        num: BigInt::from(num),
        exp,
    }
    .reduced()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(c: &[i64]) -> Poly {
        Poly::new(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    fn bounds(p: &[i64]) -> Vec<(f64, f64)> {
        roots_in_unit(&poly(p))
            .iter()
            .map(|r| r.bounds(0.0))
            .collect()
    }

    #[test]
    fn roots_of_simple_polynomials() {
        // (t − 1/2)(t − 1/4)·16 = 16t² − 12t + 2
        assert_eq!(bounds(&[2, -12, 16]), vec![(0.25, 0.25), (0.5, 0.5)]);
        // t(t − 1)
        assert_eq!(bounds(&[0, -1, 1]), vec![(0.0, 0.0), (1.0, 1.0)]);
        // Double root at 1/3: 9t² − 6t + 1.
        let r = bounds(&[1, -6, 9]);
        assert_eq!(r.len(), 1);
        // 1/3 is no f64: the bounds are the two neighbouring f64s around it, one of which is
        // the f64 nearest to 1/3.
        let third = 1.0 / 3.0;
        assert!(r[0].0 < r[0].1 && r[0].0.next_up() == r[0].1, "{r:?}");
        assert!(r[0].0 == third || r[0].1 == third, "{r:?}");
        // No root in [0, 1]: t² + 1, t − 2.
        assert!(bounds(&[1, 0, 1]).is_empty());
        assert!(bounds(&[-2, 1]).is_empty());
        assert!(bounds(&[5]).is_empty());
    }

    #[test]
    fn sign_at_roots_is_exact() {
        // Root of 3t − 1 is 1/3 (isolated, not dyadic).
        let roots = roots_in_unit(&poly(&[-1, 3]));
        assert_eq!(roots.len(), 1);
        let r = &roots[0];
        assert_eq!(r.sign_of(&poly(&[-1, 3])), Ordering::Equal);
        assert_eq!(r.sign_of(&poly(&[-1, 6])), Ordering::Greater); // 6/3 − 1
        assert_eq!(r.sign_of(&poly(&[1, -6, 9])), Ordering::Equal); // (3t − 1)²
        assert_eq!(r.sign_of(&poly(&[-1, 0, 9])), Ordering::Equal); // 9t² − 1
        assert_eq!(r.sign_of(&poly(&[-2, 0, 9])), Ordering::Less);
        assert_eq!(
            r.sign_of(&poly(&[0, 0, 0, 27, 0, 0, -1])),
            Ordering::Greater
        );
    }

    #[test]
    fn dyadic_rounding_is_directed() {
        let third = Dyadic {
            num: (BigInt::from(1) << 200usize) / 3,
            exp: 200,
        };
        let (lo, hi) = (third.to_f64_directed(false), third.to_f64_directed(true));
        assert!(lo < hi && lo.next_up() == hi);
        assert_eq!(dyadic(3, 2).to_f64_directed(false), 0.75);
        assert_eq!(dyadic(3, 2).to_f64_directed(true), 0.75);
    }
}
