//! The double-sphere tree of the double-sphere paper: Table 1's polyhedra, the tree's invariants and
//! the exactness of `DoubleSphereTree::collides_at` against an independent brute force.

use std::sync::OnceLock;

use cga_collide::collider::Collider;
use cga_collide::hierarchy::double_sphere::{Decision, DoubleSphereTree, InnerSphereKind};
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::testing::double_sphere::{
    chebyshev_brute, depth, part, smallest_enclosing_ball, smallest_enclosing_ball_brute,
};
use cga_collide::Error;
use cga_collide::{Intersects, Triangle};
use proptest::prelude::*;

const KINDS: [InnerSphereKind; 2] = [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev];
const PAIRS: [(&str, &str); 4] = [
    ("truncated_octahedron", "diamond"),
    ("truncated_octahedron", "rh"),
    ("octahedron", "diamond"),
    ("cube", "cube"),
];

fn poly(name: &str) -> &'static ConvexPolyhedron {
    static P: OnceLock<Vec<(&'static str, ConvexPolyhedron)>> = OnceLock::new();
    let all = P.get_or_init(|| {
        ConvexPolyhedron::NAMES
            .iter()
            .map(|&n| (n, ConvexPolyhedron::by_name(n).unwrap()))
            .collect()
    });
    &all.iter().find(|(n, _)| *n == name).unwrap().1
}

/// Trees for every solid, level 0..=4, both kinds (built once).
fn tree(name: &str, level: usize, kind: InnerSphereKind) -> &'static DoubleSphereTree {
    static T: OnceLock<Vec<(&'static str, usize, InnerSphereKind, DoubleSphereTree)>> =
        OnceLock::new();
    let all = T.get_or_init(|| {
        let mut v = Vec::new();
        for &n in &ConvexPolyhedron::NAMES {
            for l in 0..=4 {
                for k in KINDS {
                    v.push((n, l, k, DoubleSphereTree::build(poly(n), l, k).unwrap()));
                }
            }
        }
        v
    });
    &all.iter()
        .find(|(n, l, k, _)| *n == name && *l == level && *k == kind)
        .unwrap()
        .3
}

#[test]
fn table_1_counts() {
    let want = [
        ("cube", 8, 12, 6),
        ("octahedron", 6, 12, 8),
        ("diamond", 41, 88, 49),
        ("rh", 120, 180, 62),
        ("truncated_octahedron", 24, 36, 14),
    ];
    for (name, v, e, f) in want {
        let p = poly(name);
        assert_eq!(
            (p.num_vertices(), p.num_edges(), p.num_faces()),
            (v, e, f),
            "{name}"
        );
        // Fan triangulation: a k-gon gives k - 2 triangles.
        let t: usize = p.faces().iter().map(|f| f.len() - 2).sum();
        assert_eq!(p.triangles().len(), t);
        assert_eq!(p.triangle_faces().len(), t);
        // Closed: the triangle mesh uses every edge twice.
        assert!(p.to_trimesh().is_closed(), "{name}");
    }
}

#[test]
fn polyhedra_are_convex_outward_and_unit() {
    for name in ConvexPolyhedron::NAMES {
        let p = poly(name);
        assert!(
            p.volume() > 0.0,
            "{name}: outward orientation gives a positive volume"
        );
        let centroid =
            p.vertices().iter().map(|v| v.coords).sum::<Vector3<f64>>() / p.num_vertices() as f64;
        for f in 0..p.num_faces() {
            let n = p.face_normal(f);
            let v0 = p.vertices()[p.faces()[f][0]];
            // Outward: the centroid is behind every face.
            assert!(n.dot(&(centroid - v0.coords)) < 0.0, "{name} face {f}");
            // Convex: every vertex is behind every face plane.
            for v in p.vertices() {
                assert!(n.dot(&(v - v0)) < 1e-12, "{name} face {f}");
            }
        }
        // Circumradius 1 about the origin (the smallest enclosing sphere).
        let b = smallest_enclosing_ball(p.vertices());
        assert!(b.centre.coords.norm() < 1e-9, "{name}: {:?}", b.centre);
        assert!((b.radius - 1.0).abs() < 1e-9, "{name}: {}", b.radius);
        // The triangle map points to the face that contains the triangle.
        for (t, &f) in p.triangle_faces().iter().enumerate() {
            assert!(p.triangles()[t]
                .iter()
                .all(|&i| p.faces()[f].contains(&(i as usize))));
        }
    }
    assert!(matches!(
        ConvexPolyhedron::by_name("dodecahedron"),
        Err(Error::UnknownPolyhedron { .. })
    ));
}

