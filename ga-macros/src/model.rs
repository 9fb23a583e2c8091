//! The algebra model: validated declaration, blade names, declared types and, for every product,
//! the list of nonzero terms with the inferred result type. Everything here is plain data; the
//! emitter turns it into tokens.

use std::collections::BTreeMap;

use proc_macro2::Span;
use syn::{Attribute, Ident};

use crate::blade::{self, Blade};
use crate::parse::{BladeSpec, Declaration};

/// Largest number of generators supported (64 blades, so a blade set fits a `u64`).
pub const MAX_GENERATORS: usize = 6;

/// A set of blades as a bitset over blade masks.
pub type BladeSet = u64;

/// One declared type (or the dense type, last).
pub struct TypeModel {
    pub name: Ident,
    pub attrs: Vec<Attribute>,
    /// Blades in canonical order.
    pub blades: Vec<Blade>,
    pub set: BladeSet,
    pub is_dense: bool,
}

impl TypeModel {
    pub fn contains(&self, b: Blade) -> bool {
        self.set & (1u64 << b) != 0
    }
}

/// The type a product or unary operation returns.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Output {
    /// The scalar `T` itself (the result can only have a scalar part, or is always zero).
    Scalar,
    /// `types[i]`.
    Type(usize),
}

/// The binary products, each a restriction of the geometric product of basis blades.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
#[allow(clippy::enum_variant_names)] // `ScalarProduct` is the product's name
pub enum Product {
    Geometric,
    Wedge,
    LeftContraction,
    RightContraction,
    ScalarProduct,
    Regressive,
}

impl Product {
    /// Every product, in the order of [`PRODUCTS`] (kept for emitters that need only the kinds).
    #[allow(dead_code)]
    pub const ALL: [Product; 6] = [
        Product::Geometric,
        Product::Wedge,
        Product::LeftContraction,
        Product::RightContraction,
        Product::ScalarProduct,
        Product::Regressive,
    ];
}

