//! Emitting Rust tokens from the algebra model: one struct per type, straight-line products
//! generic over the scalar, operator impls, conversions, formatting and `approx` support.

use std::collections::BTreeMap;

use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote};

use crate::blade::{self, Blade};
use crate::model::{Algebra, BladeSet, Output, Product, Term, TypeModel, PRODUCTS};

/// Everything the declaration expands to.
pub fn emit(alg: &Algebra) -> TokenStream {
    let mut items = vec![emit_module_items(alg)];
    let emitted: Vec<usize> = (0..alg.types.len())
        .filter(|&i| alg.types[i].emitted)
        .collect();
    for &i in &emitted {
        items.push(emit_type(alg, i, &alg.types[i]));
    }
    // Only pairs of generated types; an operation whose result no generated type holds is
    // skipped (possible only without a dense type).
    for &a in &emitted {
        for &b in &emitted {
            items.push(emit_pair(alg, a, b));
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
fn signed_sum(terms: Vec<(i32, TokenStream)>) -> TokenStream {
    let mut out = TokenStream::new();
    for (k, (sign, t)) in terms.into_iter().enumerate() {
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

fn emit_module_items(alg: &Algebra) -> TokenStream {
    let n = alg.n();
    let nb = 1usize << n;
    let sig = alg
        .signature
        .iter()
        .map(|&s| Literal::i8_unsuffixed(s as i8));
    let basis = &alg.basis;
    let names = alg
        .canonical
        .iter()
        .map(|&b| alg.blade_names[b as usize].clone());
    let label = alg.module.to_string();
    let sig_doc = format!("Squares of the generators of `{label}`, in basis order.");
    let ring = ring();
    let blade_fns = alg.canonical.iter().skip(1).map(|&b| {
        let out = alg.resolve(BladeSet::single(b));
        if !alg.is_emitted(out) {
            return TokenStream::new();
        }
        let ty = out_ty(alg, out);
        let name = format_ident!("{}", alg.field_names[b as usize]);
        let mut exprs = BTreeMap::new();
        exprs.insert(b, quote!(<T as #ring>::one()));
        let value = construct(alg, out, exprs);
        let doc = format!("The basis blade `{}`.", alg.blade_names[b as usize]);
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn #name<T: #ring>() -> #ty { #value }
        }
    });
    quote! {
        #[doc = #sig_doc]
        pub const SIGNATURE: [i8; #n] = [#(#sig),*];
        /// Names of the generators, in basis order.
        pub const BASIS: [&str; #n] = [#(#basis),*];
        /// Names of all blades in canonical order (grade, then lexicographic on indices).
        pub const BLADE_NAMES: [&str; #nb] = [#(#names),*];
        #(#blade_fns)*
    }
}

fn emit_type(alg: &Algebra, index: usize, t: &TypeModel) -> TokenStream {
    let ring = ring();
    let name = &t.name;
    let fields: Vec<Ident> = t.blades.iter().map(|&b| field_ident(alg, b)).collect();
    let names: Vec<String> = t
        .blades
        .iter()
        .map(|&b| alg.blade_names[b as usize].clone())
        .collect();
    let count = t.blades.len();
    let attrs = &t.attrs;
    let auto_doc = if t.is_dense {
        format!(
            "A general multivector of `{}`: all {count} blades, in canonical order.",
            alg.module
        )
    } else {
        format!(
            "A multivector of `{}` with the blades `{}`.",
            alg.module,
            names.join(", ")
        )
    };
    let field_docs = names.iter().map(|n| format!("Coefficient of `{n}`."));
    let zero = quote!(<T as #ring>::zero());

    let unary_signs = |f: fn(Blade) -> i32| {
        let exprs = t.blades.iter().map(|&b| {
            let fi = field_ident(alg, b);
            if f(b) < 0 {
                quote!(#fi: -self.#fi.clone())
            } else {
                quote!(#fi: self.#fi.clone())
            }
        });
        quote!(#name { #(#exprs),* })
    };
    let reverse = unary_signs(blade::reverse_sign);
    let involution = unary_signs(blade::involution_sign);
    let conjugate = unary_signs(blade::conjugate_sign);

    let blade_map_fn = |fname: Ident, doc: &str, f: &dyn Fn(Blade) -> (i32, Blade)| {
        let map = alg.blade_map(&t.blades, f);
        if !alg.is_emitted(map.output) {
            return TokenStream::new();
        }
        let ty = out_ty(alg, map.output);
        let exprs = map
            .entries
            .iter()
            .map(|&(o, s, b)| {
                let fi = field_ident(alg, b);
                let e = if s < 0 {
                    quote!(-self.#fi.clone())
                } else {
                    quote!(self.#fi.clone())
                };
                (o, e)
            })
            .collect();
        let value = construct(alg, map.output, exprs);
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn #fname(&self) -> #ty { #value }
        }
    };
    let dual_doc = if alg.degenerate {
        "The dual: the right complement (the signature is degenerate, so `I` has no inverse)."
    } else {
        "The dual `A I⁻¹`."
    };
    let undual_doc = if alg.degenerate {
        "The undual: the left complement, inverse of [`dual`](Self::dual)."
    } else {
        "The undual `A I`, inverse of [`dual`](Self::dual)."
    };
    let dual = blade_map_fn(format_ident!("dual"), dual_doc, &|b| alg.dual_blade(b));
    let undual = blade_map_fn(format_ident!("undual"), undual_doc, &|b| {
        alg.undual_blade(b)
    });
    let dual_out = alg.blade_map(&t.blades, |b| alg.dual_blade(b)).output;
    let dual_ty = out_ty(alg, dual_out);
    let not_impls = if alg.is_emitted(dual_out) {
        quote! {
            impl<T: #ring> ::core::ops::Not for #name<T> {
                type Output = #dual_ty;
                /// The dual.
                #[inline]
                fn not(self) -> #dual_ty { self.dual() }
            }
            impl<T: #ring> ::core::ops::Not for &#name<T> {
                type Output = #dual_ty;
                /// The dual.
                #[inline]
                fn not(self) -> #dual_ty { self.dual() }
            }
        }
    } else {
        TokenStream::new()
    };

    let grades = t.blades.iter().map(|&b| {
        let fi = field_ident(alg, b);
        let g = blade::grade(b);
        quote!(#fi: if k == #g { self.#fi.clone() } else { #zero })
    });
    let norm_terms: Vec<(i32, TokenStream)> = alg
        .norm_squared_terms(&t.blades)
        .into_iter()
        .map(|(s, b)| {
            let fi = field_ident(alg, b);
            (s, quote!(self.#fi.clone() * self.#fi.clone()))
        })
        .collect();
    let norm = if norm_terms.is_empty() {
        zero.clone()
    } else {
        signed_sum(norm_terms)
    };

    let masks: Vec<Literal> = t
        .blades
        .iter()
        .map(|&b| Literal::u32_unsuffixed(b))
        .collect();
    let inverse_doc = inverse_doc(t);
    let dense_items = if t.is_dense {
        let coeffs: Vec<Ident> = (0..count).map(|i| format_ident!("c{i}")).collect();
        quote! {
            impl<T> #name<T> {
                /// Builds a multivector from its coefficients in canonical blade order.
                #[inline]
                pub fn from_coefficients(coefficients: [T; #count]) -> Self {
                    let [#(#coeffs),*] = coefficients;
                    #name { #(#fields: #coeffs),* }
                }
                /// The coefficients in canonical blade order.
                #[inline]
                pub fn into_coefficients(self) -> [T; #count] {
                    [#(self.#fields),*]
                }
            }
            impl<T: Clone> #name<T> {
                /// The coefficients in canonical blade order.
                #[inline]
                pub fn coefficients(&self) -> [T; #count] {
                    [#(self.#fields.clone()),*]
                }
            }
            impl<T: ::ga_core::scalar::Field> #name<T> {
                /// The unchecked solution of `A X = 1` by Gaussian elimination on the
                /// left-multiplication matrix (partial pivoting by `Field::pivot_score`); `None`
                /// when a pivot is exactly zero. Exact for exact scalars; for floats a nearly
                /// singular `A` gives an inaccurate result: prefer [`inverse`](Self::inverse),
                /// which checks its answer.
                pub fn general_inverse(&self) -> Option<Self> {
                    let span: [u32; #count] = [#(#masks),*];
                    let solution = ::ga_core::inverse::solve(&SIGNATURE, &span, &self.coefficients(), &span)?;
                    let array: [T; #count] = solution.try_into().ok()?;
                    Some(Self::from_coefficients(array))
                }
            }
        }
    } else if !alg.types[alg.dense()].emitted {
        TokenStream::new()
    } else {
        let dense = &alg.types[alg.dense()].name;
        quote! {
            impl<T: #ring> From<#name<T>> for #dense<T> {
                #[inline]
                fn from(v: #name<T>) -> Self {
                    let mut m = #dense::<T>::zero();
                    #(m.#fields = v.#fields;)*
                    m
                }
            }
            impl<T: #ring> #name<T> {
                /// The projection of a general multivector onto this type's blades (the other
                /// blades are dropped).
                #[inline]
                pub fn from_multivector(m: &#dense<T>) -> Self {
                    #name { #(#fields: m.#fields.clone()),* }
                }
            }
        }
    };
    let subset_conversions = alg.types.iter().enumerate().filter_map(|(j, other)| {
        if j == index || other.is_dense || !t.set.is_subset_of(&other.set) {
            return None;
        }
        let oname = &other.name;
        let assigns = other.blades.iter().map(|&b| {
            let fi = field_ident(alg, b);
            if t.contains(b) {
                quote!(#fi: v.#fi)
            } else {
                quote!(#fi: #zero)
            }
        });
        Some(quote! {
            impl<T: #ring> From<#name<T>> for #oname<T> {
                #[inline]
                fn from(v: #name<T>) -> Self { #oname { #(#assigns),* } }
            }
        })
    });
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

    let struct_attributes = &alg.struct_attributes;
    quote! {
        #(#attrs)*
        #[doc = #auto_doc]
        #[derive(Clone, Copy, PartialEq, Eq, Hash)]
        #[repr(C)]
        #(#struct_attributes)*
        pub struct #name<T> {
            #(#[doc = #field_docs] pub #fields: T,)*
        }

        impl<T> #name<T> {
            /// Canonical names of this type's blades, in field order (`1` is the scalar).
            pub const BLADES: [&'static str; #count] = [#(#names),*];
            /// Builds a value from its coefficients in canonical blade order.
            #[allow(clippy::too_many_arguments)]
            #[inline]
            pub const fn new(#(#fields: T),*) -> Self {
                #name { #(#fields),* }
            }
        }

        impl<T: #ring> #name<T> {
            /// The zero value.
            #[inline]
            pub fn zero() -> Self {
                #name { #(#fields: #zero),* }
            }
            /// The reverse `Ã` (order of factors reversed).
            #[inline]
            pub fn reverse(&self) -> Self { #reverse }
            /// The grade involution `Â` (odd grades negated).
            #[inline]
            pub fn grade_involution(&self) -> Self { #involution }
            /// The Clifford conjugate `Ā` (reverse of the grade involution).
            #[inline]
            pub fn conjugate(&self) -> Self { #conjugate }
            #dual
            #undual
            /// The grade-`k` part (all other grades zeroed).
            #[inline]
            pub fn grade(&self, k: usize) -> Self {
                #name { #(#grades),* }
            }
            /// `⟨A Ã⟩₀`; may be negative or zero in non-Euclidean signatures.
            #[inline]
            pub fn norm_squared(&self) -> T { #norm }
            /// Every coefficient multiplied by `s`.
            #[inline]
            pub fn scale(&self, s: &T) -> Self {
                #name { #(#fields: self.#fields.clone() * s.clone()),* }
            }
        }

        impl<T: ::ga_core::scalar::Field> #name<T> {
            /// The versor inverse `Ã / ⟨A Ã⟩₀`, `None` when `⟨A Ã⟩₀` is zero. Precondition: `A`
            /// is a versor (a product of invertible vectors) or a blade; then this is its
            /// inverse. For any other `A` the result is not an inverse: use
            /// [`inverse`](Self::inverse), which checks.
            #[inline]
            pub fn versor_inverse(&self) -> Option<Self> {
                let inv = ::ga_core::scalar::Field::checked_recip(&self.norm_squared())?;
                Some(self.reverse().scale(&inv))
            }
            #[doc = #inverse_doc]
            pub fn inverse(&self) -> Option<Self> {
                let x = [#(self.#fields.clone()),*];
                let [#(#fields),*]: [T; #count] =
                    ::ga_core::inverse::inverse(&SIGNATURE, &[#(#masks),*], &x)?.try_into().ok()?;
                Some(#name { #(#fields),* })
            }
        }

        impl<T: #ring> Default for #name<T> {
            #[inline]
            fn default() -> Self { Self::zero() }
        }

        impl<T: #ring> ::core::ops::Neg for #name<T> {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self { #name { #(#fields: -self.#fields),* } }
        }
        impl<T: #ring> ::core::ops::Neg for &#name<T> {
            type Output = #name<T>;
            #[inline]
            fn neg(self) -> #name<T> { #name { #(#fields: -self.#fields.clone()),* } }
        }
        #not_impls
        impl<T: #ring> ::core::ops::Mul<T> for #name<T> {
            type Output = Self;
            #[inline]
            fn mul(self, s: T) -> Self { #name { #(#fields: self.#fields * s.clone()),* } }
        }
        impl ::core::ops::Mul<#name<f64>> for f64 {
            type Output = #name<f64>;
            #[inline]
            fn mul(self, v: #name<f64>) -> #name<f64> { v * self }
        }
        impl ::core::ops::Mul<#name<f32>> for f32 {
            type Output = #name<f32>;
            #[inline]
            fn mul(self, v: #name<f32>) -> #name<f32> { v * self }
        }

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

        #dense_items
        #(#subset_conversions)*
    }
}

/// The documentation of `inverse()`: what `None` means depends on whether the type is closed
/// under the geometric product.
fn inverse_doc(t: &TypeModel) -> String {
    let masks: Vec<Blade> = t.blades.clone();
    let mut span = vec![0 as Blade];
    for &m in &masks {
        if !span.contains(&m) {
            let more: Vec<Blade> = span.iter().map(|s| s ^ m).collect();
            span.extend(more);
        }
    }
    let closed = span.iter().all(|b| t.contains(*b));
    let none = if closed {
        "`None` when `A` has no inverse"
    } else {
        "`None` when `A` has no inverse, or when its inverse has blades outside this type (the \
         type is not closed under the geometric product: convert to a larger type first)"
    };
    format!(
        "The inverse `A⁻¹` with `A A⁻¹ = A⁻¹ A = 1`, checked: {none}. For floats, `Some` means \
         the products equal 1 up to the rounding error of computing them (see \
         `ga_core::inverse` for the exact tolerance), and non-finite input gives `None`. Tries \
         the versor formula first (see [`versor_inverse`](Self::versor_inverse)), then Gaussian \
         elimination; slower than `versor_inverse`, which is enough when `A` is known to be a \
         versor."
    )
}

/// Products, sums and sandwiches of one ordered pair of types.
fn emit_pair(alg: &Algebra, a: usize, b: usize) -> TokenStream {
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
        let ty = out_ty(alg, model.output);
        let body = bilinear_body(
            alg,
            &model.outputs,
            model.output,
            (&lhs, Output::Type(a)),
            (&rhs, Output::Type(b)),
        );
        let trait_ident = format_ident!("{}", spec.trait_name);
        let method = format_ident!("{}", spec.method);
        let terms: usize = model.outputs.iter().map(|(_, t)| t.len()).sum();
        let out_name = match model.output {
            Output::Scalar => "scalar".to_string(),
            Output::Type(i) => alg.types[i].name.to_string(),
        };
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
    items.push(emit_sandwich(alg, a, b));
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

/// Sandwiches with at most this many multiplications (both stages) are `#[inline(always)]`:
/// this covers the versors of Cl(4,1) applied to points (rotor: 110, even versor: 160).
const SANDWICH_INLINE_ALWAYS_MAX: usize = 192;

/// `V X Ṽ` projected on `X`: the geometric product `V X` (written out for small sandwiches,
/// called for large ones), then
/// only the terms of `(V X) Ṽ` that land on `X`'s blades.
fn emit_sandwich(alg: &Algebra, v: usize, x: usize) -> TokenStream {
    let ring = ring();
    let (tv, tx) = (&alg.types[v], &alg.types[x]);
    let (vn, xn) = (&tv.name, &tx.name);
    let first = alg.bilinear(Product::Geometric, &tv.blades, &tx.blades);
    if !alg.is_emitted(first.output) {
        return TokenStream::new();
    }
    let p_blades: Vec<Blade> = first.outputs.iter().map(|(b, _)| *b).collect();
    let outputs = alg.sandwich_terms(&p_blades, &tv.blades, &tx.blades);
    let p = quote!(p);
    let me = quote!(self);
    let xv = quote!(x);
    // For small sandwiches the first stage is written out here rather than called, so that the
    // whole sandwich is one straight-line body (the call to `geometric` was not inlined).
    let first_body = bilinear_body(
        alg,
        &first.outputs,
        first.output,
        (&me, Output::Type(v)),
        (&xv, Output::Type(x)),
    );
    let body = bilinear_body(
        alg,
        &outputs,
        Output::Type(x),
        (&p, first.output),
        (&me, Output::Type(v)),
    );
    // The two stages together are too large for LLVM's inlining threshold even for small
    // versors (a rotor applied to a point: 110 multiplications), so a loop of sandwiches would
    // pay a call per element and lose vectorisation across iterations (measured: 2x slower than
    // the same code inlined, see ga-core/examples/callgrind_products.rs). Small sandwiches are
    // always inlined, as a hand-written kernel would be; large ones (e.g. dense × dense) keep
    // the hint only, to bound code size.
    let mults: usize = first.outputs.iter().map(|(_, t)| t.len()).sum::<usize>()
        + outputs.iter().map(|(_, t)| t.len()).sum::<usize>();
    // Large sandwiches call the generated geometric product for the first stage instead of
    // repeating its terms (this keeps the expansion, and the compile time, small).
    let (inline, first_stage) = if mults <= SANDWICH_INLINE_ALWAYS_MAX {
        (quote!(#[inline(always)]), first_body)
    } else {
        (
            quote!(#[inline]),
            quote!(::ga_core::ops::Geometric::geometric(self, x)),
        )
    };
    quote! {
        impl<T: #ring> ::ga_core::ops::SandwichUnit<#xn<T>> for #vn<T> {
            #inline
            fn sandwich_unit(&self, x: &#xn<T>) -> #xn<T> {
                let p = #first_stage;
                #body
            }
        }
        impl<T: ::ga_core::scalar::Field> ::ga_core::ops::Sandwich<#xn<T>> for #vn<T> {
            #[inline]
            fn sandwich(&self, x: &#xn<T>) -> Option<#xn<T>> {
                let inv = ::ga_core::scalar::Field::checked_recip(&self.norm_squared())?;
                Some(::ga_core::ops::SandwichUnit::sandwich_unit(self, x).scale(&inv))
            }
        }
    }
}