#[test]
fn validation_rejects_bad_input() {
    let cube = poly("cube");
    let v = cube.vertices().to_vec();
    let f = cube.faces().to_vec();
    assert!(ConvexPolyhedron::new(v.clone(), f.clone()).is_ok());
    // Open: drop a face.
    let err = ConvexPolyhedron::new(v.clone(), f[1..].to_vec()).unwrap_err();
    assert!(matches!(err, Error::PolyhedronBadEdge { .. }), "{err}");
    // Inward face.
    let mut g = f.clone();
    g[0].reverse();
    assert!(ConvexPolyhedron::new(v.clone(), g).is_err());
    // All faces inward: consistent but inside out.
    let g: Vec<Vec<usize>> = f
        .iter()
        .map(|x| x.iter().rev().copied().collect())
        .collect();
    let err = ConvexPolyhedron::new(v.clone(), g).unwrap_err();
    assert!(
        matches!(
            err,
            Error::PolyhedronNonConvexFace { .. } | Error::PolyhedronNotConvex { .. }
        ),
        "{err}"
    );
    // Non-planar face: push a vertex out.
    let mut w = v.clone();
    w[0].x *= 1.1;
    let err = ConvexPolyhedron::new(w, f.clone()).unwrap_err();
    assert!(
        matches!(err, Error::PolyhedronNonPlanarFace { .. }),
        "{err}"
    );
    // Dent: move a vertex inwards along its diagonal (faces stay non-planar -> error).
    let mut w = v.clone();
    w[0] = Point3::from(w[0].coords * 0.5);
    assert!(ConvexPolyhedron::new(w, f.clone()).is_err());
    // Index out of range.
    let mut g = f.clone();
    g[0][0] = 99;
    assert!(matches!(
        ConvexPolyhedron::new(v.clone(), g).unwrap_err(),
        Error::PolyhedronIndexOutOfRange { index: 99, .. }
    ));
    // Non-finite.
    let mut w = v.clone();
    w[3].y = f64::NAN;
    assert!(matches!(
        ConvexPolyhedron::new(w, f).unwrap_err(),
        Error::PolyhedronNonFiniteVertex { vertex: 3, .. }
    ));
}

/// Independent brute force: every pair of transformed triangles with the exact test, plus
/// containment by the mesh collider's exact point-in-solid test.
fn brute(
    a: &ConvexPolyhedron,
    pa: &Isometry3<f64>,
    b: &ConvexPolyhedron,
    pb: &Isometry3<f64>,
) -> bool {
    let ma: TriMesh = a.to_trimesh().transformed(pa).unwrap();
    let mb: TriMesh = b.to_trimesh().transformed(pb).unwrap();
    let ta: Vec<Triangle> = (0..ma.num_triangles())
        .map(|i| ma.triangle(i as u32))
        .collect();
    let tb: Vec<Triangle> = (0..mb.num_triangles())
        .map(|i| mb.triangle(i as u32))
        .collect();
    if ta.iter().any(|x| tb.iter().any(|y| x.intersects(y))) {
        return true;
    }
    let ca = Collider::new(ma.clone());
    let cb = Collider::new(mb.clone());
    cb.contains_point(&ma.vertices()[0]) || ca.contains_point(&mb.vertices()[0])
}

fn pose(t: [f64; 3], axis: [f64; 3], angle: f64) -> Isometry3<f64> {
    let axis = Vector3::new(axis[0], axis[1], axis[2]);
    let rot = if axis.norm() > 1e-9 {
        UnitQuaternion::from_axis_angle(&cga_collide::nalgebra::Unit::new_normalize(axis), angle)
    } else {
        UnitQuaternion::identity()
    };
    Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rot)
}

