//! `nearest` against the brute force: every part pair of every tested pair measured without a
//! cutoff, on a robot of meshes (a scaled bunny, bars) and primitives, at random
//! configurations, at colliding ones and at configurations a hair from contact.

use std::path::PathBuf;

use nalgebra::{Isometry3, Point3, Vector3};
use proptest::prelude::*;

use super::geometry::PairTest;
use super::*;
use crate::query::CertifiedDistance;
use crate::shape::{Cuboid, Shape};
use crate::Ball;

/// A chain of five links: meshes (the bunny scaled to about 0.2, a bar of 12 triangles) and
/// boxes and a ball, on revolute joints about several axes.
fn chain() -> Robot {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let bunny = dir.join("data/bunny.obj");
    let bar = dir.join("cli/tests/data/robot/toy_arm/meshes/fore.obj");
    let (bunny, bar) = (bunny.display(), bar.display());
    let urdf = format!(
        r#"<robot name="chain">
  <link name="base">
    <collision><origin xyz="0 0 0.05"/><geometry><box size="0.6 0.6 0.1"/></geometry></collision>
    <collision><origin xyz="0.2 0.1 0.1"/><geometry><mesh filename="file://{bunny}" scale="0.02 0.02 0.02"/></geometry></collision>
  </link>
  <link name="l1"><collision><origin rpy="0 -1.5707963 0"/><geometry><mesh filename="file://{bar}"/></geometry></collision></link>
  <link name="l2"><collision><origin rpy="0.3 0 0"/><geometry><mesh filename="file://{bunny}" scale="0.025 0.02 0.02"/></geometry></collision></link>
  <link name="l3">
    <collision><geometry><mesh filename="file://{bar}" scale="0.6 1 1"/></geometry></collision>
    <collision><origin xyz="0.5 0 0"/><geometry><box size="0.08 0.05 0.06"/></geometry></collision>
  </link>
  <link name="l4">
    <collision><geometry><mesh filename="file://{bunny}" scale="0.015 0.015 0.015"/></geometry></collision>
    <collision><origin xyz="0.1 0 0"/><geometry><sphere radius="0.03"/></geometry></collision>
  </link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="-3.1" upper="3.1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="0 0 0.8"/>
    <axis xyz="0 1 0"/><limit lower="-2.5" upper="2.5"/></joint>
  <joint name="j3" type="revolute"><parent link="l2"/><child link="l3"/><origin xyz="0 0 0.15"/>
    <axis xyz="0 1 0"/><limit lower="-2.8" upper="2.8"/></joint>
  <joint name="j4" type="revolute"><parent link="l3"/><child link="l4"/><origin xyz="0.48 0 0"/>
    <axis xyz="1 0 0"/><limit lower="-3" upper="3"/></joint>
</robot>"#
    );
    let mut robot = Robot::from_urdf_str(&urdf, "chain.urdf", ".", &[]).expect("the chain loads");
    let mut scene = Scene::new();
    let table: Shape =
        Cuboid::axis_aligned(Point3::new(0.6, 0.0, 0.4), Vector3::new(0.2, 0.4, 0.02))
            .unwrap()
            .into();
    scene.add_shape(table, Isometry3::identity()).unwrap();
    let ball: Shape = Ball::new(Point3::new(-0.3, 0.3, 0.9), 0.08).unwrap().into();
    scene.add_shape(ball, Isometry3::identity()).unwrap();
    robot.set_environment(&scene).unwrap();
    robot
}

/// Every tested pair's least part-pair distance, measured without a cutoff or a bound:
/// `(pair names sorted, distance)`.
fn brute(robot: &Robot, q: &[f64], against: Against) -> Vec<((String, String), CertifiedDistance)> {
    let posed = robot.pose_parts(q).unwrap();
    let mut out = Vec::new();
    let mut measure = |name: (String, String), tests: Vec<PairTest>| {
        let best = tests
            .iter()
            .map(|t| t.distance().unwrap())
            .min_by(|x, y| x.distance.total_cmp(&y.distance));
        if let Some(d) = best {
            let name = if name.0 <= name.1 {
                name
            } else {
                (name.1, name.0)
            };
            out.push((name, d));
        }
    };
    let part = |k: usize| (&robot.parts[k].geometry, &posed.parts[k]);
    if against != Against::Environment {
        for &(a, b) in &robot.pairs {
            let tests = robot.link_parts[a]
                .clone()
                .flat_map(|i| robot.link_parts[b].clone().map(move |j| (i, j)))
                .map(|(i, j)| PairTest {
                    a: part(i),
                    b: part(j),
                    solid: robot.solid,
                })
                .collect();
            measure(
                (robot.link_names[a].clone(), robot.link_names[b].clone()),
                tests,
            );
        }
    }
    if against != Against::Itself {
        for (l, range) in robot.link_parts.iter().enumerate() {
            for obj in &robot.environment {
                let tests = range
                    .clone()
                    .map(|i| PairTest {
                        a: part(i),
                        b: (&obj.geometry, &obj.placed),
                        solid: robot.solid,
                    })
                    .collect();
                measure(
                    (
                        robot.link_names[l].clone(),
                        format!("env:{}", obj.id.index()),
                    ),
                    tests,
                );
            }
        }
    }
    out
}

