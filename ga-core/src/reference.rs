//! A dense reference multivector: the test oracle for the generated algebras.
//!
//! [`DenseMultivector`] stores all `2ⁿ` coefficients of a multivector of a Clifford algebra with
//! a run-time [`Signature`] of up to [`MAX_GENERATORS`] generators (entries `+1`, `-1`, `0`) and
//! computes every product by looping over pairs of basis blades represented as bitmasks (bit `i`
//! is generator `i`). It is written independently of `ga_macros` (which has its own expansion-time
//! blade algebra) so that the two can be held against each other in the tests. It favours
//! obviousness over speed.
//!
//! # Definitions (shared by the whole project; the generated code must agree)
//!
//! * Basis blade product: `e_a e_b = reorder_sign(a, b) · ∏_{i ∈ a∩b} signature[i] · e_{a⊕b}`,
//!   where [`reorder_sign`] is `(-1)^t` with `t` the number of transpositions that sort the
//!   concatenation of the ascending index lists of `a` and `b`.
//! * Outer product: `e_a ∧ e_b = e_a e_b` if `a ∩ b = ∅`, else `0`. Left contraction:
//!   `e_a ⌋ e_b = e_a e_b` if `a ⊆ b`, else `0`. Right contraction: `e_a ⌊ e_b = e_a e_b` if
//!   `b ⊆ a`, else `0`. Scalar product: `e_a e_b` if `a = b`, else `0`. All extended bilinearly.
//! * Reverse: `(-1)^{k(k-1)/2}`, grade involution: `(-1)^k`, Clifford conjugate:
//!   `(-1)^{k(k+1)/2}` on grade `k`.
//! * Non-degenerate signature: `dual(A) = A I⁻¹`, `undual(A) = A I` with `I = e_{all bits}` and
//!   `I⁻¹ = I / (I I)`. Degenerate signature (some entry `0`): `dual` is the right complement,
//!   `dual(e_a) = s e_{¬a}` with `e_a ∧ (s e_{¬a}) = I`, and `undual` the left complement,
//!   `undual(e_a) = s' e_{¬a}` with `(s' e_{¬a}) ∧ e_a = I`; in both cases
//!   `undual(dual(A)) = A`.
//! * Regressive product: `A ∨ B = undual(dual(A) ∧ dual(B))`.
//!
//! # Canonical order
//!
//! Dense storage is indexed by bitmask. The *canonical* order of `docs/conventions.md` (by grade, then
//! lexicographic on the ascending index lists) is computed by [`canonical_order`] and used by
//! [`DenseMultivector::from_canonical`], [`DenseMultivector::to_canonical`] and
//! [`canonical_blade_names`].
//!
//! # Mismatched signatures
//!
//! Binary operations expect both operands to share a signature. This is checked with
//! `debug_assert!` (a test oracle should fail loudly in tests); [`DenseMultivector::check_same_signature`]
//! gives a typed error for callers who want to check first. In release builds a mismatch never
//! panics: the result is computed in the signature of the *left* operand and coefficients of the
//! right operand on blades that do not exist there are ignored.
//!
//! # Floating point
//!
//! Zero coefficients are skipped in the products, so `0 · ∞` terms are never formed: the
//! reference is meant for finite inputs.
//!
//! # Example
//!
//! ```
//! use ga_core::reference::{DenseMultivector, Signature};
//!
//! let sig = Signature::new(&[1, 1, 1, 1, -1]).unwrap(); // Cl(4,1)
//! let e1 = DenseMultivector::<f64>::basis_vector(&sig, 0).unwrap();
//! let e2 = DenseMultivector::<f64>::basis_vector(&sig, 1).unwrap();
//! let e12 = &e1 * &e2;
//! assert_eq!(e12, DenseMultivector::blade(&sig, 0b11, 1.0).unwrap());
//! assert_eq!(&e2 * &e1, -e12.clone());
//! let i = DenseMultivector::<f64>::pseudoscalar(&sig);
//! assert_eq!(&i * &i, DenseMultivector::scalar(&sig, -1.0));
//! ```

use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, BitAnd, BitOr, BitXor, Mul, Neg, Not, Sub};
use std::sync::Arc;

use crate::scalar::{Field, Real, Ring};

/// The largest number of generators the reference supports: 10 (1024 blades, so a product
/// visits about a million blade pairs; enough for double conformal Cl(8,2)).
pub const MAX_GENERATORS: usize = 10;

