//! Every public error type's message says what was wrong, where (argument, index, line, byte)
//! and what to do about it.

use ga_core::interop::InteropError;
use ga_core::reference::{DenseMultivector, Signature, MAX_GENERATORS};
use ga_core::symbolic::Poly;

/// Panics unless `message` contains every one of `parts`.
fn says(message: impl std::fmt::Display, parts: &[&str]) {
    let message = message.to_string();
    for part in parts {
        assert!(message.contains(part), "{part:?} missing from: {message}");
    }
}

#[test]
fn reference_errors_name_the_entry_and_the_rule() {
    says(
        Signature::new(&[1, 2, -1]).unwrap_err(),
        &["entry 1", "is 2", "+1, -1 or 0"],
    );
    says(
        Signature::new(&[1; MAX_GENERATORS + 1]).unwrap_err(),
        &["11 generators", "at most 10", "smaller algebra"],
    );
    let s = Signature::new(&[1, 1, 1]).unwrap();
    says(
        DenseMultivector::<f64>::basis_vector(&s, 3).unwrap_err(),
        &["generator index 3", "3 generators", "0 to n - 1"],
    );
    says(
        DenseMultivector::blade(&s, 0b1000, 1.0).unwrap_err(),
        &["0b1000", "3 generators", "below 2^n"],
    );
}

#[test]
fn symbolic_errors_name_the_variable_or_the_byte() {
    let p = Poly::parse("x + y").unwrap();
    says(
        p.eval_f64(&[("x", 1.0)]).unwrap_err(),
        &["`y`", "no value", "(\"y\", value)"],
    );
    says(
        Poly::parse("x + * y").unwrap_err(),
        &["parse error at byte", "`x + * y`"],
    );
    says(
        Poly::parse("x^400")
            .unwrap()
            .eval_f64(&[("x", 1e300)])
            .unwrap_err(),
        &["non-finite", "eval_rational"],
    );
}

#[test]
fn interop_errors_say_what_converts() {
    says(
        InteropError::NotARotation {
            blade: "e14",
            value: 0.5,
        },
        &["e14", "0.5", "only a pure rotation", "affine"],
    );
    says(
        InteropError::NotARotationMatrix {
            deviation: 0.25,
            determinant: 2.0,
        },
        &["2.5e-1", "determinant 2", "remove scaling"],
    );
    says(
        InteropError::NotRigid("the motor dilates"),
        &["the motor dilates", "only rotations and translations"],
    );
}
