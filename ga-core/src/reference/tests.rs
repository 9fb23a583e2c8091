//! Unit and property tests of the dense reference: the algebra laws, in `f64` (tolerance) and in
//! exact rationals (exact equality).

use super::*;
use crate::scalar::Rational;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

type Dm<T> = DenseMultivector<T>;

fn sig(entries: &[i8]) -> Signature {
    Signature::new(entries).unwrap()
}

fn cl41() -> Signature {
    sig(&[1, 1, 1, 1, -1])
}

fn named_signatures() -> Vec<Signature> {
    vec![
        cl41(),
        sig(&[1, 1, 1]),
        sig(&[0, 1, 1, 1]),
        sig(&[1, 1, 1, 0]),
        sig(&[]),
        sig(&[-1, -1]),
        sig(&[1, -1, 0, 1, 0, -1]),
    ]
}

fn rat(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

// ---------------------------------------------------------------------------------------------
// Comparison: exact for rationals, tight relative tolerance for f64.

trait Compare: Real + fmt::Debug {
    const EXACT: bool;
    fn close(a: &Self, b: &Self, scale: f64) -> bool;
}

impl Compare for f64 {
    const EXACT: bool = false;
    fn close(a: &Self, b: &Self, scale: f64) -> bool {
        (a - b).abs() <= 1e-10 * scale.max(1.0)
    }
}

impl Compare for Rational {
    const EXACT: bool = true;
    fn close(a: &Self, b: &Self, _scale: f64) -> bool {
        a == b
    }
}

fn magnitude<T: Real>(m: &Dm<T>) -> f64 {
    m.coefficients()
        .iter()
        .map(|c| c.to_f64().abs())
        .fold(0.0, f64::max)
}

fn mv_close<T: Compare>(a: &Dm<T>, b: &Dm<T>) -> bool {
    let scale = magnitude(a).max(magnitude(b));
    a.signature() == b.signature()
        && a.coefficients()
            .iter()
            .zip(b.coefficients())
            .all(|(x, y)| T::close(x, y, scale))
}

macro_rules! assert_mv {
    ($a:expr, $b:expr, $what:expr) => {{
        let (a, b) = (&$a, &$b);
        prop_assert!(
            mv_close(a, b),
            "{}: signature {:?}\n left = {:?}\nright = {:?}",
            $what,
            a.signature().entries(),
            a.to_canonical(),
            b.to_canonical()
        );
    }};
}

// ---------------------------------------------------------------------------------------------
// Strategies.

fn signature_strategy() -> impl Strategy<Value = Signature> {
    signature_strategy_up_to(6)
}

/// Random signatures of up to `max` generators, and the named ones (Cl(4,1), Cl(3,0), both
/// placements of the degenerate generator of Cl(3,0,1)).
fn signature_strategy_up_to(max: usize) -> impl Strategy<Value = Signature> {
    prop_oneof![
        3 => proptest::collection::vec(prop_oneof![Just(1i8), Just(-1i8), Just(0i8)], 0..=max),
        1 => Just(vec![1i8, 1, 1, 1, -1]),
        1 => Just(vec![1i8, 1, 1]),
        1 => Just(vec![0i8, 1, 1, 1]),
        1 => Just(vec![1i8, 1, 1, 0]),
    ]
    .prop_map(|v| sig(&v))
}

/// A small rational, zero about a third of the time (sparser inputs are faster and exercise
/// cancellations).
fn rational_coefficient() -> impl Strategy<Value = Rational> {
    prop_oneof![
        1 => Just(Rational::zero()),
        2 => (-4i64..=4, 1i64..=3).prop_map(|(n, d)| rat(n, d)),
    ]
}

fn f64_coefficient() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 3 => -2.0f64..2.0]
}

trait Coefficient: Compare + 'static {
    fn strategy() -> BoxedStrategy<Self>;
}

impl Coefficient for f64 {
    fn strategy() -> BoxedStrategy<Self> {
        f64_coefficient().boxed()
    }
}

impl Coefficient for Rational {
    fn strategy() -> BoxedStrategy<Self> {
        rational_coefficient().boxed()
    }
}

