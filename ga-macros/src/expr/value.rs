//! Symbolic multivectors: per blade a polynomial, the declared type the same expression would
//! have if evaluated product by product (so that projections such as `sandwich_unit` keep the
//! same blades), and whether the value is known to be a versor.

use std::collections::BTreeMap;

use super::poly::{int, Poly, Q};
use super::program::Program;
use crate::blade::{self, Blade};
use crate::model::{Algebra, BladeSet, Output, Product};

#[derive(Clone, Debug)]
pub struct Value {
    /// The nonzero coefficients.
    pub coeffs: BTreeMap<Blade, Poly>,
    /// The type of the product-by-product evaluation.
    pub ty: Output,
    /// Declared (or derived) to be a versor: `V X Ṽ` keeps the grades of `X`.
    pub versor: bool,
    /// `factor · B` for the declared blade `B` number `.0` (a `#[blade]` argument): the product
    /// of two multiples of one blade is the scalar `factor · factor' · B²`.
    pub multiple: Option<(usize, Poly)>,
}

fn set_of(alg: &Algebra, ty: Output) -> BladeSet {
    alg.output_blades(ty)
        .into_iter()
        .fold(BladeSet::EMPTY, |s, b| s.union(&BladeSet::single(b)))
}

impl Value {
    pub fn constant(c: Q) -> Value {
        let mut coeffs = BTreeMap::new();
        let p = Poly::constant(c);
        if !p.is_zero() {
            coeffs.insert(0, p);
        }
        Value {
            coeffs,
            ty: Output::Scalar,
            versor: false,
            multiple: None,
        }
    }

    pub fn scalar(p: Poly) -> Value {
        let mut coeffs = BTreeMap::new();
        if !p.is_zero() {
            coeffs.insert(0, p);
        }
        Value {
            coeffs,
            ty: Output::Scalar,
            versor: false,
            multiple: None,
        }
    }

    pub fn blade(alg: &Algebra, b: Blade) -> Value {
        let mut coeffs = BTreeMap::new();
        coeffs.insert(b, Poly::constant(int(1)));
        Value {
            coeffs,
            ty: alg.resolve(BladeSet::single(b)),
            versor: false,
            multiple: None,
        }
    }

    /// The scalar part when the value has no other blade.
    pub fn as_scalar(&self) -> Option<Poly> {
        if self.coeffs.keys().all(|&b| b == 0) {
            Some(self.coeffs.get(&0).cloned().unwrap_or_default())
        } else {
            None
        }
    }

    pub fn map_signs(&self, sign: fn(Blade) -> i32) -> Value {
        let coeffs = self
            .coeffs
            .iter()
            .map(|(&b, p)| (b, p.scale(&int(i64::from(sign(b))))))
            .collect();
        Value {
            coeffs,
            ty: self.ty,
            versor: self.versor,
            multiple: None,
        }
    }

    pub fn scale(&self, c: &Poly, prog: &mut Program) -> Value {
        let mut v = product_with(prog, &Value::scalar(c.clone()), self, &|_, b| vec![(1, b)]);
        v.ty = self.ty;
        v.versor = self.versor;
        v.multiple = self.multiple.as_ref().map(|(id, f)| {
            let f = product_with(
                prog,
                &Value::scalar(f.clone()),
                &Value::scalar(c.clone()),
                &|_, _| vec![(1, 0)],
            );
            (*id, f.coeffs.get(&0).cloned().unwrap_or_default())
        });
        v
    }

    /// Keeps the blades `keep` accepts, as type `ty`.
    pub fn project(&self, ty: Output, keep: impl Fn(Blade) -> bool) -> Value {
        Value {
            coeffs: self
                .coeffs
                .iter()
                .filter(|(&b, _)| keep(b))
                .map(|(&b, p)| (b, p.clone()))
                .collect(),
            ty,
            versor: false,
            multiple: None,
        }
    }

