//! Exact agreement of every product of every ordered pair of `ga_core::cga` (Cl(4,1)) types
//! with the independent dense reference, shown **symbolically**.
//!
//! # What is checked
//!
//! For each of the 81 ordered pairs `(A, B)` of declared types (the dense `Multivector`
//! included), the operands are the *general* elements of `A` and of `B`: every blade of `A`
//! carries its own variable `a_<blade>`, every blade of `B` its own `b_<blade>` (the projection
//! onto the type's blades is checked to keep exactly those variables). The geometric product,
//! the outer product, the left and right contractions, the scalar product, the regressive
//! product, `+`, `-` and the unit sandwich `a b ã` (projected onto `B`) are computed by the
//! generated code and by `ga_core::reference::DenseMultivector` (run-time bitmask products) over
//! the scalar `Sym` (`gvr_harness/sym.rs`), which is exact polynomial arithmetic with
//! rational coefficients (`ga_core::symbolic::Poly`, kept in canonical form). Each coefficient
//! of the two results must be the *same polynomial* (`==` on canonical forms). Likewise every
//! unary operation of every type (reverse, grade involution, Clifford conjugate, dual, undual,
//! negation, grade projections, norm squared, scaling by a variable `s`) on the general element.
//!
//! # Why this is exactness over the rationals
//!
//! The generated code and the reference both evaluate their results using only `+`, `-`, `*`,
//! negation and integer constants on the coefficients. Evaluating such straight-line code on the
//! variables themselves yields the polynomial it computes, in `ℚ[a, b]`. Two polynomials that are
//! equal in `ℚ[a, b]` take equal values at every point of every commutative ring containing `ℚ`'s
//! integer constants, so in particular for every choice of `Rational` coefficients: the
//! generated product equals the reference **exactly** for all rational inputs. (This does not
//! need the products to be bilinear; it is a polynomial identity. For the bilinear products it
//! amounts to comparing the generated and reference multiplication tables term by term, signs
//! included.) A single symbolic evaluation per product and pair is therefore a proof, not a
//! sample, and it runs in well under a second per pair.
//!
//! Evaluating the generic code over `Sym` is the same Rust code as evaluating it over
//! `Rational`; what differs is only the scalar's arithmetic. To show that the `Rational`
//! instantiation itself works on Cl(4,1), `rational_*` below also run a few pairs and the
//! versor sandwiches with genuine `Rational` coefficients (random, exact equality) through the
//! same harness as the f64 suite. Instantiating *all* pairs over `Rational` is what made the
//! test binary take tens of CPU-minutes to compile; `Sym` is `Copy` and each of its operations is
//! one out-of-line call, so this binary compiles in about a minute in release and runs in
//! about three seconds.
//!
//! The f64 checks of the same pairs, the operators and the unary operations (which are also
//! checked exactly over `Rational` there) are in `generated_vs_reference_cga.rs`.

#[macro_use]
#[allow(unused_macros)]
mod gvr_harness;
use ga_core::cga as alg;
use gvr_harness::sym::{self, Sym};
use gvr_harness::*;

impl_gen!(sparse Vector);
impl_gen!(sparse Bivector);
impl_gen!(sparse Trivector);
impl_gen!(sparse Quadvector);
impl_gen!(sparse Pseudoscalar);
impl_gen!(sparse Rotor);
impl_gen!(sparse Even);
impl_gen!(sparse Odd);
impl_gen!(dense Multivector);

const SIGNATURE: &[i8] = &[1, 1, 1, 1, -1];
const SOURCE: &str = include_str!("../../ga-core/src/cga.rs");

fn cx() -> Ctx {
    Ctx::new(SIGNATURE, &alg::BASIS)
}

/// Records a failure listing every blade where `got` and `expected` are different polynomials.
fn compare_exact(cx: &Ctx, fails: &mut Vec<String>, what: &str, got: &Dm<Sym>, expected: &Dm<Sym>) {
    let diffs: Vec<String> = cx
        .order
        .iter()
        .zip(&cx.names)
        .filter_map(|(&m, name)| {
            let (g, e) = (got.get(m), expected.get(m));
            (g != e).then(|| format!("blade {name}: expected {e}, got {g}"))
        })
        .collect();
    if !diffs.is_empty() {
        fails.push(format!("{what}: {}", diffs.join("; ")));
    }
}

