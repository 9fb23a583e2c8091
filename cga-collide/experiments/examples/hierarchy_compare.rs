//! The three hierarchies on the double-sphere paper's workloads: the double outer/inner sphere
//! tree (double-sphere paper), the octree sphere tree (Fuentes Socorro) and the general BVH of the mesh module,
//! on the four polyhedra pairs at the two experiment-sphere sizes, with the same placements
//! for all and every answer compared with the exact reference (`cga_collide::collider::convex`).
//!
//! Per method: build time, memory, mean time per query (everything a query needs from the two
//! poses: the double-sphere tree transforms what it visits; the BVH places both meshes (vertex
//! transform and refit) then runs the exact solid test; the octree trees are moved (every
//! centre) then descended simultaneously), agreement with the exact answer, and for the octree
//! trees (an approximation from outside) their false positives; false negatives must be 0.
//!
//! Run: `cargo run --release -p cga-experiments --example hierarchy_compare [PLACEMENTS] [SVG]`
//! (default 20000 placements per pair and size). Prints markdown; writes the plot when SVG is
//! given.

use std::time::Instant;

use cga_collide::collider::Collider;
use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
use cga_collide::hierarchy::sphere_tree::SphereTree;
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::testing::convex::ConvexMeshRef;
use cga_experiments::experiment::{calibrate_radius, placement, PAPER_PAIRS};
use cga_experiments::plot::{svg_bar_charts, BarChart};

/// What one method answered over the placements.
#[derive(Default, Clone)]
struct Score {
    nanos: u128,
    agree: u64,
    false_positives: u64,
    false_negatives: u64,
}

struct Method {
    name: String,
    exact: bool,
    build_ms: f64,
    bytes: usize,
    score: Score,
}

