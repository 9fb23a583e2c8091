//! Symbolic multivectors of Cl(4,1) in the notation of the thesis, and a checker for
//! transcribed formulas.
//!
//! The thesis (Cap. II, Apéndice A) writes the conformal basis as `e1, e2, e3, e, ē` with
//! `e = e4`, `ē = e5`, `n = e + ē` (our `n_inf`), `n̄ = e − ē` (so our `n_0 = −n̄/2`), a point
//! as `X = 2x + x²n − n̄` (= `2·up(x)`), the pseudoscalar `I = e1e2e3eē` (= our `e12345`) and
//! the dual `A* = IA` (= `−A I⁻¹`, the negative of our `dual`, since `I` is central and
//! `I² = −1`). Bivectors are written `e1e2, e2e3, e3e1` (cyclic), and the conformal vectors
//! come last: `e3e1ē = −e135`.
//!
//! [`SymMultivector`] is a small sparse multivector over [`Poly`] with its own product
//! (bitmask blades), independent of the generated `cga` module, used to read and print
//! formulas written in that notation:
//!
//! ```
//! use ga_core::symbolic::thesis::{Scope, Notation};
//! let scope = Scope::new();
//! let x = scope.parse("2(a1 e1 + a2 e2) + (a1^2 + a2^2) n - n̄").unwrap();
//! let y = scope.parse("2 a1 e1 + 2 a2 e2 + (a1^2 + a2^2 - 1) e + (a1^2 + a2^2 + 1) ē").unwrap();
//! assert_eq!(x, y);
//! let l = scope.parse("e1 ∧ e3 ∧ ē").unwrap();
//! assert_eq!(l.to_notation(Notation::Thesis), "-e3e1ē");
//! assert_eq!(l.to_notation(Notation::Canonical), "e135");
//! assert_eq!(x.to_notation(Notation::ThesisNull), "2*a1 e1 + 2*a2 e2 + (a1^2 + a2^2) n - n̄");
//! ```

use std::collections::{BTreeMap, HashMap};

use num_traits::{One, Zero};

use super::parse::{parse_with, Value};
use super::{write_poly, Poly, Style, SymbolicError};
use crate::scalar::{Rational, Ring};

/// Squares of the basis vectors `e1..e5` of Cl(4,1).
const METRIC: [i32; 5] = [1, 1, 1, 1, -1];

/// Sign of the product of basis blades `a b` from reordering (metric not included).
fn reorder_sign(a: u8, b: u8) -> i32 {
    let mut a = a >> 1;
    let mut swaps = 0;
    while a != 0 {
        swaps += (a & b).count_ones();
        a >>= 1;
    }
    if swaps % 2 == 0 {
        1
    } else {
        -1
    }
}

/// Sign of the geometric product of basis blades `a b` (reordering and metric).
fn gp_sign(a: u8, b: u8) -> i32 {
    let mut s = reorder_sign(a, b);
    let common = a & b;
    for (i, m) in METRIC.iter().enumerate() {
        if common & (1 << i) != 0 {
            s *= m;
        }
    }
    s
}

/// The 32 blade bitmasks (`e1` = bit 0 … `e5` = bit 4) in canonical order: by grade, then
/// lexicographic on indices (`1, e1, …, e5, e12, e13, …, e12345`).
pub fn canonical_masks() -> [u8; 32] {
    let mut masks: Vec<u8> = (0u8..32).collect();
    masks.sort_by_key(|&m| {
        let idx: Vec<u8> = (0..5).filter(|i| m & (1 << i) != 0).collect();
        (m.count_ones(), idx)
    });
    let mut out = [0u8; 32];
    out.copy_from_slice(&masks);
    out
}

/// Canonical name of a blade (`1`, `e1`, `e135`, `e12345`).
pub fn canonical_name(mask: u8) -> String {
    if mask == 0 {
        return "1".into();
    }
    let mut s = String::from("e");
    for i in 0..5 {
        if mask & (1 << i) != 0 {
            s.push(char::from(b'1' + i));
        }
    }
    s
}

