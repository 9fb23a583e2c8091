//! Shared harness of the generated-vs-reference tests: scalar comparison, conversion of
//! generated values to the dense reference, per-pair and per-type checks, and the
//! `algebra_suite!` macro that enumerates every ordered pair of an algebra's declared types.
#![allow(dead_code)]

pub mod sym;

pub use std::any::type_name;
pub use std::fmt::Debug;
pub use std::ops::{Add, BitAnd, BitOr, BitXor, Mul, Sub};

pub use ga_core::ops::SandwichUnit;
pub use ga_core::prelude::*;
pub use ga_core::reference::{
    canonical_blade_names, canonical_order, DenseMultivector as Dm, Signature,
};
pub use ga_core::scalar::Rational;
pub use proptest::prelude::*;

// ---------------------------------------------------------------------------------------------
// Scalars: exact comparison for rationals, relative tolerance for f64.

/// A coefficient type under test.
pub trait Scalar: Real + Debug + ToRef<Self> + 'static {
    /// Whether equality is exact.
    const EXACT: bool;
    /// `a == b` (exact), or `|a - b| <= 1e-12 · max(1, scale)` (f64).
    fn close(a: &Self, b: &Self, scale: f64) -> bool;
    /// Random coefficients (zero about a quarter of the time).
    fn strategy() -> BoxedStrategy<Self>;
}

impl Scalar for f64 {
    const EXACT: bool = false;
    fn close(a: &Self, b: &Self, scale: f64) -> bool {
        (a - b).abs() <= 1e-12 * scale.max(1.0)
    }
    fn strategy() -> BoxedStrategy<Self> {
        prop_oneof![1 => Just(0.0), 3 => -2.0f64..2.0].boxed()
    }
}

impl Scalar for Rational {
    const EXACT: bool = true;
    fn close(a: &Self, b: &Self, _scale: f64) -> bool {
        a == b
    }
    fn strategy() -> BoxedStrategy<Self> {
        prop_oneof![
            1 => Just(<Rational as Ring>::zero()),
            3 => (-5i64..=5, 1i64..=4).prop_map(|(n, d)| Rational::new(n.into(), d.into())),
        ]
        .boxed()
    }
}

/// Conversion of a generated value (or a scalar result) into the reference.
pub trait ToRef<T> {
    fn to_ref(&self, sig: &Signature) -> Dm<T>;
}

impl ToRef<f64> for f64 {
    fn to_ref(&self, sig: &Signature) -> Dm<f64> {
        Dm::scalar(sig, *self)
    }
}

impl ToRef<Rational> for Rational {
    fn to_ref(&self, sig: &Signature) -> Dm<Rational> {
        Dm::scalar(sig, self.clone())
    }
}

/// A product that is zero by grade: the zero multivector.
impl<T: Ring> ToRef<T> for ga_core::Zero<T> {
    fn to_ref(&self, sig: &Signature) -> Dm<T> {
        Dm::scalar(sig, self.value())
    }
}

/// A generated type: built from a reference value by projection onto its blades.
pub trait Gen<T>: ToRef<T> + Clone + Debug + Sized {
    /// The projection of `r` onto this type's blades, through the generated dense type and
    /// `from_multivector`.
    fn from_ref(r: &Dm<T>) -> Self;
    /// This type's blade names (`X::BLADES`).
    fn blade_names() -> &'static [&'static str];
}

pub fn short<X>() -> &'static str {
    let full = type_name::<X>();
    let base = full.split('<').next().unwrap_or(full);
    base.rsplit("::").next().unwrap_or(base)
}

pub fn magnitude<T: Scalar>(m: &Dm<T>) -> f64 {
    m.coefficients()
        .iter()
        .map(|c| c.to_f64().abs())
        .fold(0.0, f64::max)
}

// ---------------------------------------------------------------------------------------------
// Per-algebra context and comparison with a precise report.

pub struct Ctx {
    pub sig: Signature,
    /// Canonical blade names, computed by the reference from the generated `BASIS`.
    pub names: Vec<String>,
    /// Bitmasks in canonical order.
    pub order: Vec<usize>,
}

impl Ctx {
    pub fn new(signature: &[i8], basis: &[&str]) -> Self {
        let sig = Signature::new(signature).unwrap();
        let names = canonical_blade_names(sig.len(), Some(basis)).unwrap();
        let order = canonical_order(sig.len());
        Self { sig, names, order }
    }