/// How one product is named and written in the generated Rust: its `ga_core::ops` trait and
/// method, its operator (`core::ops` trait, method, symbol) if it has one, and the words and
/// symbol of its documentation.
pub struct ProductSpec {
    pub kind: Product,
    /// For documentation: "Outer product".
    pub title: &'static str,
    /// For documentation: `∧` in `Vector ∧ Bivector`.
    pub symbol: &'static str,
    pub trait_name: &'static str,
    pub method: &'static str,
    /// `(trait, method, symbol)` of the operator, e.g. `("BitXor", "bitxor", "^")`.
    pub operator: Option<(&'static str, &'static str, &'static str)>,
}

/// The one table of products: every generated product impl and operator comes from here.
pub const PRODUCTS: [ProductSpec; 6] = [
    ProductSpec {
        kind: Product::Geometric,
        title: "Geometric product",
        symbol: "*",
        trait_name: "Geometric",
        method: "geometric",
        operator: Some(("Mul", "mul", "*")),
    },
    ProductSpec {
        kind: Product::Wedge,
        title: "Outer product",
        symbol: "∧",
        trait_name: "Wedge",
        method: "wedge",
        operator: Some(("BitXor", "bitxor", "^")),
    },
    ProductSpec {
        kind: Product::LeftContraction,
        title: "Left contraction",
        symbol: "⌋",
        trait_name: "LeftContraction",
        method: "left_contraction",
        operator: Some(("BitOr", "bitor", "|")),
    },
    ProductSpec {
        kind: Product::RightContraction,
        title: "Right contraction",
        symbol: "⌊",
        trait_name: "RightContraction",
        method: "right_contraction",
        operator: None,
    },
    ProductSpec {
        kind: Product::ScalarProduct,
        title: "Scalar product",
        symbol: "∗",
        trait_name: "ScalarProduct",
        method: "scalar_product",
        operator: None,
    },
    ProductSpec {
        kind: Product::Regressive,
        title: "Regressive product",
        symbol: "∨",
        trait_name: "Regressive",
        method: "regressive",
        operator: Some(("BitAnd", "bitand", "&")),
    },
];

/// `sign * lhs_blade * rhs_blade` contributes to an output blade.
#[derive(Clone, Copy, Debug)]
pub struct Term {
    pub sign: i32,
    pub lhs: Blade,
    pub rhs: Blade,
}

/// The straight-line form of one bilinear operation: per output blade (canonical order), its
/// nonzero terms.
pub struct Bilinear {
    pub output: Output,
    pub outputs: Vec<(Blade, Vec<Term>)>,
}

/// A linear map blade -> ± blade (dual, undual).
pub struct BladeMap {
    pub output: Output,
    /// `(output blade, sign, input blade)` in canonical output order.
    pub entries: Vec<(Blade, i32, Blade)>,
}

pub struct Algebra {
    pub module: Ident,
    pub signature: Vec<i32>,
    pub basis: Vec<String>,
    /// Display names indexed by blade mask (`1`, `e1`, `e12`).
    pub blade_names: Vec<String>,
    /// Field names indexed by blade mask (`s`, `e1`, `e12`).
    pub field_names: Vec<String>,
    pub canonical: Vec<Blade>,
    /// Declared types, then the dense type last.
    pub types: Vec<TypeModel>,
    pub degenerate: bool,
    /// Outer attributes put on every generated struct (the `attributes` key).
    pub struct_attributes: Vec<Attribute>,
}

fn err(span: Span, msg: impl std::fmt::Display) -> syn::Error {
    syn::Error::new(span, msg)
}

impl Algebra {
    pub fn from_declaration(decl: Declaration) -> syn::Result<Algebra> {
        let n = decl.signature.len();
        if n == 0 || n > MAX_GENERATORS {
            return Err(err(
                decl.signature_span,
                format!(
                    "the signature has {n} entries; 1 to {MAX_GENERATORS} generators are supported"
                ),
            ));
        }
        let signature: Vec<i32> = decl.signature.iter().map(|e| e.value).collect();
        for e in &decl.signature {
            if !(-1..=1).contains(&e.value) {
                return Err(err(e.span, "signature entries are `+1`, `-1` or `0`"));
            }
        }
        let basis: Vec<String> = match &decl.basis {
            Some(idents) => {
                if idents.len() != n {
                    return Err(err(
                        decl.basis_span,
                        format!(
                            "`basis` names {} generators but the signature has {n}",
                            idents.len()
                        ),
                    ));
                }
                for (i, id) in idents.iter().enumerate() {
                    if idents[..i].iter().any(|o| o == id) {
                        return Err(err(id.span(), format!("basis name `{id}` is used twice")));
                    }
                    if id == "s" {
                        return Err(err(
                            id.span(),
                            "basis name `s` is reserved for the scalar field; choose another",
                        ));
                    }
                }
                idents.iter().map(|i| i.to_string()).collect()
            }
            None => (1..=n).map(|i| format!("e{i}")).collect(),
        };
        let (blade_names, field_names) = name_blades(&basis);
        for name in field_names.iter().skip(1) {
            if syn::parse_str::<Ident>(name).is_err() {
                return Err(err(
                    decl.basis_span,
                    format!("blade name `{name}` is not a valid Rust identifier; rename the basis"),
                ));
            }
        }
        let canonical = blade::canonical_order(n);
        let by_name: BTreeMap<&str, Blade> = (0..(1u32 << n))
            .map(|b| (blade_names[b as usize].as_str(), b))
            .collect();

        let dense_name = decl
            .dense
            .clone()
            .unwrap_or_else(|| Ident::new("Multivector", decl.name.span()));
        let mut types: Vec<TypeModel> = Vec::new();
        if decl.types.is_empty() {
            return Err(err(
                decl.types_span,
                "`types` is empty: declare at least one type",
            ));
        }
        for t in decl.types {
            if t.name == dense_name || types.iter().any(|o| o.name == t.name) {
                return Err(err(
                    t.name.span(),
                    format!(
                        "type `{}` is declared twice (the dense type is `{dense_name}`)",
                        t.name
                    ),
                ));
            }
            let mut set: BladeSet = 0;
            match &t.spec {
                BladeSpec::Grades(grades, span) => {
                    if grades.is_empty() {
                        return Err(err(
                            *span,
                            format!("type `{}` names no grade: write e.g. `grade 1`", t.name),
                        ));
                    }
                    let mut seen = Vec::new();
                    for &(g, gspan) in grades {
                        if g > n {
                            return Err(err(
                                gspan,
                                format!(
                                    "grade {g} does not exist: this algebra has grades 0 to {n}"
                                ),
                            ));
                        }
                        if seen.contains(&g) {
                            return Err(err(gspan, format!("grade {g} is listed twice")));
                        }
                        seen.push(g);
                        for b in 0..(1u32 << n) {
                            if blade::grade(b) == g {
                                set |= 1u64 << b;
                            }
                        }
                    }
                }
                BladeSpec::List(names, span) => {
                    if names.is_empty() {
                        return Err(err(
                            *span,
                            format!("type `{}` has an empty blade list", t.name),
                        ));
                    }
                    for (name, bspan) in names {
                        let b = *by_name.get(name.as_str()).ok_or_else(|| {
                            err(*bspan, unknown_blade_message(name, &blade_names, &basis))
                        })?;
                        if set & (1u64 << b) != 0 {
                            return Err(err(*bspan, format!("blade `{name}` is listed twice")));
                        }
                        set |= 1u64 << b;
                    }
                }
            }
            let blades = canonical
                .iter()
                .copied()
                .filter(|b| set & (1u64 << b) != 0)
                .collect();
            types.push(TypeModel {
                name: t.name,
                attrs: t.attrs,
                blades,
                set,
                is_dense: false,
            });
        }
        let all: BladeSet = if n == 6 {
            u64::MAX
        } else {
            (1u64 << (1u32 << n)) - 1
        };
        types.push(TypeModel {
            name: dense_name,
            attrs: Vec::new(),
            blades: canonical.clone(),
            set: all,
            is_dense: true,
        });
        Ok(Algebra {
            module: decl.name,
            struct_attributes: decl.attributes,
            degenerate: signature.contains(&0),
            signature,
            basis,
            blade_names,
            field_names,
            canonical,
            types,
        })
    }

