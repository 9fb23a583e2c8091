//! [`Expansion`]: exact sums and products of `f64` values without heap allocation, the middle
//! stage of every exact decision (after the [`ErrF64`](super::ErrF64) filter, before big
//! integers).
//!
//! A number is held as a *floating-point expansion*: a short sum of `f64` components, sorted
//! by increasing magnitude and nonoverlapping, whose exact sum is the value (Priest; Shewchuk,
//! "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997).
//! `a + b` and `a · b` of two `f64` are computed exactly as two components each (`TwoSum`,
//! `TwoProduct` by Dekker's splitting, so no fused multiply–add is needed), and longer sums
//! and products merge component lists. The sign of an expansion is the sign of its largest
//! component, so an exact zero, the common case on engineering meshes (coplanar neighbours),
//! costs a few dozen `f64` operations instead of big-integer arithmetic.
//!
//! The storage is a fixed array of [`CAPACITY`] components. A value that needs more, or an
//! operation whose exactness the hardware cannot guarantee (a product whose partial products
//! could underflow, or a sum that could overflow), *poisons* the result: its sign is then
//! unknown ([`Expansion::sign`] gives `None`) and the caller goes on to big integers. Poison
//! propagates through every later operation, so a poisoned intermediate can never produce a
//! wrong sign.

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use ga_core::scalar::Ring;

/// The most components an [`Expansion`] holds (values needing more are poisoned).
pub const CAPACITY: usize = 16;

/// `x < limit`, false for NaN (so a NaN never passes a range check).
#[inline(always)]
fn below(x: f64, limit: f64) -> bool {
    x < limit
}

/// `2^27 + 1`: Dekker's splitter for 53-bit significands.
const SPLITTER: f64 = 134_217_729.0;
/// Products whose smallest components multiply below this could lose their lowest bits to
/// underflow in the split products (`2^-900`, far above the subnormal range).
const TINY: f64 = 1.1834109918413096e-271;
/// Products or sums whose largest components reach this could overflow (`2^900`).
const HUGE: f64 = 8.452712498170644e270;

/// An exact real number as a sum of nonoverlapping `f64` components in fixed storage, or a
/// poisoned value (too many components, or out of the exactly representable range). See the
/// module docs.
#[derive(Clone, Copy)]
pub struct Expansion {
    len: u8,
    poisoned: bool,
    /// Components `c[..len]`, increasing magnitude, nonzero.
    c: [f64; CAPACITY],
}

impl core::fmt::Debug for Expansion {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.poisoned {
            write!(f, "Expansion(poisoned)")
        } else {
            write!(f, "Expansion({:?})", self.components())
        }
    }
}

#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let bv = x - a;
    let av = x - bv;
    (x, (a - av) + (b - bv))
}

#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    (x, b - (x - a))
}

#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a · b = x + y` exactly, with `(bh, bl)` the split of `b`.
#[inline(always)]
fn two_product_presplit(a: f64, b: f64, bh: f64, bl: f64) -> (f64, f64) {
    let x = a * b;
    let (ah, al) = split(a);
    let err = x - ah * bh - al * bh - ah * bl;
    (x, al * bl - err)
}

/// `e + f` for nonoverlapping component lists (Shewchuk's `fast_expansion_sum_zeroelim`),
/// written into `h` (room for `e.len() + f.len()`); returns the length.
fn sum_into(e: &[f64], f: &[f64], h: &mut [f64]) -> usize {
    if e.is_empty() {
        h[..f.len()].copy_from_slice(f);
        return f.len();
    }
    if f.is_empty() {
        h[..e.len()].copy_from_slice(e);
        return e.len();
    }
    let (mut ei, mut fi) = (0, 0);
    let take_e = |ei: &mut usize, fi: &mut usize| -> f64 {
        // The smaller in magnitude comes first.
        if *fi >= f.len() || (*ei < e.len() && ((f[*fi] > e[*ei]) == (f[*fi] > -e[*ei]))) {
            *ei += 1;
            e[*ei - 1]
        } else {
            *fi += 1;
            f[*fi - 1]
        }
    };
    let mut q = take_e(&mut ei, &mut fi);
    let mut n = 0;
    if ei < e.len() && fi < f.len() {
        let next = take_e(&mut ei, &mut fi);
        let (qn, hh) = fast_two_sum(next, q);
        q = qn;
        if hh != 0.0 {
            h[n] = hh;
            n += 1;
        }
    }
    while ei < e.len() || fi < f.len() {
        let next = take_e(&mut ei, &mut fi);
        let (qn, hh) = two_sum(q, next);
        q = qn;
        if hh != 0.0 {
            h[n] = hh;
            n += 1;
        }
    }
    if q != 0.0 || n == 0 {
        h[n] = q;
        n += 1;
    }
    n
}

