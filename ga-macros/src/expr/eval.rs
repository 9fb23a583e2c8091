//! Evaluating the body of a declared function symbolically: Rust expressions over multivectors
//! (`*`, `^`, `|`, `&`, `+`, `-`, `!`, method calls such as `reverse()` and `sandwich_unit(&x)`,
//! blade constructors `e1()`, exact literals, `let` bindings, calls of the other declared
//! functions, which are inlined) become [`Value`]s over the atoms of a [`Program`].

use std::collections::HashMap;

use num_bigint::BigInt;
use num_traits::{One, Zero};
use quote::ToTokens;
use syn::{BinOp, Expr, FnArg, Lit, Pat, Stmt, Type, UnOp};

use super::poly::{Poly, Q};
use super::program::Program;
use super::value::{grades_of, linear, product, sum, Value};
use crate::blade;
use crate::model::{Algebra, Output, Product};

/// How deep declared functions may call each other (a guard against recursion).
const MAX_CALL_DEPTH: usize = 32;

pub type Scope = HashMap<String, Value>;

pub struct Compiler<'a> {
    pub alg: &'a Algebra,
    pub prog: Program,
    pub fns: &'a HashMap<String, &'a syn::ItemFn>,
    depth: usize,
    /// The declared blades' squares `⟨B B⟩₀` (see [`Value::multiple`]).
    blade_squares: Vec<Poly>,
}

fn err(span: &impl ToTokens, msg: impl std::fmt::Display) -> syn::Error {
    syn::Error::new_spanned(span, msg)
}

/// `#[versor]` or `#[unit]` on a parameter (`#[blade]` is read by
/// [`Compiler::declare_blade`]).
pub fn is_versor_attr(attrs: &[syn::Attribute]) -> bool {
    attrs
        .iter()
        .any(|a| a.path().is_ident("versor") || a.path().is_ident("unit"))
}

/// The generated type a written type names: `T` (the scalar) or a declared type.
pub fn type_of(alg: &Algebra, ty: &Type) -> syn::Result<Output> {
    let ty = match ty {
        Type::Reference(r) => &*r.elem,
        t => t,
    };
    if let Type::Path(p) = ty {
        if let Some(id) = p.path.get_ident() {
            if id == "T" {
                return Ok(Output::Scalar);
            }
            if let Some(i) = alg.types.iter().position(|t| t.emitted && t.name == *id) {
                return Ok(Output::Type(i));
            }
        }
    }
    let names: Vec<String> = alg
        .types
        .iter()
        .filter(|t| t.emitted)
        .map(|t| t.name.to_string())
        .collect();
    Err(err(
        ty,
        format!(
            "expected `T` (the scalar) or one of this algebra's types: {}",
            names.join(", ")
        ),
    ))
}

/// Unwraps parentheses, groups and references.
fn strip(e: &Expr) -> &Expr {
    match e {
        Expr::Paren(p) => strip(&p.expr),
        Expr::Group(g) => strip(&g.expr),
        Expr::Reference(r) => strip(&r.expr),
        e => e,
    }
}

fn same(a: &Expr, b: &Expr) -> bool {
    strip(a).to_token_stream().to_string() == strip(b).to_token_stream().to_string()
}

/// `receiver.reverse()` → `receiver`.
fn reversed(e: &Expr) -> Option<&Expr> {
    match strip(e) {
        Expr::MethodCall(m) if m.method == "reverse" && m.args.is_empty() => Some(&m.receiver),
        _ => None,
    }
}

/// `(V * X) * V.reverse()` or `V * (X * V.reverse())` → `(V, X)`.
fn sandwich_pattern(lhs: &Expr, rhs: &Expr) -> Option<(Expr, Expr)> {
    if let (Expr::Binary(inner), Some(v)) = (strip(lhs), reversed(rhs)) {
        if matches!(inner.op, BinOp::Mul(_)) && same(&inner.left, v) {
            return Some(((*inner.left).clone(), (*inner.right).clone()));
        }
    }
    if let Expr::Binary(inner) = strip(rhs) {
        if let (BinOp::Mul(_), Some(v)) = (inner.op, reversed(&inner.right)) {
            if same(lhs, v) {
                return Some((lhs.clone(), (*inner.left).clone()));
            }
        }
    }
    None
}