/// The general element of type `X`: a fresh variable `<prefix>_<blade>` on each of its blades.
/// Checks that the projection keeps exactly those blades, so that no product is checked on a
/// value that lost some of its coefficients.
fn general<X: Gen<Sym>>(cx: &Ctx, prefix: &str, fails: &mut Vec<String>) -> (X, Dm<Sym>) {
    let masks = cx.masks_of(X::blade_names());
    let names: Vec<String> = (0..cx.sig.blade_count())
        .map(|m| {
            let i = cx.order.iter().position(|&o| o == m).unwrap();
            format!("{prefix}_{}", cx.names[i])
        })
        .collect();
    let all = Dm::from_fn(&cx.sig, |m| Sym::var(&names[m]));
    let x = X::from_ref(&all);
    let rx = x.to_ref(&cx.sig);
    let expected = all.project(|m| masks.contains(&m));
    compare_exact(
        cx,
        fails,
        &format!("{} from_multivector (projection)", short::<X>()),
        &rx,
        &expected,
    );
    let nonzero = (0..cx.sig.blade_count())
        .filter(|&m| !rx.get(m).is_zero())
        .count();
    if nonzero != masks.len() {
        fails.push(format!(
            "{}: {nonzero} variables survive the projection, the type has {} blades",
            short::<X>(),
            masks.len()
        ));
    }
    (x, rx)
}

/// Every product of the pair `(A, B)`, symbolically, against the reference.
#[inline(never)]
fn check_pair_symbolic<A, B>(cx: &Ctx, fails: &mut Vec<String>)
where
    A: Gen<Sym>
        + Geometric<B>
        + Wedge<B>
        + LeftContraction<B>
        + RightContraction<B>
        + ScalarProduct<B>
        + Regressive<B>
        + SandwichUnit<B>
        + Add<B>
        + Sub<B>,
    B: Gen<Sym>,
    <A as Geometric<B>>::Output: ToRef<Sym>,
    <A as Wedge<B>>::Output: ToRef<Sym>,
    <A as LeftContraction<B>>::Output: ToRef<Sym>,
    <A as RightContraction<B>>::Output: ToRef<Sym>,
    <A as ScalarProduct<B>>::Output: ToRef<Sym>,
    <A as Regressive<B>>::Output: ToRef<Sym>,
    <A as Add<B>>::Output: ToRef<Sym>,
    <A as Sub<B>>::Output: ToRef<Sym>,
{
    sym::reset();
    let sig = &cx.sig;
    let (a, ra) = general::<A>(cx, "a", fails);
    let (b, rb) = general::<B>(cx, "b", fails);
    let pair = format!("{} × {}", short::<A>(), short::<B>());
    let mut cmp = |what: &str, got: Dm<Sym>, expected: Dm<Sym>| {
        compare_exact(cx, fails, &format!("{pair}: {what}"), &got, &expected)
    };
    cmp(
        "geometric",
        op2(<A as Geometric<B>>::geometric, &a, &b).to_ref(sig),
        ra.geometric(&rb),
    );
    cmp(
        "wedge",
        op2(<A as Wedge<B>>::wedge, &a, &b).to_ref(sig),
        ra.wedge(&rb),
    );
    cmp(
        "left_contraction",
        op2(<A as LeftContraction<B>>::left_contraction, &a, &b).to_ref(sig),
        ra.left_contraction(&rb),
    );
    cmp(
        "right_contraction",
        op2(<A as RightContraction<B>>::right_contraction, &a, &b).to_ref(sig),
        ra.right_contraction(&rb),
    );
    cmp(
        "scalar_product",
        op2(<A as ScalarProduct<B>>::scalar_product, &a, &b).to_ref(sig),
        Dm::scalar(sig, ra.scalar_product(&rb)),
    );
    cmp(
        "regressive",
        op2(<A as Regressive<B>>::regressive, &a, &b).to_ref(sig),
        ra.regressive(&rb),
    );
    cmp(
        "+",
        op2v(<A as Add<B>>::add, a.clone(), b.clone()).to_ref(sig),
        &ra + &rb,
    );
    cmp(
        "-",
        op2v(<A as Sub<B>>::sub, a.clone(), b.clone()).to_ref(sig),
        &ra - &rb,
    );
    let b_masks = cx.masks_of(B::blade_names());
    cmp(
        "sandwich_unit",
        op2(<A as SandwichUnit<B>>::sandwich_unit, &a, &b).to_ref(sig),
        ra.sandwich_unit(&rb).project(|k| b_masks.contains(&k)),
    );
}

macro_rules! symbolic_pair {
    (($cx:ident, $fails:ident, $seen:ident); $a:ident, $b:ident) => {
        $seen.push((stringify!($a), stringify!($b)));
        check_pair_symbolic::<alg::$a<Sym>, alg::$b<Sym>>(&$cx, &mut $fails);
    };
}

