//! Symbolic scalars: multivariate polynomials with exact rational coefficients.
//!
//! [`Poly`] implements [`Ring`](crate::scalar::Ring), so every generated product runs on it and expands formulas
//! symbolically. Polynomials are kept in a canonical form (terms sorted by monomial, no zero
//! coefficients), so `==` is structural equality of the mathematical polynomials.
//!
//! Variables are created by name ([`Poly::var`]); names are interned process-wide, so a
//! monomial is a short sorted vector of `(variable id, exponent)` pairs.
//!
//! # Expanding your own expression
//!
//! ```
//! use ga_core::symbolic::Poly;
//! let (x, y) = (Poly::var("x"), Poly::var("y"));
//! let p = (x.clone() + y.clone()) * (x.clone() - y.clone());
//! assert_eq!(p, Poly::parse("x^2 - y^2").unwrap());
//! assert_eq!(p.to_string(), "x^2 - y^2");
//! assert_eq!(p.subs("y", &Poly::from(2)).eval_f64(&[("x", 3.0)]).unwrap(), 5.0);
//! ```
//!
//! The same works for multivectors of the generated algebras, whose coefficients may be any
//! [`Ring`](crate::scalar::Ring): build them from `Poly` coefficients and use the products as usual. Expanding
//! `a ∧ b` for two symbolic conformal vectors, printed plainly and in LaTeX:
//!
//! ```
//! use ga_core::{cga::Vector, prelude::*, symbolic::Poly};
//! let v = |s: &str| Vector::new(Poly::var(&format!("{s}1")), Poly::var(&format!("{s}2")), Poly::var(&format!("{s}3")), Poly::var(&format!("{s}4")), Poly::var(&format!("{s}5")));
//! let ab = v("a").wedge(&v("b"));                       // a Bivector<Poly>, fully expanded
//! println!("{ab}\n{}", ab.e12.to_latex());             // (a1*b2 - a2*b1)·e12 + ...
//! assert_eq!(ab.e12, Poly::parse("a1*b2 - a2*b1").unwrap());
//! ```
//!
//! # Parsing expressions over your own values
//!
//! [`Poly::parse`]'s grammar (sums, products by juxtaposition, `/` by constants, `^`, `∧`, `⌋`)
//! is available for any value type implementing [`parse::ExprValue`], with identifiers resolved by
//! the caller: [`parse::parse_with`]. A multivector type can read formulas written in its own basis names
//! this way without a parser of its own.

pub mod parse;

use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};
use std::collections::HashMap;
use std::sync::{OnceLock, RwLock};

use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::scalar::{Rational, Ring as RingTrait};

/// Errors of the symbolic module: evaluation with missing values, parse errors.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SymbolicError {
    /// A variable of the polynomial has no value in the bindings given to an evaluation.
    #[error("variable `{0}` has no value in the bindings; add (\"{0}\", value) to the values passed to the evaluation")]
    Unbound(String),
    /// Evaluation produced a non-finite `f64` (overflow).
    #[error("evaluation overflowed to a non-finite f64; scale the values down, or evaluate exactly with eval_rational")]
    NonFinite,
    /// Text that is not a polynomial (or multivector) expression.
    #[error("parse error at byte {position} of `{input}`: {message}")]
    Parse {
        /// The whole input.
        input: String,
        /// Byte offset of the offending token.
        position: usize,
        /// What was wrong.
        message: String,
    },
}

// ---------------------------------------------------------------------------------------------
// Variable interning.

#[derive(Default)]
struct Interner {
    names: Vec<String>,
    ids: HashMap<String, u32>,
}

fn interner() -> &'static RwLock<Interner> {
    static INTERNER: OnceLock<RwLock<Interner>> = OnceLock::new();
    INTERNER.get_or_init(Default::default)
}

