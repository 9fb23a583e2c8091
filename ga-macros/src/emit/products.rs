//! The products of one ordered pair of types, driven by the product table
//! [`PRODUCTS`](crate::model::PRODUCTS), with their operators; and sums and differences.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::{bilinear_body, construct, field_ident, out_ty, ring};
use crate::model::{Algebra, Output, PRODUCTS};

/// Products, sums and sandwiches of one ordered pair of types.
pub(super) fn emit_pair(alg: &Algebra, a: usize, b: usize) -> TokenStream {
    let ring = ring();
    let (ta, tb) = (&alg.types[a], &alg.types[b]);
    let (an, bn) = (&ta.name, &tb.name);
    let lhs = quote!(self);
    let rhs = quote!(rhs);
    let mut items = Vec::new();
    for spec in &PRODUCTS {
        let model = alg.bilinear(spec.kind, &ta.blades, &tb.blades);
        if !alg.is_emitted(model.output) {
            continue;
        }
        let terms: usize = model.outputs.iter().map(|(_, t)| t.len()).sum();
        // Zero by grade (no pair of blades contributes): a zero-sized `Zero<T>`, so the product
        // costs nothing and storing its result writes nothing.
        let (ty, body, out_name) = if terms == 0 {
            (
                quote!(::ga_core::Zero<T>),
                quote!(let _ = rhs; ::ga_core::Zero::new()),
                "Zero".to_string(),
            )
        } else {
            let body = bilinear_body(
                alg,
                &model.outputs,
                model.output,
                (&lhs, Output::Type(a)),
                (&rhs, Output::Type(b)),
            );
            let out_name = match model.output {
                Output::Scalar => "scalar".to_string(),
                Output::Type(i) => alg.types[i].name.to_string(),
            };
            (out_ty(alg, model.output), body, out_name)
        };
        let trait_ident = format_ident!("{}", spec.trait_name);
        let method = format_ident!("{}", spec.method);
        let doc = format!(
            "{} `{an} {} {bn} → {out_name}`, {terms} multiplications.",
            spec.title, spec.symbol
        );
        items.push(quote! {
            impl<T: #ring> ::ga_core::ops::#trait_ident<#bn<T>> for #an<T> {
                type Output = #ty;
                #[doc = #doc]
                #[inline]
                fn #method(&self, rhs: &#bn<T>) -> #ty { #body }
            }
        });
        if let Some((op_trait, op_method, op_symbol)) = spec.operator {
            let op_trait = format_ident!("{op_trait}");
            let op_method = format_ident!("{op_method}");
            let op_doc = format!(
                "`{an} {op_symbol} {bn}`: the {} (`{an} {} {bn} → {out_name}`, {terms} \
                 multiplications).",
                spec.title.to_lowercase(),
                spec.symbol
            );
            items.push(quote! {
                impl<T: #ring> ::core::ops::#op_trait<#bn<T>> for #an<T> {
                    type Output = #ty;
                    #[doc = #op_doc]
                    #[inline]
                    fn #op_method(self, rhs: #bn<T>) -> #ty {
                        ::ga_core::ops::#trait_ident::#method(&self, &rhs)
                    }
                }
                impl<T: #ring> ::core::ops::#op_trait<&#bn<T>> for &#an<T> {
                    type Output = #ty;
                    #[doc = #op_doc]
                    #[inline]
                    fn #op_method(self, rhs: &#bn<T>) -> #ty {
                        ::ga_core::ops::#trait_ident::#method(self, rhs)
                    }
                }
            });
        }
    }
    items.push(emit_sum(alg, a, b, false));
    items.push(emit_sum(alg, a, b, true));
    items.push(super::sandwich::emit_sandwich(alg, a, b));
    quote! { #(#items)* }
}

fn emit_sum(alg: &Algebra, a: usize, b: usize, subtract: bool) -> TokenStream {
    let ring = ring();
    let (ta, tb) = (&alg.types[a], &alg.types[b]);
    let (an, bn) = (&ta.name, &tb.name);
    let out = alg.resolve(ta.set.union(&tb.set));
    // Sums of non-scalar types never resolve to `T`; a scalar-only pair cannot be declared
    // without a blade list `[1]`, which resolves to the declared type too.
    let out = match out {
        Output::Scalar => Output::Type(if ta.blades.len() <= tb.blades.len() {
            a
        } else {
            b
        }),
        o => o,
    };
    if !alg.is_emitted(out) {
        return TokenStream::new();
    }
    let ty = out_ty(alg, out);
    let make = |owned: bool| {
        let exprs = alg
            .output_blades(out)
            .into_iter()
            .filter_map(|bl| {
                let f = field_ident(alg, bl);
                let (x, y) = if owned {
                    (quote!(self.#f), quote!(rhs.#f))
                } else {
                    (quote!(self.#f.clone()), quote!(rhs.#f.clone()))
                };
                let e = match (ta.contains(bl), tb.contains(bl), subtract) {
                    (true, true, false) => quote!(#x + #y),
                    (true, true, true) => quote!(#x - #y),
                    (true, false, _) => x,
                    (false, true, false) => y,
                    (false, true, true) => quote!(-#y),
                    (false, false, _) => return None,
                };
                Some((bl, e))
            })
            .collect();
        construct(alg, out, exprs)
    };
    let (owned, borrowed) = (make(true), make(false));
    let (tr, m) = if subtract {
        (quote!(Sub), quote!(sub))
    } else {
        (quote!(Add), quote!(add))
    };
    quote! {
        impl<T: #ring> ::core::ops::#tr<#bn<T>> for #an<T> {
            type Output = #ty;
            #[inline]
            fn #m(self, rhs: #bn<T>) -> #ty { #owned }
        }
        impl<T: #ring> ::core::ops::#tr<&#bn<T>> for &#an<T> {
            type Output = #ty;
            #[inline]
            fn #m(self, rhs: &#bn<T>) -> #ty { #borrowed }
        }
    }
}