/// The thesis's spelling of a blade and the sign relating it to ours:
/// `blade(mask) = sign · (thesis blade)`. Euclidean part `e1, e2, e3, e1e2, e2e3, e3e1,
/// e1e2e3`, then `e`, then `ē`; the scalar is `1`.
pub fn thesis_name(mask: u8) -> (i32, String) {
    let euclid = mask & 0b111;
    let seq: Vec<u8> = match euclid {
        0 => vec![],
        0b001 => vec![0],
        0b010 => vec![1],
        0b100 => vec![2],
        0b011 => vec![0, 1],
        0b110 => vec![1, 2],
        0b101 => vec![2, 0],
        _ => vec![0, 1, 2],
    };
    let mut seq = seq;
    if mask & 0b01000 != 0 {
        seq.push(3);
    }
    if mask & 0b10000 != 0 {
        seq.push(4);
    }
    if seq.is_empty() {
        return (1, "1".into());
    }
    let names = ["e1", "e2", "e3", "e", "ē"];
    let name: String = seq.iter().map(|&i| names[i as usize]).collect();
    // Product of the sequence = sign · blade(mask); the sign is its own inverse.
    let mut acc = 0u8;
    let mut sign = 1;
    for &i in &seq {
        sign *= reorder_sign(acc, 1 << i);
        acc |= 1 << i;
    }
    (sign, name)
}

/// Order in which [`Notation::Thesis`] prints blades: by grade, Euclidean part first.
fn thesis_order() -> Vec<u8> {
    let mut masks: Vec<u8> = (0u8..32).collect();
    let euclid_rank = |m: u8| match m & 0b111 {
        0 => 0,
        0b001 => 1,
        0b010 => 2,
        0b100 => 3,
        0b011 => 4,
        0b110 => 5,
        0b101 => 6,
        _ => 7,
    };
    masks.sort_by_key(|&m| (m.count_ones(), m >> 3, euclid_rank(m)));
    masks
}

/// How blades are spelled when printing a [`SymMultivector`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notation {
    /// Our canonical names (`e135`) and signs, canonical blade order.
    Canonical,
    /// The thesis's names (`e3e1ē`) and signs, in its usual order.
    Thesis,
    /// The thesis's null basis: Euclidean blades times `1`, `n`, `n̄` or `n∧n̄` (using
    /// `e = (n + n̄)/2`, `ē = (n − n̄)/2`, `eē = −½ n∧n̄`), so that the point `2·up(x)` prints as
    /// the thesis's `2x + x²n − n̄`.
    ThesisNull,
}

/// A sparse multivector of Cl(4,1) with polynomial coefficients, keyed by blade bitmask.
#[derive(Clone, Default, PartialEq, Eq)]
pub struct SymMultivector {
    coeffs: BTreeMap<u8, Poly>,
}