#[test]
fn quick_random_agreement() {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(42);
    let mut hits = 0;
    for (na, nb) in PAIRS {
        for level in [0, 3] {
            for kind in KINDS {
                let (ta, tb) = (tree(na, level, kind), tree(nb, level, kind));
                for _ in 0..200 {
                    let pa = pose(
                        [0.0; 3],
                        [rng.float(-1., 1.), rng.float(-1., 1.), rng.float(-1., 1.)],
                        rng.float(0., 6.3),
                    );
                    let pb = pose(
                        [rng.float(-2., 2.), rng.float(-2., 2.), rng.float(-2., 2.)],
                        [rng.float(-1., 1.), rng.float(-1., 1.), rng.float(-1., 1.)],
                        rng.float(0., 6.3),
                    );
                    let got = ta.collides_at(&pa, tb, &pb);
                    let want = brute(poly(na), &pa, poly(nb), &pb);
                    assert_eq!(
                        got.collides, want,
                        "{na} {nb} level {level} {kind:?} {pa:?} {pb:?} {got:?}"
                    );
                    hits += usize::from(want);
                }
            }
        }
    }
    assert!(hits > 100);
}

/// The trees' solids and levels exercised by the invariant tests.
fn all_trees() -> impl Iterator<
    Item = (
        &'static str,
        usize,
        InnerSphereKind,
        &'static DoubleSphereTree,
    ),
> {
    ConvexPolyhedron::NAMES.iter().flat_map(|&n| {
        (0..=4).flat_map(move |l| KINDS.iter().map(move |&k| (n, l, k, tree(n, l, k))))
    })
}

#[test]
fn outer_spheres_contain_their_node_and_are_minimal() {
    for (name, level, kind, t) in all_trees() {
        for (i, node) in t.nodes().iter().enumerate() {
            let sub = part(t, i);
            for v in &sub.vertices {
                assert!(
                    (v - node.outer.centre).norm() <= node.outer.radius,
                    "{name} L{level} {kind:?} node {i}"
                );
            }
            // Minimal: against the brute force over all 1-4 point support sets (small nodes).
            if level <= 2 && kind == InnerSphereKind::Centroid && sub.vertices.len() <= 30 {
                let b = smallest_enclosing_ball_brute(&sub.vertices);
                assert!(
                    (b.radius - node.outer.radius).abs() < 1e-9,
                    "{name} L{level} node {i}: {} vs brute {}",
                    node.outer.radius,
                    b.radius
                );
            }
        }
    }
}

#[test]
fn smallest_enclosing_ball_matches_brute_force_on_random_points() {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(5);
    for n in [1, 2, 3, 4, 5, 8, 13, 20] {
        for _ in 0..20 {
            let pts: Vec<Point3<f64>> = (0..n).map(|_| rng.point()).collect();
            let w = smallest_enclosing_ball(&pts);
            let b = smallest_enclosing_ball_brute(&pts);
            assert!(pts.iter().all(|p| (p - w.centre).norm() <= w.radius));
            assert!(
                (w.radius - b.radius).abs() < 1e-9,
                "{n}: {} vs {}",
                w.radius,
                b.radius
            );
        }
    }
}

#[test]
fn inner_spheres_are_inside_and_chebyshev_is_larger() {
    for (name, level, _, t) in all_trees().filter(|x| x.2 == InnerSphereKind::Centroid) {
        let cheb = tree(name, level, InnerSphereKind::Chebyshev);
        let solid: Vec<(Vector3<f64>, f64)> = (0..poly(name).num_faces())
            .map(|f| {
                let n = poly(name).face_normal(f);
                (
                    n,
                    n.dot(&poly(name).vertices()[poly(name).faces()[f][0]].coords),
                )
            })
            .collect();
        assert_eq!(t.nodes().len(), cheb.nodes().len());
        for (i, (a, b)) in t.nodes().iter().zip(cheb.nodes()).enumerate() {
            for (kind, s) in [("centroid", &a.inner), ("chebyshev", &b.inner)] {
                let planes = part(t, i).planes();
                assert!(
                    depth(&planes, &s.centre) >= s.radius,
                    "{name} L{level} node {i} {kind}"
                );
                assert!(
                    depth(&solid, &s.centre) >= s.radius,
                    "{name} L{level} node {i} {kind}"
                );
            }
            assert!(b.inner.radius >= a.inner.radius, "{name} L{level} node {i}");
            // The same splits for both kinds.
            assert_eq!(a.outer, b.outer);
            // Chebyshev is the LP optimum (brute force over plane quadruples, small nodes).
            let planes = part(t, i).planes();
            if planes.len() <= 20 {
                let (_, r) = chebyshev_brute(&planes);
                assert!(
                    (r - b.inner.radius).abs() < 1e-9,
                    "{name} L{level} node {i}: {r} vs {}",
                    b.inner.radius
                );
            }
        }
    }
}