/// An exact decimal literal: `114.2` is `1142/10`, `1e-3` is `1/1000`.
fn decimal(text: &str) -> Option<Q> {
    let text = text.replace('_', "");
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
        None => (text.as_str(), 0),
    };
    let (int_part, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: BigInt = format!("{int_part}{frac}").parse().ok()?;
    let scale = exponent - frac.len() as i32;
    let ten = BigInt::from(10);
    Some(if scale >= 0 {
        Q::from_integer(digits * num_traits::pow(ten, scale as usize))
    } else {
        Q::new(digits, num_traits::pow(ten, (-scale) as usize))
    })
}

impl<'a> Compiler<'a> {
    pub fn new(alg: &'a Algebra, fns: &'a HashMap<String, &'a syn::ItemFn>) -> Self {
        Compiler {
            alg,
            prog: Program::default(),
            fns,
            depth: 0,
            blade_squares: Vec::new(),
        }
    }

    /// Gives a `#[blade]` argument its blade number (its square is a scalar).
    pub fn declare_blade(&mut self, v: Value, attrs: &[syn::Attribute]) -> Value {
        if !attrs.iter().any(|a| a.path().is_ident("blade")) {
            return v;
        }
        let square = product(self.alg, &mut self.prog, Product::ScalarProduct, &v, &v);
        self.blade_squares
            .push(square.coeffs.get(&0).cloned().unwrap_or_default());
        Value {
            multiple: Some((self.blade_squares.len() - 1, Poly::constant(Q::one()))),
            ..v
        }
    }

    /// Checks that `v` fits `ty` and gives it that type.
    pub fn fit(&self, v: Value, ty: Output, at: &impl ToTokens, what: &str) -> syn::Result<Value> {
        let outside = v.outside(self.alg, ty);
        if !outside.is_empty() {
            let name = match ty {
                Output::Scalar => "T".to_string(),
                Output::Type(i) => self.alg.types[i].name.to_string(),
            };
            return Err(err(
                at,
                format!(
                    "{what} has nonzero blades {} that `{name}` does not hold: declare a wider \
                     type, project (`grade(k)`, `sandwich_unit`), or mark the versor of a \
                     sandwich `#[versor]`",
                    outside.join(", ")
                ),
            ));
        }
        Ok(Value { ty, ..v })
    }

    /// Evaluates a block: `let` bindings, then the final expression.
    pub fn block(&mut self, block: &syn::Block, scope: &mut Scope) -> syn::Result<Value> {
        let mut last = None;
        for (k, stmt) in block.stmts.iter().enumerate() {
            match stmt {
                Stmt::Local(local) => {
                    let Some(init) = &local.init else {
                        return Err(err(local, "a `let` needs a value"));
                    };
                    let value = self.expr(&init.expr, scope)?;
                    let (name, value) = match &local.pat {
                        Pat::Ident(p) => (p.ident.to_string(), value),
                        Pat::Type(pt) => {
                            let Pat::Ident(p) = &*pt.pat else {
                                return Err(err(&pt.pat, "expected a name"));
                            };
                            let ty = type_of(self.alg, &pt.ty)?;
                            let v = self.fit(value, ty, &init.expr, "this value")?;
                            (p.ident.to_string(), v)
                        }
                        other => return Err(err(other, "expected `let name = …;`")),
                    };
                    scope.insert(name, value);
                }
                Stmt::Expr(e, None) if k + 1 == block.stmts.len() => {
                    last = Some(self.expr(e, scope)?);
                }
                other => {
                    return Err(err(
                        other,
                        "a declared function's body is `let` bindings and a final expression",
                    ))
                }
            }
        }
        last.ok_or_else(|| err(block, "the body needs a final expression (the result)"))
    }

    fn scalar_arg(&mut self, e: &Expr, scope: &mut Scope, what: &str) -> syn::Result<Poly> {
        self.expr(e, scope)?
            .as_scalar()
            .ok_or_else(|| err(e, format!("{what} must be a scalar")))
    }