impl core::fmt::Debug for SymMultivector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.to_notation(Notation::Canonical))
    }
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
                let t = pa * pb;
                let t = if gp_sign(a, b) < 0 { -t } else { t };
                acc.entry(a ^ b).or_default().push(t);
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
    /// Reverse (`Ã`).
    pub fn reverse(&self) -> Self {
        let mut r = Self::zero();
        for (&m, p) in &self.coeffs {
            let g = m.count_ones();
            let p = if (g * g.saturating_sub(1) / 2) % 2 == 1 {
                -p
            } else {
                p.clone()
            };
            r.coeffs.insert(m, p);
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
    /// Prints as a sum of `coefficient blade` terms in the given notation.
    pub fn to_notation(&self, notation: Notation) -> String {
        self.render(notation, Style::Plain)
    }
    /// LaTeX form in the given notation (`ē` becomes `\bar{e}`).
    pub fn to_latex(&self, notation: Notation) -> String {
        self.render(notation, Style::Latex)
    }
    /// The terms `(blade name, coefficient)` in the given notation and its sign convention.
    pub fn terms(&self, notation: Notation) -> Vec<(String, Poly)> {
        let order: Vec<u8> = match notation {
            Notation::Canonical => canonical_masks().to_vec(),
            Notation::Thesis => thesis_order(),
            Notation::ThesisNull => return self.null_terms(),
        };
        order
            .into_iter()
            .filter_map(|m| {
                let p = self.coeffs.get(&m)?;
                Some(match notation {
                    Notation::Canonical => (canonical_name(m), p.clone()),
                    _ => {
                        let (s, n) = thesis_name(m);
                        (n, if s < 0 { -p } else { p.clone() })
                    }
                })
            })
            .collect()
    }
    /// Terms in the null basis (see [`Notation::ThesisNull`]).
    fn null_terms(&self) -> Vec<(String, Poly)> {
        let half = Poly::ratio(1, 2).unwrap_or_default();
        let mut out = Vec::new();
        // Euclidean parts in the thesis's order.
        for e in [0u8, 1, 2, 4, 3, 6, 5, 7] {
            let (sign, name) = thesis_name(e);
            let fix = |p: Poly| if sign < 0 { -p } else { p };
            let c = |m: u8| fix(self.get(e | m));
            let (c0, ce, cb, ceb) = (c(0), c(8), c(16), c(24));
            let join = |suffix: &str| {
                if name == "1" {
                    suffix.to_string()
                } else if suffix.is_empty() {
                    name.clone()
                } else {
                    format!("{name}{suffix}")
                }
            };
            let parts = [
                (join(""), c0),
                (join("n"), &(&ce + &cb) * &half),
                (join("n̄"), &(&ce - &cb) * &half),
                (join("nn̄"), -(&ceb * &half)),
            ];
            for (n, p) in parts {
                if !p.is_zero() {
                    out.push((if n.is_empty() { "1".into() } else { n }, p));
                }
            }
        }
        out.sort_by_key(|(n, _)| {
            let g = n.matches('e').count() + n.matches('n').count();
            (g, n.contains('n'))
        });
        out
    }

    /// The thesis's dual `A* = I A` with `I = e1e2e3eē` (the negative of our `dual`).
    pub fn thesis_dual(&self) -> Self {
        SymMultivector::blade(31, <Poly as Ring>::one()).gp(self)
    }

    /// The thesis's point `F(x) = 2x + x²n − n̄` (= `2·up(x)`).
    pub fn thesis_point(x: [Poly; 3]) -> Self {
        let [a, b, c] = x;
        let sq = &(&(&a * &a) + &(&b * &b)) + &(&c * &c);
        let two = Poly::from(2);
        let one = <Poly as Ring>::one();
        SymMultivector::blade(1, &two * &a)
            .add(&SymMultivector::blade(2, &two * &b))
            .add(&SymMultivector::blade(4, &two * &c))
            .add(&SymMultivector::blade(8, &sq - &one))
            .add(&SymMultivector::blade(16, &sq + &one))
    }

    fn render(&self, notation: Notation, style: Style) -> String {
        let terms = self.terms(notation);
        if terms.is_empty() {
            return "0".into();
        }
        let mut out = String::new();
        for (i, (name, p)) in terms.iter().enumerate() {
            let name = if style == Style::Latex {
                latex_blade(name)
            } else {
                name.clone()
            };
            let single = p.num_terms() == 1;
            let (neg, body) = if single {
                let (c, _) = &p.terms()[0];
                let neg = c < &<Rational as Zero>::zero();
                let abs = if neg { -p } else { p.clone() };
                (neg, abs)
            } else {
                (false, p.clone())
            };
            if i > 0 {
                out.push_str(if neg { " - " } else { " + " });
            } else if neg {
                out.push('-');
            }
            let is_one = body.as_constant().is_some_and(|c| c.is_one());
            let mut coef = String::new();
            write_poly(&mut coef, &body, style);
            let blade_is_scalar = name == "1";
            if blade_is_scalar {
                out.push_str(&coef);
            } else if is_one {
                out.push_str(&name);
            } else if single {
                out.push_str(&coef);
                out.push(' ');
                out.push_str(&name);
            } else if style == Style::Latex {
                out.push_str(&format!("\\left({coef}\\right) {name}"));
            } else {
                out.push_str(&format!("({coef}) {name}"));
            }
        }
        out
    }
}

fn latex_blade(name: &str) -> String {
    let mut s = String::new();
    let chars: Vec<char> = name.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            'ē' => {
                s.push_str("\\bar{e}");
                i += 1;
            }
            'e' if i + 1 < chars.len() && chars[i + 1].is_ascii_digit() => {
                s.push_str(&format!("e_{{{}}}", chars[i + 1]));
                i += 2;
            }
            c => {
                s.push(c);
                i += 1;
            }
        }
    }
    s
}

impl From<&crate::cga::Multivector<Poly>> for SymMultivector {
    /// The same multivector, for printing in the thesis's notation or comparing.
    fn from(m: &crate::cga::Multivector<Poly>) -> Self {
        SymMultivector::from_coefficients(&m.coefficients())
    }
}

impl Value for SymMultivector {
    fn constant(c: Rational) -> Self {
        Self::scalar(Poly::constant(c))
    }
    fn add(&self, o: &Self) -> Self {
        SymMultivector::add(self, o)
    }
    fn sub(&self, o: &Self) -> Self {
        SymMultivector::sub(self, o)
    }
    fn mul(&self, o: &Self) -> Self {
        self.gp(o)
    }
    fn neg(&self) -> Self {
        SymMultivector::neg(self)
    }
    fn wedge(&self, o: &Self) -> Result<Self, String> {
        Ok(SymMultivector::wedge(self, o))
    }
    fn left_contraction(&self, o: &Self) -> Result<Self, String> {
        Ok(SymMultivector::left_contraction(self, o))
    }
    fn as_constant(&self) -> Option<Rational> {
        match self.coeffs.len() {
            0 => Some(<Rational as Zero>::zero()),
            1 => self.coeffs.get(&0).and_then(|p| p.as_constant()),
            _ => None,
        }
    }
}