#[test]
fn children_partition_the_parent_and_labels_hold() {
    for (name, level, kind, t) in all_trees() {
        let solid: Vec<(Vector3<f64>, f64)> = (0..poly(name).num_faces())
            .map(|f| {
                let n = poly(name).face_normal(f);
                (
                    n,
                    n.dot(&poly(name).vertices()[poly(name).faces()[f][0]].coords),
                )
            })
            .collect();
        let mut leaves = 0;
        for (i, node) in t.nodes().iter().enumerate() {
            let v = part(t, i).volume();
            assert!(v > 0.0);
            match node.children {
                Some([c0, c1]) => {
                    let (v0, v1) = (part(t, c0 as usize).volume(), part(t, c1 as usize).volume());
                    assert!(
                        ((v0 + v1) - v).abs() <= 1e-9 * v,
                        "{name} L{level} {kind:?} node {i}: {v0} + {v1} != {v}"
                    );
                    // Each child lies on its side of the split plane.
                    let (a, d) = node.split.unwrap();
                    for p in &part(t, c0 as usize).vertices {
                        assert!(a.dot(&p.coords) <= d + 1e-9);
                    }
                    for p in &part(t, c1 as usize).vertices {
                        assert!(a.dot(&p.coords) >= d - 1e-9);
                    }
                }
                None => leaves += 1,
            }
            let depth_of_centre = depth(&solid, &node.outer.centre);
            if node.internal {
                assert!(depth_of_centre >= node.outer.radius, "{name} node {i}");
            } else {
                assert!(
                    depth_of_centre <= node.outer.radius + 1e-9,
                    "{name} node {i}"
                );
            }
        }
        assert_eq!(leaves, t.num_leaves());
        assert!(leaves <= 1 << level && leaves > level);
        let volume: f64 = t
            .nodes()
            .iter()
            .enumerate()
            .filter(|(_, n)| n.is_leaf())
            .map(|(i, _)| part(t, i).volume())
            .sum();
        assert!((volume - poly(name).volume()).abs() < 1e-9);
    }
}

/// The leaf whose region holds `p` (either side on a split plane: both are tried).
fn leaves_holding(t: &DoubleSphereTree, node: usize, p: &Point3<f64>, out: &mut Vec<usize>) {
    let n = &t.nodes()[node];
    match (n.children, n.split) {
        (Some([c0, c1]), Some((a, d))) => {
            let s = a.dot(&p.coords) - d;
            if s <= 1e-12 {
                leaves_holding(t, c0 as usize, p, out);
            }
            if s >= -1e-12 {
                leaves_holding(t, c1 as usize, p, out);
            }
        }
        _ => out.push(node),
    }
}