fn intern(name: &str) -> u32 {
    {
        let r = interner().read().unwrap_or_else(|e| e.into_inner());
        if let Some(&id) = r.ids.get(name) {
            return id;
        }
    }
    let mut w = interner().write().unwrap_or_else(|e| e.into_inner());
    if let Some(&id) = w.ids.get(name) {
        return id;
    }
    let id = u32::try_from(w.names.len()).expect("fewer than 2^32 variables");
    w.names.push(name.to_owned());
    w.ids.insert(name.to_owned(), id);
    id
}

fn lookup(name: &str) -> Option<u32> {
    let r = interner().read().unwrap_or_else(|e| e.into_inner());
    r.ids.get(name).copied()
}

fn var_name(id: u32) -> String {
    let r = interner().read().unwrap_or_else(|e| e.into_inner());
    r.names[id as usize].clone()
}

// ---------------------------------------------------------------------------------------------
// Monomials.

/// A monomial: variable ids (interned) with positive exponents, sorted by id.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Debug, Default)]
struct Monomial(Box<[(u32, u32)]>);

impl Monomial {
    fn one() -> Self {
        Monomial(Box::new([]))
    }
    fn mul(&self, other: &Monomial) -> Monomial {
        let (a, b) = (&self.0, &other.0);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                Ordering::Less => {
                    out.push(a[i]);
                    i += 1;
                }
                Ordering::Greater => {
                    out.push(b[j]);
                    j += 1;
                }
                Ordering::Equal => {
                    out.push((a[i].0, a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Monomial(out.into_boxed_slice())
    }
    fn degree(&self) -> u32 {
        self.0.iter().map(|&(_, e)| e).sum()
    }
}

// ---------------------------------------------------------------------------------------------
// Polynomials.

/// A multivariate polynomial with exact rational coefficients over named variables.
///
/// Canonical: terms sorted by monomial with no zero coefficient, so the derived `==` and
/// `Hash` are those of the polynomial itself.
///
/// ```
/// use ga_core::symbolic::Poly;
/// use ga_core::scalar::Ring;
/// let x = Poly::var("x");
/// let p = x.clone() * x.clone() - Poly::from_i64(1);
/// assert_eq!(p, (x.clone() - Poly::one()) * (x + Poly::one()));
/// assert_eq!(p.to_latex(), "x^{2} - 1");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    terms: Vec<(Monomial, Rational)>,
}

impl Poly {
    /// The variable called `name` (any string; interned process-wide).
    pub fn var(name: &str) -> Poly {
        let id = intern(name);
        Poly {
            terms: vec![(Monomial(Box::new([(id, 1)])), <Rational as One>::one())],
        }
    }

    /// The constant polynomial `c`.
    pub fn constant(c: Rational) -> Poly {
        if Zero::is_zero(&c) {
            Poly::default()
        } else {
            Poly {
                terms: vec![(Monomial::one(), c)],
            }
        }
    }

    /// The constant `numer / denom`, or `None` if `denom` is zero.
    pub fn ratio(numer: i64, denom: i64) -> Option<Poly> {
        if denom == 0 {
            return None;
        }
        Some(Poly::constant(Rational::new(
            BigInt::from(numer),
            BigInt::from(denom),
        )))
    }

    /// Parses a polynomial such as `3*x^2 - y/2 + (a1 - b1)*(a2 + 1)`: integers, decimal
    /// fractions, variables (letters, digits, `_`), `+ - * /` (division by constants only),
    /// `^` with a non-negative integer exponent, parentheses; juxtaposition multiplies.
    pub fn parse(text: &str) -> Result<Poly, SymbolicError> {
        parse::parse_poly(text)
    }

    /// Number of (nonzero) terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// Total degree (0 for constants, including zero).
    pub fn degree(&self) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| m.degree())
            .max()
            .unwrap_or(0)
    }

    /// The value if the polynomial is a constant (zero included).
    pub fn as_constant(&self) -> Option<Rational> {
        match self.terms.as_slice() {
            [] => Some(<Rational as Zero>::zero()),
            [(m, c)] if m.0.is_empty() => Some(c.clone()),
            _ => None,
        }
    }

