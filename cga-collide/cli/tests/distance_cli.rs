//! `cga distance`, `cga self-intersect`, and `cga collide --clearance/--contacts` with the
//! contact class.

mod common;

use common::{cga, json, temp_dir};

/// A unit cube as an OFF file.
fn cube(dir: &std::path::Path) -> String {
    let path = dir.join("cube.off");
    std::fs::write(
        &path,
        "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n\
         3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n\
         3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n",
    )
    .unwrap();
    path.display().to_string()
}

#[test]
fn distance_between_cubes() {
    let dir = temp_dir("distance");
    let c = cube(&dir);
    let v = json(&cga(
        &[
            "distance",
            &c,
            &c,
            "--translate",
            "1.5,0.25,0",
            "--json",
            "--exact",
        ],
        &dir,
    ));
    let d = v["distance"].as_f64().unwrap();
    let e = v["error_bound"].as_f64().unwrap();
    assert!((d - 0.5).abs() <= e && e < 1e-12, "{v}");
    assert_eq!(v["exact_distance2"], "1/4");
    assert_eq!(v["witness_triangles"].as_array().unwrap().len(), 2);
    let wa = &v["witness_a"];
    assert!((wa[0].as_f64().unwrap() - 1.0).abs() < 1e-12, "{v}");
    assert!(v["millis"].as_f64().unwrap() >= 0.0);
}

#[test]
fn collide_clearance_contacts_and_class() {
    let dir = temp_dir("clearance");
    let c = cube(&dir);
    let run = |extra: &[&str]| {
        let mut args = vec!["collide", c.as_str(), c.as_str(), "--json", "--repeat", "1"];
        args.extend_from_slice(extra);
        json(&cga(&args, &dir))
    };
    // A gap of exactly 0.5: within 0.5, not within 0.49.
    let v = run(&[
        "--translate",
        "1.5,0,0",
        "--clearance",
        "0.5",
        "--pairs",
        "p.txt",
    ]);
    assert!(v["pairs"].as_u64().unwrap() > 0);
    assert_eq!(v["contact"], "disjoint");
    let listed = std::fs::read_to_string(dir.join("p.txt")).unwrap();
    assert_eq!(listed.lines().count() as u64, v["pairs"].as_u64().unwrap());
    let v = run(&["--translate", "1.5,0,0", "--clearance", "0.49"]);
    assert_eq!(v["pairs"], 0);
    // Face to face: touching; pushed in: penetrating, with the contact geometry written.
    assert_eq!(run(&["--translate", "1,0,0"])["contact"], "touching");
    let v = run(&["--translate", "0.5,0.25,0.25", "--contacts", "k.txt"]);
    assert_eq!(v["contact"], "penetrating");
    let k = std::fs::read_to_string(dir.join("k.txt")).unwrap();
    assert_eq!(k.lines().count() as u64, v["pairs"].as_u64().unwrap());
    // Negative clearance is a typed error, not a panic.
    let out = cga(&["collide", &c, &c, "--clearance", "-1"], &dir);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--clearance"));
}

#[test]
fn self_intersect_json_and_pairs() {
    let dir = temp_dir("self");
    let c = cube(&dir);
    let v = json(&cga(&["self-intersect", &c, "--json"], &dir));
    assert_eq!(v["pairs"], 0);
    assert_eq!(v["closed"], true);
    // Two triangles folded onto each other across their shared edge.
    let fold = dir.join("fold.off");
    std::fs::write(
        &fold,
        "OFF\n4 2 0\n0 0 0\n2 0 0\n1 1 0\n1 2 0\n3 0 1 2\n3 1 0 3\n",
    )
    .unwrap();
    let fold = fold.display().to_string();
    let v = json(&cga(
        &["self-intersect", &fold, "--json", "--pairs", "s.txt"],
        &dir,
    ));
    assert_eq!(v["pairs"], 1);
    assert_eq!(std::fs::read_to_string(dir.join("s.txt")).unwrap(), "0 1\n");
}