#[test]
fn leaves_cover_every_piece_of_every_triangle() {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(77);
    for (name, level, kind, t) in all_trees() {
        let p = poly(name);
        let mut covered = vec![false; p.triangles().len()];
        for (i, n) in t.nodes().iter().enumerate() {
            if n.is_leaf() {
                for &tri in t.leaf_triangles(i) {
                    covered[tri as usize] = true;
                }
            } else {
                assert!(t.leaf_triangles(i).is_empty());
            }
        }
        assert!(covered.iter().all(|&c| c), "{name} L{level} {kind:?}");
        // Random points of each triangle (and its corners) are in a leaf that lists it.
        for (k, _) in p.triangles().iter().enumerate() {
            let [a, b, c] = p.triangle(k);
            let mut samples = vec![a, b, c];
            for _ in 0..20 {
                let (mut u, mut v) = (rng.float(0.0, 1.0), rng.float(0.0, 1.0));
                if u + v > 1.0 {
                    (u, v) = (1.0 - u, 1.0 - v);
                }
                samples.push(a + (b - a) * u + (c - a) * v);
            }
            for q in samples {
                let mut leaves = Vec::new();
                leaves_holding(t, 0, &q, &mut leaves);
                assert!(!leaves.is_empty());
                for l in leaves {
                    assert!(
                        t.leaf_triangles(l).contains(&(k as u32)),
                        "{name} L{level} {kind:?}: triangle {k} not listed in leaf {l}"
                    );
                }
            }
        }
    }
}

fn random_rotation(rng: &mut cga_collide::testing::adversarial::SplitMix64) -> UnitQuaternion<f64> {
    loop {
        let q = cga_collide::nalgebra::Quaternion::new(
            rng.float(-1.0, 1.0),
            rng.float(-1.0, 1.0),
            rng.float(-1.0, 1.0),
            rng.float(-1.0, 1.0),
        );
        let n = q.norm();
        if n > 0.1 && n <= 1.0 {
            return UnitQuaternion::from_quaternion(q);
        }
    }
}