/// The declared types, the dense one last (checked against the declaration below).
macro_rules! with_types {
    ($cb:ident ! $ctx:tt) => {
        cartesian!($cb!$ctx;
            [Vector, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Even, Odd, Multivector];
            [Vector, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Even, Odd, Multivector])
    };
}

#[test]
fn every_pair_every_product_is_the_reference_polynomial() {
    let cx = cx();
    let mut fails = Vec::new();
    let mut seen = Vec::new();
    with_types!(symbolic_pair!(cx, fails, seen));
    assert!(
        fails.is_empty(),
        "{} mismatches:\n{}",
        fails.len(),
        fails.join("\n")
    );
    // Every declared type, every ordered pair, each once.
    let mut declared = declared_types(SOURCE);
    declared.sort();
    let mut listed: Vec<&str> = seen.iter().map(|(a, _)| *a).collect();
    listed.sort();
    listed.dedup();
    assert_eq!(listed, declared, "the pairs cover the declared types");
    let mut distinct = seen.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), 81);
    assert_eq!(seen.len(), 81);
}

/// Every unary operation of one type, symbolically, against the reference.
macro_rules! unary_symbolic {
    (($cx:ident, $fails:ident, $seen:ident); $($x:ident),*) => {$({
        #[inline(never)]
        fn unary(cx: &Ctx, fails: &mut Vec<String>) {
            sym::reset();
            let sig = &cx.sig;
            let (a, ra) = general::<alg::$x<Sym>>(cx, "a", fails);
            let s = Sym::var("s");
            let mut cmp = |what: &str, got: Dm<Sym>, expected: Dm<Sym>| {
                compare_exact(cx, fails, &format!("{}: {what}", stringify!($x)), &got, &expected)
            };
            cmp("reverse", a.reverse().to_ref(sig), ra.reverse());
            cmp("grade_involution", a.grade_involution().to_ref(sig), ra.grade_involution());
            cmp("conjugate", a.conjugate().to_ref(sig), ra.conjugate());
            cmp("dual", a.dual().to_ref(sig), ra.dual());
            cmp("undual", a.undual().to_ref(sig), ra.undual());
            cmp("-a", (-a.clone()).to_ref(sig), -&ra);
            for k in 0..=sig.len() + 1 {
                cmp(&format!("grade({k})"), a.grade(k).to_ref(sig), ra.grade(k));
            }
            cmp(
                "norm_squared",
                Dm::scalar(sig, a.norm_squared()),
                Dm::scalar(sig, ra.norm_squared()),
            );
            cmp("scale(&s)", a.scale(&s).to_ref(sig), ra.scale(&s));
        }
        $seen.push(stringify!($x));
        unary(&$cx, &mut $fails);
    })*};
}

#[test]
fn every_unary_operation_is_the_reference_polynomial() {
    let cx = cx();
    let mut fails = Vec::new();
    let mut seen = Vec::new();
    unary_symbolic!((cx, fails, seen);
        Vector, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Even, Odd, Multivector);
    assert!(
        fails.is_empty(),
        "{} mismatches:\n{}",
        fails.len(),
        fails.join("\n")
    );
    let mut declared = declared_types(SOURCE);
    declared.sort();
    seen.sort();
    assert_eq!(seen, declared, "every declared type");
}

// ---------------------------------------------------------------------------------------------
// The checker can fail: a wrong sign, a missing term and a product in the wrong algebra are
// caught. (If `Sym` equality were vacuous, these would pass.)