/// The products an expression is evaluated with by [`Scope::evaluate`]: supplied by the caller,
/// so that a check can compute with an implementation other than [`SymMultivector`]'s own
/// (for example the generated `cga` products over [`Poly`]).
pub trait Products {
    /// Geometric product `a b`.
    fn geometric(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector;
    /// Outer product `a ∧ b`.
    fn wedge(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector;
    /// Left contraction `a ⌋ b`.
    fn left_contraction(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector;
}

/// A value of [`Scope::evaluate`]: a multivector and the products to combine it with (`None`
/// for constants, which only scale).
#[derive(Clone)]
struct Evaluated<'a> {
    m: SymMultivector,
    products: Option<&'a dyn Products>,
}

impl<'a> Evaluated<'a> {
    fn with(&self, o: &Self, m: SymMultivector) -> Self {
        Evaluated {
            m,
            products: self.products.or(o.products),
        }
    }
    /// Combines two values: by scaling when one is a constant, else with the products.
    fn combine(
        &self,
        o: &Self,
        f: impl Fn(&dyn Products, &SymMultivector, &SymMultivector) -> SymMultivector,
    ) -> Self {
        let scalar = |v: &Self| v.m.iter().all(|(mask, _)| mask == 0);
        match self.products.or(o.products) {
            Some(p) if !(scalar(self) || scalar(o)) => self.with(o, f(p, &self.m, &o.m)),
            // A scalar factor only scales, in every product.
            _ => self.with(o, self.m.gp(&o.m)),
        }
    }
}

impl Value for Evaluated<'_> {
    fn constant(c: Rational) -> Self {
        Evaluated {
            m: SymMultivector::scalar(Poly::constant(c)),
            products: None,
        }
    }
    fn add(&self, o: &Self) -> Self {
        self.with(o, self.m.add(&o.m))
    }
    fn sub(&self, o: &Self) -> Self {
        self.with(o, self.m.sub(&o.m))
    }
    fn mul(&self, o: &Self) -> Self {
        self.combine(o, |p, a, b| p.geometric(a, b))
    }
    fn neg(&self) -> Self {
        Evaluated {
            m: self.m.neg(),
            products: self.products,
        }
    }
    fn wedge(&self, o: &Self) -> Result<Self, String> {
        Ok(self.combine(o, |p, a, b| p.wedge(a, b)))
    }
    fn left_contraction(&self, o: &Self) -> Result<Self, String> {
        // A scalar contracted onto anything scales it; anything of grade > 0 onto a scalar is 0.
        let scalar = |v: &Self| v.m.iter().all(|(mask, _)| mask == 0);
        if scalar(self) {
            return Ok(self.with(o, self.m.gp(&o.m)));
        }
        if scalar(o) {
            return Ok(self.with(o, SymMultivector::zero()));
        }
        Ok(self.combine(o, |p, a, b| p.left_contraction(a, b)))
    }
    fn as_constant(&self) -> Option<Rational> {
        <SymMultivector as Value>::as_constant(&self.m)
    }
}

/// Reads a word of thesis basis symbols as a blade: `e1e2e`, `e3e1ē`, `e2eebar` (geometric
/// product of the symbols), or, in the null basis, words with `n` and `n̄`/`nbar` such as
/// `e1n`, `e3e1n̄`, `nn̄` (outer product of the symbols).
fn parse_blade_word(word: &str) -> Option<SymMultivector> {
    let one = <Poly as Ring>::one;
    let e = |bit: u8| SymMultivector::blade(1 << bit, one());
    let mut rest = word;
    let mut symbols: Vec<SymMultivector> = Vec::new();
    let mut null = false;
    if rest.is_empty() {
        return None;
    }
    while !rest.is_empty() {
        let (sym, len) = if rest.starts_with("ebar") {
            (e(4), 4)
        } else if rest.starts_with("nbar") {
            null = true;
            (e(3).sub(&e(4)), 4)
        } else if rest.starts_with("n\u{304}") {
            null = true;
            (e(3).sub(&e(4)), 1 + '\u{304}'.len_utf8())
        } else if rest.starts_with('n') {
            null = true;
            (e(3).add(&e(4)), 1)
        } else if rest.starts_with("e1") {
            (e(0), 2)
        } else if rest.starts_with("e2") {
            (e(1), 2)
        } else if rest.starts_with("e3") {
            (e(2), 2)
        } else if rest.starts_with("e4") {
            (e(3), 2)
        } else if rest.starts_with("e5") {
            (e(4), 2)
        } else if rest.starts_with('ē') {
            (e(4), 'ē'.len_utf8())
        } else if rest.starts_with("e\u{304}") {
            (e(4), 1 + '\u{304}'.len_utf8())
        } else if rest.starts_with('e') {
            (e(3), 1)
        } else {
            return None;
        };
        symbols.push(sym);
        rest = &rest[len..];
    }
    let mut acc = SymMultivector::scalar(one());
    for sym in &symbols {
        acc = if null { acc.wedge(sym) } else { acc.gp(sym) };
    }
    Some(acc)
}

/// Name resolution for multivector expressions: points, auxiliary symbols, blades.
///
/// Identifiers resolve, in order, to: a point declared with [`Scope::point`] (the vector
/// `x₁e1 + x₂e2 + x₃e3`); an auxiliary symbol declared with [`Scope::define`] (kept as the
/// scalar variable of that name, see [`Scope::expand`]); `n` (`e + ē`), `nbar`/`n̄` (`e − ē`),
/// `I` (`e1e2e3eē`); a word of basis symbols (`e1`, `e2`, `e3`, `e`/`e4`, `ē`/`ebar`/`e5`);
/// otherwise a scalar variable.
#[derive(Clone, Default)]
pub struct Scope {
    points: HashMap<String, SymMultivector>,
    defs: Vec<(String, String)>,
}

impl Scope {
    /// An empty scope.
    pub fn new() -> Self {
        Self::default()
    }
    /// Declares the point `name = c1 e1 + c2 e2 + c3 e3` with coordinate variables `coords`.
    pub fn point(&mut self, name: &str, coords: [&str; 3]) -> &mut Self {
        let mut v = SymMultivector::zero();
        for (i, c) in coords.iter().enumerate() {
            v = v.add(&SymMultivector::blade(1 << i, Poly::var(c)));
        }
        self.points.insert(name.to_string(), v);
        self
    }
    /// Declares the auxiliary scalar `name := expr`. A later definition of the same name
    /// shadows the earlier one from that point on (definitions made before it keep using the
    /// earlier meaning, as the thesis reuses names such as `α124` per section).
    pub fn define(&mut self, name: &str, expr: &str) -> &mut Self {
        self.defs.push((name.to_string(), expr.to_string()));
        self
    }
    /// The auxiliary symbols, in declaration order.
    pub fn definitions(&self) -> &[(String, String)] {
        &self.defs
    }
    fn resolve(&self, name: &str) -> Result<SymMultivector, String> {
        if let Some(p) = self.points.get(name) {
            return Ok(p.clone());
        }
        if self.defs.iter().any(|(n, _)| n == name) {
            return Ok(SymMultivector::scalar(Poly::var(name)));
        }
        let one = <Poly as Ring>::one;
        match name {
            "n" => {
                return Ok(SymMultivector::blade(8, one()).add(&SymMultivector::blade(16, one())))
            }
            "nbar" | "n̄" => {
                return Ok(SymMultivector::blade(8, one()).sub(&SymMultivector::blade(16, one())))
            }
            "I" => return Ok(SymMultivector::blade(31, one())),
            _ => {}
        }
        if let Some(b) = parse_blade_word(name) {
            return Ok(b);
        }
        Ok(SymMultivector::scalar(Poly::var(name)))
    }
    /// Parses an expression; auxiliary symbols stay symbolic.
    pub fn parse(&self, text: &str) -> Result<SymMultivector, SymbolicError> {
        parse_with(text, &|n: &str| self.resolve(n))
    }
    /// Evaluates an expression with the caller's `products`: identifiers are looked up in
    /// `names` first (values the caller builds, for example conformal points from its own
    /// conventions), then as in [`Scope::parse`]. Juxtaposition is the geometric product, `∧`
    /// the outer product and `⌋` the left contraction.
    pub fn evaluate(
        &self,
        text: &str,
        products: &dyn Products,
        names: &dyn Fn(&str) -> Option<SymMultivector>,
    ) -> Result<SymMultivector, SymbolicError> {
        let resolve = |n: &str| -> Result<Evaluated<'_>, String> {
            let m = match names(n) {
                Some(m) => m,
                None => self.resolve(n)?,
            };
            Ok(Evaluated {
                m,
                products: Some(products),
            })
        };
        parse_with(text, &resolve).map(|v| v.m)
    }
    /// The fully expanded value (in point coordinates) of every auxiliary symbol (the last
    /// definition of each name).
    pub fn expansions(&self) -> Result<Vec<(String, Poly)>, SymbolicError> {
        let mut done: Vec<(String, Poly)> = Vec::new();
        for (name, text) in &self.defs {
            let v = self.parse(text)?;
            let v = v.subs_all(
                &done
                    .iter()
                    .map(|(n, p)| (n.as_str(), p.clone()))
                    .collect::<Vec<_>>(),
            );
            if v.iter().any(|(m, _)| m != 0) {
                return Err(SymbolicError::Parse {
                    input: text.clone(),
                    position: 0,
                    message: format!("auxiliary symbol `{name}` is not a scalar"),
                });
            }
            done.retain(|(n, _)| n != name);
            done.push((name.clone(), v.get(0)));
        }
        Ok(done)
    }
    /// Evaluates an expression exactly for rational values of the point coordinates: every
    /// auxiliary symbol is evaluated in turn (cheap even when its expansion would be huge).
    pub fn eval_rational(
        &self,
        text: &str,
        values: &[(&str, Rational)],
    ) -> Result<SymMultivector, SymbolicError> {
        let mut known: Vec<(String, Poly)> = values
            .iter()
            .map(|(n, v)| (n.to_string(), Poly::constant(v.clone())))
            .collect();
        let subs = |m: &SymMultivector, known: &[(String, Poly)]| {
            m.subs_all(
                &known
                    .iter()
                    .map(|(n, p)| (n.as_str(), p.clone()))
                    .collect::<Vec<_>>(),
            )
        };
        for (name, def) in &self.defs {
            let v = subs(&self.parse(def)?, &known);
            known.retain(|(n, _)| n != name);
            known.push((name.clone(), v.get(0)));
        }
        Ok(subs(&self.parse(text)?, &known))
    }
    /// Replaces every auxiliary symbol by its expansion in point coordinates (definitions may
    /// use earlier ones).
    pub fn expand(&self, m: &SymMultivector) -> Result<SymMultivector, SymbolicError> {
        let ex = self.expansions()?;
        Ok(m.subs_all(
            &ex.iter()
                .map(|(n, p)| (n.as_str(), p.clone()))
                .collect::<Vec<_>>(),
        ))
    }
}

