//! Defects a new user fell into (issue 23): each gives a clear error, at once, naming what
//! failed; JSON keys say what they hold; poses are numbered from 0 as pairs are.

mod common;

use std::time::Instant;

use common::{cga, cube_off, error, json, temp_dir};

/// A triangle with corners at ±`s` (side `2 s`) as an OFF file.
fn triangle_off(s: f64) -> String {
    format!(
        "OFF\n3 1 0\n{} {} 0\n{s} {} 0\n{} {s} 0\n3 0 1 2\n",
        -s, -s, -s, -s
    )
}

#[test]
fn unit_works_at_every_scale_and_is_never_blamed_on_the_pose() {
    // `--unit` once failed (and the failure was blamed on `--rotate`/`--translate`) for meshes
    // about 1e-320 or 1e308 across. Scaling is exact by powers of two now: the same triangle at
    // every scale gives the same answer as at size 1.
    let dir = temp_dir("defect-unit");
    for (name, s) in [("tiny.off", 1e-320), ("one.off", 1.0), ("huge.off", 1e308)] {
        std::fs::write(dir.join(name), triangle_off(s)).unwrap();
    }
    let counts = |mesh: &str| {
        let v = json(&cga(
            &[
                "collide", mesh, "one.off", "--unit", "--rotate", "90,0,0", "--json",
            ],
            &dir,
        ));
        v["pairs"].clone()
    };
    let want = counts("one.off");
    assert_eq!(counts("tiny.off"), want);
    assert_eq!(counts("huge.off"), want);
    for args in [
        &[
            "distance",
            "huge.off",
            "tiny.off",
            "--unit",
            "--translate",
            "2,0,0",
        ][..],
        &["query", "tiny.off", "--unit", "--ball", "0,0,0,1"][..],
    ] {
        let out = cga(args, &dir);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{args:?}: {stderr}");
    }
}

#[test]
fn a_library_failure_is_an_error_message_not_a_panic() {
    // `cga collide tiny.off bunny --unit` once panicked inside the library; whatever the
    // library does with such a mesh, the command line reports an error and a non-zero code.
    let dir = temp_dir("defect-tiny");
    std::fs::write(dir.join("tiny.off"), triangle_off(1e-320)).unwrap();
    for args in [
        &["collide", "tiny.off", "bunny", "--unit", "--repeat", "1"][..],
        &["collide", "tiny.off", "bunny", "--repeat", "1"][..],
        &["distance", "tiny.off", "bunny"][..],
    ] {
        let out = cga(args, &dir);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(!stderr.contains("stack backtrace"), "{args:?}: {stderr}");
        if !out.status.success() {
            assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
        }
    }
}

#[test]
fn output_paths_are_checked_before_any_work() {
    let dir = temp_dir("defect-output");
    std::fs::write(dir.join("c.off"), cube_off(0.0, 1.0)).unwrap();
    // Mesh A does not exist: an error about the output shows it was checked first.
    let collide = ["collide", "absent.off", "c.off"];
    let cases: [(Vec<&str>, &[&str]); 6] = [
        (
            [&collide[..], &["--pairs", "no/dir/p.txt"]].concat(),
            &[
                "--pairs no/dir/p.txt",
                "the directory no/dir does not exist",
            ],
        ),
        (
            [&collide[..], &["--contacts", "no/c.txt"]].concat(),
            &["--contacts no/c.txt", "does not exist"],
        ),
        (
            [&collide[..], &["--image", "no/x.png"]].concat(),
            &["--image no/x.png", "does not exist"],
        ),
        (
            [&collide[..], &["--pairs", "."]].concat(),
            &["--pairs .", "is a directory"],
        ),
        (
            vec!["self-intersect", "absent.off", "--pairs", "no/s.txt"],
            &["--pairs no/s.txt", "does not exist"],
        ),
        (
            vec!["spheretree", "build", "absent.off", "-o", "no/t.txt"],
            &["--output no/t.txt", "does not exist"],
        ),
    ];
    for (args, parts) in cases {
        let start = Instant::now();
        let err = error(&cga(&args, &dir));
        for part in parts {
            assert!(err.contains(part), "{args:?}: {part:?} missing from: {err}");
        }
        assert!(
            !err.contains("absent.off"),
            "{args:?}: the mesh came first: {err}"
        );
        assert!(start.elapsed().as_secs() < 30, "{args:?}: slow to fail");
    }
}