/// `e · b` (Shewchuk's `scale_expansion_zeroelim`) into `h` (room for `2 e.len()`).
fn scale_into(e: &[f64], b: f64, h: &mut [f64]) -> usize {
    let (bh, bl) = split(b);
    let (mut q, hh) = two_product_presplit(e[0], b, bh, bl);
    let mut n = 0;
    if hh != 0.0 {
        h[n] = hh;
        n += 1;
    }
    for &x in &e[1..] {
        let (p1, p0) = two_product_presplit(x, b, bh, bl);
        let (s, hh) = two_sum(q, p0);
        if hh != 0.0 {
            h[n] = hh;
            n += 1;
        }
        let (qn, hh) = fast_two_sum(p1, s);
        q = qn;
        if hh != 0.0 {
            h[n] = hh;
            n += 1;
        }
    }
    if q != 0.0 || n == 0 {
        h[n] = q;
        n += 1;
    }
    n
}

/// Shewchuk's `compress`: the same value in (usually far) fewer, nonadjacent components,
/// in place; returns the new length.
fn compress(e: &mut [f64]) -> usize {
    let m = e.len();
    if m <= 1 {
        return m;
    }
    let mut g = [0.0f64; 3 * CAPACITY];
    let mut bottom = m - 1;
    let mut q = e[m - 1];
    for i in (0..m - 1).rev() {
        let (qn, low) = fast_two_sum(q, e[i]);
        if low != 0.0 {
            g[bottom] = qn;
            bottom -= 1;
            q = low;
        } else {
            q = qn;
        }
    }
    let mut top = 0;
    for &hnow in &g[bottom + 1..m] {
        let (qn, low) = fast_two_sum(hnow, q);
        if low != 0.0 {
            e[top] = low;
            top += 1;
        }
        q = qn;
    }
    if q != 0.0 || top == 0 {
        e[top] = q;
        top += 1;
    }
    top
}

/// `a - b = x + y` exactly.
#[inline(always)]
fn two_diff(a: f64, b: f64) -> (f64, f64) {
    let x = a - b;
    let bv = a - x;
    let av = x + bv;
    (x, (a - av) + (bv - b))
}

/// `a · b = x + y` exactly (no underflow or overflow assumed).
#[inline(always)]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let (bh, bl) = split(b);
    two_product_presplit(a, b, bh, bl)
}

/// `(a1 + a0) - (b1 + b0)` as four nonoverlapping components, smallest first (Shewchuk's
/// `Two_Two_Diff`, zeros kept).
#[inline(always)]
fn two_two_diff(a1: f64, a0: f64, b1: f64, b0: f64) -> [f64; 4] {
    let (i, x0) = two_diff(a0, b0);
    let (j, k) = two_sum(a1, i);
    let (i, x1) = two_diff(k, b1);
    let (x3, x2) = two_sum(j, i);
    [x0, x1, x2, x3]
}

/// The sign of the largest nonzero component.
#[inline(always)]
fn sign_of_components(c: &[f64]) -> Ordering {
    for &x in c.iter().rev() {
        if x != 0.0 {
            return if x > 0.0 {
                Ordering::Greater
            } else {
                Ordering::Less
            };
        }
    }
    Ordering::Equal
}

/// Whether every value is zero or within `2^±200`: then products of up to three such values,
/// and of their split pieces (whose lowest bits lie at most 52 places lower), neither
/// underflow nor overflow.
#[inline(always)]
fn in_safe_range(x: &[f64]) -> bool {
    const LO: f64 = 6.223015277861142e-61; // 2^-200
    const HI: f64 = 1.6069380442589903e60; // 2^200
    x.iter()
        .all(|&v| v == 0.0 || (v.abs() > LO && v.abs() < HI))
}

/// The exact differences `x[2k + 1] - x[2k]`... of the pairs `(b, a)`, or `None` when one
/// of them is not an `f64` (or out of the safe range).
#[inline(always)]
fn exact_differences<const M: usize>(pairs: [(f64, f64); M]) -> Option<[f64; M]> {
    let mut out = [0.0; M];
    for (o, (b, a)) in out.iter_mut().zip(pairs) {
        let (d, tail) = two_diff(b, a);
        if tail != 0.0 || !d.is_finite() {
            return None;
        }
        *o = d;
    }
    in_safe_range(&out).then_some(out)
}

