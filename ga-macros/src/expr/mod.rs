//! Expression-level generation: the `functions` of a declaration (`fn sandwich(#[versor] m:
//! Motor, x: Vector) -> Vector { m * x * m.reverse() }`) each become one generated function
//! whose body is straight-line code over the scalar.
//!
//! The body is evaluated symbolically at expansion time ([`eval`]): every coefficient is a
//! polynomial with exact rational coefficients ([`poly`]) in the arguments' coefficients, so
//! the blades a declared type does not hold are zero from the start, constants (literals,
//! blades, constant arguments of inlined functions) are folded exactly, the metric is applied
//! blade by blade (`ei ei = 0` in a null basis, `e4 e4 - e5 e5` cancelling exactly in an
//! orthogonal one), terms that cancel leave nothing, a sandwich `V X Ṽ` of a `#[versor]` keeps
//! only the grades of `X`, and intermediate coefficients are shared temporaries
//! ([`program`]): one per distinct polynomial, emitted only when an output needs it.

use std::collections::HashMap;

use proc_macro2::TokenStream;
use quote::quote;
use syn::{FnArg, Pat, Type};

use crate::model::{Algebra, Output};

mod eval;
mod poly;
mod program;
mod value;

use eval::{is_versor_attr, type_of, Compiler, Scope};
use value::Value;

