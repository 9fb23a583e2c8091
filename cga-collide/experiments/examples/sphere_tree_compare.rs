//! Octree sphere trees (Fuentes Socorro's method) against the exact BVH answer, on the `cga` main job's
//! meshes (bunny00 vs armadillo, both `--unit`, armadillo moved by `--translate 0.3,0.05,0`)
//! and on random rigid placements of the armadillo: build time and memory per depth, query
//! time and ball–ball tests of the paper's method and of the simultaneous descent, and the
//! sphere trees' false positives / negatives against `Collider::collides_solid`.
//!
//! Run: `cargo run --release -p cga-experiments --example sphere_tree_compare [PLACEMENTS] [MAX_DEPTH]`
//! (defaults 1000 and 7). Prints markdown tables.

use std::time::{Duration, Instant};

use cga_collide::collider::Collider;
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
use cga_collide::hierarchy::sphere_tree::{CollisionResult, SphereTree};
use cga_collide::nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::testing::sphere_tree::{paper_method, paper_method_as_published};

/// splitmix64: a small deterministic generator (no dependency).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A uniformly random rotation (Shoemake) and a translation uniform in a ball of radius `r`.
fn placement(rng: &mut Rng, r: f64) -> Isometry3<f64> {
    let (u1, u2, u3) = (rng.uniform(), rng.uniform(), rng.uniform());
    let tau = std::f64::consts::TAU;
    let q = Quaternion::new(
        (1.0 - u1).sqrt() * (tau * u2).sin(),
        (1.0 - u1).sqrt() * (tau * u2).cos(),
        u1.sqrt() * (tau * u3).sin(),
        u1.sqrt() * (tau * u3).cos(),
    );
    let t = loop {
        let v = [
            2.0 * rng.uniform() - 1.0,
            2.0 * rng.uniform() - 1.0,
            2.0 * rng.uniform() - 1.0,
        ];
        if v.iter().map(|x| x * x).sum::<f64>() <= 1.0 {
            break v;
        }
    };
    Isometry3::from_parts(
        Translation3::new(r * t[0], r * t[1], r * t[2]),
        UnitQuaternion::from_quaternion(q),
    )
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let placements: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let max_depth: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(7);

    let a_mesh = TriMesh::bunny00().unit();
    let b_mesh = TriMesh::armadillo().unit();
    println!(
        "bunny00: {} triangles (closed: {}), armadillo: {} triangles (closed: {}); {} random placements, {} threads\n",
        a_mesh.num_triangles(),
        a_mesh.is_closed(),
        b_mesh.num_triangles(),
        b_mesh.is_closed(),
        placements,
        rayon::current_num_threads(),
    );
    let t = Instant::now();
    let a = Collider::new(a_mesh);
    let b = Collider::new(b_mesh);
    let bvh_build = t.elapsed();
    let bvh_bytes = a.bvh().heap_bytes() + b.bvh().heap_bytes();

    // The placements: the main job's, then random ones.
    let mut rng = Rng(2026);
    let mut isos = vec![Isometry3::translation(0.3, 0.05, 0.0)];
    isos.extend((0..placements).map(|_| placement(&mut rng, 1.2)));
    let placed: Vec<Collider> = isos.iter().map(|iso| b.placed(iso).unwrap()).collect();
    let t = Instant::now();
    let exact: Vec<bool> = placed.iter().map(|pb| a.collides_solid(pb)).collect();
    let bvh_query = t.elapsed();
    let colliding = exact[1..].iter().filter(|&&e| e).count();
    println!(
        "Exact answer (`Collider::collides_solid`, BVH + exact triangle tests + point-in-solid): main placement collides: {}; {} of {} random placements collide. BVH build (both meshes) {:.1} ms, {} bytes; mean query {:.3} ms.\n",
        exact[0],
        colliding,
        placements,
        ms(bvh_build),
        bvh_bytes,
        ms(bvh_query) / isos.len() as f64,
    );

    println!("| depth | nodes (bunny / armadillo) | leaves | build ms (bunny / armadillo) | bytes (both trees) | main placement: paper / simult. / exact | paper µs/query | simult. µs/query | paper ball tests/query | simult. ball tests/query | false positives | false negatives | paper as published: misses |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for depth in 3..=max_depth {
        let t = Instant::now();
        let (ta, _) = build(&a, &BuildOptions::depth(depth)).expect("bunny00 tree");
        let build_a = t.elapsed();
        let t = Instant::now();
        let (tb, _) = build(&b, &BuildOptions::depth(depth)).expect("armadillo tree");
        let build_b = t.elapsed();
        assert!(ta.nesting_violations().is_empty() && tb.nesting_violations().is_empty());
        let moved: Vec<SphereTree> = isos.iter().map(|iso| tb.transformed(iso)).collect();

        let time = |f: &dyn Fn(&SphereTree, &SphereTree) -> CollisionResult| {
            let t = Instant::now();
            let r: Vec<CollisionResult> = moved.iter().map(|m| f(&ta, m)).collect();
            (t.elapsed(), r)
        };
        let (paper_t, paper) = time(&paper_method);
        let (sim_t, sim) = time(&SphereTree::collides);
        let (_, written) = time(&paper_method_as_published);
        let n = isos.len() as f64;
        let mut fp = 0;
        let mut fneg = 0;
        let mut misses = 0;
        for k in 0..isos.len() {
            assert_eq!(
                paper[k].collides, sim[k].collides,
                "paper method and simultaneous descent disagree at placement {k}"
            );
            if k == 0 {
                continue;
            }
            match (sim[k].collides, exact[k]) {
                (true, false) => fp += 1,
                (false, true) => fneg += 1,
                _ => {}
            }
            if sim[k].collides && !written[k].collides {
                misses += 1;
            }
        }
        let tests =
            |r: &[CollisionResult]| r.iter().map(|x| x.sphere_tests).sum::<u64>() as f64 / n;
        println!(
            "| {depth} | {} / {} | {} / {} | {:.1} / {:.1} | {} | {} / {} / {} | {:.1} | {:.1} | {:.0} | {:.0} | {fp} of {} | {fneg} of {} | {misses} |",
            ta.len(),
            tb.len(),
            ta.leaf_count(),
            tb.leaf_count(),
            ms(build_a),
            ms(build_b),
            ta.heap_bytes() + tb.heap_bytes(),
            paper[0].collides,
            sim[0].collides,
            exact[0],
            paper_t.as_secs_f64() * 1e6 / n,
            sim_t.as_secs_f64() * 1e6 / n,
            tests(&paper),
            tests(&sim),
            placements - colliding,
            colliding,
        );
    }
    println!(
        "\nFalse positives: placements where the trees collide but the solids do not (out of the non-colliding ones); false negatives: the reverse (out of the colliding ones; zero by construction). \"Paper as published\": colliding placements (by the fixed methods) where the paper's C++ as written (first meeting child only) answers no collision."
    );
}
