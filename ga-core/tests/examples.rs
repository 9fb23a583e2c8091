//! Runs the user-facing examples, so they stay true.

#[path = "../examples/declare_algebra.rs"]
mod declare_algebra;
// Only the sanity check is called here; the benchmark runs as the example.
#[allow(dead_code)]
#[path = "../examples/ik_chain.rs"]
mod ik_chain;
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

#[test]
fn ik_chain_matches_ga_benchmarks_sanity_values() {
    ik_chain::check_sanity();
}

#[test]
fn ik_chain_sanity_gripper_is_within_1e16_of_exact() {
    ik_chain::check_sanity_accuracy();
}
