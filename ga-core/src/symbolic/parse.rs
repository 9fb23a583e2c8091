//! A small expression parser shared by [`Poly::parse`](super::Poly::parse) and by callers that
//! compute with values of their own (multivectors, say): one grammar, any value type that
//! implements [`ExprValue`], identifiers resolved by the caller ([`parse_with`]).
//!
//! Grammar (juxtaposition multiplies, `∧` binds tighter than products, `^` tighter still):
//! ```text
//! expr    := ['+'|'-'] term (('+'|'-') term)*
//! term    := wedge (('*' | '/' | <juxtaposition>) wedge)*      // '/' by constants only
//! wedge   := power (('∧' | '⌋') power)*                     // outer, left contraction
//! power   := primary ['^' integer]
//! primary := number | identifier | '(' expr ')' | '-' primary
//! ```

use num_bigint::BigInt;
use num_traits::{One, Zero};

use super::{Poly, SymbolicError};
use crate::scalar::Rational;

/// What [`parse_with`] computes with: the operations of the grammar on the caller's values.
///
/// `Err` messages of the fallible operations become the message of a
/// [`SymbolicError::Parse`] at the operator's position.
pub trait ExprValue: Sized + Clone {
    /// The value of a number literal.
    fn constant(c: Rational) -> Self;
    /// `self + o`.
    fn add(&self, o: &Self) -> Self;
    /// `self - o`.
    fn sub(&self, o: &Self) -> Self;
    /// `self * o`, also written as juxtaposition (for multivectors: the geometric product).
    fn mul(&self, o: &Self) -> Self;
    /// `-self`.
    fn neg(&self) -> Self;
    /// Outer product `self ∧ o` (only multivector values have one).
    fn wedge(&self, o: &Self) -> Result<Self, String>;
    /// Left contraction `self ⌋ o` (only multivector values have one).
    fn left_contraction(&self, _o: &Self) -> Result<Self, String> {
        Err("`⌋` is not defined for scalar polynomials".into())
    }
    /// The value as a rational constant, if it is one (divisors must be constants).
    fn as_constant(&self) -> Option<Rational>;
    /// `self^k` (by repeated multiplication unless overridden).
    fn pow(&self, k: u32) -> Self {
        let mut r = Self::constant(<Rational as One>::one());
        for _ in 0..k {
            r = r.mul(self);
        }
        r
    }
}