/// What went wrong when building reference multivectors.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ReferenceError {
    /// The signature has more than [`MAX_GENERATORS`] entries.
    #[error("signature has {0} generators; the dense reference supports at most {MAX_GENERATORS} (its size grows as 2^n): use a smaller algebra")]
    TooManyGenerators(usize),
    /// A signature entry is not `+1`, `-1` or `0`.
    #[error("signature entry {index} is {value}; entries must be +1, -1 or 0")]
    BadSignatureEntry {
        /// Position of the entry (0-based).
        index: usize,
        /// The offending value.
        value: i8,
    },
    /// A generator index is not below the number of generators.
    #[error("generator index {index} is out of range for a signature of {n} generators (indices are 0-based: 0 to n - 1)")]
    GeneratorOutOfRange {
        /// The requested (0-based) generator.
        index: usize,
        /// The number of generators.
        n: usize,
    },
    /// A blade bitmask has bits beyond the number of generators.
    #[error("blade mask {mask:#b} is out of range for a signature of {n} generators (bit i is generator i: masks below 2^n)")]
    MaskOutOfRange {
        /// The requested bitmask.
        mask: usize,
        /// The number of generators.
        n: usize,
    },
    /// A coefficient or name list has the wrong length.
    #[error("expected {expected} {what} (one per blade of the signature), got {got}")]
    WrongLength {
        /// What was counted ("coefficients", "basis names").
        what: &'static str,
        /// The required length.
        expected: usize,
        /// The given length.
        got: usize,
    },
    /// Two operands have different signatures.
    #[error("signature mismatch: left operand has {left:?}, right operand has {right:?}; both operands must come from the same Signature")]
    SignatureMismatch {
        /// Signature of the left operand.
        left: Vec<i8>,
        /// Signature of the right operand.
        right: Vec<i8>,
    },
}

/// A validated metric signature: `signature[i]` is `e_i²` (`+1`, `-1` or `0`), at most
/// [`MAX_GENERATORS`] entries. Cheap to clone (shared).
///
/// ```
/// use ga_core::reference::Signature;
/// let pga = Signature::new(&[0, 1, 1, 1]).unwrap();
/// assert!(pga.is_degenerate());
/// assert!(Signature::new(&[2]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Signature(Arc<[i8]>);

impl Signature {
    /// Validates and stores a signature.
    pub fn new(entries: &[i8]) -> Result<Self, ReferenceError> {
        if entries.len() > MAX_GENERATORS {
            return Err(ReferenceError::TooManyGenerators(entries.len()));
        }
        if let Some((index, &value)) = entries
            .iter()
            .enumerate()
            .find(|(_, &v)| !(-1..=1).contains(&v))
        {
            return Err(ReferenceError::BadSignatureEntry { index, value });
        }
        Ok(Self(entries.into()))
    }

    /// `p` entries `+1`, then `q` entries `-1`, then `r` entries `0` (Cl(p,q,r)).
    pub fn pqr(p: usize, q: usize, r: usize) -> Result<Self, ReferenceError> {
        let mut v = vec![1i8; p];
        v.extend(std::iter::repeat_n(-1, q));
        v.extend(std::iter::repeat_n(0, r));
        Self::new(&v)
    }

    /// The entries.
    pub fn entries(&self) -> &[i8] {
        &self.0
    }

    /// The number of generators `n`.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether there are no generators (the algebra is just the scalars).
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The number of blades, `2ⁿ`.
    pub fn blade_count(&self) -> usize {
        1 << self.0.len()
    }

    /// The bitmask of the pseudoscalar `I` (all bits set).
    pub fn pseudoscalar_mask(&self) -> usize {
        self.blade_count() - 1
    }

    /// Whether some generator squares to zero.
    pub fn is_degenerate(&self) -> bool {
        self.0.contains(&0)
    }

    /// The product of two basis blades: `e_a e_b = sign · e_mask`; `sign ∈ {-1, 0, 1}`.
    pub fn blade_product(&self, a: usize, b: usize) -> (i8, usize) {
        blade_product(&self.0, a, b)
    }
}

