//! Runs the user-facing examples, so they stay true.

#[path = "../examples/conformal_meets.rs"]
mod conformal_meets;

#[test]
fn conformal_meets_runs() {
    conformal_meets::main().expect("the example's inputs are valid");
}