    pub fn n(&self) -> usize {
        self.signature.len()
    }

    pub fn pseudoscalar(&self) -> Blade {
        (1u32 << self.n()) - 1
    }

    pub fn dense(&self) -> usize {
        self.types.len() - 1
    }

    /// The smallest type holding `set` (ties: first declared), or `T` for scalar-only sets.
    pub fn resolve(&self, set: BladeSet) -> Output {
        if set & !1 == 0 {
            return Output::Scalar;
        }
        let best = self
            .types
            .iter()
            .enumerate()
            .filter(|(_, t)| t.set & set == set)
            .min_by_key(|(i, t)| (t.blades.len(), *i))
            .map(|(i, _)| i)
            .unwrap_or(self.dense());
        Output::Type(best)
    }

    /// The blades an output holds (just the scalar blade for `T`).
    pub fn output_blades(&self, out: Output) -> Vec<Blade> {
        match out {
            Output::Scalar => vec![0],
            Output::Type(i) => self.types[i].blades.clone(),
        }
    }

    /// `sign, blade` of the product of two basis blades, or `None` when it vanishes.
    pub fn blade_product(&self, kind: Product, a: Blade, b: Blade) -> Option<(i32, Blade)> {
        let keep = match kind {
            Product::Geometric => true,
            Product::Wedge => a & b == 0,
            Product::LeftContraction => a & b == a,
            Product::RightContraction => a & b == b,
            Product::ScalarProduct => a == b,
            Product::Regressive => {
                let (s1, da) = self.dual_blade(a);
                let (s2, db) = self.dual_blade(b);
                if da & db != 0 {
                    return None;
                }
                let w = blade::reorder_sign(da, db);
                let (s3, out) = self.undual_blade(da | db);
                return Some((s1 * s2 * w * s3, out));
            }
        };
        if !keep {
            return None;
        }
        let (sign, out) = blade::geometric(a, b, &self.signature);
        (sign != 0).then_some((sign, out))
    }

    /// `dual(e_b)`: `e_b I⁻¹`, or the right complement for degenerate signatures.
    pub fn dual_blade(&self, b: Blade) -> (i32, Blade) {
        let full = self.pseudoscalar();
        if self.degenerate {
            (blade::reorder_sign(b, full ^ b), full ^ b)
        } else {
            // I⁻¹ = I / (I I) and I I = ±1, so I⁻¹ = (I I) I.
            let (ii, _) = blade::geometric(full, full, &self.signature);
            let (s, out) = blade::geometric(b, full, &self.signature);
            (s * ii, out)
        }
    }

    /// `undual(e_b)`: `e_b I`, or the left complement for degenerate signatures.
    pub fn undual_blade(&self, b: Blade) -> (i32, Blade) {
        let full = self.pseudoscalar();
        if self.degenerate {
            (blade::reorder_sign(full ^ b, b), full ^ b)
        } else {
            blade::geometric(b, full, &self.signature)
        }
    }

    /// Nonzero terms of `lhs ∘ rhs` grouped by output blade, with the inferred output type.
    pub fn bilinear(&self, kind: Product, lhs: &[Blade], rhs: &[Blade]) -> Bilinear {
        let mut by_out: BTreeMap<Blade, Vec<Term>> = BTreeMap::new();
        for &a in lhs {
            for &b in rhs {
                if let Some((sign, out)) = self.blade_product(kind, a, b) {
                    by_out.entry(out).or_default().push(Term {
                        sign,
                        lhs: a,
                        rhs: b,
                    });
                }
            }
        }
        let set = by_out.keys().fold(0u64, |s, b| s | (1u64 << b));
        let output = self.resolve(set);
        let outputs = self
            .canonical
            .iter()
            .filter_map(|b| by_out.remove(b).map(|terms| (*b, terms)))
            .collect();
        Bilinear { output, outputs }
    }