    pub fn expr(&mut self, e: &Expr, scope: &mut Scope) -> syn::Result<Value> {
        let alg = self.alg;
        match e {
            Expr::Paren(p) => self.expr(&p.expr, scope),
            Expr::Group(g) => self.expr(&g.expr, scope),
            Expr::Reference(r) => self.expr(&r.expr, scope),
            Expr::Lit(l) => match &l.lit {
                Lit::Int(i) => Ok(Value::constant(Q::from_integer(
                    i.base10_parse::<BigInt>()?,
                ))),
                Lit::Float(f) => decimal(f.base10_digits())
                    .map(Value::constant)
                    .ok_or_else(|| err(f, "not a decimal number")),
                other => Err(err(other, "expected a number")),
            },
            Expr::Path(p) => {
                let name = p.path.get_ident().map(|i| i.to_string());
                name.and_then(|n| scope.get(&n).cloned()).ok_or_else(|| {
                    err(
                        p,
                        "unknown name: use a parameter, a `let` binding, a blade such as `e12()` \
                         or a function declared in the same block",
                    )
                })
            }
            Expr::Unary(u) => {
                let v = self.expr(&u.expr, scope)?;
                match u.op {
                    UnOp::Neg(_) => {
                        let m = v.multiple.clone();
                        let neg = v.map_signs(|_| -1);
                        Ok(Value {
                            multiple: m.map(|(i, f)| (i, f.scale(&-Q::one()))),
                            ..neg
                        })
                    }
                    UnOp::Not(_) => Ok(linear(alg, &v, &|b| alg.dual_blade(b))),
                    UnOp::Deref(_) => Ok(v),
                    _ => Err(err(u, "unsupported operator")),
                }
            }
            Expr::Binary(b) => self.binary(b, scope),
            Expr::Field(f) => {
                let v = self.expr(&f.base, scope)?;
                let syn::Member::Named(name) = &f.member else {
                    return Err(err(
                        &f.member,
                        "expected a blade field such as `e12` or `s`",
                    ));
                };
                let Some(b) = alg.field_names.iter().position(|n| name == n) else {
                    return Err(err(name, "no such blade"));
                };
                if !alg.output_blades(v.ty).contains(&(b as u32)) {
                    return Err(err(name, "this value's type has no such blade"));
                }
                Ok(Value::scalar(
                    v.coeffs.get(&(b as u32)).cloned().unwrap_or_default(),
                ))
            }
            Expr::Call(c) => self.call(c, scope),
            Expr::MethodCall(m) => self.method(m, scope),
            other => Err(err(other, "unsupported expression in a declared function")),
        }
    }