    /// Names of the variables that occur, sorted.
    pub fn variables(&self) -> Vec<String> {
        let mut ids: Vec<u32> = self
            .terms
            .iter()
            .flat_map(|(m, _)| m.0.iter().map(|&(v, _)| v))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let mut names: Vec<String> = ids.into_iter().map(var_name).collect();
        names.sort();
        names
    }

    /// The terms as `(coefficient, [(variable, exponent)])`, in display order.
    pub fn terms(&self) -> Vec<(Rational, Vec<(String, u32)>)> {
        let mut out: Vec<(Rational, Vec<(String, u32)>)> = self
            .terms
            .iter()
            .map(|(m, c)| {
                let mut vars: Vec<(String, u32)> =
                    m.0.iter().map(|&(v, e)| (var_name(v), e)).collect();
                vars.sort_by(|a, b| natural_cmp(&a.0, &b.0));
                (c.clone(), vars)
            })
            .collect();
        out.sort_by(|a, b| display_cmp(&a.1, &b.1));
        out
    }

    /// `self` raised to the power `k`.
    pub fn pow(&self, k: u32) -> Poly {
        let mut result = <Poly as RingTrait>::one();
        let mut base = self.clone();
        let mut k = k;
        while k > 0 {
            if k & 1 == 1 {
                result = &result * &base;
            }
            k >>= 1;
            if k > 0 {
                base = &base * &base;
            }
        }
        result
    }

    /// Multiplies every coefficient by the constant `c`.
    pub fn scale(&self, c: &Rational) -> Poly {
        if Zero::is_zero(c) {
            return Poly::default();
        }
        Poly {
            terms: self.terms.iter().map(|(m, k)| (m.clone(), k * c)).collect(),
        }
    }

    /// Replaces the variable `name` by `value` everywhere.
    pub fn subs(&self, name: &str, value: &Poly) -> Poly {
        self.subs_all(&[(name, value.clone())])
    }

    /// Simultaneous substitution: every listed variable is replaced by its polynomial (the
    /// replacements are not themselves substituted again).
    pub fn subs_all(&self, values: &[(&str, Poly)]) -> Poly {
        let map: HashMap<u32, &Poly> = values
            .iter()
            .filter_map(|(n, p)| lookup(n).map(|id| (id, p)))
            .collect();
        if map.is_empty() {
            return self.clone();
        }
        let mut powers: HashMap<(u32, u32), Poly> = HashMap::new();
        let mut acc: Vec<(Monomial, Rational)> = Vec::new();
        let mut replaced: Vec<Poly> = Vec::new();
        for (m, c) in &self.terms {
            let mut kept = Vec::new();
            let mut factor: Option<Poly> = None;
            for &(v, e) in m.0.iter() {
                if let Some(p) = map.get(&v) {
                    let pw = powers.entry((v, e)).or_insert_with(|| p.pow(e)).clone();
                    factor = Some(match factor {
                        None => pw,
                        Some(f) => &f * &pw,
                    });
                } else {
                    kept.push((v, e));
                }
            }
            let mono = Monomial(kept.into_boxed_slice());
            match factor {
                None => acc.push((mono, c.clone())),
                Some(f) => {
                    let t = Poly {
                        terms: vec![(mono, c.clone())],
                    };
                    replaced.push(&t * &f);
                }
            }
        }
        let mut all = acc;
        for p in replaced {
            all.extend(p.terms);
        }
        Poly::from_unsorted(all)
    }