    /// The blades (names) that are nonzero but outside `ty`.
    pub fn outside(&self, alg: &Algebra, ty: Output) -> Vec<String> {
        let set = set_of(alg, ty);
        self.coeffs
            .keys()
            .filter(|&&b| !set.contains(b))
            .map(|&b| alg.blade_names[b as usize].clone())
            .collect()
    }
}

/// The bilinear map `terms` applied coefficient-wise: each coefficient used as a factor against a
/// non-constant one is first made a constant or `c · atom` (a shared temporary if longer).
fn product_with(
    prog: &mut Program,
    a: &Value,
    b: &Value,
    terms: &dyn Fn(Blade, Blade) -> Vec<(i32, Blade)>,
) -> Value {
    let factor = |prog: &mut Program, p: &Poly, other: &BTreeMap<Blade, Poly>| {
        if other.values().all(|q| q.as_constant().is_some()) {
            p.clone()
        } else {
            prog.atomize(p)
        }
    };
    let fa: Vec<(Blade, Poly)> = a
        .coeffs
        .iter()
        .map(|(&k, p)| (k, factor(prog, p, &b.coeffs)))
        .collect();
    let fb: Vec<(Blade, Poly)> = b
        .coeffs
        .iter()
        .map(|(&k, p)| (k, factor(prog, p, &a.coeffs)))
        .collect();
    let mut out: BTreeMap<Blade, Poly> = BTreeMap::new();
    for (ba, pa) in &fa {
        for (bb, pb) in &fb {
            let t = terms(*ba, *bb);
            if t.is_empty() {
                continue;
            }
            let prod = pa.mul(pb);
            for (s, o) in t {
                out.entry(o)
                    .or_default()
                    .add_scaled(&prod, &int(i64::from(s)));
            }
        }
    }
    out.retain(|_, p| !p.is_zero());
    Value {
        coeffs: out,
        ty: Output::Scalar,
        versor: false,
        multiple: None,
    }
}

/// `a ∘ b` for one of the algebra's products.
pub fn product(alg: &Algebra, prog: &mut Program, kind: Product, a: &Value, b: &Value) -> Value {
    let mut v = product_with(prog, a, b, &|x, y| alg.blade_terms(kind, x, y));
    v.ty = alg
        .bilinear(kind, &alg.output_blades(a.ty), &alg.output_blades(b.ty))
        .output;
    v.versor = kind == Product::Geometric && a.versor && b.versor;
    v
}

/// `a + c · b` (`c = ±1`).
pub fn sum(alg: &Algebra, a: &Value, b: &Value, c: i64) -> Value {
    let mut coeffs = a.coeffs.clone();
    for (&k, p) in &b.coeffs {
        coeffs.entry(k).or_default().add_scaled(p, &int(c));
    }
    coeffs.retain(|_, p| !p.is_zero());
    let set = set_of(alg, a.ty).union(&set_of(alg, b.ty));
    Value {
        coeffs,
        ty: alg.resolve(set),
        versor: false,
        multiple: None,
    }
}

/// A blade-wise linear map (dual, undual).
pub fn linear(alg: &Algebra, a: &Value, f: &dyn Fn(Blade) -> Vec<(i32, Blade)>) -> Value {
    let mut coeffs: BTreeMap<Blade, Poly> = BTreeMap::new();
    for (&k, p) in &a.coeffs {
        for (s, o) in f(k) {
            coeffs
                .entry(o)
                .or_default()
                .add_scaled(p, &int(i64::from(s)));
        }
    }
    coeffs.retain(|_, p| !p.is_zero());
    let ty = alg.blade_map(&alg.output_blades(a.ty), f).output;
    Value {
        coeffs,
        ty,
        versor: false,
        multiple: None,
    }
}

/// The grades present in a type.
pub fn grades_of(alg: &Algebra, ty: Output) -> Vec<usize> {
    let mut g: Vec<usize> = alg
        .output_blades(ty)
        .into_iter()
        .map(blade::grade)
        .collect();
    g.sort_unstable();
    g.dedup();
    g
}
