//! Formatting (`Display`, `Debug`) and the `approx` comparisons.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::{field_ident, ring};
use crate::model::{Algebra, TypeModel};

pub(super) fn emit_format(alg: &Algebra, t: &TypeModel) -> TokenStream {
    let ring = ring();
    let name = &t.name;
    let fields: Vec<Ident> = t.blades.iter().map(|&b| field_ident(alg, b)).collect();
    let names: Vec<String> = t
        .blades
        .iter()
        .map(|&b| alg.blade_names[b as usize].clone())
        .collect();
    let fmt_terms: Vec<TokenStream> = fields
        .iter()
        .zip(&names)
        .map(|(f, n)| quote!((&self.#f, #n)))
        .collect();
    let abs_eq = fields
        .iter()
        .map(|f| quote!(self.#f.abs_diff_eq(&other.#f, epsilon.clone())));
    let rel_eq = fields
        .iter()
        .map(|f| quote!(self.#f.relative_eq(&other.#f, epsilon.clone(), max_relative.clone())));
    let ulps_eq = fields
        .iter()
        .map(|f| quote!(self.#f.ulps_eq(&other.#f, epsilon.clone(), max_ulps)));

    quote! {
        impl<T: #ring + ::core::fmt::Display> ::core::fmt::Display for #name<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                ::ga_core::format::write_terms(f, &[#(#fmt_terms),*], false)
            }
        }
        impl<T: #ring + ::core::fmt::Debug> ::core::fmt::Debug for #name<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                ::ga_core::format::write_terms_debug(f, &[#(#fmt_terms),*])
            }
        }

        impl<T: ::ga_core::approx::AbsDiffEq> ::ga_core::approx::AbsDiffEq for #name<T>
        where
            T::Epsilon: Clone,
        {
            type Epsilon = T::Epsilon;
            fn default_epsilon() -> T::Epsilon { T::default_epsilon() }
            fn abs_diff_eq(&self, other: &Self, epsilon: T::Epsilon) -> bool {
                #(#abs_eq)&&*
            }
        }
        impl<T: ::ga_core::approx::RelativeEq> ::ga_core::approx::RelativeEq for #name<T>
        where
            T::Epsilon: Clone,
        {
            fn default_max_relative() -> T::Epsilon { T::default_max_relative() }
            fn relative_eq(&self, other: &Self, epsilon: T::Epsilon, max_relative: T::Epsilon) -> bool {
                #(#rel_eq)&&*
            }
        }
        impl<T: ::ga_core::approx::UlpsEq> ::ga_core::approx::UlpsEq for #name<T>
        where
            T::Epsilon: Clone,
        {
            fn default_max_ulps() -> u32 { T::default_max_ulps() }
            fn ulps_eq(&self, other: &Self, epsilon: T::Epsilon, max_ulps: u32) -> bool {
                #(#ulps_eq)&&*
            }
        }

    }
}