    pub fn mask_of(&self, name: &str) -> usize {
        let i = self
            .names
            .iter()
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("blade name {name} is not canonical: {:?}", self.names));
        self.order[i]
    }

    pub fn masks_of(&self, names: &[&str]) -> Vec<usize> {
        names.iter().map(|n| self.mask_of(n)).collect()
    }

    /// Records a failure listing every blade where `got` differs from `expected`.
    pub fn compare<T: Scalar>(
        &self,
        fails: &mut Vec<String>,
        what: &str,
        got: &Dm<T>,
        expected: &Dm<T>,
        scale: f64,
    ) {
        let diffs: Vec<String> = self
            .order
            .iter()
            .zip(&self.names)
            .filter_map(|(&m, name)| {
                let (g, e) = (got.get(m), expected.get(m));
                (!T::close(&g, &e, scale))
                    .then(|| format!("blade {name}: expected {e:?}, got {g:?}"))
            })
            .collect();
        if !diffs.is_empty() {
            fails.push(format!("{what}: {}", diffs.join("; ")));
        }
    }

    pub fn compare_option<T: Scalar>(
        &self,
        fails: &mut Vec<String>,
        what: &str,
        got: Option<Dm<T>>,
        expected: Option<Dm<T>>,
        scale: f64,
    ) {
        match (got, expected) {
            (Some(g), Some(e)) => self.compare(fails, what, &g, &e, scale),
            (None, None) => {}
            (g, e) => fails.push(format!(
                "{what}: expected {:?}, got {:?}",
                e.map(|m| m.to_canonical()),
                g.map(|m| m.to_canonical())
            )),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Opaque calls. Every generated product is called through a `black_box`ed function pointer, so
// that the optimiser compiles each generated function once, on its own, instead of inlining
// hundreds of large straight-line bodies into one test function (which made this file take
// tens of minutes to compile).

pub fn op1<A, O>(f: fn(&A) -> O, a: &A) -> O {
    std::hint::black_box(f)(a)
}

pub fn op2<A, B, O>(f: fn(&A, &B) -> O, a: &A, b: &B) -> O {
    std::hint::black_box(f)(a, b)
}

pub fn op2v<A, B, O>(f: fn(A, B) -> O, a: A, b: B) -> O {
    std::hint::black_box(f)(a, b)
}

// ---------------------------------------------------------------------------------------------
// Every product of one ordered pair (A, B).

#[inline(never)]
pub fn check_pair<T, A, B>(cx: &Ctx, xa: &Dm<T>, xb: &Dm<T>, fails: &mut Vec<String>)
where
    T: Scalar,
    A: Gen<T>
        + Geometric<B>
        + Wedge<B>
        + LeftContraction<B>
        + RightContraction<B>
        + ScalarProduct<B>
        + Regressive<B>
        + Sandwich<B>
        + SandwichUnit<B>
        + Add<B>
        + Sub<B>,
    B: Gen<T>,
    <A as Geometric<B>>::Output: ToRef<T>,
    <A as Wedge<B>>::Output: ToRef<T>,
    <A as LeftContraction<B>>::Output: ToRef<T>,
    <A as RightContraction<B>>::Output: ToRef<T>,
    <A as ScalarProduct<B>>::Output: ToRef<T>,
    <A as Regressive<B>>::Output: ToRef<T>,
    <A as Add<B>>::Output: ToRef<T>,
    <A as Sub<B>>::Output: ToRef<T>,
{
    let sig = &cx.sig;
    let a = A::from_ref(xa);
    let b = B::from_ref(xb);
    let ra = a.to_ref(sig);
    let rb = b.to_ref(sig);
    let pair = format!("{} × {}", short::<A>(), short::<B>());
    let len = cx.order.len() as f64;
    let s2 = (magnitude(&ra) * magnitude(&rb) * len).max(1.0);
    let mut cmp = |what: &str, got: Dm<T>, expected: &Dm<T>, scale: f64| {
        cx.compare(fails, &format!("{pair}: {what}"), &got, expected, scale)
    };

    let expected = ra.geometric(&rb);
    cmp(
        "geometric",
        op2(<A as Geometric<B>>::geometric, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = ra.wedge(&rb);
    cmp(
        "wedge",
        op2(<A as Wedge<B>>::wedge, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = ra.left_contraction(&rb);
    cmp(
        "left_contraction",
        op2(<A as LeftContraction<B>>::left_contraction, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = ra.right_contraction(&rb);
    cmp(
        "right_contraction",
        op2(<A as RightContraction<B>>::right_contraction, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = Dm::scalar(sig, ra.scalar_product(&rb));
    cmp(
        "scalar_product",
        op2(<A as ScalarProduct<B>>::scalar_product, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = ra.regressive(&rb);
    cmp(
        "regressive",
        op2(<A as Regressive<B>>::regressive, &a, &b).to_ref(sig),
        &expected,
        s2,
    );

    let expected = &ra + &rb;
    cmp(
        "+",
        op2v(<A as Add<B>>::add, a.clone(), b.clone()).to_ref(sig),
        &expected,
        s2,
    );
    let expected = &ra - &rb;
    cmp(
        "-",
        op2v(<A as Sub<B>>::sub, a.clone(), b.clone()).to_ref(sig),
        &expected,
        s2,
    );

    // Sandwiches V X V⁻¹ and V X Ṽ, projected onto X's blades (here V = a, X = b).
    let b_masks = cx.masks_of(B::blade_names());
    let on_b = |m: Dm<T>| m.project(|k| b_masks.contains(&k));
    let s3 = (magnitude(&ra).powi(2) * magnitude(&rb) * len * len).max(1.0);
    cmp(
        "sandwich_unit",
        op2(<A as SandwichUnit<B>>::sandwich_unit, &a, &b).to_ref(sig),
        &on_b(ra.sandwich_unit(&rb)),
        s3,
    );
    let ns = ra.norm_squared().to_f64().abs();
    let s3_inv = if ns > 0.0 { s3 / ns } else { s3 };
    cx.compare_option(
        fails,
        &format!("{pair}: sandwich"),
        op2(<A as Sandwich<B>>::sandwich, &a, &b).map(|x| x.to_ref(sig)),
        ra.sandwich(&rb).map(on_b),
        s3_inv,
    );
}

/// The operators of one ordered pair are the methods (checked in `f64` only: the operators are
/// scalar-independent wrappers, and instantiating them for every scalar type would double the
/// compile time of this test).
#[inline(never)]
pub fn check_ops<A, B>(cx: &Ctx, xa: &Dm<f64>, xb: &Dm<f64>, fails: &mut Vec<String>)
where
    A: Gen<f64>
        + Geometric<B>
        + Wedge<B>
        + LeftContraction<B>
        + Regressive<B>
        + Mul<B, Output = <A as Geometric<B>>::Output>
        + BitXor<B, Output = <A as Wedge<B>>::Output>
        + BitOr<B, Output = <A as LeftContraction<B>>::Output>
        + BitAnd<B, Output = <A as Regressive<B>>::Output>
        + Add<B>
        + Sub<B>,
    B: Gen<f64>,
    <A as Geometric<B>>::Output: ToRef<f64>,
    <A as Wedge<B>>::Output: ToRef<f64>,
    <A as LeftContraction<B>>::Output: ToRef<f64>,
    <A as Regressive<B>>::Output: ToRef<f64>,
    <A as Add<B>>::Output: ToRef<f64>,
    <A as Sub<B>>::Output: ToRef<f64>,
    for<'x> &'x A: Mul<&'x B, Output = <A as Geometric<B>>::Output>
        + BitXor<&'x B, Output = <A as Wedge<B>>::Output>
        + BitOr<&'x B, Output = <A as LeftContraction<B>>::Output>
        + BitAnd<&'x B, Output = <A as Regressive<B>>::Output>
        + Add<&'x B, Output = <A as Add<B>>::Output>
        + Sub<&'x B, Output = <A as Sub<B>>::Output>,
{
    let sig = &cx.sig;
    let a = A::from_ref(xa);
    let b = B::from_ref(xb);
    let pair = format!("{} × {}", short::<A>(), short::<B>());
    // The operators call the very same code: the results must be identical.
    let mut same = |what: &str, got: Dm<f64>, expected: Dm<f64>| {
        cx.compare(fails, &format!("{pair}: {what}"), &got, &expected, 0.0)
    };
    same(
        "a * b",
        op2v(<A as Mul<B>>::mul, a.clone(), b.clone()).to_ref(sig),
        op2(<A as Geometric<B>>::geometric, &a, &b).to_ref(sig),
    );
    same(
        "&a * &b",
        op2v(<&A as Mul<&B>>::mul, &a, &b).to_ref(sig),
        op2(<A as Geometric<B>>::geometric, &a, &b).to_ref(sig),
    );
    same(
        "a ^ b",
        op2v(<A as BitXor<B>>::bitxor, a.clone(), b.clone()).to_ref(sig),
        op2(<A as Wedge<B>>::wedge, &a, &b).to_ref(sig),
    );
    same(
        "&a ^ &b",
        op2v(<&A as BitXor<&B>>::bitxor, &a, &b).to_ref(sig),
        op2(<A as Wedge<B>>::wedge, &a, &b).to_ref(sig),
    );
    same(
        "a | b",
        op2v(<A as BitOr<B>>::bitor, a.clone(), b.clone()).to_ref(sig),
        op2(<A as LeftContraction<B>>::left_contraction, &a, &b).to_ref(sig),
    );
    same(
        "&a | &b",
        op2v(<&A as BitOr<&B>>::bitor, &a, &b).to_ref(sig),
        op2(<A as LeftContraction<B>>::left_contraction, &a, &b).to_ref(sig),
    );
    same(
        "a & b",
        op2v(<A as BitAnd<B>>::bitand, a.clone(), b.clone()).to_ref(sig),
        op2(<A as Regressive<B>>::regressive, &a, &b).to_ref(sig),
    );
    same(
        "&a & &b",
        op2v(<&A as BitAnd<&B>>::bitand, &a, &b).to_ref(sig),
        op2(<A as Regressive<B>>::regressive, &a, &b).to_ref(sig),
    );
    same(
        "&a + &b",
        op2v(<&A as Add<&B>>::add, &a, &b).to_ref(sig),
        op2v(<A as Add<B>>::add, a.clone(), b.clone()).to_ref(sig),
    );
    same(
        "&a - &b",
        op2v(<&A as Sub<&B>>::sub, &a, &b).to_ref(sig),
        op2v(<A as Sub<B>>::sub, a.clone(), b.clone()).to_ref(sig),
    );
}

// ---------------------------------------------------------------------------------------------
// Cartesian enumeration of the pairs: `cartesian!(callback!(ctx); [A, B, ...]; [A, B, ...])`
// invokes `callback!(ctx; X, Y)` for every X of the first list and Y of the second.

macro_rules! cartesian {
    ($cb:ident ! $ctx:tt; [$($a:ident),* $(,)?]; $bs:tt) => {
        $( cartesian!(@row $cb ! $ctx; $a; $bs); )*
    };
    (@row $cb:ident ! $ctx:tt; $a:ident; [$($b:ident),* $(,)?]) => {
        $( $cb!($ctx; $a, $b); )*
    };
}

macro_rules! pair_check {
    (($T:ident, $cx:ident, $xa:ident, $xb:ident, $fails:ident, $seen:ident); $a:ident, $b:ident) => {
        $seen.push((stringify!($a), stringify!($b)));
        check_pair::<$T, alg::$a<$T>, alg::$b<$T>>($cx, $xa, $xb, &mut $fails);
    };
}

macro_rules! ops_check {
    (($cx:ident, $xa:ident, $xb:ident, $fails:ident, $seen:ident); $a:ident, $b:ident) => {
        $seen.push((stringify!($a), stringify!($b)));
        check_ops::<alg::$a<f64>, alg::$b<f64>>($cx, $xa, $xb, &mut $fails);
    };
}

/// Every unary operation of one type against the reference.
macro_rules! unary_check {
    (($T:ident, $cx:ident, $xa:ident, $s:ident, $fails:ident); $x:ident) => {{
        // A function of its own (not inlined) per type, to keep compile times small.
        #[inline(never)]
        fn unary<$T: Scalar>($cx: &Ctx, $xa: &Dm<$T>, $s: &$T, $fails: &mut Vec<String>) {
            unary_check!(@body ($T, $cx, $xa, $s, $fails); $x);
        }
        unary::<$T>($cx, $xa, $s, &mut $fails);
    }};
    (@body ($T:ident, $cx:ident, $xa:ident, $s:ident, $fails:ident); $x:ident) => {{
        let sig = &$cx.sig;
        let a = <alg::$x<$T> as Gen<$T>>::from_ref($xa);
        let ra = a.to_ref(sig);
        let name = stringify!($x);
        let n = sig.len();
        let m = magnitude(&ra).max(1.0);
        let len = $cx.order.len() as f64;
        // The projection keeps exactly the type's blades.
        let masks = $cx.masks_of(<alg::$x<$T> as Gen<$T>>::blade_names());
        $cx.compare(
            $fails,
            &format!("{name}::from_multivector (projection)"),
            &ra,
            &$xa.project(|k| masks.contains(&k)),
            m,
        );
        let mut cmp = |what: &str, got: Dm<$T>, expected: Dm<$T>, scale: f64| {
            $cx.compare($fails, &format!("{name}: {what}"), &got, &expected, scale)
        };
        cmp("reverse", a.reverse().to_ref(sig), ra.reverse(), m);
        cmp("grade_involution", a.grade_involution().to_ref(sig), ra.grade_involution(), m);
        cmp("conjugate", a.conjugate().to_ref(sig), ra.conjugate(), m);
        cmp("dual", a.dual().to_ref(sig), ra.dual(), m);
        cmp("undual", a.undual().to_ref(sig), ra.undual(), m);
        cmp("!a", (!a.clone()).to_ref(sig), ra.dual(), m);
        cmp("!&a", (!&a).to_ref(sig), ra.dual(), m);
        cmp("-a", (-a.clone()).to_ref(sig), -&ra, m);
        cmp("-&a", (-&a).to_ref(sig), -&ra, m);
        for k in 0..=n + 1 {
            cmp(&format!("grade({k})"), a.grade(k).to_ref(sig), ra.grade(k), m);
        }
        cmp(
            "norm_squared",
            a.norm_squared().to_ref(sig),
            Dm::scalar(sig, ra.norm_squared()),
            m * m * len,
        );
        cmp("scale(&s)", a.scale($s).to_ref(sig), ra.scale($s), m * 4.0);
        cmp("a * s", (a.clone() * $s.clone()).to_ref(sig), ra.scale($s), m * 4.0);
        let ns = ra.norm_squared().to_f64().abs();
        $cx.compare_option(
            $fails,
            &format!("{name}: versor_inverse"),
            a.versor_inverse().map(|x| x.to_ref(sig)),
            ra.versor_inverse(),
            // The relative error of a near-zero ⟨AÃ⟩₀ (cancellation) is ~ m² len / |⟨AÃ⟩₀| ulps.
            if ns > 0.0 { (m / ns) * (1.0 + m * m * len / ns) } else { m },
        );
        // The checked inverse: exactly the reference's general inverse when that lies in the
        // type, else `None`; in f64, a returned value is an inverse (both products are 1).
        // (An inverse is unique, so checking both products is checking equality with it.)
        match a.inverse().map(|x| x.to_ref(sig)) {
            Some(y) => {
                let one = Dm::one(sig);
                let scale = m * magnitude(&y) * len * len;
                $cx.compare($fails, &format!("{name}: x inverse(x)"), &(&ra * &y), &one, scale);
                $cx.compare($fails, &format!("{name}: inverse(x) x"), &(&y * &ra), &one, scale);
            }
            None if $T::EXACT => {
                let expected = ra
                    .general_inverse()
                    .filter(|inv| inv.project(|k| masks.contains(&k)) == *inv);
                $cx.compare_option($fails, &format!("{name}: inverse"), None, expected, m);
            }
            None => {}
        }
    }};
}

/// Sandwich of every type by one versor type, for the reference versors that fit in it.
macro_rules! versor_check {
    (($T:ident, $cx:ident, $versors:ident, $x:ident, $fails:ident); $vt:ident, $xt:ident) => {{
        let sig = &$cx.sig;
        let v_masks = $cx.masks_of(<alg::$vt<$T> as Gen<$T>>::blade_names());
        for rv in &$versors {
            if rv.project(|k| v_masks.contains(&k)) != *rv {
                continue; // this versor does not fit in the type
            }
            let v = <alg::$vt<$T> as Gen<$T>>::from_ref(rv);
            let xv = <alg::$xt<$T> as Gen<$T>>::from_ref($x);
            let rx = xv.to_ref(sig);
            let grade = (0..rv.coefficients().len())
                .filter(|&m| !rv.get(m).is_zero())
                .map(|m| m.count_ones())
                .max()
                .unwrap_or(0);
            let what = format!(
                "versor {} (grade {grade}) sandwich {}",
                stringify!($vt),
                stringify!($xt)
            );
            let scale = (magnitude(rv).powi(2) * magnitude(&rx) * ($cx.order.len() as f64).powi(2))
                .max(1.0);
            let ns = rv.norm_squared().to_f64().abs();
            $cx.compare(
                &mut $fails,
                &format!("{what} (unit)"),
                &op2(
                    <alg::$vt<$T> as SandwichUnit<alg::$xt<$T>>>::sandwich_unit,
                    &v,
                    &xv,
                )
                .to_ref(sig),
                &rv.sandwich_unit(&rx),
                scale,
            );
            $cx.compare_option(
                &mut $fails,
                &what,
                op2(<alg::$vt<$T> as Sandwich<alg::$xt<$T>>>::sandwich, &v, &xv)
                    .map(|y| y.to_ref(sig)),
                rv.sandwich(&rx),
                if ns > 0.0 { scale / ns } else { scale },
            );
        }
    }};
}

/// Implements `ToRef`/`Gen` for the generated types of the algebra `alg` in scope.
macro_rules! impl_gen {
    (sparse $x:ident) => {
        impl<T: Ring + Debug + 'static> ToRef<T> for alg::$x<T> {
            fn to_ref(&self, sig: &Signature) -> Dm<T> {
                let m: alg::Multivector<T> = self.clone().into();
                Dm::from_canonical(sig, m.coefficients().to_vec()).unwrap()
            }
        }
        impl<T: Ring + Debug + 'static> Gen<T> for alg::$x<T> {
            fn from_ref(r: &Dm<T>) -> Self {
                let coeffs = r.to_canonical().try_into().unwrap();
                alg::$x::from_multivector(&alg::Multivector::from_coefficients(coeffs))
            }
            fn blade_names() -> &'static [&'static str] {
                &alg::$x::<f64>::BLADES
            }
        }
    };
    (dense $x:ident) => {
        impl<T: Ring + Debug + 'static> ToRef<T> for alg::$x<T> {
            fn to_ref(&self, sig: &Signature) -> Dm<T> {
                Dm::from_canonical(sig, self.coefficients().to_vec()).unwrap()
            }
        }
        impl<T: Ring + Debug + 'static> Gen<T> for alg::$x<T> {
            fn from_ref(r: &Dm<T>) -> Self {
                alg::$x::from_coefficients(r.to_canonical().try_into().unwrap())
            }
            fn blade_names() -> &'static [&'static str] {
                &alg::$x::<f64>::BLADES
            }
        }
    };
}

/// The names declared in `types: { ... }` and `dense:` of an `algebra!` invocation's source.
pub fn declared_types(source: &str) -> Vec<String> {
    let start = source.find("types: {").expect("a `types: {` block") + "types: {".len();
    let end = start + source[start..].find('}').expect("closing `}`");
    let mut names: Vec<String> = source[start..end]
        .lines()
        .map(str::trim)
        .filter(|l| !l.starts_with("//") && l.contains(':'))
        .map(|l| l.split(':').next().unwrap().trim().to_string())
        .collect();
    let dense = source.find("dense:").expect("a `dense:` entry") + "dense:".len();
    let dense_name: String = source[dense..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    names.push(dense_name);
    names
}

/// The exact (rational) product test of a suite, when `yes`; `no` leaves it out (compile time:
/// see the note on the Cl(4,1) suite).
macro_rules! exact_products {
    (no) => {};
    (yes) => {
        proptest! {
            #![proptest_config(ProptestConfig {
                cases: 64,
                max_shrink_iters: 256,
                ..ProptestConfig::default()
            })]

                #[test]
                fn products_exact(xa in dense_strategy::<Rational>(), xb in dense_strategy::<Rational>()) {
                    let (fails, seen) = all_pairs(&cx(), &xa, &xb);
                    prop_assert_eq!(seen.len(), type_list().len().pow(2));
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

        }
    };
}

/// The exact (rational) versor test of a suite, when `yes`.
macro_rules! exact_versors {
    (no) => {};
    (yes) => {
        proptest! {
            #![proptest_config(ProptestConfig {
                cases: 64,
                max_shrink_iters: 256,
                ..ProptestConfig::default()
            })]

                #[test]
                fn versors_exact(
                    v0 in vector_strategy::<Rational>(),
                    v1 in vector_strategy::<Rational>(),
                    v2 in vector_strategy::<Rational>(),
                    x in dense_strategy::<Rational>(),
                ) {
                    let fails = all_versors(&cx(), &[v0, v1, v2], &x);
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

        }
    };
}

/// One algebra's whole suite, in a module of its own.
macro_rules! algebra_suite {
    (
        mod $modname:ident for $alg:ident,
        signature: [$($s:expr),*],
        source: $src:expr,
        types: [$($ty:ident),*],
        dense: $dense:ident,
        versors: [$($v:ident),*],
        exact_products: $ep:ident,
        exact_versors: $ev:ident $(,)?
    ) => {
        mod $modname {
            use super::*;
            use ga_core::$alg as alg;

            $( impl_gen!(sparse $ty); )*
            impl_gen!(dense $dense);

            const SIGNATURE: &[i8] = &[$($s),*];
            const SOURCE: &str = $src;

            fn cx() -> Ctx {
                Ctx::new(SIGNATURE, &alg::BASIS)
            }

            fn type_list() -> Vec<&'static str> {
                vec![$(stringify!($ty),)* stringify!($dense)]
            }

            /// Every ordered pair, every product. Returns the failures and the pairs visited.
            fn all_pairs<T: Scalar>(
                cx: &Ctx,
                xa: &Dm<T>,
                xb: &Dm<T>,
            ) -> (Vec<String>, Vec<(&'static str, &'static str)>) {
                let mut fails = Vec::new();
                let mut seen = Vec::new();
                cartesian!(pair_check!(T, cx, xa, xb, fails, seen); [$($ty,)* $dense]; [$($ty,)* $dense]);
                (fails, seen)
            }

            /// Every ordered pair: the operators are the methods (f64).
            fn all_ops(
                cx: &Ctx,
                xa: &Dm<f64>,
                xb: &Dm<f64>,
            ) -> (Vec<String>, Vec<(&'static str, &'static str)>) {
                let mut fails = Vec::new();
                let mut seen = Vec::new();
                cartesian!(ops_check!(cx, xa, xb, fails, seen); [$($ty,)* $dense]; [$($ty,)* $dense]);
                (fails, seen)
            }

            /// Every type, every unary operation; the dense type's general inverse.
            fn all_unary<T: Scalar>(cx: &Ctx, xa: &Dm<T>, s: &T) -> Vec<String> {
                let mut fails = Vec::new();
                $( unary_check!((T, cx, xa, s, fails); $ty); )*
                unary_check!((T, cx, xa, s, fails); $dense);
                // General inverse of the dense type (elimination on both sides).
                let a = <alg::$dense<T> as Gen<T>>::from_ref(xa);
                let ra = a.to_ref(&cx.sig);
                let expected = ra.general_inverse();
                let got = op1(alg::$dense::<T>::general_inverse, &a).map(|x| x.to_ref(&cx.sig));
                let cond = match &expected {
                    Some(inv) => magnitude(&ra) * magnitude(inv) * cx.order.len() as f64,
                    None => 0.0,
                };
                if T::EXACT || (cond < 1e4 && got.is_some()) {
                    cx.compare_option(&mut fails, "general_inverse", got, expected, cond);
                }
                fails
            }

            /// Sandwiches by true versors (a vector, a product of two and of three vectors):
            /// the generated result equals the *unprojected* reference (grade is preserved).
            fn all_versors<T: Scalar>(cx: &Ctx, vs: &[Dm<T>; 3], x: &Dm<T>) -> Vec<String> {
                let mut fails = Vec::new();
                let versors = [
                    vs[0].clone(),
                    &vs[0] * &vs[1],
                    &vs[0] * &vs[1] * &vs[2],
                ];
                cartesian!(versor_check!(T, cx, versors, x, fails); [$($v),*]; [$($ty,)* $dense]);
                fails
            }

            exact_products!($ep);
            exact_versors!($ev);

            fn dense_strategy<T: Scalar>() -> BoxedStrategy<Dm<T>> {
                let sig = Signature::new(SIGNATURE).unwrap();
                proptest::collection::vec(T::strategy(), sig.blade_count())
                    .prop_map(move |c| Dm::from_bitmask_order(&sig, c).unwrap())
                    .boxed()
            }

            fn vector_strategy<T: Scalar>() -> BoxedStrategy<Dm<T>> {
                dense_strategy::<T>().prop_map(|m| m.grade(1)).boxed()
            }

            #[test]
            fn declaration_matches_the_reference_conventions() {
                let cx = cx();
                assert_eq!(alg::SIGNATURE.as_slice(), SIGNATURE, "signature");
                let names: Vec<&str> = cx.names.iter().map(String::as_str).collect();
                assert_eq!(alg::BLADE_NAMES.as_slice(), names.as_slice(), "BLADE_NAMES");
                assert_eq!(alg::$dense::<f64>::BLADES.as_slice(), names.as_slice());
                // Every type's blades are canonical names, listed in canonical order.
                $(
                    let masks = cx.masks_of(&alg::$ty::<f64>::BLADES);
                    let mut sorted = masks.clone();
                    sorted.sort_by(|&a, &b| ga_core::reference::canonical_cmp(a, b));
                    sorted.dedup();
                    assert_eq!(masks, sorted, "{} blades in canonical order", stringify!($ty));
                )*
            }

            #[test]
            fn every_declared_pair_is_enumerated() {
                let declared = declared_types(SOURCE);
                let mut listed: Vec<String> = type_list().iter().map(|s| s.to_string()).collect();
                let mut declared_sorted = declared.clone();
                declared_sorted.sort();
                listed.sort();
                assert_eq!(listed, declared_sorted, "the test's type list is the declaration");
                let cx = cx();
                let zero = Dm::<f64>::zero(&cx.sig);
                let (fails, seen) = all_pairs(&cx, &zero, &zero);
                assert!(fails.is_empty(), "{fails:#?}");
                let mut distinct = seen.clone();
                distinct.sort();
                distinct.dedup();
                assert_eq!(seen.len(), declared.len() * declared.len(), "pairs tested");
                assert_eq!(distinct.len(), seen.len(), "pairs are distinct");
            }

            proptest! {
                // Few cases: each one inverts general elements over `Rational` (a full
                // elimination per element, minutes for 64 cases). The division-free unary
                // operations are proved identical for every rational input by the symbolic
                // suite; these cases are the exact check of the inverses.
                #![proptest_config(ProptestConfig {
                    cases: 8,
                    max_shrink_iters: 32,
                    ..ProptestConfig::default()
                })]

                #[test]
                fn unary_exact(xa in dense_strategy::<Rational>(), s in Rational::strategy()) {
                    let fails = all_unary(&cx(), &xa, &s);
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }
            }

            proptest! {
                #![proptest_config(ProptestConfig {
                    cases: 64,
                    max_shrink_iters: 256,
                    ..ProptestConfig::default()
                })]

                #[test]
                fn products_f64(xa in dense_strategy::<f64>(), xb in dense_strategy::<f64>()) {
                    let (fails, seen) = all_pairs(&cx(), &xa, &xb);
                    prop_assert_eq!(seen.len(), type_list().len().pow(2));
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

                #[test]
                fn operators_are_the_methods(xa in dense_strategy::<f64>(), xb in dense_strategy::<f64>()) {
                    let (fails, seen) = all_ops(&cx(), &xa, &xb);
                    prop_assert_eq!(seen.len(), type_list().len().pow(2));
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

                #[test]
                fn unary_f64(xa in dense_strategy::<f64>(), s in f64::strategy()) {
                    let fails = all_unary(&cx(), &xa, &s);
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

                #[test]
                fn versors_f64(
                    v0 in vector_strategy::<f64>(),
                    v1 in vector_strategy::<f64>(),
                    v2 in vector_strategy::<f64>(),
                    x in dense_strategy::<f64>(),
                ) {
                    let fails = all_versors(&cx(), &[v0, v1, v2], &x);
                    prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
                }

                #[test]
                fn scalar_times_value_f64(xa in dense_strategy::<f64>(), s in -3.0f64..3.0) {
                    let cx = cx();
                    let mut fails = Vec::new();
                    $(
                        let a = <alg::$ty<f64> as Gen<f64>>::from_ref(&xa);
                        cx.compare(
                            &mut fails,
                            concat!("s * ", stringify!($ty)),
                            &(s * a).to_ref(&cx.sig),
                            &a.to_ref(&cx.sig).scale(&s),
                            4.0 * magnitude(&xa),
                        );
                    )*
                    let a = <alg::$dense<f64> as Gen<f64>>::from_ref(&xa);
                    cx.compare(&mut fails, "s * dense", &(s * a).to_ref(&cx.sig), &xa.scale(&s), 4.0 * magnitude(&xa));
                    prop_assert!(fails.is_empty(), "{}", fails.join("\n"));
                }
            }
        }
    };
}