fn mv_in<T: Coefficient>(s: &Signature) -> BoxedStrategy<Dm<T>> {
    let s = s.clone();
    proptest::collection::vec(T::strategy(), s.blade_count())
        .prop_map(move |c| Dm::from_bitmask_order(&s, c).unwrap())
        .boxed()
}

fn vector_in<T: Coefficient>(s: &Signature) -> BoxedStrategy<Dm<T>> {
    mv_in::<T>(s).prop_map(|m| m.grade(1)).boxed()
}

fn three_mvs<T: Coefficient>() -> impl Strategy<Value = (Dm<T>, Dm<T>, Dm<T>)> {
    signature_strategy().prop_flat_map(|s| (mv_in::<T>(&s), mv_in::<T>(&s), mv_in::<T>(&s)))
}

// ---------------------------------------------------------------------------------------------
// Laws, generic over the coefficient type.

fn laws_of_three<T: Compare>(a: &Dm<T>, b: &Dm<T>, c: &Dm<T>) -> Result<(), TestCaseError> {
    // Associativity.
    assert_mv!((a * b) * c, a * (b * c), "geometric associativity");
    assert_mv!((a ^ b) ^ c, a ^ (b ^ c), "outer associativity");
    assert_mv!(
        a.regressive(b).regressive(c),
        a.regressive(&b.regressive(c)),
        "regressive associativity"
    );
    // Distributivity, both sides, for every bilinear product.
    type P<T> = fn(&Dm<T>, &Dm<T>) -> Dm<T>;
    let products: [(&str, P<T>); 6] = [
        ("geometric", Dm::geometric),
        ("wedge", Dm::wedge),
        ("left contraction", Dm::left_contraction),
        ("right contraction", Dm::right_contraction),
        ("regressive", Dm::regressive),
        ("scalar product", |x, y| {
            Dm::scalar(x.signature(), x.scalar_product(y))
        }),
    ];
    for (name, p) in products {
        assert_mv!(
            p(a, &(b + c)),
            p(a, b) + p(a, c),
            format!("{name}: left distributivity")
        );
        assert_mv!(
            p(&(a + b), c),
            p(a, c) + p(b, c),
            format!("{name}: right distributivity")
        );
    }
    // Contraction identities.
    assert_mv!(
        a.left_contraction(&b.left_contraction(c)),
        (a ^ b).left_contraction(c),
        "A⌋(B⌋C) = (A∧B)⌋C"
    );
    assert_mv!(
        a.right_contraction(b).right_contraction(c),
        a.right_contraction(&(b ^ c)),
        "(A⌊B)⌊C = A⌊(B∧C)"
    );
    Ok(())
}

fn laws_of_two<T: Compare>(a: &Dm<T>, b: &Dm<T>) -> Result<(), TestCaseError> {
    let s = a.signature();
    // Reverse is an anti-automorphism, grade involution an automorphism, conjugate both at once.
    assert_mv!(
        (a * b).reverse(),
        b.reverse() * a.reverse(),
        "~(AB) = ~B ~A"
    );
    assert_mv!(
        (a * b).grade_involution(),
        a.grade_involution() * b.grade_involution(),
        "(AB)^ = Â B̂"
    );
    assert_mv!(
        (a * b).conjugate(),
        b.conjugate() * a.conjugate(),
        "conj(AB) = conj(B) conj(A)"
    );
    assert_mv!(
        a.conjugate(),
        a.reverse().grade_involution(),
        "conj = reverse ∘ involution"
    );
    assert_mv!(a.reverse().reverse(), a.clone(), "reverse is an involution");
    // Duality.
    assert_mv!(a.dual().undual(), a.clone(), "undual(dual(A)) = A");
    assert_mv!(a.undual().dual(), a.clone(), "dual(undual(A)) = A");
    assert_mv!(!a, a.dual(), "! is dual");
    assert_mv!(
        (a & b).dual(),
        a.dual() ^ b.dual(),
        "dual(A ∨ B) = dual(A) ∧ dual(B)"
    );
    let i = Dm::pseudoscalar(s);
    assert_mv!(a & &i, a.clone(), "A ∨ I = A");
    assert_mv!(&i & a, a.clone(), "I ∨ A = A");
    // Grade decomposition and scalar product.
    let mut sum = Dm::zero(s);
    for k in 0..=s.len() {
        sum = sum + a.grade(k);
    }
    assert_mv!(sum, a.clone(), "sum of grade parts");
    prop_assert!(T::close(
        &a.scalar_product(b),
        &(a * b).scalar_part(),
        magnitude(a) * magnitude(b) * 64.0
    ));
    prop_assert!(T::close(
        &a.norm_squared(),
        &(a * &a.reverse()).scalar_part(),
        magnitude(a) * magnitude(a) * 64.0
    ));
    // Operators are the methods.
    assert_mv!(a * b, a.geometric(b), "* is geometric");
    assert_mv!(a ^ b, a.wedge(b), "^ is wedge");
    assert_mv!(a | b, a.left_contraction(b), "| is left contraction");
    assert_mv!(a - b, a + &(-b), "a - b = a + (-b)");
    // Canonical order round trip.
    assert_mv!(
        Dm::from_canonical(s, a.to_canonical()).unwrap(),
        a.clone(),
        "canonical round trip"
    );
    Ok(())
}

