//! Prints the README table: on the fixed adversarial set, how often each method is wrong
//! (against the independent exact oracle).
//!
//! Run: `cargo run --release -p cga-experiments --example adversarial_table`

use cga_collide::exact::ExactKernel;
use cga_collide::testing::adversarial::{adversarial_set, Case};
use cga_collide::testing::baseline;
use cga_collide::testing::FloatKernel;

/// The seed and size of the fixed set.
const SEED: u64 = 2026;
const PER_KIND: usize = 1000;

fn reference(c: &Case) -> Option<bool> {
    Some(match c {
        Case::SegSeg(..) => return None,
        Case::SegTri(a, b) => baseline::moller_trumbore_segment_triangle(a, b),
        Case::SegSphere(a, b) => baseline::segment_sphere(a, b),
        Case::SegBall(a, b) => baseline::segment_ball(a, b),
        Case::TriTri(a, b) => baseline::moller_tri_tri(a, b),
        Case::TriSphere(a, b) => baseline::triangle_sphere(a, b),
        Case::TriBall(a, b) => baseline::triangle_ball(a, b),
        Case::SphereSphere(a, b) => baseline::sphere_sphere(a, b),
        Case::BallBall(a, b) => baseline::ball_ball(a, b),
    })
}

fn main() {
    let start = std::time::Instant::now();
    let set = adversarial_set(SEED, PER_KIND);
    let kinds = [
        "segment–segment",
        "segment–triangle",
        "segment–sphere",
        "segment–ball",
        "triangle–triangle",
        "triangle–sphere",
        "triangle–ball",
        "sphere–sphere",
        "ball–ball",
    ];
    println!(
        "Adversarial set: seed {SEED}, {PER_KIND} cases per pair kind ({} in all).\n",
        set.len()
    );
    println!("| pair | cases | true | Euclidean reference wrong | f64 without fall-back wrong | exact wrong |");
    println!("|---|---:|---:|---:|---:|---:|");
    let mut total = [0usize; 5];
    for kind in kinds {
        let (mut n, mut t, mut refw, mut fw, mut ew, mut has_ref) = (0, 0, 0, 0, 0, false);
        for c in set.iter().filter(|c| c.kind() == kind) {
            let truth = c.truth();
            n += 1;
            t += truth as usize;
            if let Some(r) = reference(c) {
                has_ref = true;
                refw += (r != truth) as usize;
            }
            fw += (c.intersects_with::<FloatKernel>() != truth) as usize;
            ew += (c.intersects_with::<ExactKernel>() != truth) as usize;
        }
        let pct = |w: usize| format!("{w} ({:.1} %)", 100.0 * w as f64 / n as f64);
        let r = if has_ref {
            pct(refw)
        } else {
            "–".to_string()
        };
        println!("| {kind} | {n} | {t} | {r} | {} | {} |", pct(fw), pct(ew));
        total[0] += n;
        total[1] += refw;
        total[2] += fw;
        total[3] += ew;
        total[4] += t;
    }
    println!(
        "| all | {} | {} | {} | {} | {} |",
        total[0], total[4], total[1], total[2], total[3]
    );
    println!("\nEuclidean references: Möller 1997 (epsilon 1e-6) for triangle–triangle, Möller–Trumbore for");
    println!("segment–triangle, closest-point f64 tests for spheres and balls; none for segment–segment.");
    eprintln!("(took {:.1} s)", start.elapsed().as_secs_f64());
}