/// The outcome of comparing a printed formula with the computed one.
#[derive(Clone, Debug, PartialEq)]
pub enum Comparison {
    /// Identical polynomials on every blade.
    Equal,
    /// `printed = factor · computed` for a rational factor other than 1.
    Scaled(Rational),
    /// Not proportional: the blades (thesis spelling) whose coefficients differ, with the
    /// printed and the computed coefficient (thesis sign convention).
    Differs(Vec<(String, Poly, Poly)>),
}

/// Compares a printed formula with the computed one.
pub fn compare(printed: &SymMultivector, computed: &SymMultivector) -> Comparison {
    if printed == computed {
        return Comparison::Equal;
    }
    if let Some(k) = printed.ratio_to(computed) {
        return Comparison::Scaled(k);
    }
    let mut diffs = Vec::new();
    for m in thesis_order() {
        let (a, b) = (printed.get(m), computed.get(m));
        if a != b {
            let (s, name) = thesis_name(m);
            let fix = |p: Poly| if s < 0 { -p } else { p };
            diffs.push((name, fix(a), fix(b)));
        }
    }
    Comparison::Differs(diffs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metric_and_names() {
        let s = Scope::new();
        assert_eq!(s.parse("ē ē").unwrap(), s.parse("-1").unwrap());
        assert_eq!(s.parse("n n").unwrap(), SymMultivector::zero());
        assert_eq!(s.parse("n̄ n̄").unwrap(), SymMultivector::zero());
        // n·n̄ = 2 (II table), n ∧ n̄ = -2 eē.
        let nn = s.parse("n nbar").unwrap();
        assert_eq!(nn.grade(0), s.parse("2").unwrap());
        assert_eq!(s.parse("n ∧ nbar").unwrap(), s.parse("-2 eē").unwrap());
        assert_eq!(s.parse("I I").unwrap(), s.parse("-1").unwrap());
        assert_eq!(thesis_name(0b00101), (-1, "e3e1".to_string()));
        assert_eq!(thesis_name(0b11000), (1, "eē".to_string()));
        assert_eq!(s.parse("e3e1ē").unwrap(), s.parse("-e1e3e5").unwrap());
        for m in 0u8..32 {
            let (sign, name) = thesis_name(m);
            let b = s.parse(&name).unwrap();
            assert_eq!(b.get(m), Poly::from(i64::from(sign)), "{name}");
        }
    }

    #[test]
    fn null_basis_printing_and_helpers() {
        let s = Scope::new();
        for text in [
            "n",
            "n̄",
            "n ∧ n̄",
            "e1 ∧ n",
            "e3e1 ∧ n̄",
            "3 e1e2e3 ∧ n ∧ n̄ + e2",
            "x e1e2e + y e2eē - z e3e1ē + 2 e",
        ] {
            let m = s.parse(text).unwrap();
            let printed = m.to_notation(Notation::ThesisNull);
            assert_eq!(s.parse(&printed).unwrap(), m, "{text} printed as {printed}");
            let printed = m.to_notation(Notation::Thesis);
            assert_eq!(s.parse(&printed).unwrap(), m, "{text} printed as {printed}");
        }
        assert_eq!(s.parse("nn̄").unwrap(), s.parse("-2 eē").unwrap());
        let p = SymMultivector::thesis_point([Poly::var("a1"), Poly::var("a2"), Poly::var("a3")]);
        assert_eq!(
            p,
            s.parse("2(a1 e1 + a2 e2 + a3 e3) + (a1^2 + a2^2 + a3^2) n - n̄")
                .unwrap()
        );
        assert!(p.gp(&p).is_zero(), "points are null");
        let l = s.parse("e1e2e").unwrap();
        assert_eq!(l.thesis_dual(), s.parse("I e1e2e").unwrap());
    }

    #[test]
    fn latex_in_thesis_notation() {
        let s = Scope::new();
        let m = s.parse("(alpha1 - 1/2) e1e2e - beta4 e3e1ē").unwrap();
        assert_eq!(
            m.to_latex(Notation::Thesis),
            "\\left(\\alpha_{1} - \\frac{1}{2}\\right) e_{1}e_{2}e - \\beta_{4} e_{3}e_{1}\\bar{e}"
        );
        assert_eq!(
            m.to_notation(Notation::Thesis),
            "(alpha1 - 1/2) e1e2e - beta4 e3e1ē"
        );
    }

    /// Counts the products it is asked for, and computes them with the sparse ones.
    struct Counting(std::cell::Cell<usize>);
    impl Products for Counting {
        fn geometric(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
            self.0.set(self.0.get() + 1);
            a.gp(b)
        }
        fn wedge(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
            self.0.set(self.0.get() + 1);
            a.wedge(b)
        }
        fn left_contraction(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
            self.0.set(self.0.get() + 1);
            a.left_contraction(b)
        }
    }

    #[test]
    fn evaluate_uses_the_callers_products_and_names() {
        let s = Scope::new();
        let p = Counting(std::cell::Cell::new(0));
        let names = |n: &str| (n == "Q").then(|| s.parse("e1 + e").unwrap());
        // (e1 + e) ⌋ (e1 ∧ e2) = e2; scalars only scale and need no product.
        let v = s.evaluate("2 Q ⌋ (e1 ∧ e2)", &p, &names).unwrap();
        assert_eq!(v, s.parse("2 e2").unwrap());
        assert_eq!(p.0.get(), 2, "one outer product and one contraction");
        assert_eq!(
            s.evaluate("e1 ⌋ 3", &p, &names).unwrap(),
            SymMultivector::zero()
        );
        assert_eq!(s.parse("e1 ⌋ e1e2").unwrap(), s.parse("e2").unwrap());
        assert!(s.evaluate("Q ⌋", &p, &names).is_err());
    }

    #[test]
    fn defs_expand() {
        let mut s = Scope::new();
        s.point("x1", ["a1", "a2", "a3"])
            .define("k", "x1^2 + 1")
            .define("j", "2k");
        let v = s.parse("j e1").unwrap();
        let ex = s.expand(&v).unwrap();
        assert_eq!(ex, s.parse("2(a1^2 + a2^2 + a3^2 + 1) e1").unwrap());
        assert!(s.define("bad", "e1").expansions().is_err());
    }
}

/// One entry of a formula fixture: an equation of the thesis as printed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The equation number (`II.53`).
    pub id: String,
    /// A short title.
    pub title: String,
    /// The `key = value` fields in file order (`source`, `kind`, `formula`, `cases`, `note`,
    /// `uses`); continuation lines are joined with a space.
    pub fields: Vec<(String, String)>,
    /// The auxiliary symbols defined by `let` lines, in order.
    pub lets: Vec<(String, String)>,
    /// The 1-based line of the `[ID]` header.
    pub line: usize,
}