/// For a vector `v` and any `B`: `v B = v⌋B + v∧B`, `B v = B⌊v + B∧v`.
fn vector_laws<T: Compare>(v: &Dm<T>, w: &Dm<T>, b: &Dm<T>) -> Result<(), TestCaseError> {
    assert_mv!(v * w, (v | w) + (v ^ w), "vw = v·w + v∧w");
    prop_assert!(
        (v | w).grade(0) == (v | w),
        "the dot of vectors is a scalar"
    );
    assert_mv!(v * b, (v | b) + (v ^ b), "vB = v⌋B + v∧B");
    assert_mv!(b * v, b.right_contraction(v) + (b ^ v), "Bv = B⌊v + B∧v");
    // The square of a vector is its quadratic form.
    let s = v.signature();
    let mut q = T::zero();
    for (i, &si) in s.entries().iter().enumerate() {
        let c = v.get(1 << i);
        q = q + T::from_i64(si as i64) * c.clone() * c;
    }
    assert_mv!(v * v, Dm::scalar(s, q.clone()), "v² = Σ signature[i] vᵢ²");
    prop_assert!(T::close(
        &v.norm_squared(),
        &q,
        1.0 + magnitude(v).powi(2) * 8.0
    ));
    Ok(())
}

/// A product of three vectors, with its versor inverse.
fn versor_laws<T: Compare>(
    v1: &Dm<T>,
    v2: &Dm<T>,
    v3: &Dm<T>,
    x: &Dm<T>,
) -> Result<(), TestCaseError> {
    let s = v1.signature();
    let one = Dm::one(s);
    let v = v1 * v2 * v3;
    let nonnull = [v1, v2, v3].iter().all(|w| !w.norm_squared().is_zero());
    match v.versor_inverse() {
        Some(inv) => {
            prop_assert!(
                nonnull,
                "⟨VṼ⟩₀ = ∏ vᵢ² is nonzero only for non-null vectors"
            );
            assert_mv!(&v * &inv, one.clone(), "V V⁻¹ = 1");
            assert_mv!(&inv * &v, one.clone(), "V⁻¹ V = 1");
            let expected = v3.versor_inverse().unwrap()
                * v2.versor_inverse().unwrap()
                * v1.versor_inverse().unwrap();
            assert_mv!(inv, expected, "(v1 v2 v3)⁻¹ = v3⁻¹ v2⁻¹ v1⁻¹");
            let g = v.general_inverse();
            prop_assert!(g.is_some(), "a versor has a general inverse");
            assert_mv!(
                g.unwrap(),
                inv,
                "general inverse = versor inverse for versors"
            );
            // Sandwiches: V X V⁻¹ and its unit form differ by the scalar ⟨VṼ⟩₀.
            let sw = v.sandwich(x).unwrap();
            assert_mv!(sw, &v * x * &inv, "sandwich = V X V⁻¹");
            assert_mv!(
                v.sandwich_unit(x),
                sw.scale(&v.norm_squared()),
                "sandwich_unit = ⟨VṼ⟩₀ · sandwich"
            );
            // A versor maps a vector to a vector (grade preservation).
            let y = v.sandwich(&x.grade(1)).unwrap();
            assert_mv!(y.grade(1), y, "versors preserve grade 1");
        }
        None => prop_assert!(!nonnull, "the versor inverse exists for non-null vectors"),
    }
    Ok(())
}