#[test]
fn touching_and_near_touching_agree_with_brute_force() {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(99);
    // Bisect along random directions to the last colliding float and the first free one.
    for (na, nb) in PAIRS {
        for _ in 0..6 {
            let ra = random_rotation(&mut rng);
            let rb = random_rotation(&mut rng);
            let dir = loop {
                let p = rng.point().coords;
                if p.norm() > 0.3 {
                    break p.normalize();
                }
            };
            let pa = Isometry3::from_parts(Translation3::identity(), ra);
            let at = |s: f64| Isometry3::from_parts(Translation3::from(dir * s), rb);
            let (mut lo, mut hi) = (0.0f64, 2.5f64);
            assert!(brute(poly(na), &pa, poly(nb), &at(lo)));
            assert!(!brute(poly(na), &pa, poly(nb), &at(hi)));
            while hi - lo > f64::EPSILON * hi {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if brute(poly(na), &pa, poly(nb), &at(mid)) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            for s in [lo, hi] {
                let want = brute(poly(na), &pa, poly(nb), &at(s));
                for level in 0..=4 {
                    for kind in KINDS {
                        let got =
                            tree(na, level, kind).collides_at(&pa, tree(nb, level, kind), &at(s));
                        assert_eq!(
                            got.collides, want,
                            "{na}-{nb} L{level} {kind:?} s={s:e} dir={dir:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn exact_face_contact_and_identical_poses() {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(3);
    let s = poly("cube").vertices()[0].x.abs();
    for level in 0..=4 {
        for kind in KINDS {
            let c = tree("cube", level, kind);
            // Face on face: x = s against x = -s + 2s (exact), lateral dyadic offsets.
            for k in -40..=40 {
                let y = k as f64 / 32.0;
                let pb = Isometry3::translation(2.0 * s, y, 0.0);
                let got = c.collides_at(&Isometry3::identity(), c, &pb);
                assert_eq!(
                    got.collides,
                    brute(poly("cube"), &Isometry3::identity(), poly("cube"), &pb)
                );
                assert_eq!(got.collides, y.abs() <= 2.0 * s, "y = {y}");
            }
            // Identical poses always collide.
            for (na, _) in PAIRS {
                let pose = Isometry3::from_parts(
                    Translation3::new(rng.float(-9., 9.), rng.float(-9., 9.), rng.float(-9., 9.)),
                    random_rotation(&mut rng),
                );
                let t = tree(na, level, kind);
                assert!(t.collides_at(&pose, t, &pose).collides);
            }
        }
    }
}

#[test]
fn containment_without_surface_contact() {
    // A small cube well inside Rh (and the reverse order).
    let small = {
        let c = poly("cube");
        ConvexPolyhedron::new(
            c.vertices()
                .iter()
                .map(|v| Point3::from(v.coords * 0.25))
                .collect(),
            c.faces().to_vec(),
        )
        .unwrap()
    };
    let mut rng = cga_collide::testing::adversarial::SplitMix64(8);
    for level in [0, 3] {
        for kind in KINDS {
            let ts = DoubleSphereTree::build(&small, level, kind).unwrap();
            let trh = tree("rh", level, kind);
            for _ in 0..50 {
                let ps = Isometry3::from_parts(
                    Translation3::new(
                        rng.float(-0.5, 0.5),
                        rng.float(-0.5, 0.5),
                        rng.float(-0.5, 0.5),
                    ),
                    random_rotation(&mut rng),
                );
                let pr = Isometry3::from_parts(Translation3::identity(), random_rotation(&mut rng));
                let want = brute(&small, &ps, poly("rh"), &pr);
                let got = ts.collides_at(&ps, trh, &pr);
                assert_eq!(got.collides, want);
                let got2 = trh.collides_at(&pr, &ts, &ps);
                assert_eq!(got2.collides, want);
                if want
                    && got.decided_by != Decision::InnerSpheres
                    && got.decided_by != Decision::Faces
                {
                    assert_eq!(got.decided_by, Decision::Containment);
                }
            }
        }
    }
    // A tiny cube inside Rh near its boundary, where no inner sphere reaches it: only the
    // containment test can see the collision.
    let tiny = {
        let c = poly("cube");
        ConvexPolyhedron::new(
            c.vertices()
                .iter()
                .map(|v| Point3::from(v.coords * 0.02))
                .collect(),
            c.faces().to_vec(),
        )
        .unwrap()
    };
    let mut by_containment = 0;
    for kind in KINDS {
        let tt = DoubleSphereTree::build(&tiny, 0, kind).unwrap();
        let trh = tree("rh", 3, kind);
        for k in 0..=100 {
            let z = k as f64 / 100.0;
            let pt = Isometry3::translation(0.0, 0.0, z);
            let want = brute(&tiny, &pt, poly("rh"), &Isometry3::identity());
            let got = tt.collides_at(&pt, trh, &Isometry3::identity());
            assert_eq!(got.collides, want, "z = {z}");
            let got2 = trh.collides_at(&Isometry3::identity(), &tt, &pt);
            assert_eq!(got2.collides, want, "z = {z}");
            by_containment += usize::from(got.decided_by == Decision::Containment);
            by_containment += usize::from(got2.decided_by == Decision::Containment);
        }
    }
    assert!(by_containment > 0);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 600, ..ProptestConfig::default() })]

    /// `collide` agrees with the brute force on random poses for the four pairs, levels 0-4,
    /// both kinds.
    #[test]
    fn collide_agrees_with_brute_force(
        pair in 0usize..4,
        level in 0usize..=4,
        kind in 0usize..2,
        ta in prop::array::uniform3(-3.0f64..3.0),
        tb in prop::array::uniform3(-3.0f64..3.0),
        qa in prop::array::uniform4(-1.0f64..1.0),
        qb in prop::array::uniform4(-1.0f64..1.0),
    ) {
        let (na, nb) = PAIRS[pair];
        let kind = KINDS[kind];
        let rot = |q: [f64; 4]| {
            let q = cga_collide::nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]);
            if q.norm() < 1e-3 { UnitQuaternion::identity() } else { UnitQuaternion::from_quaternion(q) }
        };
        // Bring B near A so that about half the cases collide.
        let pa = Isometry3::from_parts(Translation3::new(ta[0], ta[1], ta[2]), rot(qa));
        let tb = Vector3::new(ta[0], ta[1], ta[2]) + Vector3::new(tb[0], tb[1], tb[2]) * 0.6;
        let pb = Isometry3::from_parts(Translation3::from(tb), rot(qb));
        let got = tree(na, level, kind).collides_at(&pa, tree(nb, level, kind), &pb);
        prop_assert_eq!(got.collides, brute(poly(na), &pa, poly(nb), &pb));
    }
}