/// `b - a` as two nonoverlapping components `[tail, head]` (exact).
#[inline(always)]
fn diff2(b: f64, a: f64) -> [f64; 2] {
    let (x, y) = two_diff(b, a);
    [y, x]
}

/// `a · b` of two two-component values, exactly, into `out` (room for 8); returns the length.
#[inline(always)]
fn product22(a: &[f64; 2], b: &[f64; 2], out: &mut [f64]) -> usize {
    let mut lo = [0.0; 4];
    let mut hi = [0.0; 4];
    let nl = scale_into(a, b[0], &mut lo);
    let nh = scale_into(a, b[1], &mut hi);
    sum_into(&lo[..nl], &hi[..nh], out)
}

/// `a · d - b · c` of two-component values, exactly, into `out` (room for 16).
#[inline(always)]
fn minor22(a: &[f64; 2], d: &[f64; 2], b: &[f64; 2], c: &[f64; 2], out: &mut [f64]) -> usize {
    let mut ad = [0.0; 8];
    let mut bc = [0.0; 8];
    let n1 = product22(a, d, &mut ad);
    let n2 = product22(b, c, &mut bc);
    for x in &mut bc[..n2] {
        *x = -*x;
    }
    sum_into(&ad[..n1], &bc[..n2], out)
}

/// The exact sign of `orient2d` (inputs as [`Orient2d`](super::predicates::Orient2d)),
/// without allocation: from `f64` differences when they are exact (the common case on meshes),
/// otherwise from two-component differences. `None` only for inputs beyond `2^±200`.
#[inline]
pub(crate) fn orient2d_sign(x: &[f64; 6]) -> Option<Ordering> {
    // An exact zero from zero differences (equal coordinates: points on an axis-parallel line),
    // decided by comparisons alone.
    if (x[2] == x[0] || x[5] == x[1]) && (x[3] == x[1] || x[4] == x[0]) {
        return Some(Ordering::Equal);
    }
    if let Some([ux, uy, vx, vy]) =
        exact_differences([(x[2], x[0]), (x[3], x[1]), (x[4], x[0]), (x[5], x[1])])
    {
        let (a1, a0) = two_product(ux, vy);
        let (b1, b0) = two_product(uy, vx);
        return Some(sign_of_components(&two_two_diff(a1, a0, b1, b0)));
    }
    if !in_safe_range(x) {
        return None;
    }
    let (ux, uy) = (diff2(x[2], x[0]), diff2(x[3], x[1]));
    let (vx, vy) = (diff2(x[4], x[0]), diff2(x[5], x[1]));
    let mut det = [0.0; 16];
    let n = minor22(&ux, &vy, &uy, &vx, &mut det);
    Some(sign_of_components(&det[..n]))
}

/// The exact sign of `orient3d` (inputs `[a, b, c, d]` as
/// [`Orient3d`](super::predicates::Orient3d)), without allocation: the three 2x2 minors of the
/// differences from `a`, scaled and summed without rounding (Shewchuk's exact stage). The
/// differences are single `f64` values when exact (the common case on meshes), two components
/// otherwise. `None` only for inputs beyond `2^±200`.
#[inline]
pub(crate) fn orient3d_sign(x: &[f64; 12]) -> Option<Ordering> {
    let pairs = [
        (x[3], x[0]),
        (x[4], x[1]),
        (x[5], x[2]),
        (x[6], x[0]),
        (x[7], x[1]),
        (x[8], x[2]),
        (x[9], x[0]),
        (x[10], x[1]),
        (x[11], x[2]),
    ];
    if let Some([u0, u1, u2, v0, v1, v2, w0, w1, w2]) = exact_differences(pairs) {
        // det = w · (u × v)
        let minor = |a: f64, b: f64, c: f64, d: f64| {
            let (p1, p0) = two_product(a, b);
            let (q1, q0) = two_product(c, d);
            two_two_diff(p1, p0, q1, q0)
        };
        let m = [
            minor(u1, v2, u2, v1),
            minor(u2, v0, u0, v2),
            minor(u0, v1, u1, v0),
        ];
        let mut s = [[0.0; 8]; 3];
        let n0 = scale_into(&m[0], w0, &mut s[0]);
        let n1 = scale_into(&m[1], w1, &mut s[1]);
        let n2 = scale_into(&m[2], w2, &mut s[2]);
        let mut t = [0.0; 16];
        let nt = sum_into(&s[0][..n0], &s[1][..n1], &mut t);
        let mut total = [0.0; 24];
        let n = sum_into(&t[..nt], &s[2][..n2], &mut total);
        return Some(sign_of_components(&total[..n]));
    }
    if !in_safe_range(x) {
        return None;
    }
    let d = pairs.map(|(b, a)| diff2(b, a));
    let [u0, u1, u2, v0, v1, v2, w0, w1, w2] = d;
    let mut det = [0.0; 192];
    let mut n = 0;
    for (a, d_, b, c, w) in [
        (&u1, &v2, &u2, &v1, &w0),
        (&u2, &v0, &u0, &v2, &w1),
        (&u0, &v1, &u1, &v0, &w2),
    ] {
        let mut minor = [0.0; 16];
        let nm = minor22(a, d_, b, c, &mut minor);
        let nm = compress(&mut minor[..nm]);
        let mut lo = [0.0; 32];
        let mut hi = [0.0; 32];
        let nl = scale_into(&minor[..nm], w[0], &mut lo);
        let nh = scale_into(&minor[..nm], w[1], &mut hi);
        let mut term = [0.0; 64];
        let k = sum_into(&lo[..nl], &hi[..nh], &mut term);
        let mut next = [0.0; 192];
        n = sum_into(&det[..n], &term[..k], &mut next);
        det[..n].copy_from_slice(&next[..n]);
    }
    Some(sign_of_components(&det[..n]))
}