    /// Evaluates with exact rationals; every variable must be bound.
    pub fn eval_rational(&self, values: &[(&str, Rational)]) -> Result<Rational, SymbolicError> {
        let map: HashMap<u32, &Rational> = values
            .iter()
            .filter_map(|(n, v)| lookup(n).map(|id| (id, v)))
            .collect();
        let mut sum = <Rational as Zero>::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for &(v, e) in m.0.iter() {
                let x = map
                    .get(&v)
                    .ok_or_else(|| SymbolicError::Unbound(var_name(v)))?;
                t *= num_traits::pow::pow((*x).clone(), e as usize);
            }
            sum += t;
        }
        Ok(sum)
    }

    /// Evaluates in `f64`; every variable must be bound.
    pub fn eval_f64(&self, values: &[(&str, f64)]) -> Result<f64, SymbolicError> {
        let map: HashMap<u32, f64> = values
            .iter()
            .filter_map(|(n, v)| lookup(n).map(|id| (id, *v)))
            .collect();
        let mut sum = 0.0;
        for (m, c) in &self.terms {
            let mut t = c.to_f64().unwrap_or(f64::NAN);
            for &(v, e) in m.0.iter() {
                let x = map
                    .get(&v)
                    .ok_or_else(|| SymbolicError::Unbound(var_name(v)))?;
                t *= x.powi(e as i32);
            }
            sum += t;
        }
        if sum.is_finite() {
            Ok(sum)
        } else {
            Err(SymbolicError::NonFinite)
        }
    }

    /// Plain-text form, as [`Display`](fmt::Display): `3*a1*b2^2 - 1/2*c`.
    pub fn to_plain(&self) -> String {
        self.to_string()
    }

    /// LaTeX form: `3 a_{1} b_{2}^{2} - \frac{1}{2} c`; names such as `alpha12` become
    /// `\alpha_{12}`.
    pub fn to_latex(&self) -> String {
        let mut s = String::new();
        write_poly(&mut s, self, Style::Latex);
        s
    }

    /// The constant `c` with `self == c * other`, if there is one (`None` when either side is
    /// zero or they are not proportional).
    pub fn ratio_to(&self, other: &Poly) -> Option<Rational> {
        if self.terms.len() != other.terms.len() || self.terms.is_empty() {
            return None;
        }
        let c = &self.terms[0].1 / &other.terms[0].1;
        for ((m1, c1), (m2, c2)) in self.terms.iter().zip(&other.terms) {
            if m1 != m2 || *c1 != c2 * &c {
                return None;
            }
        }
        Some(c)
    }

    fn from_unsorted(mut terms: Vec<(Monomial, Rational)>) -> Poly {
        terms.sort_unstable_by(|a, b| a.0.cmp(&b.0));
        let mut out: Vec<(Monomial, Rational)> = Vec::with_capacity(terms.len());
        for (m, c) in terms {
            match out.last_mut() {
                Some((lm, lc)) if *lm == m => *lc += c,
                _ => {
                    if let Some((_, lc)) = out.last() {
                        if Zero::is_zero(lc) {
                            out.pop();
                        }
                    }
                    out.push((m, c));
                }
            }
        }
        if let Some((_, lc)) = out.last() {
            if Zero::is_zero(lc) {
                out.pop();
            }
        }
        Poly { terms: out }
    }

    fn merge(&self, other: &Poly, negate_other: bool) -> Poly {
        let (a, b) = (&self.terms, &other.terms);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        let neg = |c: &Rational| if negate_other { -c } else { c.clone() };
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                Ordering::Less => {
                    out.push(a[i].clone());
                    i += 1;
                }
                Ordering::Greater => {
                    out.push((b[j].0.clone(), neg(&b[j].1)));
                    j += 1;
                }
                Ordering::Equal => {
                    let c = &a[i].1 + neg(&b[j].1);
                    if !Zero::is_zero(&c) {
                        out.push((a[i].0.clone(), c));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend(a[i..].iter().cloned());
        out.extend(b[j..].iter().map(|(m, c)| (m.clone(), neg(c))));
        Poly { terms: out }
    }

    /// The integer coefficients as `i64`, if every coefficient is an integer that fits.
    fn small_integer_coefficients(&self) -> Option<Vec<i64>> {
        self.terms
            .iter()
            .map(|(_, c)| {
                if c.is_integer() {
                    c.numer().to_i64()
                } else {
                    None
                }
            })
            .collect()
    }

    /// Fast path of the product when every coefficient is a small integer: `i128`
    /// accumulation, `None` (use the exact general path) if anything could overflow.
    fn mul_small_integers(&self, other: &Poly) -> Option<Poly> {
        let a = self.small_integer_coefficients()?;
        let b = other.small_integer_coefficients()?;
        let max_a = a.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0) as u128;
        let max_b = b.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0) as u128;
        // |sum| ≤ n_a · n_b · max_a · max_b must stay below 2^126.
        let bound = max_a
            .checked_mul(max_b)?
            .checked_mul(a.len() as u128)?
            .checked_mul(b.len() as u128)?;
        if bound >= 1u128 << 126 {
            return None;
        }
        let mut acc: HashMap<Monomial, i128> =
            HashMap::with_capacity(self.terms.len() * other.terms.len() / 2 + 1);
        for ((m1, _), c1) in self.terms.iter().zip(&a) {
            for ((m2, _), c2) in other.terms.iter().zip(&b) {
                *acc.entry(m1.mul(m2)).or_insert(0) += i128::from(*c1) * i128::from(*c2);
            }
        }
        let mut terms: Vec<(Monomial, Rational)> = acc
            .into_iter()
            .filter(|(_, c)| *c != 0)
            .map(|(m, c)| (m, Rational::from_integer(BigInt::from(c))))
            .collect();
        terms.sort_unstable_by(|x, y| x.0.cmp(&y.0));
        Some(Poly { terms })
    }

    fn mul_ref(&self, other: &Poly) -> Poly {
        if self.terms.is_empty() || other.terms.is_empty() {
            return Poly::default();
        }
        if self.terms.len() == 1 || other.terms.len() == 1 {
            // Multiplying by one term keeps monomials distinct, but not necessarily in order.
            let (single, many) = if self.terms.len() == 1 {
                (&self.terms[0], other)
            } else {
                (&other.terms[0], self)
            };
            let mut terms: Vec<(Monomial, Rational)> = many
                .terms
                .iter()
                .map(|(m, c)| (m.mul(&single.0), c * &single.1))
                .collect();
            terms.sort_unstable_by(|a, b| a.0.cmp(&b.0));
            return Poly { terms };
        }
        if let Some(p) = self.mul_small_integers(other) {
            return p;
        }
        let mut acc: HashMap<Monomial, Rational> =
            HashMap::with_capacity(self.terms.len() * other.terms.len() / 2 + 1);
        for (m1, c1) in &self.terms {
            for (m2, c2) in &other.terms {
                let c = c1 * c2;
                match acc.entry(m1.mul(m2)) {
                    std::collections::hash_map::Entry::Occupied(mut e) => *e.get_mut() += c,
                    std::collections::hash_map::Entry::Vacant(e) => {
                        e.insert(c);
                    }
                }
            }
        }
        let mut terms: Vec<(Monomial, Rational)> =
            acc.into_iter().filter(|(_, c)| !Zero::is_zero(c)).collect();
        terms.sort_unstable_by(|a, b| a.0.cmp(&b.0));
        Poly { terms }
    }
}