    fn binary(&mut self, b: &syn::ExprBinary, scope: &mut Scope) -> syn::Result<Value> {
        let alg = self.alg;
        if let BinOp::Mul(_) = b.op {
            if let Some((v, x)) = sandwich_pattern(&b.left, &b.right) {
                let vv = self.expr(&v, scope)?;
                if vv.versor {
                    let xv = self.expr(&x, scope)?;
                    let p = product(alg, &mut self.prog, Product::Geometric, &vv, &xv);
                    let full = product(
                        alg,
                        &mut self.prog,
                        Product::Geometric,
                        &p,
                        &vv.map_signs(blade::reverse_sign),
                    );
                    // A versor keeps grades: project on those of `X`.
                    let grades = grades_of(alg, xv.ty);
                    let kept: Vec<u32> = alg
                        .output_blades(full.ty)
                        .into_iter()
                        .filter(|&o| grades.contains(&blade::grade(o)))
                        .collect();
                    let set = kept.iter().fold(crate::model::BladeSet::EMPTY, |s, &o| {
                        s.union(&crate::model::BladeSet::single(o))
                    });
                    let ty = alg.resolve(set);
                    return Ok(full.project(ty, |o| grades.contains(&blade::grade(o))));
                }
            }
        }
        let l = self.expr(&b.left, scope)?;
        let r = self.expr(&b.right, scope)?;
        let kind = match b.op {
            BinOp::Add(_) => return Ok(sum(alg, &l, &r, 1)),
            BinOp::Sub(_) => return Ok(sum(alg, &l, &r, -1)),
            BinOp::Div(_) => {
                let d = r
                    .as_scalar()
                    .ok_or_else(|| err(&b.right, "only division by a scalar is supported"))?;
                let recip = match d.as_constant() {
                    Some(c) if c.is_zero() => return Err(err(&b.right, "division by zero")),
                    Some(c) => Poly::constant(Q::one() / c),
                    None => self.prog.reciprocal(&d),
                };
                return Ok(l.scale(&recip, &mut self.prog));
            }
            BinOp::Mul(_) => Product::Geometric,
            BinOp::BitXor(_) => Product::Wedge,
            BinOp::BitOr(_) => Product::LeftContraction,
            BinOp::BitAnd(_) => Product::Regressive,
            _ => return Err(err(b, "unsupported operator")),
        };
        // Two multiples of one declared blade: `f B f' B = f f' B²`, a scalar.
        if let (Product::Geometric, Some((i, f)), Some((j, g))) = (kind, &l.multiple, &r.multiple) {
            if i == j {
                let fg = Value::scalar(f.clone()).scale(g, &mut self.prog);
                return Ok(
                    Value::scalar(fg.coeffs.get(&0).cloned().unwrap_or_default())
                        .scale(&self.blade_squares[*i].clone(), &mut self.prog),
                );
            }
        }
        // A scalar factor keeps the other operand's type (and versor-ness).
        if let (Product::Geometric, Some(s)) = (kind, l.as_scalar()) {
            if l.ty == Output::Scalar {
                return Ok(r.scale(&s, &mut self.prog));
            }
        }
        if let (Product::Geometric, Some(s)) = (kind, r.as_scalar()) {
            if r.ty == Output::Scalar {
                return Ok(l.scale(&s, &mut self.prog));
            }
        }
        Ok(product(alg, &mut self.prog, kind, &l, &r))
    }

    fn call(&mut self, c: &syn::ExprCall, scope: &mut Scope) -> syn::Result<Value> {
        let alg = self.alg;
        let name = match &*c.func {
            Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
            _ => None,
        }
        .ok_or_else(|| {
            err(
                &c.func,
                "expected a blade such as `e12()` or a declared function",
            )
        })?;
        if let Some(f) = self.fns.get(&name).copied() {
            return self.inline(f, c, scope);
        }
        match alg.field_names.iter().position(|n| *n == name) {
            Some(b) if b > 0 && c.args.is_empty() => Ok(Value::blade(alg, b as u32)),
            _ => Err(err(
                &c.func,
                format!("`{name}` is neither a blade of this algebra nor a declared function"),
            )),
        }
    }

    fn inline(
        &mut self,
        f: &syn::ItemFn,
        c: &syn::ExprCall,
        scope: &mut Scope,
    ) -> syn::Result<Value> {
        if self.depth >= MAX_CALL_DEPTH {
            return Err(err(
                c,
                "declared functions call each other too deeply (recursion?)",
            ));
        }
        if f.sig.inputs.len() != c.args.len() {
            return Err(err(
                c,
                format!(
                    "`{}` takes {} arguments, {} given",
                    f.sig.ident,
                    f.sig.inputs.len(),
                    c.args.len()
                ),
            ));
        }
        let mut inner = Scope::new();
        for (param, arg) in f.sig.inputs.iter().zip(&c.args) {
            let FnArg::Typed(pt) = param else {
                return Err(err(param, "declared functions take no `self`"));
            };
            let Pat::Ident(id) = &*pt.pat else {
                return Err(err(&pt.pat, "expected a parameter name"));
            };
            let ty = type_of(self.alg, &pt.ty)?;
            let v = self.expr(arg, scope)?;
            let mut v = self.fit(v, ty, arg, "this argument")?;
            v.versor |= is_versor_attr(&pt.attrs);
            let v = self.declare_blade(v, &pt.attrs);
            inner.insert(id.ident.to_string(), v);
        }
        self.depth += 1;
        let result = self.block(&f.block, &mut inner);
        self.depth -= 1;
        let result = result?;
        match &f.sig.output {
            syn::ReturnType::Type(_, ty) if !matches!(**ty, Type::Tuple(_)) => {
                let ty = type_of(self.alg, ty)?;
                self.fit(result, ty, c, &format!("the result of `{}`", f.sig.ident))
            }
            _ => Err(err(c, "only functions returning one value can be called")),
        }
    }