fn tree_bytes(t: &DoubleSphereTree) -> usize {
    let leaves: usize = (0..t.nodes().len())
        .filter(|&i| t.nodes()[i].is_leaf())
        .map(|i| t.leaf_triangles(i).len() * 4)
        .sum();
    std::mem::size_of_val(t.nodes()) + leaves
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let placements: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let svg = args.get(2);
    let seed = 2008;
    let octree_depths = [2u32, 3, 4];
    println!(
        "Hierarchies on the double-sphere workloads: {placements} placements per pair and size \
         (seed {seed}); times are means per query on one thread.\n"
    );
    println!("| pair | size | method | exact | build ms (both) | memory KB (both) | µs per query | agrees with exact | false positives | false negatives |");
    println!("|---|---|---|---|---:|---:|---:|---:|---:|---:|");
    let mut groups = Vec::new();
    let mut series: Vec<(String, Vec<f64>)> = Vec::new();
    for (a_name, b_name) in PAPER_PAIRS {
        let pa = ConvexPolyhedron::by_name(a_name).expect("a paper solid");
        let pb = ConvexPolyhedron::by_name(b_name).expect("a paper solid");
        let ma = ConvexMeshRef::new(pa.vertices(), pa.triangles()).expect("valid mesh");
        let mb = ConvexMeshRef::new(pb.vertices(), pb.triangles()).expect("valid mesh");

        // Builds (timed once per pair).
        let mut methods: Vec<Method> = Vec::new();
        let mut ds = Vec::new();
        for kind in [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev] {
            let t0 = Instant::now();
            let ta = DoubleSphereTree::build(&pa, 3, kind).expect("level 3 builds");
            let tb = DoubleSphereTree::build(&pb, 3, kind).expect("level 3 builds");
            methods.push(Method {
                name: format!(
                    "double spheres, level 3, {}",
                    if kind == InnerSphereKind::Centroid {
                        "centroid"
                    } else {
                        "Chebyshev"
                    }
                ),
                exact: true,
                build_ms: t0.elapsed().as_secs_f64() * 1e3,
                bytes: tree_bytes(&ta) + tree_bytes(&tb),
                score: Score::default(),
            });
            ds.push((ta, tb));
        }
        let t0 = Instant::now();
        let (ca, cb) = (
            Collider::new(pa.to_trimesh()),
            Collider::new(pb.to_trimesh()),
        );
        methods.push(Method {
            name: "BVH (mesh module), exact solid test".into(),
            exact: true,
            build_ms: t0.elapsed().as_secs_f64() * 1e3,
            bytes: ca.bvh().heap_bytes() + cb.bvh().heap_bytes(),
            score: Score::default(),
        });
        let mut octrees: Vec<(SphereTree, SphereTree)> = Vec::new();
        for depth in octree_depths {
            let t0 = Instant::now();
            let ta = build(&ca, &BuildOptions::depth(depth))
                .expect("octree builds")
                .0;
            let tb = build(&cb, &BuildOptions::depth(depth))
                .expect("octree builds")
                .0;
            methods.push(Method {
                name: format!("octree spheres, depth {depth}, simultaneous descent"),
                exact: false,
                build_ms: t0.elapsed().as_secs_f64() * 1e3,
                bytes: ta.heap_bytes() + tb.heap_bytes(),
                score: Score::default(),
            });
            octrees.push((ta, tb));
        }

        for target in [0.25, 0.75] {
            let radius = calibrate_radius(&pa, &pb, target, 4000, seed);
            let mut methods = methods
                .iter()
                .map(|m| Method {
                    name: m.name.clone(),
                    score: Score::default(),
                    ..*m
                })
                .collect::<Vec<_>>();
            let (mut va, mut vb) = (Vec::new(), Vec::new());
            for i in 0..placements {
                let (pose_a, pose_b) = placement(seed, i, radius);
                va.clear();
                va.extend(pa.vertices().iter().map(|v| pose_a * v));
                vb.clear();
                vb.extend(pb.vertices().iter().map(|v| pose_b * v));
                let truth = ma
                    .with_vertices(&va)
                    .expect("finite")
                    .collides_solid(&mb.with_vertices(&vb).expect("finite"))
                    .intersect;
                let record = |m: &mut Method, answer: bool, nanos: u128| {
                    m.score.nanos += nanos;
                    m.score.agree += u64::from(answer == truth);
                    m.score.false_positives += u64::from(answer && !truth);
                    m.score.false_negatives += u64::from(!answer && truth);
                };
                for (k, (ta, tb)) in ds.iter().enumerate() {
                    let t = Instant::now();
                    let answer = ta.collides_at(&pose_a, tb, &pose_b).collides;
                    record(&mut methods[k], answer, t.elapsed().as_nanos());
                }
                let t = Instant::now();
                let answer = match (ca.placed(&pose_a), cb.placed(&pose_b)) {
                    (Ok(x), Ok(y)) => x.collides_solid(&y),
                    _ => unreachable!("finite poses of finite meshes"),
                };
                record(&mut methods[2], answer, t.elapsed().as_nanos());
                for (k, (ta, tb)) in octrees.iter().enumerate() {
                    let t = Instant::now();
                    let answer = ta.collides_at(&pose_a, tb, &pose_b).collides;
                    record(&mut methods[3 + k], answer, t.elapsed().as_nanos());
                }
            }
            let size = if target < 0.5 {
                "large (25%)"
            } else {
                "small (75%)"
            };
            fn short(n: &str) -> &str {
                match n {
                    "truncated_octahedron" => "troctahedron",
                    "rh" => "Rh",
                    other => other,
                }
            }
            let pair = format!("{} – {}", short(a_name), short(b_name));
            groups.push(format!("{pair}\n{size}"));
            for (k, m) in methods.iter().enumerate() {
                let us = m.score.nanos as f64 / placements as f64 / 1e3;
                println!(
                    "| {pair} | {size} | {} | {} | {:.2} | {:.1} | {:.2} | {:.2}% | {} | {} |",
                    m.name,
                    if m.exact { "yes" } else { "no (outer approx.)" },
                    m.build_ms,
                    m.bytes as f64 / 1024.0,
                    us,
                    100.0 * m.score.agree as f64 / placements as f64,
                    m.score.false_positives,
                    m.score.false_negatives
                );
                if series.len() <= k {
                    series.push((m.name.clone(), Vec::new()));
                }
                series[k].1.push(us);
            }
        }
    }
    if let Some(path) = svg {
        let plot = svg_bar_charts(&[BarChart {
            title: "Mean time per query (µs), paper pairs, same placements".into(),
            groups,
            series,
        }]);
        std::fs::write(path, plot).expect("the plot file can be written");
        println!("\nPlot written to {path}.");
    }
}
