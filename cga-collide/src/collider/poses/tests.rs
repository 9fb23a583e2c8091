//! Tests of the pose queries against placed copies, and the pose helpers other modules'
//! tests share.

use super::*;
use crate::bounding::pose_bounds::U;
use nalgebra::{UnitQuaternion, Vector3};
use proptest::prelude::*;

fn pose(r: [f64; 3], t: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        nalgebra::Translation3::new(t[0], t[1], t[2]),
        UnitQuaternion::from_euler_angles(r[0], r[1], r[2]),
    )
}

proptest! {
    /// The analysed matrix and the rounding bound `δ` cover nalgebra's `pose * v`.
    #[test]
    fn rounding_bound_covers_the_transform(
        r in prop::array::uniform3(-4.0f64..4.0),
        t in prop::array::uniform3(-100.0f64..100.0),
        v in prop::array::uniform3(-1000.0f64..1000.0),
    ) {
        let iso = pose(r, t);
        let map = PoseMap::new(&iso).unwrap();
        let p = iso * Point3::new(v[0], v[1], v[2]);
        let rho = v.iter().fold(0.0f64, |s, x| s.max(x.abs()));
        for i in 0..3 {
            let exactish = map.m[i][0] * v[0] + map.m[i][1] * v[1] + map.m[i][2] * v[2] + t[i];
            // M̂ is within a few ulps of M; the bound must hold with room to spare.
            let slack = map.delta(rho) + 3.0 * rho * map.matrix_error() + 8.0 * U * (3.0 * rho + 100.0);
            prop_assert!((p[i] - exactish).abs() <= slack, "{} vs {}", p[i], exactish);
        }
    }

    /// World boxes of a box hold the placed images of its corners.
    #[test]
    fn world_boxes_hold_placed_points(
        r in prop::array::uniform3(-4.0f64..4.0),
        t in prop::array::uniform3(-10.0f64..10.0),
        lo in prop::array::uniform3(-2.0f64..0.0),
        hi in prop::array::uniform3(0.0f64..2.0),
    ) {
        let iso = pose(r, t);
        let map = PoseMap::new(&iso).unwrap();
        let w = WorldBoxes::new(&map, 2.0);
        let b = Aabb { min: lo, max: hi };
        let wb = w.world(&b);
        for k in 0..8 {
            let c = Point3::new(
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            );
            let p = iso * c;
            let point = Aabb { min: p.coords.into(), max: p.coords.into() };
            prop_assert!(wb.overlaps(&point));
        }
    }
}

/// Nodes from the leaf of triangle `t` (leaf position in the tree's order) up to the root.
fn ancestors(c: &Collider, t: u32) -> Vec<usize> {
    let nodes = c.pose_tree().nodes();
    let mut parent = vec![usize::MAX; nodes.len()];
    for (i, n) in nodes.iter().enumerate() {
        if !n.is_leaf() {
            parent[n.start as usize] = i;
            parent[n.start as usize + 1] = i;
        }
    }
    let k = c.bvh().order().iter().position(|&u| u == t).unwrap();
    let mut at = nodes
        .iter()
        .position(|n| n.is_leaf() && (n.start..n.start + n.count).contains(&(k as u32)))
        .unwrap();
    let mut out = vec![at];
    while parent[at] != usize::MAX {
        at = parent[at];
        out.push(at);
    }
    out
}

/// Every pair of nodes holding two placed triangles that meet passes the box test under
/// the poses (not only the pairs the traversal happens to visit), and the traversal finds
/// exactly the pairs brute force finds. Returns the number of meeting pairs.
fn box_test_keeps_meeting_pairs(
    a: &Collider,
    pa: &Isometry3<f64>,
    b: &Collider,
    pb: &Isometry3<f64>,
) -> Result<usize, TestCaseError> {
    let (wa, wb) = (a.placed(pa).unwrap(), b.placed(pb).unwrap());
    let want = wa
        .clone()
        .with_mode(crate::collider::Mode::Brute)
        .intersecting_pairs(&wb);
    let pair = PosedPair::new(a, pa, b, pb).unwrap();
    let (na, nb) = (a.pose_tree().nodes(), b.pose_tree().nodes());
    for &(i, j) in &want {
        for &x in &ancestors(a, i) {
            for &y in &ancestors(b, j) {
                prop_assert!(pair.may_overlap(&na[x], &nb[y]), "{i} {j}: nodes {x} {y}");
            }
        }
    }
    let mut got = pair.collect_pairs(&[(0, 0)]);
    got.sort_unstable();
    prop_assert_eq!(got, want.clone());
    Ok(want.len())
}

