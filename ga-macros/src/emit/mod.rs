//! Emitting Rust tokens from the algebra model, one module per kind of generated item: the
//! structs and their constructors ([`types`]), unary operations ([`unary`]), conversions
//! ([`conversions`]), formatting and `approx` ([`format`]), products and sums ([`products`]) and
//! sandwiches ([`sandwich`]). The helpers shared by all of them are here.

use std::collections::BTreeMap;

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use crate::blade::Blade;
use crate::model::{Algebra, Output, Term};

mod conversions;
mod format;
mod products;
mod sandwich;
mod types;
mod unary;

/// Everything the declaration expands to.
pub fn emit(alg: &Algebra) -> TokenStream {
    let mut items = vec![types::emit_module_items(alg)];
    let emitted: Vec<usize> = (0..alg.types.len())
        .filter(|&i| alg.types[i].emitted)
        .collect();
    for &i in &emitted {
        items.push(types::emit_type(alg, i, &alg.types[i]));
    }
    // Only pairs of generated types; an operation whose result no generated type holds is
    // skipped (possible only without a dense type).
    for &a in &emitted {
        for &b in &emitted {
            items.push(products::emit_pair(alg, a, b));
        }
    }
    quote! { #(#items)* }
}

fn ring() -> TokenStream {
    quote!(::ga_core::scalar::Ring)
}

fn field_ident(alg: &Algebra, b: Blade) -> Ident {
    format_ident!("{}", alg.field_names[b as usize])
}

/// `Name<T>` or `T`.
fn out_ty(alg: &Algebra, out: Output) -> TokenStream {
    match out {
        Output::Scalar => quote!(T),
        Output::Type(i) => {
            let name = &alg.types[i].name;
            quote!(#name<T>)
        }
    }
}

/// A value of `out` whose blades come from `exprs` (missing blades are zero).
fn construct(alg: &Algebra, out: Output, mut exprs: BTreeMap<Blade, TokenStream>) -> TokenStream {
    let ring = ring();
    match out {
        Output::Scalar => exprs
            .remove(&0)
            .unwrap_or_else(|| quote!(<T as #ring>::zero())),
        Output::Type(i) => {
            let t = &alg.types[i];
            let name = &t.name;
            let fields = t.blades.iter().map(|&b| {
                let f = field_ident(alg, b);
                let e = exprs
                    .remove(&b)
                    .unwrap_or_else(|| quote!(<T as #ring>::zero()));
                quote!(#f: #e)
            });
            quote!(#name { #(#fields),* })
        }
    }
}

/// `x1 - x2 + x3`: a flat left-to-right sum, so the float evaluation order is the written one.
/// A coefficient other than `±1` (only with a `metric`) multiplies its term by the integer.
fn signed_sum(terms: Vec<(i32, TokenStream)>) -> TokenStream {
    let ring = ring();
    let mut out = TokenStream::new();
    for (k, (sign, t)) in terms.into_iter().enumerate() {
        let t = if sign.abs() == 1 {
            t
        } else {
            let m = i64::from(sign.abs());
            quote!((#t) * <T as #ring>::from_i64(#m))
        };
        out = match (k, sign < 0) {
            (0, false) => t,
            (0, true) => quote!(-(#t)),
            (_, false) => quote!(#out + #t),
            (_, true) => quote!(#out - #t),
        };
    }
    out
}

/// Access to a blade of an operand: a field, or the operand itself when it is a bare `T`.
fn access(alg: &Algebra, operand: &TokenStream, out: Output, b: Blade) -> TokenStream {
    match out {
        Output::Scalar => quote!(#operand.clone()),
        Output::Type(_) => {
            let f = field_ident(alg, b);
            quote!(#operand.#f.clone())
        }
    }
}

fn bilinear_body(
    alg: &Algebra,
    outputs: &[(Blade, Vec<Term>)],
    output: Output,
    lhs: (&TokenStream, Output),
    rhs: (&TokenStream, Output),
) -> TokenStream {
    let exprs = outputs
        .iter()
        .filter(|(_, terms)| !terms.is_empty())
        .map(|(o, terms)| {
            let products = terms
                .iter()
                .map(|t| {
                    let a = access(alg, lhs.0, lhs.1, t.lhs);
                    let b = access(alg, rhs.0, rhs.1, t.rhs);
                    (t.sign, quote!(#a * #b))
                })
                .collect();
            (*o, signed_sum(products))
        })
        .collect();
    construct(alg, output, exprs)
}
