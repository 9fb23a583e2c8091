//! [`Scope`]: reads multivector expressions written in the thesis's notation.
//!
//! Identifiers are the thesis's names (points, auxiliary scalars such as `α124`, `n`, `n̄`, `I`,
//! words of basis symbols such as `e3e1ē`); the grammar is `ga_core::symbolic`'s
//! ([`parse_with`]). [`Scope::evaluate`] takes the products from the caller, so that a check
//! computes with the generated `cga` code while printed formulas are read with
//! [`SymMultivector`]'s own products.

use std::collections::HashMap;

use ga_core::scalar::{Rational, Ring};
use ga_core::symbolic::parse::{parse_with, ExprValue};
use ga_core::symbolic::{Poly, SymbolicError};
use num_traits::Zero;

use crate::multivector::SymMultivector;

impl ExprValue for SymMultivector {
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

impl ExprValue for Evaluated<'_> {
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
        <SymMultivector as ExprValue>::as_constant(&self.m)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::notation::thesis_name;

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
}
