//! Decision statistics of the double-sphere tree on random placements (no timing: use the
//! `double_sphere` benchmark for that).
//!
//! `cargo run -p cga-experiments --release --example double_sphere_stats -- [placements] [radius] [level]`
//!
//! For each of the paper's four pairs and both inner-sphere kinds: how many placements collide,
//! how each answer was decided, the mean numbers of sphere and triangle tests, and a check of
//! every answer against the GJK reference of `cga_collide::collider::convex`.

use std::collections::BTreeMap;

use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
use cga_collide::nalgebra::Point3;
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::testing::convex::ConvexMeshRef;
use cga_experiments::experiment::placement;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let radius: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(2.0);
    let level: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(3);
    let pairs = [
        ("truncated_octahedron", "diamond"),
        ("truncated_octahedron", "rh"),
        ("octahedron", "diamond"),
        ("cube", "cube"),
    ];
    println!("{n} placements per pair, both centres uniform in an experiment sphere of radius {radius} (`experiment::placement`), level {level}");
    for (na, nb) in pairs {
        let (a, b) = (
            ConvexPolyhedron::by_name(na).unwrap(),
            ConvexPolyhedron::by_name(nb).unwrap(),
        );
        for kind in [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev] {
            let (ta, tb) = (
                DoubleSphereTree::build(&a, level, kind).unwrap(),
                DoubleSphereTree::build(&b, level, kind).unwrap(),
            );
            let poses: Vec<_> = (0..n as u64).map(|i| placement(2009, i, radius)).collect();
            let mut decisions: BTreeMap<String, usize> = BTreeMap::new();
            let (mut spheres, mut triangles, mut collisions, mut mismatches) = (0u64, 0u64, 0, 0);
            for (pa, pb) in &poses {
                let out = ta.collides_at(pa, &tb, pb);
                *decisions
                    .entry(format!("{:?}", out.decided_by))
                    .or_default() += 1;
                spheres += u64::from(out.sphere_tests);
                triangles += u64::from(out.triangle_tests);
                collisions += usize::from(out.collides);
                let va: Vec<Point3<f64>> = a.vertices().iter().map(|v| *pa * v).collect();
                let vb: Vec<Point3<f64>> = b.vertices().iter().map(|v| *pb * v).collect();
                let truth = ConvexMeshRef::new(&va, a.triangles())
                    .unwrap()
                    .collides_solid(&ConvexMeshRef::new(&vb, b.triangles()).unwrap())
                    .intersect;
                mismatches += usize::from(truth != out.collides);
            }
            println!(
                "{na:>21}-{nb:<8} {kind:<9?}: {collisions:>6} collide ({:.1}%), mean sphere tests {:.1}, triangle tests {:.1}, mismatches {mismatches}; {decisions:?}",
                100.0 * collisions as f64 / n as f64,
                spheres as f64 / n as f64,
                triangles as f64 / n as f64,
            );
        }
    }
}