/// `nearest` holds the brute-force minimum in its interval, names a pair at that distance, and
/// its witnesses are that far apart; with a clear winner, it is the brute force's answer.
fn check(robot: &Robot, q: &[f64], against: Against) -> CertifiedDistance {
    let all = brute(robot, q, against);
    let n = robot
        .nearest(q, against)
        .unwrap()
        .expect("pairs are tested");
    let d = &n.distance;
    let least = all
        .iter()
        .map(|(_, d)| d.distance)
        .fold(f64::INFINITY, f64::min);
    let slack = d.error_bound + 1e-12;
    assert!(
        (d.distance - least).abs() <= slack,
        "q = {q:?}: {d:?} against {least}"
    );
    let own = all
        .iter()
        .find(|(p, _)| *p == n.pair)
        .expect("a tested pair");
    assert!(
        (own.1.distance - d.distance).abs() <= slack + own.1.error_bound,
        "q = {q:?}"
    );
    let apart = (d.witness_a - d.witness_b).norm();
    assert!(
        (apart - d.distance).abs() <= slack + 1e-9,
        "q = {q:?}: {apart} {d:?}"
    );
    let mut sorted: Vec<f64> = all.iter().map(|(_, d)| d.distance).collect();
    sorted.sort_by(f64::total_cmp);
    if sorted.len() > 1 && sorted[1] - sorted[0] > 1e-9 {
        let (pair, winner) = all.iter().find(|(_, d)| d.distance == least).unwrap();
        assert_eq!(&n.pair, pair, "q = {q:?}");
        assert_eq!(d.distance, winner.distance, "q = {q:?}");
    }
    // The interval is proved: nothing within its lower end (exact clearance), the pair
    // within its upper end.
    let within = robot
        .pairs_within_distance(q, d.distance + d.error_bound, against)
        .unwrap();
    assert!(within.contains(&n.pair), "q = {q:?}");
    let below = (d.distance - d.error_bound) * (1.0 - 1e-9);
    if below > 0.0 {
        assert!(robot
            .pairs_within_distance(q, below, against)
            .unwrap()
            .is_empty());
    }
    n.distance
}

fn within_limits(robot: &Robot, unit: &[f64]) -> Vec<f64> {
    robot
        .joint_limits()
        .iter()
        .zip(unit)
        .map(|(l, u)| {
            let (lo, hi) = l.unwrap_or((-3.0, 3.0));
            lo + (hi - lo) * u
        })
        .collect()
}

/// A configuration on the segment `free` → `hit` a hair before the first contact found by
/// bisection on the exact collision test (the free end of the last interval).
fn near_contact(robot: &Robot, free: &[f64], hit: &[f64], against: Against) -> Vec<f64> {
    let at = |t: f64| -> Vec<f64> { free.iter().zip(hit).map(|(a, b)| a + (b - a) * t).collect() };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..48 {
        let mid = 0.5 * (lo + hi);
        if robot.collides(&at(mid), against).unwrap() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    at(lo)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn nearest_equals_the_brute_force(
        unit in prop::collection::vec(0.0f64..1.0, 4),
        against in prop::sample::select(vec![Against::Itself, Against::Environment, Against::Both]),
    ) {
        let robot = chain();
        let q = within_limits(&robot, &unit);
        check(&robot, &q, against);
    }

    #[test]
    fn nearest_is_right_a_hair_from_contact_and_in_contact(
        a in prop::collection::vec(0.0f64..1.0, 4),
        b in prop::collection::vec(0.0f64..1.0, 4),
        against in prop::sample::select(vec![Against::Itself, Against::Both]),
    ) {
        let robot = chain();
        let (qa, qb) = (within_limits(&robot, &a), within_limits(&robot, &b));
        let (ca, cb) = (robot.collides(&qa, against).unwrap(), robot.collides(&qb, against).unwrap());
        prop_assume!(ca != cb);
        let (free, hit) = if ca { (qb, qa) } else { (qa, qb) };
        // Touching surfaces are 0 apart (up to the bound).
        let d = check(&robot, &hit, against);
        prop_assert!(d.distance - d.error_bound <= 0.0, "{:?}", d);
        let near = near_contact(&robot, &free, &hit, against);
        let d = check(&robot, &near, against);
        prop_assert!(d.distance < 1e-6, "{:?}", d);
    }
}