#[test]
fn image_must_be_png() {
    let dir = temp_dir("defect-jpg");
    for name in ["out.jpg", "out"] {
        let err = error(&cga(
            &["collide", "bunny", "bunny", "--unit", "--image", name],
            &dir,
        ));
        assert!(
            err.contains(&format!("--image {name}")) && err.contains("must end in .png"),
            "{err}"
        );
        assert!(!dir.join(name).exists(), "nothing written to {name}");
    }
    // The demo's image is checked too (`cga` writes collision.png unless told otherwise).
    let err = error(&cga(&["collide", "--image", "demo.jpeg"], &dir));
    assert!(err.contains("--image demo.jpeg"), "{err}");
}

#[test]
fn a_malformed_obj_is_an_error_naming_the_file() {
    let dir = temp_dir("defect-obj");
    std::fs::write(dir.join("garbage.obj"), b"\xff\xfe\x00garbage\x80\n").unwrap();
    let err = error(&cga(&["collide", "garbage.obj", "bunny"], &dir));
    assert!(err.contains("garbage.obj"), "{err}");
    assert!(err.contains("mesh A"), "{err}");
}

#[test]
fn json_keys_say_what_they_count() {
    let dir = temp_dir("defect-json");
    std::fs::write(dir.join("c.off"), cube_off(0.0, 1.0)).unwrap();
    let v = json(&cga(
        &[
            "collide",
            "c.off",
            "c.off",
            "--translate",
            "3,0,0",
            "--json",
        ],
        &dir,
    ));
    assert_eq!(v["triangle_counts"], serde_json::json!([12, 12]));
    assert!(v.get("triangles").is_none(), "{v}");
    let v = json(&cga(&["self-intersect", "c.off", "--json"], &dir));
    assert_eq!(v["triangle_count"], 12);
    assert!(v.get("triangles").is_none(), "{v}");
    let v = json(&cga(
        &[
            "distance",
            "c.off",
            "c.off",
            "--translate",
            "3,0,0",
            "--json",
        ],
        &dir,
    ));
    let w = v["witness_triangles"].as_array().unwrap();
    assert!(w.iter().all(|t| t.as_u64().unwrap() < 12), "{v}");
    assert!(v.get("triangles").is_none(), "{v}");
}

#[test]
fn poses_are_numbered_from_zero() {
    let dir = temp_dir("defect-poses");
    std::fs::write(dir.join("c.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(dir.join("p.txt"), "0 0 0 0.5 0 0\n0 0 0 3 0 0\n").unwrap();
    let out = cga(
        &[
            "collide",
            "c.off",
            "c.off",
            "--poses",
            "p.txt",
            "--all-pairs",
        ],
        &dir,
    );
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("pose 0: collides true"), "{text}");
    assert!(lines[1].starts_with("pose 1: collides false"), "{text}");
}

#[test]
fn a_distance_that_cannot_be_certified_is_an_error() {
    let dir = temp_dir("defect-far");
    std::fs::write(dir.join("lo.off"), cube_off(-1.7e308, -1.6e308)).unwrap();
    std::fs::write(dir.join("hi.off"), cube_off(1.6e308, 1.7e308)).unwrap();
    let out = cga(&["distance", "lo.off", "hi.off"], &dir);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(!stdout.contains("certified"), "{stdout}");
    let err = error(&out);
    assert!(
        err.contains("out of the range where the distance can be certified"),
        "{err}"
    );
}