/// The generated functions; `path` prefixes the type names (`::ga_core::cga_null::`) when
/// they are emitted outside the algebra's module.
pub fn emit(
    alg: &Algebra,
    functions: &[syn::ItemFn],
    path: Option<&syn::Path>,
) -> syn::Result<TokenStream> {
    let fns: HashMap<String, &syn::ItemFn> = functions
        .iter()
        .map(|f| (f.sig.ident.to_string(), f))
        .collect();
    let mut errors = crate::errors::Errors::default();
    let mut out = Vec::new();
    for f in functions {
        match emit_fn(alg, &fns, f, path) {
            Ok(t) => out.push(t),
            Err(e) => errors.push(e),
        }
    }
    errors.finish()?;
    Ok(quote!(#(#out)*))
}

fn type_tokens(alg: &Algebra, ty: Output, path: Option<&syn::Path>) -> TokenStream {
    match ty {
        Output::Scalar => quote!(T),
        Output::Type(i) => {
            let name = &alg.types[i].name;
            match path {
                Some(p) => quote!(#p::#name<T>),
                None => quote!(#name<T>),
            }
        }
    }
}

fn emit_fn(
    alg: &Algebra,
    fns: &HashMap<String, &syn::ItemFn>,
    f: &syn::ItemFn,
    path: Option<&syn::Path>,
) -> syn::Result<TokenStream> {
    if !f.sig.generics.params.is_empty() {
        return Err(syn::Error::new_spanned(
            &f.sig.generics,
            "declared functions are generic over the scalar `T` already: write no generics",
        ));
    }
    let mut c = Compiler::new(alg, fns);
    let mut scope = Scope::new();
    let mut params = Vec::new();
    for input in &f.sig.inputs {
        let FnArg::Typed(pt) = input else {
            return Err(syn::Error::new_spanned(
                input,
                "declared functions take no `self`",
            ));
        };
        let Pat::Ident(id) = &*pt.pat else {
            return Err(syn::Error::new_spanned(
                &pt.pat,
                "expected a parameter name",
            ));
        };
        let ident = &id.ident;
        let ty = type_of(alg, &pt.ty)?;
        let tokens = type_tokens(alg, ty, path);
        let value = match ty {
            Output::Scalar => {
                params.push(quote!(#ident: #tokens));
                Value::scalar(poly::Poly::atom(c.prog.input(quote!(#ident))))
            }
            Output::Type(_) => {
                params.push(quote!(#ident: &#tokens));
                let mut coeffs = std::collections::BTreeMap::new();
                for b in alg.output_blades(ty) {
                    let field = syn::Ident::new(&alg.field_names[b as usize], ident.span());
                    let a = c.prog.input(quote!(#ident.#field));
                    coeffs.insert(b, poly::Poly::atom(a));
                }
                Value {
                    coeffs,
                    ty,
                    versor: is_versor_attr(&pt.attrs),
                    multiple: None,
                }
            }
        };
        let value = c.declare_blade(value, &pt.attrs);
        scope.insert(ident.to_string(), value);
    }
    let returns: Vec<Type> = match &f.sig.output {
        syn::ReturnType::Default => {
            return Err(syn::Error::new_spanned(
                &f.sig,
                "declare the result type, e.g. `-> Vector`",
            ))
        }
        syn::ReturnType::Type(_, ty) => match &**ty {
            Type::Tuple(t) => t.elems.iter().cloned().collect(),
            t => vec![t.clone()],
        },
    };
    let tuple =
        matches!(&f.sig.output, syn::ReturnType::Type(_, t) if matches!(**t, Type::Tuple(_)));
    // The result expressions: a tuple's elements, or the whole body.
    let mut results = Vec::new();
    if tuple {
        let (init, last) = f
            .block
            .stmts
            .split_at(f.block.stmts.len().saturating_sub(1));
        let Some(syn::Stmt::Expr(syn::Expr::Tuple(t), None)) = last.first() else {
            return Err(syn::Error::new_spanned(
                &f.block,
                "a function returning a tuple ends with a tuple expression",
            ));
        };
        if t.elems.len() != returns.len() {
            return Err(syn::Error::new_spanned(
                t,
                "the tuple's length differs from the type's",
            ));
        }
        let prefix = syn::Block {
            brace_token: f.block.brace_token,
            stmts: init
                .iter()
                .cloned()
                .chain(std::iter::once(syn::Stmt::Expr(syn::parse_quote!(0), None)))
                .collect(),
        };
        c.block(&prefix, &mut scope)?;
        for (e, ty) in t.elems.iter().zip(&returns) {
            let v = c.expr(e, &mut scope)?;
            results.push(c.fit(v, type_of(alg, ty)?, e, "this result")?);
        }
    } else {
        let v = c.block(&f.block, &mut scope)?;
        results.push(c.fit(v, type_of(alg, &returns[0])?, &f.block, "the result")?);
    }
    let polys: Vec<&poly::Poly> = results.iter().flat_map(|v| v.coeffs.values()).collect();
    let mut em = c.prog.emit(&polys)?;
    let mut values = Vec::new();
    for v in &results {
        let zero = poly::Poly::zero();
        values.push(match v.ty {
            Output::Scalar => em.render(v.coeffs.get(&0).unwrap_or(&zero))?,
            Output::Type(i) => {
                let name = &alg.types[i].name;
                let name = match path {
                    Some(p) => quote!(#p::#name),
                    None => quote!(#name),
                };
                let mut fields = Vec::new();
                for b in alg.output_blades(v.ty) {
                    let field = syn::Ident::new(&alg.field_names[b as usize], name_span());
                    let e = em.render(v.coeffs.get(&b).unwrap_or(&zero))?;
                    fields.push(quote!(#field: #e));
                }
                quote!(#name { #(#fields),* })
            }
        });
    }
    let constants = em.constant_lets()?;
    let lets = &em.lets;
    let bound = if em.needs_field {
        quote!(::ga_core::scalar::Field)
    } else {
        quote!(::ga_core::scalar::Ring)
    };
    let ret_types: Vec<TokenStream> = returns
        .iter()
        .map(|t| type_of(alg, t).map(|o| type_tokens(alg, o, path)))
        .collect::<syn::Result<_>>()?;
    let (ret, value) = if tuple {
        (quote!((#(#ret_types),*)), quote!((#(#values),*)))
    } else {
        (ret_types[0].clone(), values.remove(0))
    };
    let attrs = &f.attrs;
    let cost = format!(
        "Generated whole by the expression compiler: {} multiplications, {} additions.",
        em.multiplications, em.additions
    );
    let vis = &f.vis;
    let name = &f.sig.ident;
    Ok(quote! {
        #(#attrs)*
        #[doc = ""]
        #[doc = #cost]
        #[allow(unused_variables, unused_parens, clippy::too_many_arguments, clippy::double_parens, clippy::neg_multiply, clippy::let_and_return)]
        #vis fn #name<T: #bound>(#(#params),*) -> #ret {
            #(#constants)*
            #(#lets)*
            #value
        }
    })
}

fn name_span() -> proc_macro2::Span {
    proc_macro2::Span::call_site()
}