    fn method(&mut self, m: &syn::ExprMethodCall, scope: &mut Scope) -> syn::Result<Value> {
        let alg = self.alg;
        let recv = self.expr(&m.receiver, scope)?;
        let name = m.method.to_string();
        let args: Vec<&Expr> = m.args.iter().collect();
        let arity = |n: usize| -> syn::Result<()> {
            if args.len() == n {
                Ok(())
            } else {
                Err(err(m, format!("`{name}` takes {n} argument(s)")))
            }
        };
        let binary = |kind| Some(kind);
        let kind = match name.as_str() {
            "geometric" => binary(Product::Geometric),
            "wedge" => binary(Product::Wedge),
            "left_contraction" => binary(Product::LeftContraction),
            "right_contraction" => binary(Product::RightContraction),
            "scalar_product" => binary(Product::ScalarProduct),
            "regressive" => binary(Product::Regressive),
            _ => None,
        };
        if let Some(kind) = kind {
            arity(1)?;
            let rhs = self.expr(args[0], scope)?;
            return Ok(product(alg, &mut self.prog, kind, &recv, &rhs));
        }
        match name.as_str() {
            "clone" => {
                arity(0)?;
                Ok(recv)
            }
            "reverse" | "grade_involution" | "conjugate" => {
                arity(0)?;
                Ok(match name.as_str() {
                    "reverse" => recv.map_signs(blade::reverse_sign),
                    "grade_involution" => recv.map_signs(blade::involution_sign),
                    _ => recv.map_signs(blade::conjugate_sign),
                })
            }
            "dual" => {
                arity(0)?;
                Ok(linear(alg, &recv, &|b| alg.dual_blade(b)))
            }
            "undual" => {
                arity(0)?;
                Ok(linear(alg, &recv, &|b| alg.undual_blade(b)))
            }
            "grade" => {
                arity(1)?;
                let k = match strip(args[0]) {
                    Expr::Lit(syn::ExprLit {
                        lit: Lit::Int(i), ..
                    }) => i.base10_parse::<usize>()?,
                    other => return Err(err(other, "the grade must be an integer literal")),
                };
                let ty = recv.ty;
                Ok(recv.project(ty, |b| blade::grade(b) == k))
            }
            "scale" => {
                arity(1)?;
                let s = self.scalar_arg(args[0], scope, "the factor")?;
                Ok(recv.scale(&s, &mut self.prog))
            }
            "norm_squared" => {
                arity(0)?;
                let rev = recv.map_signs(blade::reverse_sign);
                let p = product(alg, &mut self.prog, Product::ScalarProduct, &recv, &rev);
                Ok(Value::scalar(p.coeffs.get(&0).cloned().unwrap_or_default()))
            }
            "sandwich_unit" => {
                arity(1)?;
                let x = self.expr(args[0], scope)?;
                let p = product(alg, &mut self.prog, Product::Geometric, &recv, &x);
                let rev = recv.map_signs(blade::reverse_sign);
                let full = product(alg, &mut self.prog, Product::Geometric, &p, &rev);
                let keep = alg.output_blades(x.ty);
                Ok(full.project(x.ty, |b| keep.contains(&b)))
            }
            _ => Err(err(
                &m.method,
                "unsupported method: reverse, grade_involution, conjugate, dual, undual, \
                 grade(k), scale(s), norm_squared, sandwich_unit(x), geometric, wedge, \
                 left_contraction, right_contraction, scalar_product, regressive",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::poly::int;
    use super::*;

    #[test]
    fn decimals_are_exact() {
        assert_eq!(decimal("114.2"), Some(Q::new(1142.into(), 10.into())));
        assert_eq!(decimal("1e-3"), Some(Q::new(1.into(), 1000.into())));
        assert_eq!(decimal("2.5e1"), Some(int(25)));
    }
}
