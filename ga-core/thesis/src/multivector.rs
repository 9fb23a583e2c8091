//! [`SymMultivector`]: a sparse multivector of Cl(4,1) over the symbolic scalar [`Poly`].
//!
//! The thesis's formulas are sums of a few blades with long polynomial coefficients, and the
//! checker reads, compares and prints them blade by blade; a sparse map from blade bitmask
//! (`e1` = bit 0 … `e5` = bit 4) to coefficient fits that better than the generated dense
//! `cga::Multivector`. Its own products take their signs from
//! `ga_core::reference` (the project's one definition of blade products), so reading a printed
//! formula never depends on the generated code that the checks test.

use std::collections::BTreeMap;

use ga_core::reference::blade_product;
use ga_core::scalar::{Rational, Ring};
use ga_core::symbolic::Poly;

use crate::notation::canonical_masks;

/// Squares of the basis vectors `e1..e5` of Cl(4,1).
const METRIC: [i8; 5] = [1, 1, 1, 1, -1];

/// A sparse multivector of Cl(4,1) with polynomial coefficients, keyed by blade bitmask.
#[derive(Clone, Default, PartialEq, Eq)]
pub struct SymMultivector {
    pub(crate) coeffs: BTreeMap<u8, Poly>,
}

impl SymMultivector {
    /// The zero multivector.
    pub fn zero() -> Self {
        Self::default()
    }
    /// The scalar `p`.
    pub fn scalar(p: Poly) -> Self {
        Self::blade(0, p)
    }
    /// `p` times the basis blade with bitmask `mask` (bit `i` = `e(i+1)`; masks ≥ 32 give 0).
    pub fn blade(mask: u8, p: Poly) -> Self {
        let mut m = Self::zero();
        if mask < 32 && !p.is_zero() {
            m.coeffs.insert(mask, p);
        }
        m
    }
    /// The coefficient of the blade `mask` (our sign convention).
    pub fn get(&self, mask: u8) -> Poly {
        self.coeffs.get(&mask).cloned().unwrap_or_default()
    }
    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
    /// The nonzero blades with their coefficients, by bitmask.
    pub fn iter(&self) -> impl Iterator<Item = (u8, &Poly)> {
        self.coeffs.iter().map(|(&m, p)| (m, p))
    }
    /// The 32 coefficients in canonical order (the order of `cga::Multivector`).
    pub fn coefficients(&self) -> Vec<Poly> {
        canonical_masks().iter().map(|&m| self.get(m)).collect()
    }
    /// From 32 coefficients in canonical order (extra entries are ignored).
    pub fn from_coefficients(c: &[Poly]) -> Self {
        let mut m = Self::zero();
        for (mask, p) in canonical_masks().iter().zip(c) {
            if !p.is_zero() {
                m.coeffs.insert(*mask, p.clone());
            }
        }
        m
    }
    fn add_term(&mut self, mask: u8, p: Poly) {
        if p.is_zero() {
            return;
        }
        let e = self.coeffs.entry(mask).or_default();
        *e += &p;
        if e.is_zero() {
            self.coeffs.remove(&mask);
        }
    }
    /// Sum.
    pub fn add(&self, o: &Self) -> Self {
        let mut r = self.clone();
        for (&m, p) in &o.coeffs {
            r.add_term(m, p.clone());
        }
        r
    }
    /// Difference.
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    /// Negation.
    pub fn neg(&self) -> Self {
        self.map(|p| -p)
    }
    /// Applies `f` to every coefficient.
    pub fn map(&self, f: impl Fn(&Poly) -> Poly) -> Self {
        let mut r = Self::zero();
        for (&m, p) in &self.coeffs {
            r.add_term(m, f(p));
        }
        r
    }
    /// Multiplies every coefficient by the polynomial `s`.
    pub fn scale(&self, s: &Poly) -> Self {
        self.map(|p| p * s)
    }
    fn product(&self, o: &Self, keep: impl Fn(u8, u8) -> bool) -> Self {
        let mut acc: BTreeMap<u8, Vec<Poly>> = BTreeMap::new();
        for (&a, pa) in &self.coeffs {
            for (&b, pb) in &o.coeffs {
                if !keep(a, b) {
                    continue;
                }
                let (sign, mask) = blade_product(&METRIC, usize::from(a), usize::from(b));
                let t = pa * pb;
                let t = if sign < 0 { -t } else { t };
                let mask = u8::try_from(mask).unwrap_or_else(|_| unreachable!("5-bit masks"));
                acc.entry(mask).or_default().push(t);
            }
        }
        let mut r = Self::zero();
        for (m, terms) in acc {
            r.add_term(m, terms.into_iter().sum());
        }
        r
    }
    /// Geometric product.
    pub fn gp(&self, o: &Self) -> Self {
        self.product(o, |_, _| true)
    }
    /// Outer product.
    pub fn wedge(&self, o: &Self) -> Self {
        self.product(o, |a, b| a & b == 0)
    }
    /// Left contraction `self ⌋ o`.
    pub fn left_contraction(&self, o: &Self) -> Self {
        self.product(o, |a, b| a & b == a)
    }
    /// The part of grade `k`.
    pub fn grade(&self, k: u32) -> Self {
        let mut r = Self::zero();
        for (&m, p) in &self.coeffs {
            if m.count_ones() == k {
                r.coeffs.insert(m, p.clone());
            }
        }
        r
    }
    /// Simultaneous substitution in every coefficient.
    pub fn subs_all(&self, values: &[(&str, Poly)]) -> Self {
        self.map(|p| p.subs_all(values))
    }
    /// The rational `k` with `self == k · other`, if any (both nonzero).
    pub fn ratio_to(&self, other: &Self) -> Option<Rational> {
        if self.coeffs.len() != other.coeffs.len() || self.is_zero() {
            return None;
        }
        let mut k: Option<Rational> = None;
        for ((ma, pa), (mb, pb)) in self.coeffs.iter().zip(&other.coeffs) {
            if ma != mb {
                return None;
            }
            let r = pa.ratio_to(pb)?;
            match &k {
                None => k = Some(r),
                Some(k0) if *k0 == r => {}
                Some(_) => return None,
            }
        }
        k
    }
}
