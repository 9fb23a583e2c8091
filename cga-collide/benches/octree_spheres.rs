//! Octree sphere trees (Fuentes Socorro's method): build time per depth, and one collision query on the
//! `cga` main job's placement (bunny00 vs armadillo, `--unit`, armadillo moved by
//! `(0.3, 0.05, 0)`) by the paper's method (`cga_collide::testing::sphere_tree::paper_method`) and the
//! simultaneous descent (`SphereTree::collides`), with the exact BVH
//! query (`Collider::collides_solid`) as the baseline in the same run; plus a near miss (the
//! solids do not collide, the depth-5 trees do: a false positive of the approximation).
//!
//! `cargo bench -p cga-collide --bench octree_spheres -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use cga_collide::collider::Collider;
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
use cga_collide::nalgebra::{Isometry3, UnitQuaternion, Vector3};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::testing::sphere_tree::paper_method;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

fn build_time(c: &mut Criterion) {
    let bunny = Collider::new(TriMesh::bunny().unit());
    let mut g = c.benchmark_group("octree_build_bunny3674");
    g.sample_size(10);
    for depth in [3u32, 5, 6] {
        g.bench_with_input(BenchmarkId::from_parameter(depth), &depth, |b, &d| {
            b.iter(|| build(&bunny, &BuildOptions::depth(d)).map(|t| t.0.len()))
        });
    }
    g.finish();
}

fn queries(c: &mut Criterion) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let b = Collider::new(TriMesh::armadillo().unit());
    let (ta, _) = build(&a, &BuildOptions::depth(5)).expect("tree");
    let (tb, _) = build(&b, &BuildOptions::depth(5)).expect("tree");
    let placements = [
        ("main_job", Isometry3::translation(0.3, 0.05, 0.0)),
        (
            "near_miss",
            Isometry3::from_parts(
                Vector3::new(0.62, 0.55, 0.0).into(),
                UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1),
            ),
        ),
    ];
    let mut g = c.benchmark_group("octree_query_depth5");
    for (name, iso) in placements {
        let pb = b.placed(&iso).expect("placed");
        let mb = tb.transformed(&iso);
        eprintln!(
            "{name}: exact {}, paper {}, simultaneous {}",
            a.collides_solid(&pb),
            paper_method(&ta, &mb).collides,
            ta.collides(&mb).collides
        );
        g.bench_function(format!("{name}/exact_bvh_baseline"), |bch| {
            bch.iter(|| black_box(a.collides_solid(&pb)))
        });
        g.bench_function(format!("{name}/paper"), |bch| {
            bch.iter(|| black_box(paper_method(&ta, &mb).collides))
        });
        g.bench_function(format!("{name}/simultaneous"), |bch| {
            bch.iter(|| black_box(ta.collides(&mb).collides))
        });
    }
    g.finish();
}

criterion_group!(benches, build_time, queries);
criterion_main!(benches);
