//! The straight-line program behind one generated function: its atoms (input coefficients,
//! shared temporaries, reciprocals) and the emission of the ones the outputs need.
//!
//! A product multiplies coefficients that are each a constant or `c · atom`: a coefficient that
//! is a longer polynomial is first stored in a temporary ([`Program::atomize`]). Temporaries are
//! keyed by their polynomial (up to sign), so a subexpression computed twice is stored once;
//! after evaluation only the temporaries the outputs reach are emitted, so blades that a
//! projection drops cost nothing.

use std::collections::HashMap;

use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive};
use proc_macro2::{Ident, Span, TokenStream};
use quote::{format_ident, quote};

use super::poly::{Atom, Poly, Q};

enum AtomDef {
    /// A coefficient of an argument (`m.e12`) or a scalar argument.
    Input(TokenStream),
    /// A shared intermediate value.
    Temp(Poly),
    /// `1 / p` (needs a field).
    Recip(Poly),
}

#[derive(Default)]
pub struct Program {
    atoms: Vec<AtomDef>,
    memo: HashMap<Poly, Atom>,
    inputs: HashMap<String, Atom>,
    recips: HashMap<Poly, Atom>,
}

fn atom_ident(a: Atom) -> Ident {
    format_ident!("__ga_t{}", a)
}

impl Program {
    /// The atom reading `access` (e.g. `m.e12`), one per distinct access.
    pub fn input(&mut self, access: TokenStream) -> Atom {
        let key = access.to_string();
        if let Some(&a) = self.inputs.get(&key) {
            return a;
        }
        let a = self.atoms.len() as Atom;
        self.atoms.push(AtomDef::Input(access));
        self.inputs.insert(key, a);
        a
    }

    /// `p` as a constant or `c · atom`, storing it in a (shared) temporary when it is longer.
    pub fn atomize(&mut self, p: &Poly) -> Poly {
        if p.0.len() <= 1 && p.0.keys().all(|m| m.len() <= 1) {
            return p.clone();
        }
        let sign = if p.leads_negative() {
            -Q::one()
        } else {
            Q::one()
        };
        let normal = p.scale(&sign);
        let a = match self.memo.get(&normal) {
            Some(&a) => a,
            None => {
                let a = self.atoms.len() as Atom;
                self.atoms.push(AtomDef::Temp(normal.clone()));
                self.memo.insert(normal, a);
                a
            }
        };
        Poly::atom(a).scale(&sign)
    }

    /// `1 / p` as an atom (`p` not a constant).
    pub fn reciprocal(&mut self, p: &Poly) -> Poly {
        if let Some(&a) = self.recips.get(p) {
            return Poly::atom(a);
        }
        let a = self.atoms.len() as Atom;
        self.atoms.push(AtomDef::Recip(p.clone()));
        self.recips.insert(p.clone(), a);
        Poly::atom(a)
    }

    /// The `let` statements of every atom the `outputs` reach (in order), the constants they
    /// use, and whether division is needed; then `render` writes an output polynomial.
    pub fn emit(&self, outputs: &[&Poly]) -> syn::Result<Emitted> {
        let mut used = vec![false; self.atoms.len()];
        for p in outputs {
            for a in p.atoms() {
                used[a as usize] = true;
            }
        }
        for i in (0..self.atoms.len()).rev() {
            if !used[i] {
                continue;
            }
            if let AtomDef::Temp(p) | AtomDef::Recip(p) = &self.atoms[i] {
                for a in p.atoms() {
                    used[a as usize] = true;
                }
            }
        }
        let mut out = Emitted::default();
        let mut lets = Vec::new();
        for (i, def) in self.atoms.iter().enumerate() {
            if !used[i] {
                continue;
            }
            let name = atom_ident(i as Atom);
            let value = match def {
                AtomDef::Input(access) => quote!((#access).clone()),
                AtomDef::Temp(p) => out.render(p)?,
                AtomDef::Recip(p) => {
                    out.needs_field = true;
                    let p = out.render(p)?;
                    quote!(<T as ::ga_core::scalar::Ring>::one() / (#p))
                }
            };
            lets.push(quote!(let #name: T = #value;));
        }
        out.lets = lets;
        Ok(out)
    }
}

/// What [`Program::emit`] produced.
#[derive(Default)]
pub struct Emitted {
    pub lets: Vec<TokenStream>,
    /// Constants other than `±1`, each bound once.
    constants: Vec<(Q, Ident)>,
    pub needs_field: bool,
    /// Multiplications and additions (subtractions included) of everything rendered.
    pub multiplications: usize,
    pub additions: usize,
}

impl Emitted {
    /// The `let` statements of the constants (after every [`render`](Self::render)).
    pub fn constant_lets(&self) -> syn::Result<Vec<TokenStream>> {
        self.constants
            .iter()
            .map(|(c, name)| {
                let value = integer_or_ratio(c)?;
                Ok(quote!(let #name: T = #value;))
            })
            .collect()
    }

    fn constant(&mut self, c: &Q) -> Ident {
        if let Some((_, id)) = self.constants.iter().find(|(k, _)| k == c) {
            return id.clone();
        }
        if !c.is_integer() {
            self.needs_field = true;
        }
        let id = format_ident!("__ga_k{}", self.constants.len());
        self.constants.push((c.clone(), id.clone()));
        id
    }

    /// `p` as a left-to-right sum of products.
    pub fn render(&mut self, p: &Poly) -> syn::Result<TokenStream> {
        let ring = quote!(::ga_core::scalar::Ring);
        let mut out = TokenStream::new();
        self.additions += p.0.len().saturating_sub(1);
        for (k, (m, c)) in p.0.iter().enumerate() {
            self.multiplications +=
                m.len().saturating_sub(1) + usize::from(!m.is_empty() && !c.abs().is_one());
            let factors: Vec<TokenStream> = m
                .iter()
                .map(|&a| {
                    let id = atom_ident(a);
                    quote!(#id.clone())
                })
                .collect();
            let magnitude = c.abs();
            let mut term = if magnitude.is_one() {
                None
            } else {
                let id = self.constant(&magnitude);
                Some(quote!(#id.clone()))
            };
            for f in factors {
                term = Some(match term {
                    None => f,
                    Some(t) => quote!(#t * #f),
                });
            }
            let term = term.unwrap_or_else(|| quote!(<T as #ring>::one()));
            out = match (k, c.is_negative()) {
                (0, false) => term,
                (0, true) => quote!(-(#term)),
                (_, false) => quote!(#out + #term),
                (_, true) => quote!(#out - #term),
            };
        }
        if out.is_empty() {
            out = quote!(<T as #ring>::zero());
        }
        Ok(out)
    }
}

fn small(n: &BigInt) -> syn::Result<i64> {
    n.to_i64().ok_or_else(|| {
        syn::Error::new(
            Span::call_site(),
            format!("the constant {n} does not fit in an i64; scale the expression"),
        )
    })
}

fn integer_or_ratio(c: &Q) -> syn::Result<TokenStream> {
    let ring = quote!(::ga_core::scalar::Ring);
    let n = small(c.numer())?;
    if c.denom().is_one() {
        return Ok(quote!(<T as #ring>::from_i64(#n)));
    }
    let d = small(c.denom())?;
    Ok(quote!(<T as #ring>::from_i64(#n) / <T as #ring>::from_i64(#d)))
}
