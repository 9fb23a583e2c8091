//! Bad declarations must fail with a readable error pointing at the offending token.

#[test]
fn bad_declarations_are_rejected_with_spans() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/compile_fail/*.rs");
}