/// `A A⁻¹ = A⁻¹ A = 1` and `(A⁻¹)⁻¹ = A` whenever the general inverse exists. In `f64` the
/// residual is compared against the backward-error scale `|A| |A⁻¹|` (ill-conditioned elements
/// are legitimately inaccurate); in rationals equality is exact.
fn inverse_laws<T: Compare>(a: &Dm<T>) -> Result<(), TestCaseError> {
    let one = Dm::one(a.signature());
    let close = |x: &Dm<T>, y: &Dm<T>, scale: f64| {
        x.coefficients()
            .iter()
            .zip(y.coefficients())
            .all(|(p, q)| T::close(p, q, scale))
    };
    if let Some(inv) = a.general_inverse() {
        let cond = magnitude(a) * magnitude(&inv) * a.coefficients().len() as f64;
        if !T::EXACT && cond > 1e4 {
            // Ill-conditioned in floating point (often singular in exact arithmetic): the
            // residuals carry no information; the exact test covers these cases.
            return Ok(());
        }
        prop_assert!(close(&(a * &inv), &one, cond), "A A⁻¹ = 1: {a:?} {inv:?}");
        prop_assert!(close(&(&inv * a), &one, cond), "A⁻¹ A = 1: {a:?} {inv:?}");
        let back = inv.general_inverse();
        prop_assert!(back.is_some(), "(A⁻¹)⁻¹ exists");
        let back = back.unwrap();
        prop_assert!(
            close(&back, a, cond * cond * magnitude(a)),
            "(A⁻¹)⁻¹ = A: {a:?} {back:?}"
        );
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Property tests.

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn laws_of_three_f64((a, b, c) in three_mvs::<f64>()) {
        laws_of_three(&a, &b, &c)?;
    }

    #[test]
    fn laws_of_three_exact((a, b, c) in three_mvs::<Rational>()) {
        laws_of_three(&a, &b, &c)?;
    }

    #[test]
    fn laws_of_two_f64((a, b, _c) in three_mvs::<f64>()) {
        laws_of_two(&a, &b)?;
    }

    #[test]
    fn laws_of_two_exact((a, b, _c) in three_mvs::<Rational>()) {
        laws_of_two(&a, &b)?;
    }

    #[test]
    fn vector_laws_f64((v, w, b) in signature_strategy()
        .prop_flat_map(|s| (vector_in::<f64>(&s), vector_in::<f64>(&s), mv_in::<f64>(&s)))) {
        vector_laws(&v, &w, &b)?;
    }

    #[test]
    fn vector_laws_exact((v, w, b) in signature_strategy()
        .prop_flat_map(|s| (vector_in::<Rational>(&s), vector_in::<Rational>(&s), mv_in::<Rational>(&s)))) {
        vector_laws(&v, &w, &b)?;
    }

    #[test]
    fn versor_laws_f64((v1, v2, v3, x) in signature_strategy()
        .prop_flat_map(|s| (vector_in::<f64>(&s), vector_in::<f64>(&s), vector_in::<f64>(&s), mv_in::<f64>(&s)))) {
        // In f64 the inverse of a nearly null vector is ill-conditioned: rounding, not a broken
        // law, then decides the comparison. The exact twin below covers null and near-null ones.
        let ill_conditioned = |v: &Dm<f64>| {
            let q = v.norm_squared().abs();
            q != 0.0 && q < 1e-3 * magnitude(v).powi(2)
        };
        if [&v1, &v2, &v3].into_iter().any(ill_conditioned) {
            return Ok(());
        }
        versor_laws(&v1, &v2, &v3, &x)?;
    }

    #[test]
    fn versor_laws_exact((v1, v2, v3, x) in signature_strategy()
        .prop_flat_map(|s| (vector_in::<Rational>(&s), vector_in::<Rational>(&s), vector_in::<Rational>(&s), mv_in::<Rational>(&s)))) {
        versor_laws(&v1, &v2, &v3, &x)?;
    }

    #[test]
    fn inverse_laws_f64(a in signature_strategy().prop_flat_map(|s| mv_in::<f64>(&s))) {
        inverse_laws(&a)?;
    }

}

proptest! {
    // Exact elimination on 2ⁿ × 2ⁿ rational matrices is the slow part of this suite: fewer
    // cases, and random signatures of at most 5 generators (Cl(4,1) is among the named ones).
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn inverse_laws_exact(a in signature_strategy_up_to(5).prop_flat_map(|s| mv_in::<Rational>(&s))) {
        inverse_laws(&a)?;
    }
}

// ---------------------------------------------------------------------------------------------
// Unit tests.

#[test]
fn generators_square_to_the_signature_and_anticommute() {
    for s in named_signatures() {
        for i in 0..s.len() {
            let ei = Dm::<i64x>::basis_vector(&s, i).unwrap();
            assert_eq!(&ei * &ei, Dm::scalar(&s, i64x(s.entries()[i] as i64)));
            for j in 0..s.len() {
                if i != j {
                    let ej = Dm::<i64x>::basis_vector(&s, j).unwrap();
                    assert_eq!(&ei * &ej, -(&ej * &ei), "e{i} e{j} = -e{j} e{i}");
                    assert_eq!(&ei * &ej, &ei ^ &ej, "e{i} e{j} = e{i} ∧ e{j}");
                    assert!((&ei | &ej).is_zero());
                }
            }
        }
    }
}

#[test]
fn reorder_sign_counts_inversions() {
    // Brute force: concatenate index lists and count inversions.
    for a in 0usize..64 {
        for b in 0usize..64 {
            let list: Vec<usize> = indices(a).chain(indices(b)).collect();
            let mut inv = 0;
            for x in 0..list.len() {
                for y in x + 1..list.len() {
                    if list[x] > list[y] {
                        inv += 1;
                    }
                }
            }
            assert_eq!(
                reorder_sign(a, b),
                if inv % 2 == 0 { 1 } else { -1 },
                "{a:b} {b:b}"
            );
        }
    }
}

#[test]
fn blade_products_by_hand() {
    let e = [1i8, 1, 1];
    assert_eq!(blade_product(&e, 0b011, 0b110), (1, 0b101)); // e12 e23 = e13
    assert_eq!(blade_product(&e, 0b110, 0b011), (-1, 0b101)); // e23 e12 = -e13
    assert_eq!(blade_product(&e, 0b111, 0b111), (-1, 0)); // e123² = -1
    assert_eq!(blade_product(&e, 0b101, 0b010), (-1, 0b111)); // e13 e2 = -e123
    let p = [0i8, 1, 1, 1];
    assert_eq!(blade_product(&p, 0b0011, 0b0001), (0, 0b0010)); // e01 e0 = 0
    assert_eq!(blade_product(&p, 0b0011, 0b0010), (1, 0b0001)); // e01 e1 = e0
    let m = [1i8, 1, 1, 1, -1];
    assert_eq!(blade_product(&m, 0b10000, 0b10000), (-1, 0)); // e5² = -1
    assert_eq!(blade_product(&m, 0b11000, 0b11000), (1, 0)); // e45² = -e4e4e5e5 = 1
}

#[test]
fn canonical_order_of_cl41_is_the_design_list() {
    // The list exactly as written in docs/conventions.md.
    let design = "1, e1, e2, e3, e4, e5, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45, e123, \
                  e124, e125, e134, e135, e145, e234, e235, e245, e345, e1234, e1235, e1245, \
                  e1345, e2345, e12345";
    let expected: Vec<&str> = design.split(',').map(str::trim).collect();
    assert_eq!(canonical_blade_names(5, None).unwrap(), expected);
    let names = ["e1", "e2", "e3", "e4", "e5"];
    assert_eq!(canonical_blade_names(5, Some(&names)).unwrap(), expected);
    // The masks agree with the names.
    for (mask, name) in canonical_order(5).into_iter().zip(&expected) {
        let from_name: usize = name
            .chars()
            .skip(1)
            .map(|c| 1usize << (c.to_digit(10).unwrap() - 1))
            .sum();
        assert_eq!(mask, from_name, "{name}");
    }
    assert!(canonical_blade_names(3, Some(&names)).is_err());
}

#[test]
fn canonical_order_is_sorted_and_complete() {
    for n in 0..=6 {
        let order = canonical_order(n);
        assert_eq!(order.len(), 1 << n);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..1usize << n).collect::<Vec<_>>());
        for w in order.windows(2) {
            assert_eq!(canonical_cmp(w[0], w[1]), Ordering::Less);
        }
    }
}