impl RingTrait for Poly {
    fn zero() -> Self {
        Poly::default()
    }
    fn one() -> Self {
        Poly::constant(<Rational as One>::one())
    }
    fn from_i64(n: i64) -> Self {
        Poly::constant(Rational::from_integer(BigInt::from(n)))
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}

impl From<i64> for Poly {
    fn from(n: i64) -> Poly {
        <Poly as RingTrait>::from_i64(n)
    }
}

impl From<Rational> for Poly {
    fn from(c: Rational) -> Poly {
        Poly::constant(c)
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $body:expr) => {
        impl $tr<&Poly> for &Poly {
            type Output = Poly;
            fn $m(self, rhs: &Poly) -> Poly {
                let f: fn(&Poly, &Poly) -> Poly = $body;
                f(self, rhs)
            }
        }
        impl $tr<Poly> for Poly {
            type Output = Poly;
            fn $m(self, rhs: Poly) -> Poly {
                (&self).$m(&rhs)
            }
        }
        impl $tr<&Poly> for Poly {
            type Output = Poly;
            fn $m(self, rhs: &Poly) -> Poly {
                (&self).$m(rhs)
            }
        }
        impl $tr<Poly> for &Poly {
            type Output = Poly;
            fn $m(self, rhs: Poly) -> Poly {
                self.$m(&rhs)
            }
        }
    };
}
binop!(Add, add, |a, b| a.merge(b, false));
binop!(Sub, sub, |a, b| a.merge(b, true));
binop!(Mul, mul, |a, b| a.mul_ref(b));

impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for (_, c) in &mut self.terms {
            *c = -core::mem::take(c);
        }
        self
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        -self.clone()
    }
}