#[test]
fn the_symbolic_comparison_detects_wrong_results() {
    let cx = cx();
    sym::reset();
    let mut fails = Vec::new();
    let (a, ra) = general::<alg::Vector<Sym>>(&cx, "a", &mut fails);
    let (b, rb) = general::<alg::Vector<Sym>>(&cx, "b", &mut fails);
    assert!(fails.is_empty(), "{fails:?}");
    let good = a.geometric(&b).to_ref(&cx.sig);
    compare_exact(&cx, &mut fails, "a b", &good, &ra.geometric(&rb));
    assert!(fails.is_empty(), "{fails:?}");

    // b a differs from a b in every bivector coefficient (wrong sign), not in the scalar.
    let swapped = b.geometric(&a).to_ref(&cx.sig);
    compare_exact(&cx, &mut fails, "b a", &swapped, &ra.geometric(&rb));
    assert_eq!(fails.len(), 1);
    assert_eq!(fails[0].matches("blade").count(), 10, "{}", fails[0]);
    fails.clear();

    // Dropping one term: the e5 e5 term of the scalar part.
    let mut dropped = good.clone();
    let e5 = cx.mask_of("e5");
    let term = ra.get(e5) * rb.get(e5);
    dropped.set(0, dropped.get(0) + term).unwrap();
    compare_exact(&cx, &mut fails, "dropped", &dropped, &ra.geometric(&rb));
    assert_eq!(fails.len(), 1);
    fails.clear();

    // The Euclidean Cl(5,0) product differs in the same coefficient.
    let euclid = Signature::new(&[1, 1, 1, 1, 1]).unwrap();
    let ea = Dm::from_fn(&euclid, |m| ra.get(m));
    let eb = Dm::from_fn(&euclid, |m| rb.get(m));
    let e = ea.geometric(&eb);
    let e_in_cga = Dm::from_fn(&cx.sig, |m| e.get(m));
    compare_exact(&cx, &mut fails, "Cl(5,0)", &e_in_cga, &ra.geometric(&rb));
    assert_eq!(fails.len(), 1);
    assert!(fails[0].starts_with("Cl(5,0): blade 1:"), "{}", fails[0]);
}

#[test]
fn sym_is_exact_polynomial_arithmetic() {
    use ga_core::symbolic::Poly;
    sym::reset();
    let (x, y) = (Sym::var("x"), Sym::var("y"));
    let p = (x + y) * (x - y);
    assert_eq!(p.poly(), Poly::parse("x^2 - y^2").unwrap());
    assert!((p - x * x + y * y).is_zero());
    assert!(!(p - x * x).is_zero());
    assert_eq!(-Sym::one() + Sym::from_i64(3), Sym::from_i64(2));
    assert!(sym::arena_len() > 0);
}

#[test]
#[should_panic(expected = "stale Sym")]
fn a_stale_sym_panics() {
    sym::reset();
    let x = Sym::var("x");
    sym::reset();
    let _ = x.is_zero();
}

// ---------------------------------------------------------------------------------------------
// Genuine `Rational` instantiations on Cl(4,1): a few pairs through the full per-pair check
// (six products, sums, sandwiches), and versor sandwiches by true versors (products of random
// vectors), with random exact coefficients and `==`.

fn rational_dense() -> BoxedStrategy<Dm<Rational>> {
    let sig = Signature::new(SIGNATURE).unwrap();
    proptest::collection::vec(Rational::strategy(), sig.blade_count())
        .prop_map(move |c| Dm::from_bitmask_order(&sig, c).unwrap())
        .boxed()
}

fn rational_vector() -> BoxedStrategy<Dm<Rational>> {
    rational_dense().prop_map(|m| m.grade(1)).boxed()
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 32,
        max_shrink_iters: 256,
        ..ProptestConfig::default()
    })]

    #[test]
    fn rational_pairs(xa in rational_dense(), xb in rational_dense()) {
        let cx = cx();
        let mut fails = Vec::new();
        check_pair::<Rational, alg::Vector<Rational>, alg::Vector<Rational>>(&cx, &xa, &xb, &mut fails);
        check_pair::<Rational, alg::Rotor<Rational>, alg::Vector<Rational>>(&cx, &xa, &xb, &mut fails);
        check_pair::<Rational, alg::Even<Rational>, alg::Vector<Rational>>(&cx, &xa, &xb, &mut fails);
        check_pair::<Rational, alg::Odd<Rational>, alg::Bivector<Rational>>(&cx, &xa, &xb, &mut fails);
        check_pair::<Rational, alg::Trivector<Rational>, alg::Vector<Rational>>(&cx, &xa, &xb, &mut fails);
        prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
    }

    #[test]
    fn rational_versors(
        v0 in rational_vector(),
        v1 in rational_vector(),
        v2 in rational_vector(),
        x in rational_dense(),
    ) {
        let cx = cx();
        let mut fails = Vec::new();
        let versors = [v0.clone(), &v0 * &v1, &v0 * &v1 * &v2];
        let x = &x;
        versor_check!((Rational, cx, versors, x, fails); Rotor, Vector);
        versor_check!((Rational, cx, versors, x, fails); Even, Vector);
        versor_check!((Rational, cx, versors, x, fails); Odd, Vector);
        versor_check!((Rational, cx, versors, x, fails); Even, Bivector);
        prop_assert!(fails.is_empty(), "{} mismatches:\n{}", fails.len(), fails.join("\n"));
    }
}