#[test]
fn canonical_round_trip_by_value() {
    let s = sig(&[1, 1, 1]);
    let m = Dm::from_canonical(&s, (0..8).map(|i| i as f64).collect()).unwrap();
    assert_eq!(m.get(0b011), 4.0); // e12 is the 5th canonical blade
    assert_eq!(m.get(0b100), 3.0); // e3
    assert_eq!(m.get(0b110), 6.0); // e23
    assert_eq!(
        m.to_canonical(),
        (0..8).map(|i| i as f64).collect::<Vec<_>>()
    );
    assert!(Dm::from_canonical(&s, vec![0.0; 7]).is_err());
}

#[test]
fn pseudoscalar_squares() {
    let i = Dm::<f64>::pseudoscalar(&cl41());
    assert_eq!(&i * &i, Dm::scalar(&cl41(), -1.0), "I² = -1 in Cl(4,1)");
    let s3 = sig(&[1, 1, 1]);
    let i3 = Dm::<f64>::pseudoscalar(&s3);
    assert_eq!(&i3 * &i3, Dm::scalar(&s3, -1.0));
    let p = sig(&[0, 1, 1, 1]);
    let ip = Dm::<f64>::pseudoscalar(&p);
    assert!((&ip * &ip).is_zero());
}

#[test]
fn dual_by_hand_in_cl3() {
    // I = e123, I² = -1, I⁻¹ = -e123; dual(e12) = e12 (-e123) = e3.
    let s = sig(&[1, 1, 1]);
    let b = |m: usize, c: f64| Dm::blade(&s, m, c).unwrap();
    assert_eq!(b(0b011, 1.0).dual(), b(0b100, 1.0));
    assert_eq!(b(0b110, 1.0).dual(), b(0b001, 1.0));
    assert_eq!(b(0b001, 1.0).dual(), b(0b110, -1.0)); // e1 (-e123) = -e23
    assert_eq!(b(0, 1.0).dual(), b(0b111, -1.0));
    // e12 ∨ e23 = undual(e3 ∧ e1) = undual(-e13) = -e13 e123 = -e2.
    assert_eq!(b(0b011, 1.0) & b(0b110, 1.0), b(0b010, -1.0));
    // Non-degenerate dual is A times the (independently computed) inverse of I.
    let i_inv = Dm::<f64>::pseudoscalar(&s).general_inverse().unwrap();
    let a = Dm::from_fn(&s, |m| m as f64 - 3.5);
    assert_eq!(a.dual(), &a * &i_inv);
}

