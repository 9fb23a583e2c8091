//! Printing a [`SymMultivector`] in the thesis's notation or ours ([`Notation`]), as plain text
//! or LaTeX; [`Scope`](crate::scope::Scope) reads what this prints:
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

use ga_core::scalar::{Rational, Ring as _};
use ga_core::symbolic::Poly;
use num_traits::{One, Zero};

use crate::multivector::SymMultivector;
use crate::notation::{canonical_masks, canonical_name, thesis_name, thesis_order, Notation};

impl core::fmt::Debug for SymMultivector {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.to_notation(Notation::Canonical))
    }
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