impl ExprValue for Poly {
    fn constant(c: Rational) -> Self {
        Poly::constant(c)
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn wedge(&self, _o: &Self) -> Result<Self, String> {
        Err("`∧` is not defined for scalar polynomials".into())
    }
    fn as_constant(&self) -> Option<Rational> {
        Poly::as_constant(self)
    }
    fn pow(&self, k: u32) -> Self {
        Poly::pow(self, k)
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(Rational),
    Ident(String),
    Op(char),
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '\u{304}'
}

fn tokenize(s: &str) -> Result<Vec<(usize, Tok)>, (usize, String)> {
    let mut out = Vec::new();
    let chars: Vec<(usize, char)> = s.char_indices().collect();
    let mut i = 0;
    while i < chars.len() {
        let (pos, c) = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() {
            let mut j = i;
            let mut int = String::new();
            let mut frac = String::new();
            while j < chars.len() && chars[j].1.is_ascii_digit() {
                int.push(chars[j].1);
                j += 1;
            }
            if j + 1 < chars.len() && chars[j].1 == '.' && chars[j + 1].1.is_ascii_digit() {
                j += 1;
                while j < chars.len() && chars[j].1.is_ascii_digit() {
                    frac.push(chars[j].1);
                    j += 1;
                }
            }
            let digits: BigInt = format!("{int}{frac}")
                .parse()
                .map_err(|_| (pos, "bad number".to_string()))?;
            let den = num_traits::pow::pow(BigInt::from(10), frac.len());
            out.push((pos, Tok::Num(Rational::new(digits, den))));
            i = j;
        } else if is_ident_char(c) {
            let mut j = i;
            let mut name = String::new();
            while j < chars.len() && is_ident_char(chars[j].1) {
                name.push(chars[j].1);
                j += 1;
            }
            out.push((pos, Tok::Ident(name)));
            i = j;
        } else if "+-*/^()∧⌋".contains(c) {
            out.push((pos, Tok::Op(c)));
            i += 1;
        } else {
            return Err((pos, format!("unexpected character `{c}`")));
        }
    }
    Ok(out)
}

struct Parser<'a, V> {
    toks: Vec<(usize, Tok)>,
    i: usize,
    end: usize,
    resolve: &'a dyn Fn(&str) -> Result<V, String>,
}

type PResult<V> = Result<V, (usize, String)>;

impl<V: ExprValue> Parser<'_, V> {
    fn pos(&self) -> usize {
        self.toks.get(self.i).map(|t| t.0).unwrap_or(self.end)
    }
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.i).map(|t| &t.1)
    }
    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(&Tok::Op(c)) {
            self.i += 1;
            true
        } else {
            false
        }
    }
    fn expr(&mut self) -> PResult<V> {
        let mut acc = if self.eat('-') {
            self.term()?.neg()
        } else {
            self.eat('+');
            self.term()?
        };
        loop {
            if self.eat('+') {
                acc = acc.add(&self.term()?);
            } else if self.eat('-') {
                acc = acc.sub(&self.term()?);
            } else {
                return Ok(acc);
            }
        }
    }
    fn starts_primary(&self) -> bool {
        matches!(
            self.peek(),
            Some(Tok::Num(_)) | Some(Tok::Ident(_)) | Some(Tok::Op('('))
        )
    }
    fn term(&mut self) -> PResult<V> {
        let mut acc = self.wedge()?;
        loop {
            if self.eat('*') {
                acc = acc.mul(&self.wedge()?);
            } else if self.eat('/') {
                let pos = self.pos();
                let d = self.wedge()?;
                let c = d
                    .as_constant()
                    .filter(|c| !Zero::is_zero(c))
                    .ok_or((pos, "division only by nonzero constants".to_string()))?;
                acc = acc.mul(&V::constant(c.recip()));
            } else if self.starts_primary() {
                acc = acc.mul(&self.wedge()?);
            } else {
                return Ok(acc);
            }
        }
    }
    fn wedge(&mut self) -> PResult<V> {
        let mut acc = self.power()?;
        loop {
            let pos = self.pos();
            if self.eat('∧') {
                let rhs = self.power()?;
                acc = acc.wedge(&rhs).map_err(|m| (pos, m))?;
            } else if self.eat('⌋') {
                let rhs = self.power()?;
                acc = acc.left_contraction(&rhs).map_err(|m| (pos, m))?;
            } else {
                return Ok(acc);
            }
        }
    }
    fn power(&mut self) -> PResult<V> {
        let base = self.primary()?;
        if self.eat('^') {
            let pos = self.pos();
            match self.peek().cloned() {
                Some(Tok::Num(n)) if n.is_integer() && n.numer() < &BigInt::from(1000) => {
                    self.i += 1;
                    let k: u32 = n
                        .numer()
                        .try_into()
                        .map_err(|_| (pos, "bad exponent".into()))?;
                    Ok(base.pow(k))
                }
                _ => Err((pos, "expected a small non-negative integer exponent".into())),
            }
        } else {
            Ok(base)
        }
    }
    fn primary(&mut self) -> PResult<V> {
        let pos = self.pos();
        match self.peek().cloned() {
            Some(Tok::Num(n)) => {
                self.i += 1;
                Ok(V::constant(n))
            }
            Some(Tok::Ident(name)) => {
                self.i += 1;
                (self.resolve)(&name).map_err(|m| (pos, m))
            }
            Some(Tok::Op('(')) => {
                self.i += 1;
                let v = self.expr()?;
                if !self.eat(')') {
                    return Err((self.pos(), "expected `)`".into()));
                }
                Ok(v)
            }
            Some(Tok::Op('-')) => {
                self.i += 1;
                Ok(self.primary()?.neg())
            }
            Some(t) => Err((pos, format!("unexpected `{t:?}`"))),
            None => Err((pos, "unexpected end of input".into())),
        }
    }
}

/// Parses `text` (the grammar above) into the caller's value type, with every identifier
/// resolved by `resolve` (an `Err` there becomes a [`SymbolicError::Parse`] at the identifier).
///
/// ```
/// use ga_core::symbolic::{parse::parse_with, Poly};
/// // Identifiers are polynomials, except `k`, which stands for 2.
/// let resolve = |name: &str| Ok(if name == "k" { Poly::from(2) } else { Poly::var(name) });
/// let p = parse_with("k x^2 - (x - 1)", &resolve).unwrap();
/// assert_eq!(p, Poly::parse("2 x^2 - x + 1").unwrap());
/// ```
pub fn parse_with<V: ExprValue>(
    text: &str,
    resolve: &dyn Fn(&str) -> Result<V, String>,
) -> Result<V, SymbolicError> {
    let err = |(position, message): (usize, String)| SymbolicError::Parse {
        input: text.to_string(),
        position,
        message,
    };
    let toks = tokenize(text).map_err(err)?;
    let mut p = Parser {
        toks,
        i: 0,
        end: text.len(),
        resolve,
    };
    let v = p.expr().map_err(err)?;
    if p.i != p.toks.len() {
        return Err(err((p.pos(), "unexpected trailing input".into())));
    }
    Ok(v)
}

pub(crate) fn parse_poly(text: &str) -> Result<Poly, SymbolicError> {
    parse_with(text, &|name: &str| Ok(Poly::var(name)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_say_where() {
        match parse_poly("x + * y") {
            Err(SymbolicError::Parse { position, .. }) => assert_eq!(position, 4),
            other => panic!("{other:?}"),
        }
        assert!(parse_poly("x / y").is_err());
        assert!(parse_poly("(x").is_err());
        assert!(parse_poly("x $").is_err());
        assert_eq!(
            parse_poly("2x(y+1)").unwrap(),
            parse_poly("2*x*y + 2*x").unwrap()
        );
        assert_eq!(parse_poly("0.25 x").unwrap(), parse_poly("x/4").unwrap());
        assert!(<Poly as crate::scalar::Ring>::is_zero(
            &parse_poly("0").unwrap()
        ));
    }
}