#[test]
fn degenerate_dual_is_the_complement() {
    for s in named_signatures()
        .into_iter()
        .filter(Signature::is_degenerate)
    {
        let i = Dm::<i64x>::pseudoscalar(&s);
        for m in 0..s.blade_count() {
            let e = Dm::<i64x>::blade(&s, m, i64x(1)).unwrap();
            assert_eq!(&e ^ &e.dual(), i, "e ∧ dual(e) = I for mask {m:b}");
            assert_eq!(&e.undual() ^ &e, i, "undual(e) ∧ e = I for mask {m:b}");
            assert_eq!(e.dual().undual(), e);
        }
    }
    // Cl(3,0,1) with e0 degenerate: the meet of the subspaces e012 and e013 is their common
    // factor e01 (up to sign); two vectors (3 + 3 < 4 in the dual) meet in zero.
    let p = sig(&[0, 1, 1, 1]);
    let b = |m: usize| Dm::<i64x>::blade(&p, m, i64x(1)).unwrap();
    let meet = b(0b0111) & b(0b1011);
    assert!(meet == b(0b0011) || meet == -b(0b0011), "{meet:?}");
    assert!((b(0b0010) & b(0b0100)).is_zero());
}

#[test]
fn known_inverses() {
    // (1 + e1)(1 - e1) = 0 in Cl(3,0): no inverse.
    let s = sig(&[1, 1, 1]);
    let one = Dm::<Rational>::one(&s);
    let e1 = Dm::<Rational>::basis_vector(&s, 0).unwrap();
    assert!((&one + &e1).general_inverse().is_none());
    assert!(Dm::<Rational>::zero(&s).general_inverse().is_none());
    // 1 + e0 with e0² = 0: the inverse is 1 - e0 (not a versor: its "versor inverse" is wrong).
    let p = sig(&[0, 1, 1, 1]);
    let one = Dm::<Rational>::one(&p);
    let e0 = Dm::<Rational>::basis_vector(&p, 0).unwrap();
    assert_eq!((&one + &e0).general_inverse().unwrap(), &one - &e0);
    // e0 alone is a null vector: neither inverse exists.
    assert!(e0.general_inverse().is_none());
    assert!(e0.versor_inverse().is_none());
    // 2 + e12 in Cl(3,0): (2 + e12)(2 - e12) = 5.
    let a = Dm::from_fn(&s, |m| match m {
        0 => rat(2, 1),
        0b011 => rat(1, 1),
        _ => Rational::zero(),
    });
    let expected = Dm::from_fn(&s, |m| match m {
        0 => rat(2, 5),
        0b011 => rat(-1, 5),
        _ => Rational::zero(),
    });
    assert_eq!(a.general_inverse().unwrap(), expected);
    assert_eq!(a.versor_inverse().unwrap(), expected);
    // f64 with a tolerance rejects a nearly singular element.
    let near = Dm::<f64>::from_fn(&s, |m| match m {
        0 => 1.0,
        0b001 => 1.0 - 1e-14,
        _ => 0.0,
    });
    assert!(near.general_inverse_with_tolerance(&1e-9).is_none());
}