impl Entry {
    /// The first value of a field.
    pub fn field(&self, key: &str) -> Option<&str> {
        self.fields
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// Errors reading a fixture.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FixtureError {
    /// A line that is not a header, a `key = value`, a `let`, a `point` or a continuation.
    #[error("line {line}: {message}")]
    Syntax {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// `uses` names an entry that does not exist.
    #[error("entry {entry} uses unknown entry {missing}; define an entry `[{missing}]` in the fixture or fix the `uses` field")]
    UnknownEntry {
        /// The entry with the `uses` field.
        entry: String,
        /// The missing id.
        missing: String,
    },
}

/// A fixture of transcribed formulas (format documented at the top of
/// `ga-core/tests/fixtures/thesis_formulas.txt`).
#[derive(Clone, Debug, Default)]
pub struct Fixture {
    /// Declared points `(name, [coordinate variables])`.
    pub points: Vec<(String, [String; 3])>,
    /// The entries in file order.
    pub entries: Vec<Entry>,
}

impl Fixture {
    /// Parses the fixture text.
    ///
    /// ```
    /// use ga_core::symbolic::thesis::Fixture;
    /// let f = Fixture::parse("point x = a1 a2 a3\n[E1] A point\nformula = 2x + x^2 n\n  - nbar\n").unwrap();
    /// assert_eq!(f.entries[0].field("formula"), Some("2x + x^2 n - nbar"));
    /// ```
    pub fn parse(text: &str) -> Result<Fixture, FixtureError> {
        let mut fx = Fixture::default();
        // Target of continuation lines: (is_let, index).
        let mut last: Option<(bool, usize)> = None;
        for (i, raw) in text.lines().enumerate() {
            let line_no = i + 1;
            let syntax = |m: &str| FixtureError::Syntax {
                line: line_no,
                message: m.to_string(),
            };
            let trimmed = raw.trim();
            if trimmed.is_empty() || trimmed.starts_with('#') {
                continue;
            }
            if raw.starts_with(char::is_whitespace) {
                let entry = fx
                    .entries
                    .last_mut()
                    .ok_or_else(|| syntax("continuation line outside an entry"))?;
                let target = match last {
                    Some((true, k)) => &mut entry.lets[k].1,
                    Some((false, k)) => &mut entry.fields[k].1,
                    None => return Err(syntax("continuation line without a key")),
                };
                target.push(' ');
                target.push_str(trimmed);
                continue;
            }
            if let Some(rest) = trimmed.strip_prefix('[') {
                let (id, title) = rest
                    .split_once(']')
                    .ok_or_else(|| syntax("header without `]`"))?;
                fx.entries.push(Entry {
                    id: id.trim().to_string(),
                    title: title.trim().to_string(),
                    fields: Vec::new(),
                    lets: Vec::new(),
                    line: line_no,
                });
                last = None;
                continue;
            }
            if let Some(rest) = trimmed.strip_prefix("point ") {
                let (name, coords) = rest
                    .split_once('=')
                    .ok_or_else(|| syntax("`point NAME = C1 C2 C3` expected"))?;
                let c: Vec<&str> = coords.split_whitespace().collect();
                if c.len() != 3 {
                    return Err(syntax("a point needs three coordinate names"));
                }
                fx.points.push((
                    name.trim().to_string(),
                    [c[0].to_string(), c[1].to_string(), c[2].to_string()],
                ));
                last = None;
                continue;
            }
            let entry = fx
                .entries
                .last_mut()
                .ok_or_else(|| syntax("field outside an entry"))?;
            if let Some(rest) = trimmed.strip_prefix("let ") {
                let (name, expr) = rest
                    .split_once('=')
                    .ok_or_else(|| syntax("`let NAME = EXPR` expected"))?;
                entry
                    .lets
                    .push((name.trim().to_string(), expr.trim().to_string()));
                last = Some((true, entry.lets.len() - 1));
                continue;
            }
            let (key, value) = trimmed
                .split_once('=')
                .ok_or_else(|| syntax("`key = value` expected"))?;
            entry
                .fields
                .push((key.trim().to_string(), value.trim().to_string()));
            last = Some((false, entry.fields.len() - 1));
        }
        for e in &fx.entries {
            for u in fx.uses(e) {
                if fx.entry(&u).is_none() {
                    return Err(FixtureError::UnknownEntry {
                        entry: e.id.clone(),
                        missing: u,
                    });
                }
            }
        }
        Ok(fx)
    }

    /// The entry with this id.
    pub fn entry(&self, id: &str) -> Option<&Entry> {
        self.entries.iter().find(|e| e.id == id)
    }

    fn uses(&self, e: &Entry) -> Vec<String> {
        e.field("uses")
            .map(|u| {
                u.split(',')
                    .map(|s| s.trim().to_string())
                    .filter(|s| !s.is_empty())
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The scope of an entry: every point, then the `let`s of the entries it `uses`
    /// (transitively, depth first), then its own.
    pub fn scope(&self, e: &Entry) -> Scope {
        let mut s = Scope::new();
        for (name, c) in &self.points {
            s.point(name, [&c[0], &c[1], &c[2]]);
        }
        let mut seen = Vec::new();
        self.add_lets(e, &mut s, &mut seen);
        s
    }

    fn add_lets(&self, e: &Entry, s: &mut Scope, seen: &mut Vec<String>) {
        if seen.contains(&e.id) {
            return;
        }
        seen.push(e.id.clone());
        for u in self.uses(e) {
            if let Some(d) = self.entry(&u) {
                self.add_lets(d, s, seen);
            }
        }
        for (n, x) in &e.lets {
            s.define(n, x);
        }
    }
}