impl Expansion {
    const POISON: Expansion = Expansion {
        len: 0,
        poisoned: true,
        c: [0.0; CAPACITY],
    };

    /// The exact value of one `f64` (poisoned for infinities and NaN).
    #[inline]
    pub fn from_f64(x: f64) -> Self {
        if !x.is_finite() {
            return Self::POISON;
        }
        let mut c = [0.0; CAPACITY];
        c[0] = x;
        Expansion {
            len: u8::from(x != 0.0),
            poisoned: false,
            c,
        }
    }

    /// The components, smallest first (empty for zero; empty also when poisoned).
    pub fn components(&self) -> &[f64] {
        &self.c[..self.len as usize]
    }

    /// Whether the value was lost (capacity or range exceeded); its sign is then unknown.
    pub fn is_poisoned(&self) -> bool {
        self.poisoned
    }

    /// The exact sign, or `None` when poisoned.
    #[inline]
    pub fn sign(&self) -> Option<Ordering> {
        if self.poisoned {
            return None;
        }
        Some(match self.components().last() {
            None => Ordering::Equal,
            Some(&top) if top > 0.0 => Ordering::Greater,
            Some(&top) if top < 0.0 => Ordering::Less,
            Some(_) => Ordering::Equal,
        })
    }

    /// A value from a list of components (at most `3 · CAPACITY`), compressed; poisoned when
    /// it does not fit or its top is not finite.
    fn from_list(h: &mut [f64]) -> Self {
        let mut n = h.len();
        if n > CAPACITY {
            n = compress(h);
            if n > CAPACITY {
                return Self::POISON;
            }
        }
        let mut out = Self::EMPTY;
        out.c[..n].copy_from_slice(&h[..n]);
        out.finish(n)
    }

    /// A value whose first `n` components were written into `self.c`.
    #[inline(always)]
    fn finish(mut self, mut n: usize) -> Self {
        if n > 8 {
            n = compress(&mut self.c[..n]);
        }
        if n > 0 && !below(self.c[n - 1].abs(), HUGE) {
            return Self::POISON;
        }
        // A single zero component is zero.
        self.len = if n == 1 && self.c[0] == 0.0 {
            0
        } else {
            n as u8
        };
        self
    }

    const EMPTY: Expansion = Expansion {
        len: 0,
        poisoned: false,
        c: [0.0; CAPACITY],
    };

    fn plus(&self, rhs: &Expansion) -> Expansion {
        if self.poisoned || rhs.poisoned {
            return Self::POISON;
        }
        let (e, f) = (self.components(), rhs.components());
        if e.len() + f.len() <= CAPACITY {
            let mut out = Self::EMPTY;
            let n = sum_into(e, f, &mut out.c);
            return out.finish(n);
        }
        let mut h = [0.0f64; 3 * CAPACITY];
        let n = sum_into(e, f, &mut h);
        Self::from_list(&mut h[..n])
    }