#[test]
fn errors_are_typed() {
    assert_eq!(
        Signature::new(&[1; 11]),
        Err(ReferenceError::TooManyGenerators(11))
    );
    assert_eq!(
        Signature::new(&[1, 3]),
        Err(ReferenceError::BadSignatureEntry { index: 1, value: 3 })
    );
    let s = sig(&[1, 1]);
    assert!(matches!(
        Dm::<f64>::basis_vector(&s, 2),
        Err(ReferenceError::GeneratorOutOfRange { index: 2, n: 2 })
    ));
    assert!(matches!(
        Dm::<f64>::blade(&s, 4, 1.0),
        Err(ReferenceError::MaskOutOfRange { mask: 4, n: 2 })
    ));
    let t = sig(&[1, -1]);
    let (a, b) = (Dm::<f64>::one(&s), Dm::<f64>::one(&t));
    assert!(a.check_same_signature(&a).is_ok());
    assert!(matches!(
        a.check_same_signature(&b),
        Err(ReferenceError::SignatureMismatch { .. })
    ));
    let msg = ReferenceError::BadSignatureEntry { index: 1, value: 3 }.to_string();
    assert!(msg.contains("entry 1") && msg.contains('3'), "{msg}");
}

#[test]
fn display_uses_canonical_names() {
    let s = sig(&[1, 1, 1]);
    let m = Dm::from_fn(&s, |m| match m {
        0b001 => 2.0,
        0b110 => -0.5,
        _ => 0.0,
    });
    assert_eq!(m.to_string(), "2·e1 + -0.5·e23");
    assert_eq!(Dm::<f64>::zero(&s).to_string(), "0");
}

#[test]
fn pqr_signatures() {
    assert_eq!(Signature::pqr(4, 1, 0).unwrap(), cl41());
    assert_eq!(Signature::pqr(3, 0, 1).unwrap().entries(), &[1, 1, 1, 0]);
}

/// A minimal exact integer ring for unit tests that need no division (keeps them independent
/// of the rational implementation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_camel_case_types)]
struct i64x(i64);

impl core::ops::Add for i64x {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self(self.0 + o.0)
    }
}
impl core::ops::Sub for i64x {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self(self.0 - o.0)
    }
}
impl core::ops::Mul for i64x {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self(self.0 * o.0)
    }
}
impl core::ops::Neg for i64x {
    type Output = Self;
    fn neg(self) -> Self {
        Self(-self.0)
    }
}
impl Ring for i64x {
    fn zero() -> Self {
        Self(0)
    }
    fn one() -> Self {
        Self(1)
    }
    fn from_i64(n: i64) -> Self {
        Self(n)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
}