/// `(-1)^t` where `t` is the number of transpositions needed to sort the concatenation of the
/// ascending index lists of blades `a` and `b`, i.e. the number of pairs `(i ∈ a, j ∈ b)` with
/// `i > j`.
///
/// ```
/// use ga_core::reference::reorder_sign;
/// assert_eq!(reorder_sign(0b01, 0b10), 1); // e1 e2 = e12
/// assert_eq!(reorder_sign(0b10, 0b01), -1); // e2 e1 = -e12
/// ```
pub fn reorder_sign(a: usize, b: usize) -> i8 {
    let mut swaps = 0u32;
    let mut rest = a >> 1;
    // For every generator j in b, count the generators of a with a larger index.
    while rest != 0 {
        swaps += (rest & b).count_ones();
        rest >>= 1;
    }
    if swaps.is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// The product of basis blades `e_a e_b` for a signature: `(sign, a xor b)` with sign in
/// `{-1, 0, 1}` (zero when a shared generator squares to zero).
///
/// ```
/// use ga_core::reference::blade_product;
/// assert_eq!(blade_product(&[1, 1, -1], 0b100, 0b100), (-1, 0)); // e3² = -1
/// assert_eq!(blade_product(&[1, 1, 1], 0b011, 0b110), (1, 0b101)); // e12 e23 = e13
/// ```
pub fn blade_product(signature: &[i8], a: usize, b: usize) -> (i8, usize) {
    let mut sign = reorder_sign(a, b);
    let common = a & b;
    for (i, &s) in signature.iter().enumerate() {
        if common & (1 << i) != 0 {
            sign *= s;
        }
    }
    (sign, a ^ b)
}

/// The grade (number of generators) of a blade bitmask.
pub fn grade_of(mask: usize) -> usize {
    mask.count_ones() as usize
}

/// Sign of the reverse on grade `k`: `(-1)^{k(k-1)/2}`.
pub fn reverse_sign(k: usize) -> i8 {
    if (k * k.saturating_sub(1) / 2).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// Sign of the grade involution on grade `k`: `(-1)^k`.
pub fn involution_sign(k: usize) -> i8 {
    if k.is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// Sign of the Clifford conjugate on grade `k`: `(-1)^{k(k+1)/2}`.
pub fn conjugate_sign(k: usize) -> i8 {
    if (k * (k + 1) / 2).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

fn indices(mask: usize) -> impl Iterator<Item = usize> {
    (0..usize::BITS as usize).filter(move |i| mask & (1 << i) != 0)
}

/// Compares two blades in canonical order: by grade, then lexicographically on the ascending
/// index lists.
pub fn canonical_cmp(a: usize, b: usize) -> Ordering {
    grade_of(a)
        .cmp(&grade_of(b))
        .then_with(|| indices(a).cmp(indices(b)))
}

/// The `2ⁿ` blade bitmasks in canonical order (grade, then lexicographic on indices).
///
/// ```
/// use ga_core::reference::canonical_order;
/// assert_eq!(canonical_order(3), vec![0, 0b001, 0b010, 0b100, 0b011, 0b101, 0b110, 0b111]);
/// ```
pub fn canonical_order(n: usize) -> Vec<usize> {
    let mut masks: Vec<usize> = (0..1usize << n).collect();
    masks.sort_by(|&a, &b| canonical_cmp(a, b));
    masks
}

/// The name of blade `mask` in the project's convention: `"1"` for the scalar; otherwise the
/// basis names of its generators in ascending order, concatenated after stripping a leading
/// `e` from every name but the first (`e1`, `e2` → `e12`). Names that do not start with `e`
/// are concatenated as they are.
pub fn blade_name(mask: usize, basis_names: &[&str]) -> String {
    if mask == 0 {
        return "1".to_string();
    }
    let mut name = String::new();
    for (k, i) in indices(mask).enumerate() {
        let b = basis_names.get(i).copied().unwrap_or("?");
        if k == 0 {
            name.push_str(b);
        } else {
            name.push_str(b.strip_prefix('e').unwrap_or(b));
        }
    }
    name
}

/// The canonical names of the `2ⁿ` blades in canonical order. `basis_names` defaults to
/// `e1 … en`.
///
/// ```
/// use ga_core::reference::canonical_blade_names;
/// let names = canonical_blade_names(3, None).unwrap();
/// assert_eq!(names, ["1", "e1", "e2", "e3", "e12", "e13", "e23", "e123"]);
/// let pga = canonical_blade_names(2, Some(&["e0", "e1"])).unwrap();
/// assert_eq!(pga, ["1", "e0", "e1", "e01"]);
/// ```
pub fn canonical_blade_names(
    n: usize,
    basis_names: Option<&[&str]>,
) -> Result<Vec<String>, ReferenceError> {
    if n > MAX_GENERATORS {
        return Err(ReferenceError::TooManyGenerators(n));
    }
    let default: Vec<String> = (1..=n).map(|i| format!("e{i}")).collect();
    let default_refs: Vec<&str> = default.iter().map(String::as_str).collect();
    let basis = match basis_names {
        Some(b) if b.len() != n => {
            return Err(ReferenceError::WrongLength {
                what: "basis names",
                expected: n,
                got: b.len(),
            })
        }
        Some(b) => b,
        None => &default_refs[..],
    };
    Ok(canonical_order(n)
        .into_iter()
        .map(|m| blade_name(m, basis))
        .collect())
}

fn signed<T: Ring>(sign: i8, x: T) -> T {
    match sign {
        1 => x,
        -1 => -x,
        _ => T::zero(),
    }
}

fn accumulate<T: Ring>(slot: &mut T, sign: i8, term: T) {
    let old = core::mem::replace(slot, T::zero());
    *slot = match sign {
        1 => old + term,
        -1 => old - term,
        _ => old,
    };
}

/// A dense multivector of a Clifford algebra with a run-time signature: `2ⁿ` coefficients
/// indexed by blade bitmask (bit `i` set means generator `i` is in the blade).
///
/// See the [module documentation](self) for the exact definitions of every operation.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseMultivector<T> {
    signature: Signature,
    coeffs: Vec<T>,
}

impl<T: Ring> DenseMultivector<T> {
    /// The zero multivector.
    pub fn zero(signature: &Signature) -> Self {
        Self {
            signature: signature.clone(),
            coeffs: vec![T::zero(); signature.blade_count()],
        }
    }

    /// The scalar `s`.
    pub fn scalar(signature: &Signature, s: T) -> Self {
        let mut m = Self::zero(signature);
        m.coeffs[0] = s;
        m
    }

    /// The unit scalar `1`.
    pub fn one(signature: &Signature) -> Self {
        Self::scalar(signature, T::one())
    }

    /// The basis vector `e_i` (0-based generator index `i`).
    pub fn basis_vector(signature: &Signature, i: usize) -> Result<Self, ReferenceError> {
        if i >= signature.len() {
            return Err(ReferenceError::GeneratorOutOfRange {
                index: i,
                n: signature.len(),
            });
        }
        Self::blade(signature, 1 << i, T::one())
    }

    /// `coeff · e_mask`.
    pub fn blade(signature: &Signature, mask: usize, coeff: T) -> Result<Self, ReferenceError> {
        if mask >= signature.blade_count() {
            return Err(ReferenceError::MaskOutOfRange {
                mask,
                n: signature.len(),
            });
        }
        let mut m = Self::zero(signature);
        m.coeffs[mask] = coeff;
        Ok(m)
    }

    /// The unit pseudoscalar `I = e_{all bits}`.
    pub fn pseudoscalar(signature: &Signature) -> Self {
        let mut m = Self::zero(signature);
        let i = signature.pseudoscalar_mask();
        m.coeffs[i] = T::one();
        m
    }

    /// The multivector whose coefficient on blade `mask` is `f(mask)`.
    pub fn from_fn(signature: &Signature, f: impl FnMut(usize) -> T) -> Self {
        Self {
            signature: signature.clone(),
            coeffs: (0..signature.blade_count()).map(f).collect(),
        }
    }

    /// From `2ⁿ` coefficients indexed by bitmask.
    pub fn from_bitmask_order(
        signature: &Signature,
        coeffs: Vec<T>,
    ) -> Result<Self, ReferenceError> {
        if coeffs.len() != signature.blade_count() {
            return Err(ReferenceError::WrongLength {
                what: "coefficients",
                expected: signature.blade_count(),
                got: coeffs.len(),
            });
        }
        Ok(Self {
            signature: signature.clone(),
            coeffs,
        })
    }

    /// From `2ⁿ` coefficients in canonical order (see [`canonical_order`]).
    pub fn from_canonical(signature: &Signature, coeffs: Vec<T>) -> Result<Self, ReferenceError> {
        if coeffs.len() != signature.blade_count() {
            return Err(ReferenceError::WrongLength {
                what: "coefficients",
                expected: signature.blade_count(),
                got: coeffs.len(),
            });
        }
        let mut m = Self::zero(signature);
        for (mask, c) in canonical_order(signature.len()).into_iter().zip(coeffs) {
            m.coeffs[mask] = c;
        }
        Ok(m)
    }

    /// The `2ⁿ` coefficients in canonical order.
    pub fn to_canonical(&self) -> Vec<T> {
        canonical_order(self.signature.len())
            .into_iter()
            .map(|m| self.coeffs[m].clone())
            .collect()
    }

    /// The signature.
    pub fn signature(&self) -> &Signature {
        &self.signature
    }

    /// The coefficients indexed by bitmask.
    pub fn coefficients(&self) -> &[T] {
        &self.coeffs
    }

    /// The coefficient of blade `mask` (zero for masks out of range).
    pub fn get(&self, mask: usize) -> T {
        self.coeffs.get(mask).cloned().unwrap_or_else(T::zero)
    }

    /// Sets the coefficient of blade `mask`.
    pub fn set(&mut self, mask: usize, value: T) -> Result<(), ReferenceError> {
        let n = self.signature.len();
        match self.coeffs.get_mut(mask) {
            Some(slot) => {
                *slot = value;
                Ok(())
            }
            None => Err(ReferenceError::MaskOutOfRange { mask, n }),
        }
    }

    /// The scalar part `⟨A⟩₀`.
    pub fn scalar_part(&self) -> T {
        self.coeffs[0].clone()
    }

    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(Ring::is_zero)
    }

    /// Applies `f` to every coefficient.
    pub fn map<U>(&self, f: impl FnMut(&T) -> U) -> DenseMultivector<U> {
        DenseMultivector {
            signature: self.signature.clone(),
            coeffs: self.coeffs.iter().map(f).collect(),
        }
    }

    /// Keeps only the blades for which `keep(mask)` holds.
    pub fn project(&self, mut keep: impl FnMut(usize) -> bool) -> Self {
        Self::from_fn(&self.signature, |m| {
            if keep(m) {
                self.coeffs[m].clone()
            } else {
                T::zero()
            }
        })
    }

    /// `Ok` when both operands have the same signature, else a typed error.
    pub fn check_same_signature(&self, other: &Self) -> Result<(), ReferenceError> {
        if self.signature == other.signature {
            Ok(())
        } else {
            Err(ReferenceError::SignatureMismatch {
                left: self.signature.entries().to_vec(),
                right: other.signature.entries().to_vec(),
            })
        }
    }

    /// The bilinear extension of `e_a ∘ e_b = [keep(a, b)] · e_a e_b`.
    fn product_where(&self, rhs: &Self, keep: impl Fn(usize, usize) -> bool) -> Self {
        debug_assert_eq!(self.signature, rhs.signature, "signature mismatch");
        let sig = self.signature.entries();
        let len = self.coeffs.len();
        let mut out = vec![T::zero(); len];
        for (a, ca) in self.coeffs.iter().enumerate() {
            if ca.is_zero() {
                continue;
            }
            for (b, cb) in rhs.coeffs.iter().enumerate().take(len) {
                if cb.is_zero() || !keep(a, b) {
                    continue;
                }
                let (sign, m) = blade_product(sig, a, b);
                if sign != 0 {
                    accumulate(&mut out[m], sign, ca.clone() * cb.clone());
                }
            }
        }
        Self {
            signature: self.signature.clone(),
            coeffs: out,
        }
    }

    /// The geometric product `A B`.
    pub fn geometric(&self, rhs: &Self) -> Self {
        self.product_where(rhs, |_, _| true)
    }

    /// The outer product `A ∧ B`.
    pub fn wedge(&self, rhs: &Self) -> Self {
        self.product_where(rhs, |a, b| a & b == 0)
    }

    /// The left contraction `A ⌋ B`.
    pub fn left_contraction(&self, rhs: &Self) -> Self {
        self.product_where(rhs, |a, b| a & b == a)
    }

    /// The right contraction `A ⌊ B`.
    pub fn right_contraction(&self, rhs: &Self) -> Self {
        self.product_where(rhs, |a, b| a & b == b)
    }

    /// The scalar product `⟨A B⟩₀` (bilinear extension of `e_a * e_b = [a = b] e_a e_b`).
    pub fn scalar_product(&self, rhs: &Self) -> T {
        self.product_where(rhs, |a, b| a == b).scalar_part()
    }

    /// The regressive product `A ∨ B = undual(dual(A) ∧ dual(B))`.
    pub fn regressive(&self, rhs: &Self) -> Self {
        self.dual().wedge(&rhs.dual()).undual()
    }

    fn map_by_grade(&self, sign: impl Fn(usize) -> i8) -> Self {
        Self::from_fn(&self.signature, |m| {
            signed(sign(grade_of(m)), self.coeffs[m].clone())
        })
    }

    /// The reverse `Ã`.
    pub fn reverse(&self) -> Self {
        self.map_by_grade(reverse_sign)
    }

    /// The grade involution `Â`.
    pub fn grade_involution(&self) -> Self {
        self.map_by_grade(involution_sign)
    }

    /// The Clifford conjugate `Ā` (reverse of the grade involution).
    pub fn conjugate(&self) -> Self {
        self.map_by_grade(conjugate_sign)
    }

    /// The grade-`k` part `⟨A⟩ₖ` (zero when `k > n`).
    pub fn grade(&self, k: usize) -> Self {
        self.project(|m| grade_of(m) == k)
    }

    /// The dual: `A I⁻¹` for a non-degenerate signature, the right complement otherwise
    /// (see the module documentation).
    pub fn dual(&self) -> Self {
        let full = self.signature.pseudoscalar_mask();
        if self.signature.is_degenerate() {
            // dual(e_a) = s e_{¬a} with e_a ∧ (s e_{¬a}) = I, i.e. s = reorder_sign(a, ¬a).
            Self::from_fn(&self.signature, |m| {
                let a = full ^ m;
                signed(reorder_sign(a, m), self.coeffs[a].clone())
            })
        } else {
            // I⁻¹ = I / (I I) and I I = ±1, so I⁻¹ = (I I) I.
            let (ii, _) = self.signature.blade_product(full, full);
            let inv = Self::blade(&self.signature, full, signed(ii, T::one()))
                .unwrap_or_else(|_| Self::zero(&self.signature));
            self.geometric(&inv)
        }
    }

    /// The undual, the inverse of [`dual`](Self::dual): `A I` for a non-degenerate signature,
    /// the left complement otherwise.
    pub fn undual(&self) -> Self {
        let full = self.signature.pseudoscalar_mask();
        if self.signature.is_degenerate() {
            // undual(e_a) = s' e_{¬a} with (s' e_{¬a}) ∧ e_a = I, i.e. s' = reorder_sign(¬a, a).
            Self::from_fn(&self.signature, |m| {
                let a = full ^ m;
                signed(reorder_sign(m, a), self.coeffs[a].clone())
            })
        } else {
            self.geometric(&Self::pseudoscalar(&self.signature))
        }
    }

    /// `⟨A Ã⟩₀`.
    pub fn norm_squared(&self) -> T {
        self.scalar_product(&self.reverse())
    }

    /// `V X Ṽ` (the sandwich for unit versors).
    pub fn sandwich_unit(&self, x: &Self) -> Self {
        self.geometric(x).geometric(&self.reverse())
    }

    /// `s A`.
    pub fn scale(&self, s: &T) -> Self {
        self.map(|c| c.clone() * s.clone())
    }

    fn zip_with(&self, rhs: &Self, f: impl Fn(T, T) -> T) -> Self {
        debug_assert_eq!(self.signature, rhs.signature, "signature mismatch");
        Self::from_fn(&self.signature, |m| f(self.coeffs[m].clone(), rhs.get(m)))
    }

    /// The left-multiplication matrix: entry `[i][j]` is the coefficient of `e_i` in `A e_j`
    /// (bitmask order).
    pub fn left_multiplication_matrix(&self) -> Vec<Vec<T>> {
        let len = self.coeffs.len();
        let mut rows = vec![vec![T::zero(); len]; len];
        for (a, ca) in self.coeffs.iter().enumerate() {
            if ca.is_zero() {
                continue;
            }
            // Column j is A e_j; the term c_a e_a e_j lands in row a ⊕ j.
            for j in 0..len {
                let (sign, i) = self.signature.blade_product(a, j);
                if let Some(entry) = rows.get_mut(i).and_then(|row| row.get_mut(j)) {
                    accumulate(entry, sign, ca.clone());
                }
            }
        }
        rows
    }
}

impl<T: Field> DenseMultivector<T> {
    /// The versor inverse `Ã / ⟨A Ã⟩₀`, `None` when `⟨A Ã⟩₀` is zero. Equals the inverse
    /// when `A` is a versor (a product of invertible vectors); otherwise it may not be one.
    pub fn versor_inverse(&self) -> Option<Self> {
        let r = self.norm_squared().checked_recip()?;
        Some(self.reverse().scale(&r))
    }

    /// `V X V⁻¹` with the versor inverse; `None` when `⟨V Ṽ⟩₀` is zero.
    pub fn sandwich(&self, x: &Self) -> Option<Self> {
        Some(self.geometric(x).geometric(&self.versor_inverse()?))
    }
}

impl<T: Real> DenseMultivector<T> {
    /// The inverse `A⁻¹` with `A A⁻¹ = A⁻¹ A = 1`, by Gaussian elimination with partial
    /// pivoting (largest absolute value) on the left-multiplication matrix; `None` when a pivot
    /// is exactly zero (`A` is singular). Exact over rationals. For floating point, a nearly
    /// singular `A` gives a huge, inaccurate result: see
    /// [`general_inverse_with_tolerance`](Self::general_inverse_with_tolerance).
    pub fn general_inverse(&self) -> Option<Self> {
        self.general_inverse_with_tolerance(&T::zero())
    }

    /// As [`general_inverse`](Self::general_inverse), but declares `A` singular when the
    /// largest available pivot has absolute value `<= tol`.
    pub fn general_inverse_with_tolerance(&self, tol: &T) -> Option<Self> {
        let len = self.coeffs.len();
        let mut m = self.left_multiplication_matrix();
        // Right-hand side: the unit scalar; we solve (A ·) x = 1, i.e. A x = 1.
        let mut rhs = vec![T::zero(); len];
        rhs[0] = T::one();
        for col in 0..len {
            // Partial pivoting: the largest |entry| in this column at or below the diagonal.
            let mut best = col;
            let mut best_abs = m[col][col].abs();
            for (r, row) in m.iter().enumerate().skip(col + 1) {
                let a = row[col].abs();
                if a > best_abs {
                    best = r;
                    best_abs = a;
                }
            }
            if best_abs.is_zero() || best_abs <= *tol {
                return None;
            }
            m.swap(col, best);
            rhs.swap(col, best);
            let inv = m[col][col].checked_recip()?;
            let pivot_row = m[col].clone();
            let pivot_rhs = rhs[col].clone();
            for r in col + 1..len {
                if m[r][col].is_zero() {
                    continue;
                }
                let f = m[r][col].clone() * inv.clone();
                for (c, p) in pivot_row.iter().enumerate().skip(col) {
                    if p.is_zero() {
                        continue;
                    }
                    let v = core::mem::replace(&mut m[r][c], T::zero());
                    m[r][c] = v - f.clone() * p.clone();
                }
                let v = core::mem::replace(&mut rhs[r], T::zero());
                rhs[r] = v - f * pivot_rhs.clone();
            }
        }
        // Back substitution.
        let mut x = vec![T::zero(); len];
        for r in (0..len).rev() {
            let mut acc = rhs[r].clone();
            for (c, xc) in x.iter().enumerate().skip(r + 1) {
                if !m[r][c].is_zero() && !xc.is_zero() {
                    acc = acc - m[r][c].clone() * xc.clone();
                }
            }
            x[r] = acc * m[r][r].checked_recip()?;
        }
        Some(Self {
            signature: self.signature.clone(),
            coeffs: x,
        })
    }
}

impl<T: Ring + fmt::Display> fmt::Display for DenseMultivector<T> {
    /// Nonzero terms in canonical order, `c·name` joined by ` + `, with default basis names
    /// `e1 … en`; zero prints `0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.signature.len();
        let names: Vec<String> = (1..=n).map(|i| format!("e{i}")).collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let mut first = true;
        for m in canonical_order(n) {
            let c = &self.coeffs[m];
            if c.is_zero() {
                continue;
            }
            if !first {
                f.write_str(" + ")?;
            }
            first = false;
            if m == 0 {
                write!(f, "{c}")?;
            } else {
                write!(f, "{c}·{}", blade_name(m, &names))?;
            }
        }
        if first {
            f.write_str("0")?;
        }
        Ok(())
    }
}

impl<T> approx::AbsDiffEq for DenseMultivector<T>
where
    T: Ring + approx::AbsDiffEq,
    T::Epsilon: Clone,
{
    type Epsilon = T::Epsilon;
    fn default_epsilon() -> Self::Epsilon {
        T::default_epsilon()
    }
    fn abs_diff_eq(&self, other: &Self, epsilon: Self::Epsilon) -> bool {
        self.signature == other.signature
            && self
                .coeffs
                .iter()
                .zip(&other.coeffs)
                .all(|(a, b)| a.abs_diff_eq(b, epsilon.clone()))
    }
}

impl<T> approx::RelativeEq for DenseMultivector<T>
where
    T: Ring + approx::RelativeEq,
    T::Epsilon: Clone,
{
    fn default_max_relative() -> Self::Epsilon {
        T::default_max_relative()
    }
    fn relative_eq(
        &self,
        other: &Self,
        epsilon: Self::Epsilon,
        max_relative: Self::Epsilon,
    ) -> bool {
        self.signature == other.signature
            && self
                .coeffs
                .iter()
                .zip(&other.coeffs)
                .all(|(a, b)| a.relative_eq(b, epsilon.clone(), max_relative.clone()))
    }
}

macro_rules! binary_operator {
    ($trait:ident, $method:ident, $call:ident, $doc:literal) => {
        #[doc = $doc]
        impl<T: Ring> $trait<&DenseMultivector<T>> for &DenseMultivector<T> {
            type Output = DenseMultivector<T>;
            fn $method(self, rhs: &DenseMultivector<T>) -> DenseMultivector<T> {
                self.$call(rhs)
            }
        }
        #[doc = $doc]
        impl<T: Ring> $trait<DenseMultivector<T>> for DenseMultivector<T> {
            type Output = DenseMultivector<T>;
            fn $method(self, rhs: DenseMultivector<T>) -> DenseMultivector<T> {
                (&self).$call(&rhs)
            }
        }
        #[doc = $doc]
        impl<T: Ring> $trait<&DenseMultivector<T>> for DenseMultivector<T> {
            type Output = DenseMultivector<T>;
            fn $method(self, rhs: &DenseMultivector<T>) -> DenseMultivector<T> {
                (&self).$call(rhs)
            }
        }
        #[doc = $doc]
        impl<T: Ring> $trait<DenseMultivector<T>> for &DenseMultivector<T> {
            type Output = DenseMultivector<T>;
            fn $method(self, rhs: DenseMultivector<T>) -> DenseMultivector<T> {
                self.$call(&rhs)
            }
        }
    };
}

impl<T: Ring> DenseMultivector<T> {
    /// `A + B`.
    pub fn add_mv(&self, rhs: &Self) -> Self {
        self.zip_with(rhs, |a, b| a + b)
    }
    /// `A - B`.
    pub fn sub_mv(&self, rhs: &Self) -> Self {
        self.zip_with(rhs, |a, b| a - b)
    }
    /// `-A`.
    pub fn neg_mv(&self) -> Self {
        self.map(|c| -c.clone())
    }
}

binary_operator!(Mul, mul, geometric, "Geometric product.");
binary_operator!(BitXor, bitxor, wedge, "Outer product.");
binary_operator!(BitOr, bitor, left_contraction, "Left contraction.");
binary_operator!(BitAnd, bitand, regressive, "Regressive product.");
binary_operator!(Add, add, add_mv, "Sum.");
binary_operator!(Sub, sub, sub_mv, "Difference.");

impl<T: Ring> Neg for DenseMultivector<T> {
    type Output = Self;
    fn neg(self) -> Self {
        self.neg_mv()
    }
}

impl<T: Ring> Neg for &DenseMultivector<T> {
    type Output = DenseMultivector<T>;
    fn neg(self) -> DenseMultivector<T> {
        self.neg_mv()
    }
}

impl<T: Ring> Not for DenseMultivector<T> {
    type Output = Self;
    /// The dual.
    fn not(self) -> Self {
        self.dual()
    }
}

impl<T: Ring> Not for &DenseMultivector<T> {
    type Output = DenseMultivector<T>;
    /// The dual.
    fn not(self) -> DenseMultivector<T> {
        self.dual()
    }
}

#[cfg(test)]
mod tests;