impl AddAssign<&Poly> for Poly {
    fn add_assign(&mut self, rhs: &Poly) {
        *self = self.merge(rhs, false);
    }
}

impl SubAssign<&Poly> for Poly {
    fn sub_assign(&mut self, rhs: &Poly) {
        *self = self.merge(rhs, true);
    }
}

impl core::iter::Sum for Poly {
    fn sum<I: Iterator<Item = Poly>>(iter: I) -> Poly {
        iter.fold(Poly::default(), |a, b| a + b)
    }
}

// ---------------------------------------------------------------------------------------------
// Printing.

/// Compares names so that `a2 < a10` (digit runs compare by value).
fn natural_cmp(a: &str, b: &str) -> Ordering {
    let (pa, na) = split_name(a);
    let (pb, nb) = split_name(b);
    pa.cmp(pb)
        .then_with(|| {
            let va = na.parse::<u64>().unwrap_or(0);
            let vb = nb.parse::<u64>().unwrap_or(0);
            (!na.is_empty(), va).cmp(&(!nb.is_empty(), vb))
        })
        .then_with(|| a.cmp(b))
}

/// Splits `alpha124` into (`alpha`, `124`).
fn split_name(name: &str) -> (&str, &str) {
    let cut = name
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_ascii_digit())
        .last()
        .map(|(i, _)| i)
        .unwrap_or(name.len());
    name.split_at(cut)
}

fn display_cmp(a: &[(String, u32)], b: &[(String, u32)]) -> Ordering {
    // Constants last; otherwise lexicographic on (name, higher exponent first).
    match (a.is_empty(), b.is_empty()) {
        (true, false) => return Ordering::Greater,
        (false, true) => return Ordering::Less,
        _ => {}
    }
    for (x, y) in a.iter().zip(b) {
        let o = natural_cmp(&x.0, &y.0).then(y.1.cmp(&x.1));
        if o != Ordering::Equal {
            return o;
        }
    }
    a.len().cmp(&b.len())
}

#[derive(Clone, Copy, PartialEq)]
pub(crate) enum Style {
    Plain,
    Latex,
}

const GREEK: [&str; 14] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "theta", "lambda", "mu", "nu", "pi", "rho",
    "sigma", "tau", "omega",
];

/// LaTeX for a variable name: `a1` → `a_{1}`, `alpha124` → `\alpha_{124}`.
pub(crate) fn latex_name(name: &str) -> String {
    let (prefix, digits) = split_name(name);
    let head = if GREEK.contains(&prefix) {
        format!("\\{prefix}")
    } else if prefix.chars().count() > 1 && prefix.chars().all(|c| c.is_ascii_alphabetic()) {
        format!("\\mathit{{{prefix}}}")
    } else {
        prefix.to_string()
    };
    if digits.is_empty() {
        head
    } else {
        format!("{head}_{{{digits}}}")
    }
}

fn write_rational(out: &mut String, c: &Rational, style: Style) {
    if c.is_integer() {
        out.push_str(&c.numer().to_string());
    } else if style == Style::Latex {
        out.push_str(&format!("\\frac{{{}}}{{{}}}", c.numer(), c.denom()));
    } else {
        out.push_str(&format!("{}/{}", c.numer(), c.denom()));
    }
}

