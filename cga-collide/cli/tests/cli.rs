//! The `cga` command line: JSON fields, pairs file, image, modes agreeing, typed errors.

mod common;

use common::{cga, cube_off, json, temp_dir};

#[test]
fn collide_modes_agree_and_write_pairs_and_image() {
    let dir = temp_dir("collide");
    let common = [
        "collide",
        "bunny",
        "bunny",
        "--unit",
        "--rotate",
        "0,40,10",
        "--translate",
        "0.2,0.05,-0.1",
        "--json",
        "--repeat",
        "1",
    ];
    let mut brute_args = common.to_vec();
    brute_args.extend(["--mode", "brute", "--pairs", "brute.txt"]);
    let mut bvh_args = common.to_vec();
    bvh_args.extend(["--mode", "bvh", "--pairs", "bvh.txt", "--image", "out.png"]);
    let brute = json(&cga(&brute_args, &dir));
    let bvh = json(&cga(&bvh_args, &dir));
    assert_eq!(brute["mode"], "brute");
    assert_eq!(bvh["mode"], "bvh");
    assert_eq!(brute["pairs"], bvh["pairs"]);
    assert_eq!(bvh["triangle_counts"], serde_json::json!([3674, 3674]));
    assert!(bvh["collides"].as_bool().unwrap());
    assert!(bvh["pairs"].as_u64().unwrap() > 0);
    assert!(bvh["millis"].as_f64().unwrap() >= 0.0);
    assert!(bvh["build_millis"].as_f64().unwrap() >= 0.0);
    let a = std::fs::read_to_string(dir.join("brute.txt")).unwrap();
    let b = std::fs::read_to_string(dir.join("bvh.txt")).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.lines().count() as u64, bvh["pairs"].as_u64().unwrap());
    for line in a.lines() {
        let ij: Vec<u32> = line.split(' ').map(|x| x.parse().unwrap()).collect();
        assert!(ij.len() == 2 && ij[0] < 3674 && ij[1] < 3674);
    }
    let png = std::fs::read(dir.join("out.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn far_apart_meshes_do_not_collide() {
    let dir = temp_dir("apart");
    let out = json(&cga(
        &[
            "collide",
            "bunny",
            "bunny",
            "--unit",
            "--translate",
            "5,0,0",
            "--json",
            "--repeat",
            "1",
        ],
        &dir,
    ));
    assert_eq!(out["collides"], false);
    assert_eq!(out["pairs"], 0);
}

#[test]
fn query_reports_hits() {
    let dir = temp_dir("query");
    let out = json(&cga(
        &[
            "query",
            "bunny",
            "--unit",
            "--segment",
            "0,0,-2,0,0,2",
            "--json",
        ],
        &dir,
    ));
    assert_eq!(out["query"], "segment");
    // A segment through the middle of a closed mesh crosses its surface an even, nonzero number
    // of times (or touches an edge/vertex, which counts every triangle there).
    assert!(out["hits"].as_u64().unwrap() >= 2);
}

#[test]
fn bad_input_gives_an_error_not_a_panic() {
    let dir = temp_dir("bad");
    std::fs::write(
        dir.join("broken.off"),
        "OFF\n3 1 0\n0 0 0\n1 nope 0\n0 1 0\n3 0 1 2\n",
    )
    .unwrap();
    let out = cga(&["collide", "broken.off", "bunny"], &dir);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("broken.off"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let out = cga(&["collide", "missing.obj", "bunny"], &dir);
    assert!(!out.status.success());
    let out = cga(&["query", "bunny", "--sphere", "0,0,0,-1"], &dir);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("radius"));
    let out = cga(&["collide", "bunny", "bunny", "--translate", "1,2"], &dir);
    assert!(!out.status.success());
}

#[test]
fn a_mesh_wholly_inside_another_is_reported() {
    let dir = temp_dir("nested");
    std::fs::write(dir.join("big.off"), cube_off(-2.0, 2.0)).unwrap();
    std::fs::write(dir.join("small.off"), cube_off(-0.5, 0.5)).unwrap();
    let out = json(&cga(
        &["collide", "big.off", "small.off", "--json", "--repeat", "1"],
        &dir,
    ));
    assert_eq!(out["collides"], false);
    assert_eq!(out["pairs"], 0);
    assert_eq!(out["b_inside_a"], true);
    assert_eq!(out["a_inside_b"], false);
    assert_eq!(out["solids_collide"], true);
    let apart = json(&cga(
        &[
            "collide",
            "big.off",
            "small.off",
            "--translate",
            "9,0,0",
            "--json",
            "--repeat",
            "1",
        ],
        &dir,
    ));
    assert_eq!(apart["solids_collide"], false);
}

#[test]
fn spheretree_build_then_collide() {
    let dir = temp_dir("spheretree-build");
    let built = json(&cga(
        &[
            "spheretree",
            "build",
            "bunny",
            "bunny",
            "--unit",
            "--translate",
            "0.3,0.05,0",
            "--depth",
            "4",
            "-o",
            "pair.txt",
            "--json",
        ],
        &dir,
    ));
    assert_eq!(built["trees"].as_array().unwrap().len(), 2);
    assert_eq!(built["trees"][0]["nodes"], built["trees"][1]["nodes"]);
    let text = std::fs::read_to_string(dir.join("pair.txt")).unwrap();
    assert!(text.starts_with("2\n"));
    let near = json(&cga(&["spheretree", "collide", "pair.txt", "--json"], &dir));
    assert_eq!(near["collides"], true);
    assert_eq!(near["method"], "simultaneous");
    // Far apart: no collision.
    json(&cga(
        &[
            "spheretree",
            "build",
            "bunny",
            "bunny",
            "--unit",
            "--translate",
            "3,0,0",
            "--depth",
            "3",
            "-o",
            "far.txt",
            "--json",
        ],
        &dir,
    ));
    let far = json(&cga(&["spheretree", "collide", "far.txt", "--json"], &dir));
    assert_eq!(far["collides"], false);
    // One tree is not enough; a truncated file is a typed error unless --lenient.
    json(&cga(
        &[
            "spheretree",
            "build",
            "bunny",
            "--depth",
            "2",
            "-o",
            "one.txt",
            "--json",
        ],
        &dir,
    ));
    let out = cga(&["spheretree", "collide", "one.txt"], &dir);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("needs two"));
    let cut: String = text.lines().take(7).map(|l| format!("{l}\n")).collect();
    std::fs::write(dir.join("cut.txt"), cut).unwrap();
    let out = cga(&["spheretree", "collide", "cut.txt"], &dir);
    assert!(String::from_utf8_lossy(&out.stderr).contains("input ends after line 7"));
    let out = cga(&["spheretree", "collide", "cut.txt", "--lenient"], &dir);
    assert!(String::from_utf8_lossy(&out.stderr).contains("warning: tree 1 node at line 2"));
}