    /// The dual (or undual) of a type as a blade map.
    pub fn blade_map(&self, blades: &[Blade], f: impl Fn(Blade) -> (i32, Blade)) -> BladeMap {
        let mut entries: Vec<(Blade, i32, Blade)> = blades
            .iter()
            .map(|&b| {
                let (s, out) = f(b);
                (out, s, b)
            })
            .collect();
        let position = |b: Blade| self.canonical.iter().position(|&c| c == b).unwrap_or(0);
        entries.sort_by_key(|e| position(e.0));
        let set = entries.iter().fold(0u64, |s, e| s | (1u64 << e.0));
        BladeMap {
            output: self.resolve(set),
            entries,
        }
    }

    /// Terms of `⟨A Ã⟩₀`: `(sign, blade)` for each blade whose square survives.
    pub fn norm_squared_terms(&self, blades: &[Blade]) -> Vec<(i32, Blade)> {
        blades
            .iter()
            .filter_map(|&b| {
                let (s, _) = blade::geometric(b, b, &self.signature);
                (s != 0).then_some((s * blade::reverse_sign(b), b))
            })
            .collect()
    }

    /// Terms of `⟨P Ṽ⟩` restricted to the blades of `out`: the second half of a sandwich.
    pub fn sandwich_terms(
        &self,
        p: &[Blade],
        v: &[Blade],
        out: &[Blade],
    ) -> Vec<(Blade, Vec<Term>)> {
        out.iter()
            .map(|&o| {
                let terms = p
                    .iter()
                    .filter_map(|&pb| {
                        let vb = pb ^ o;
                        if !v.contains(&vb) {
                            return None;
                        }
                        let (s, r) = blade::geometric(pb, vb, &self.signature);
                        debug_assert_eq!(r, o);
                        (s != 0).then_some(Term {
                            sign: s * blade::reverse_sign(vb),
                            lhs: pb,
                            rhs: vb,
                        })
                    })
                    .collect();
                (o, terms)
            })
            .collect()
    }
}

/// Display and field names of every blade, indexed by mask. Compact (`e12`) when every basis
/// name is a shared prefix plus one character, else joined with `_` (`ep_em`).
fn name_blades(basis: &[String]) -> (Vec<String>, Vec<String>) {
    let n = basis.len();
    let prefix_of = |s: &String| {
        let mut chars = s.chars();
        chars.next_back();
        chars.as_str().to_string()
    };
    let prefix = prefix_of(&basis[0]);
    let compact = basis
        .iter()
        .all(|b| b.chars().count() == prefix.chars().count() + 1 && prefix_of(b) == prefix);
    let mut display = Vec::with_capacity(1 << n);
    let mut fields = Vec::with_capacity(1 << n);
    for b in 0..(1u32 << n) {
        let idx = blade::indices(b);
        if idx.is_empty() {
            display.push("1".to_string());
            fields.push("s".to_string());
            continue;
        }
        let name = if compact {
            let suffixes: String = idx
                .iter()
                .map(|&i| basis[i].chars().last().unwrap_or('_'))
                .collect();
            format!("{prefix}{suffixes}")
        } else {
            idx.iter()
                .map(|&i| basis[i].as_str())
                .collect::<Vec<_>>()
                .join("_")
        };
        display.push(name.clone());
        fields.push(name);
    }
    (display, fields)
}

fn unknown_blade_message(name: &str, blade_names: &[String], basis: &[String]) -> String {
    // A permutation of a real blade's factors gets a precise hint.
    let mut sorted: Vec<char> = name.chars().collect();
    sorted.sort_unstable();
    let hint = blade_names.iter().find(|b| {
        let mut c: Vec<char> = b.chars().collect();
        c.sort_unstable();
        c == sorted && b.as_str() != name
    });
    match hint {
        Some(h) => format!(
            "unknown blade `{name}`: blades are written with ascending basis indices, did you mean `{h}`?"
        ),
        None => format!(
            "unknown blade `{name}`: blades are `1` or products of the basis {} with ascending indices, e.g. `{}`",
            basis.join(", "),
            blade_names.get(3).map(String::as_str).unwrap_or("e1")
        ),
    }
}