pub(crate) fn write_poly(out: &mut String, p: &Poly, style: Style) {
    let terms = p.terms();
    if terms.is_empty() {
        out.push('0');
        return;
    }
    for (i, (c, vars)) in terms.iter().enumerate() {
        let neg = c.is_negative();
        let a = c.abs();
        if i == 0 {
            if neg {
                out.push('-');
            }
        } else {
            out.push_str(if neg { " - " } else { " + " });
        }
        let unit = One::is_one(&a);
        if !unit || vars.is_empty() {
            write_rational(out, &a, style);
        }
        for (k, (name, e)) in vars.iter().enumerate() {
            if k > 0 || !unit {
                out.push_str(if style == Style::Latex { " " } else { "*" });
            }
            match style {
                Style::Plain => out.push_str(name),
                Style::Latex => out.push_str(&latex_name(name)),
            }
            if *e > 1 {
                match style {
                    Style::Plain => out.push_str(&format!("^{e}")),
                    Style::Latex => out.push_str(&format!("^{{{e}}}")),
                }
            }
        }
    }
}

impl Poly {
    /// Whether the printed form needs parentheses when multiplied (more than one term, or a
    /// negative single term).
    pub fn needs_parens(&self) -> bool {
        self.terms.len() > 1
    }
}

impl fmt::Display for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut s = String::new();
        write_poly(&mut s, self, Style::Plain);
        f.write_str(&s)
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;

    fn p(s: &str) -> Poly {
        Poly::parse(s).unwrap()
    }

    #[test]
    fn canonical_equality() {
        assert_eq!(p("x*y + 1 - 1"), p("y*x"));
        assert_eq!(p("(a+b)^2"), p("a^2 + 2*a*b + b^2"));
        assert!(p("x - x").is_zero());
        assert_eq!(p("x/2 + x/2"), p("x"));
    }

    #[test]
    fn single_term_products_stay_canonical() {
        // x < y in id order, but x·x vs y·x compare the other way round.
        let (x, y) = (Poly::var("canon_x"), Poly::var("canon_y"));
        let s = &x + &y;
        assert_eq!(&s * &x, &(&x * &x) + &(&y * &x));
        assert_eq!(&x * &s, &(&x * &y) + &(&x * &x));
    }

    #[test]
    fn large_coefficients_take_the_exact_path() {
        let big = Poly::parse("4611686018427387904 x + 4611686018427387903 y - 1/3").unwrap();
        let sq = &big * &big;
        let at = [
            ("x", Rational::from_integer(3.into())),
            ("y", Rational::new((-5).into(), 7.into())),
        ];
        let v = big.eval_rational(&at).unwrap();
        assert_eq!(sq.eval_rational(&at).unwrap(), &v * &v);
        let ints = Poly::parse("4611686018427387904 x + 4611686018427387903 y").unwrap();
        let sq = &ints * &ints;
        let v = ints.eval_rational(&at).unwrap();
        assert_eq!(sq.eval_rational(&at).unwrap(), &v * &v);
    }

    #[test]
    fn printing() {
        assert_eq!(
            p("a2 + a10 - 3*b^2*a1 + 1/2").to_string(),
            "-3*a1*b^2 + a2 + a10 + 1/2"
        );
        assert_eq!(p("-x").to_string(), "-x");
        assert_eq!(Poly::zero().to_string(), "0");
        assert_eq!(
            p("alpha12*mu3 - x^2/3").to_latex(),
            "\\alpha_{12} \\mu_{3} - \\frac{1}{3} x^{2}"
        );
    }

    #[test]
    fn substitution_and_eval() {
        let q = p("x^2*y + y");
        assert_eq!(q.subs("y", &p("x+1")), p("x^3 + x^2 + x + 1"));
        assert_eq!(q.subs_all(&[("x", p("y")), ("y", p("x"))]), p("y^2*x + x"));
        let r = q
            .eval_rational(&[
                ("x", Rational::from_integer(2.into())),
                ("y", Rational::new(1.into(), 3.into())),
            ])
            .unwrap();
        assert_eq!(r, Rational::new(5.into(), 3.into()));
        assert_eq!(
            q.eval_f64(&[("x", 2.0)]),
            Err(SymbolicError::Unbound("y".into()))
        );
    }
}