#[test]
fn a_missing_file_is_named_once_with_its_reason_and_a_remedy() {
    let dir = temp_dir("missing");
    let out = cga(&["collide", "no-such-mesh.off", "bunny"], &dir);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.matches("no-such-mesh.off").count(), 1, "{err}");
    assert_eq!(err.matches("os error").count(), 1, "{err}");
    assert!(err.contains("check the path"), "{err}");
}

#[cfg(not(feature = "gpu"))]
#[test]
fn device_gpu_without_the_feature_says_how_to_get_it() {
    let dir = temp_dir("no-gpu-feature");
    let err = common::error(&cga(
        &[
            "query",
            "bunny",
            "--segment",
            "0,0,0,1,1,1",
            "--device",
            "gpu",
        ],
        &dir,
    ));
    assert!(err.contains("without GPU support"), "{err}");
    assert!(err.contains("--features gpu"), "{err}");
    assert!(err.contains("--device cpu"), "{err}");
}

/// Each error names what was wrong, where (file and line, or the argument) and what to do.
#[test]
fn errors_say_what_where_and_what_to_do() {
    use common::error;
    let dir = temp_dir("messages");
    let says = |args: &[&str], parts: &[&str]| {
        let err = error(&cga(args, &dir));
        for part in parts {
            assert!(err.contains(part), "{args:?}: {part:?} missing from: {err}");
        }
    };
    std::fs::write(
        dir.join("nan.off"),
        "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
    )
    .unwrap();
    says(
        &["collide", "nan.off", "bunny"],
        &["nan.off:4", "vertex 1", "must be a finite number"],
    );
    std::fs::write(dir.join("empty.off"), "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n").unwrap();
    says(
        &["query", "empty.off", "--segment", "0,0,0,1,1,1"],
        &["empty.off", "no triangles", "check that the file has faces"],
    );
    says(
        &["collide", "bunnny", "bunny"],
        &[
            "bunnny: no such file",
            "not a built-in mesh (bunny, bunny00, armadillo)",
            "check the name",
        ],
    );
    says(
        &["collide", "bunny"],
        &["only one mesh given (`bunny`)", "give two meshes"],
    );
    says(
        &["collide", "bunny", "bunny", "--repeat", "0"],
        &["--repeat 0", "at least 1"],
    );
    says(
        &["collide", "bunny", "bunny", "--clearance", "-1"],
        &["--clearance -1", "finite distance >= 0"],
    );
    says(
        &["collide", "bunny", "bunny", "--translate", "1,2"],
        &["--translate", "expected 3 comma-separated numbers, got 2"],
    );
    says(
        &["query", "bunny"],
        &[
            "no query shape",
            "--segment, --triangle, --sphere or --ball",
        ],
    );
    says(
        &["query", "bunny", "--ball", "0,0,0,-2"],
        &["--ball", "radius is negative", "finite radius >= 0"],
    );
    says(
        &["query", "bunny", "--segment", "0,0,0,1,1,inf"],
        &["--segment", "`inf` is not finite"],
    );
    // A pose that the certified query cannot take, reported at its line of the file.
    std::fs::write(
        dir.join("poses.txt"),
        "# rotation, translation\n0 0 0 0 0 0\n\n0 0 0 1e300 0 0\n",
    )
    .unwrap();
    says(
        &["collide", "bunny", "bunny", "--poses", "poses.txt"],
        &[
            "poses.txt:4",
            "too large",
            "scale the meshes and translations down",
        ],
    );
    std::fs::write(dir.join("none.txt"), "# nothing\n").unwrap();
    says(
        &["collide", "bunny", "bunny", "--poses", "none.txt"],
        &[
            "none.txt: no poses",
            "one pose `ax ay az tx ty tz` per line",
        ],
    );
    says(
        &[
            "collide",
            "bunny",
            "bunny",
            "--poses",
            "absent.txt",
            "--threads",
            "2",
        ],
        &["--poses", "absent.txt", "check the path"],
    );
    // A truncated sphere-tree file: its line, and the option that reads what is there.
    std::fs::write(dir.join("cut.txt"), "2\n0 0 0 1 0\n0 8\n").unwrap();
    says(
        &["spheretree", "collide", "cut.txt"],
        &["cut.txt", "input ends after line 3", "--lenient"],
    );
}