    fn times(&self, rhs: &Expansion) -> Expansion {
        if self.poisoned || rhs.poisoned {
            return Self::POISON;
        }
        let (e, f) = (self.components(), rhs.components());
        if e.is_empty() || f.is_empty() {
            return Self::EMPTY;
        }
        // Exactness of the split products: nothing may underflow or overflow.
        let small = e[0].abs() * f[0].abs();
        let large = e[e.len() - 1].abs() * f[f.len() - 1].abs();
        if !below(TINY, small) || !below(large, HUGE) {
            return Self::POISON;
        }
        let (long, short) = if e.len() >= f.len() { (e, f) } else { (f, e) };
        if short.len() == 1 && 2 * long.len() <= CAPACITY {
            let mut out = Self::EMPTY;
            let n = scale_into(long, short[0], &mut out.c);
            return out.finish(n);
        }
        // Scale the longer list by each component of the shorter one and accumulate.
        let (long, short) = if e.len() >= f.len() { (e, f) } else { (f, e) };
        let mut acc = [0.0f64; 3 * CAPACITY];
        let mut n = scale_into(long, short[0], &mut acc);
        for &b in &short[1..] {
            let mut part = [0.0f64; 2 * CAPACITY];
            let m = scale_into(long, b, &mut part);
            let mut sum = [0.0f64; 3 * CAPACITY];
            let k = sum_into(&acc[..n], &part[..m], &mut sum);
            n = if k > CAPACITY {
                compress(&mut sum[..k])
            } else {
                k
            };
            if n > CAPACITY {
                return Self::POISON;
            }
            acc[..n].copy_from_slice(&sum[..n]);
        }
        if n > 4 {
            n = compress(&mut acc[..n]);
        }
        Self::from_list(&mut acc[..n])
    }
}

impl Add for Expansion {
    type Output = Expansion;
    #[inline]
    fn add(self, rhs: Expansion) -> Expansion {
        self.plus(&rhs)
    }
}

impl Sub for Expansion {
    type Output = Expansion;
    #[inline]
    fn sub(self, rhs: Expansion) -> Expansion {
        self.plus(&-rhs)
    }
}

impl Mul for Expansion {
    type Output = Expansion;
    #[inline]
    fn mul(self, rhs: Expansion) -> Expansion {
        self.times(&rhs)
    }
}

impl Neg for Expansion {
    type Output = Expansion;
    #[inline]
    fn neg(mut self) -> Expansion {
        for x in &mut self.c[..self.len as usize] {
            *x = -*x;
        }
        self
    }
}

impl PartialEq for Expansion {
    /// Equal values (never equal when either is poisoned).
    fn eq(&self, other: &Expansion) -> bool {
        (*self - *other).sign() == Some(Ordering::Equal)
    }
}

impl Ring for Expansion {
    fn zero() -> Self {
        Expansion::from_f64(0.0)
    }
    fn one() -> Self {
        Expansion::from_f64(1.0)
    }
    fn from_i64(n: i64) -> Self {
        // Two exact halves: the high 32 bits (times 2^32) and the low 32 bits.
        let hi = (n >> 32) as f64 * 4_294_967_296.0;
        let lo = (n & 0xffff_ffff) as f64;
        Expansion::from_f64(hi) + Expansion::from_f64(lo)
    }
    fn is_zero(&self) -> bool {
        !self.poisoned && self.len == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(x: f64) -> Expansion {
        Expansion::from_f64(x)
    }

    #[test]
    fn sums_and_products_are_exact() {
        // 1 + 2^-80 - 1 = 2^-80, lost in f64.
        let tiny = 2f64.powi(-80);
        assert_eq!((e(1.0) + e(tiny) - e(1.0)).sign(), Some(Ordering::Greater));
        // (1 + 2^-52)^2 - 1 - 2^-51 = 2^-104 > 0.
        let a = 1.0 + f64::EPSILON;
        let s = e(a) * e(a) - e(1.0) - e(2.0 * f64::EPSILON);
        assert_eq!(s.sign(), Some(Ordering::Greater));
        assert_eq!(s.components(), &[2f64.powi(-104)]);
        assert!((e(3.0) - e(3.0)).is_zero());
        assert_eq!(Expansion::from_i64(i64::MIN).sign(), Some(Ordering::Less));
        assert!((Expansion::from_i64(i64::MAX) - Expansion::from_i64(i64::MAX)).is_zero());
    }

    #[test]
    fn out_of_range_poisons_instead_of_lying() {
        assert!(e(f64::NAN).is_poisoned());
        assert!(e(f64::INFINITY).is_poisoned());
        // Subnormal products: their low bits would be lost.
        let s = e(1e-200) * e(1e-200);
        assert_eq!(s.sign(), None);
        // Overflowing products.
        assert_eq!((e(1e200) * e(1e200)).sign(), None);
        // Poison propagates through later operations.
        assert_eq!((s * e(0.0) + e(1.0)).sign(), None);
    }
}
