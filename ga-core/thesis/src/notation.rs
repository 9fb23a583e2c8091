//! The thesis's notation for Cl(4,1): blade names, signs and print order.
//!
//! The thesis (Cap. II, Apéndice A) writes the conformal basis as `e1, e2, e3, e, ē` with
//! `e = e4`, `ē = e5`, `n = e + ē` (our `n_inf`), `n̄ = e − ē` (so our `n_0 = −n̄/2`), a point
//! as `X = 2x + x²n − n̄` (= `2·up(x)`), the pseudoscalar `I = e1e2e3eē` (= our `e12345`) and
//! the dual `A* = IA` (= `−A I⁻¹`, the negative of our `dual`, since `I` is central and
//! `I² = −1`). Bivectors are written `e1e2, e2e3, e3e1` (cyclic), and the conformal vectors
//! come last: `e3e1ē = −e135`.
//!
//! This module prints a [`SymMultivector`] in that notation (and in ours), and names blades
//! both ways; [`Scope`](crate::scope::Scope) reads it:
//!
//! ```
//! use ga_thesis::{Notation, Scope};
//! let scope = Scope::new();
//! let x = scope.parse("2(a1 e1 + a2 e2) + (a1^2 + a2^2) n - n̄").unwrap();
//! let y = scope.parse("2 a1 e1 + 2 a2 e2 + (a1^2 + a2^2 - 1) e + (a1^2 + a2^2 + 1) ē").unwrap();
//! assert_eq!(x, y);
//! let l = scope.parse("e1 ∧ e3 ∧ ē").unwrap();
//! assert_eq!(l.to_notation(Notation::Thesis), "-e3e1ē");
//! assert_eq!(l.to_notation(Notation::Canonical), "e135");
//! assert_eq!(x.to_notation(Notation::ThesisNull), "2*a1 e1 + 2*a2 e2 + (a1^2 + a2^2) n - n̄");
//! ```

use ga_core::reference::{blade_name, canonical_order, reorder_sign};
use ga_core::scalar::{Rational, Ring as _};
use ga_core::symbolic::Poly;
use num_traits::{One, Zero};

use crate::multivector::SymMultivector;

/// The 32 blade bitmasks (`e1` = bit 0 … `e5` = bit 4) in canonical order: by grade, then
/// lexicographic on indices (`1, e1, …, e5, e12, e13, …, e12345`).
pub fn canonical_masks() -> [u8; 32] {
    let mut out = [0u8; 32];
    for (o, m) in out.iter_mut().zip(canonical_order(5)) {
        *o = u8::try_from(m).unwrap_or_else(|_| unreachable!("5-bit masks"));
    }
    out
}

/// Canonical name of a blade (`1`, `e1`, `e135`, `e12345`).
pub fn canonical_name(mask: u8) -> String {
    blade_name(usize::from(mask), &["e1", "e2", "e3", "e4", "e5"])
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
        sign *= i32::from(reorder_sign(usize::from(acc), 1 << i));
        acc |= 1 << i;
    }
    (sign, name)
}

/// Order in which [`Notation::Thesis`] prints blades: by grade, Euclidean part first.
pub(crate) fn thesis_order() -> Vec<u8> {
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

/// Plain text or LaTeX.
#[derive(Clone, Copy, PartialEq)]
enum Style {
    Plain,
    Latex,
}

impl SymMultivector {
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
            let coef = match style {
                Style::Plain => body.to_plain(),
                Style::Latex => body.to_latex(),
            };
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scope::Scope;

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
        let p = s
            .parse("2(a1 e1 + a2 e2 + a3 e3) + (a1^2 + a2^2 + a3^2) n - n̄")
            .unwrap();
        assert!(p.gp(&p).is_zero(), "points are null");
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
}
