//! Runs the user-facing examples, so they stay true.

#[path = "../examples/conformal_meets.rs"]
mod conformal_meets;
#[path = "../examples/distance_clearance.rs"]
mod distance_clearance;
#[path = "../examples/pose_batch.rs"]
mod pose_batch;
#[path = "../examples/pose_queries.rs"]
mod pose_queries;

#[test]
fn conformal_meets_runs() {
    conformal_meets::main().expect("the example's inputs are valid");
}

#[test]
fn pose_queries_runs() {
    pose_queries::main().expect("the example's inputs are valid");
}

#[test]
fn pose_batch_runs() {
    pose_batch::main().expect("the example's inputs are valid");
}

#[test]
fn distance_clearance_runs() {
    distance_clearance::main().expect("the example's inputs are valid");
}
