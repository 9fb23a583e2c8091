//! Runs the user-facing examples, so they stay true.

#[path = "../examples/declare_algebra.rs"]
mod declare_algebra;
#[path = "../examples/symbolic_derivation.rs"]
mod symbolic_derivation;

#[test]
fn declare_algebra_runs() {
    declare_algebra::main();
}

#[test]
fn symbolic_derivation_runs() {
    symbolic_derivation::main();
}