/// `n` random triangles: centres in `[-spread, spread]³`, corners within `jitter` of them
/// per coordinate; with `degenerate`, every 5th has a repeated corner. Also used by the
/// tests of [`super::distance`].
pub(crate) fn soup(
    seed: u64,
    n: usize,
    spread: f64,
    jitter: f64,
    degenerate: bool,
) -> crate::TriMesh {
    // A small local generator (query sits above the `testing` module).
    let mut state = seed;
    let mut float = |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let mut v = Vec::new();
    let mut t = Vec::new();
    for k in 0..n as u32 {
        let c = Vector3::new(
            float(-spread, spread),
            float(-spread, spread),
            float(-spread, spread),
        );
        for _ in 0..3 {
            v.push(Point3::from(
                c + Vector3::new(
                    float(-jitter, jitter),
                    float(-jitter, jitter),
                    float(-jitter, jitter),
                ),
            ));
        }
        t.push(if degenerate && k % 5 == 0 {
            [3 * k, 3 * k + 1, 3 * k + 1]
        } else {
            [3 * k, 3 * k + 1, 3 * k + 2]
        });
    }
    crate::TriMesh::new(v, t).unwrap()
}

/// Exact rotations (identity, half turns about the axes) and rounded quarter turns.
fn lattice_rotation(k: usize) -> UnitQuaternion<f64> {
    let q = |w, x, y, z| UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(w, x, y, z));
    match k {
        0 => UnitQuaternion::identity(),
        1 => q(0.0, 1.0, 0.0, 0.0),
        2 => q(0.0, 0.0, 1.0, 0.0),
        3 => q(0.0, 0.0, 0.0, 1.0),
        4 => UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
        _ => UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -std::f64::consts::FRAC_PI_2),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random soups (with degenerate triangles) at random poses, both meshes moved.
    #[test]
    fn box_test_never_rejects_meeting_triangles(
        seed in any::<u64>(),
        ra in prop::array::uniform3(-4.0f64..4.0), ta in prop::array::uniform3(-1.0f64..1.0),
        rb in prop::array::uniform3(-4.0f64..4.0), tb in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let a = Collider::new(soup(seed, 60, 1.0, 0.5, true));
        let b = Collider::new(soup(seed ^ 0x5555, 40, 1.0, 0.5, true));
        box_test_keeps_meeting_pairs(&a, &pose(ra, ta), &b, &pose(rb, tb))?;
    }

    /// Integer cubes in face, edge and corner contact (and coplanar faces) at exact and
    /// quarter-turn rotations: every contact survives the box test.
    #[test]
    fn box_test_keeps_touching_cubes(
        lo in prop::array::uniform3(-2i32..2), size in prop::array::uniform3(1i32..3),
        k in 0usize..6, l in 0usize..6, t in prop::array::uniform3(-3i32..4),
    ) {
        let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
        let f = |p: [i32; 3]| Point3::from(p.map(f64::from));
        let a = Collider::new(crate::TriMesh::cuboid(f(lo), f(hi)).unwrap());
        let b = Collider::new(crate::TriMesh::cuboid(f([0, 0, 0]), f(size)).unwrap());
        let pa = Isometry3::from_parts(nalgebra::Translation3::identity(), lattice_rotation(k));
        let pb = Isometry3::from_parts(
            nalgebra::Translation3::new(t[0] as f64, t[1] as f64, t[2] as f64),
            lattice_rotation(l),
        );
        box_test_keeps_meeting_pairs(&a, &pa, &b, &pb)?;
    }
}

/// The cube tests above are not vacuous: exact face contact after a half turn is kept.
#[test]
fn touching_after_a_half_turn_is_kept() {
    let f = |x, y, z| Point3::new(x, y, z);
    let a = Collider::new(crate::TriMesh::cuboid(f(0.0, 0.0, 0.0), f(1.0, 1.0, 1.0)).unwrap());
    let pb = Isometry3::from_parts(
        nalgebra::Translation3::new(2.0, 1.0, 0.0),
        lattice_rotation(3),
    );
    let n = box_test_keeps_meeting_pairs(&a, &Isometry3::identity(), &a, &pb).unwrap();
    assert!(n > 0);
}

#[test]
fn bad_poses_are_typed_errors() {
    let c = Collider::new(
        crate::TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap(),
    );
    let id = Isometry3::identity();
    let mut nan = id;
    nan.translation.vector.x = f64::NAN;
    assert_eq!(c.collides_at(&id, &c, &nan), Err(Error::NonFinitePose));
    let q = nalgebra::Quaternion::new(3.0, 0.0, 0.0, 0.0);
    let big = Isometry3::from_parts(
        nalgebra::Translation3::identity(),
        UnitQuaternion::new_unchecked(q),
    );
    assert!(matches!(
        c.collides_at(&id, &c, &big),
        Err(Error::NotUnitRotation { .. })
    ));
    let far = Isometry3::translation(1e300, 0.0, 0.0);
    assert!(matches!(
        c.segment_hits_at(
            &far,
            &Segment::new(Point3::origin(), Point3::origin()).unwrap()
        ),
        Err(Error::OutOfRange { .. })
    ));
    let _ = Vector3::<f64>::x();
}
