//! What a new user fell into (issue 34), tried as one would: each is refused with the place
//! and the reason, or answered in the form asked for.

mod common;

use std::time::Instant;

use common::{cga, cube_off, error, json, temp_dir};

fn stdout(out: &std::process::Output) -> String {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn a_scene_pose_whose_r_is_not_a_rotation_is_refused_with_its_line() {
    // Once silently replaced by the nearest rotation: the cube scaled by 2 became a unit cube
    // 1.5 away from the other, and the answer was "0 pairs touching" for cubes that overlap.
    let dir = temp_dir("scene-not-rotation");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    for (name, r) in [
        ("scaled", "2 0 0 0 0 1 0 0 0 0 1 0"),
        ("reflected", "1 0 0 0 0 1 0 0 0 0 -1 0"),
        ("zeros", "0 0 0 0 0 0 0 0 0 0 0 0"),
    ] {
        let file = format!("{name}.txt");
        std::fs::write(
            dir.join(&file),
            format!("# a comment first\ncube.off 0 0 0 1.5 0 0\ncube.off {r}\n"),
        )
        .unwrap();
        let err = error(&cga(&["scene", &file], &dir));
        assert!(err.contains(&format!("{file}:3")), "{name}: {err}");
        assert!(err.contains("not a rotation"), "{name}: {err}");
    }
    // A rotation written with 7 digits is one (the Python binding's tolerance, 1e-6).
    std::fs::write(
        dir.join("turned.txt"),
        "cube.off 0 0 0 0 0 0\n\
         cube.off 0.7071068 -0.7071068 0 0.5 0.7071068 0.7071068 0 0 0 0 1 0\n",
    )
    .unwrap();
    let v = json(&cga(&["scene", "turned.txt", "--json"], &dir));
    assert_eq!(v["pairs"], serde_json::json!([[0, 1]]));
}

#[test]
fn a_sphere_tree_too_deep_for_memory_is_refused_with_the_estimate() {
    // `--depth 16` (the stated maximum) once ended in "memory allocation failed".
    let dir = temp_dir("spheretree-deep");
    let start = Instant::now();
    let err = error(&cga(
        &[
            "spheretree",
            "build",
            "bunny",
            "--depth",
            "16",
            "-o",
            "t.txt",
        ],
        &dir,
    ));
    for part in ["--depth 16", "spheres", "of memory", "choose --depth"] {
        assert!(err.contains(part), "{part:?} missing from: {err}");
    }
    assert!(!dir.join("t.txt").exists());
    assert!(start.elapsed().as_secs() < 60, "slow to refuse");
    // A depth that fits is built as before.
    let out = cga(
        &[
            "spheretree",
            "build",
            "bunny",
            "--depth",
            "7",
            "-o",
            "t.txt",
        ],
        &dir,
    );
    assert!(stdout(&out).contains("wrote 1 trees"));
}

#[test]
fn tiny_and_huge_numbers_print_in_scientific_notation() {
    // A distance of 1e-150 once printed as a 150-digit decimal.
    let dir = temp_dir("short-numbers");
    // Two triangles in the planes x = 0 and x = 1e-150.
    let triangle = |x: &str| format!("OFF\n3 1 0\n{x} 0 0\n{x} 1 0\n{x} 0 1\n3 0 1 2\n");
    std::fs::write(dir.join("a.off"), triangle("0")).unwrap();
    std::fs::write(dir.join("b.off"), triangle("1e-150")).unwrap();
    let text = stdout(&cga(&["distance", "a.off", "b.off"], &dir));
    assert!(text.starts_with("distance 1e-150 ±"), "{text}");
    assert!(text.contains("witness A [0, "), "{text}");
    assert!(text.contains("witness B [1e-150, "), "{text}");
    // JSON stays JSON, with the same number.
    let v = json(&cga(&["distance", "a.off", "b.off", "--json"], &dir));
    assert_eq!(v["distance"], 1e-150);
    std::fs::write(dir.join("s.txt"), "a.off 0 0 0 0 0 0\nb.off 0 0 0 0 0 0\n").unwrap();
    let text = stdout(&cga(&["scene", "s.txt", "--nearest"], &dir));
    assert!(text.contains("distance 1e-150 ±"), "{text}");
    let text = stdout(&cga(&["scene", "s.txt", "--clearance", "1e-200"], &dir));
    assert!(text.contains("0 pairs within 1e-200"), "{text}");
}

#[test]
fn the_moved_step_of_a_scene_is_in_the_text_output() {
    let dir = temp_dir("scene-moved");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(
        dir.join("apart.txt"),
        "cube.off 0 0 0 0 0 0\ncube.off 0 0 0 3 0 0\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("close.txt"),
        "cube.off 0 0 0 0 0 0\ncube.off 0 0 0 0.5 0 0\n",
    )
    .unwrap();
    let text = stdout(&cga(&["scene", "apart.txt", "--moved", "close.txt"], &dir));
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].contains("0 pairs touching"), "{text}");
    assert!(
        lines[1].starts_with("moved to close.txt: 1 pairs touching"),
        "{text}"
    );
    assert_eq!(lines[2], "0 1", "{text}");
}

#[test]
fn errors_name_the_flag_the_file_and_the_line() {
    let dir = temp_dir("named-errors");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    // An output file that opens but cannot be written (Linux's /proc files).
    if std::path::Path::new("/proc/version").exists() {
        let out = cga(
            &[
                "collide",
                "cube.off",
                "cube.off",
                "--pairs",
                "/proc/version",
            ],
            &dir,
        );
        let err = error(&out);
        assert!(err.contains("--pairs /proc/version"), "{err}");
    }
    // A missing query file is a missing file, whatever its folder.
    let err = error(&cga(&["ccd", "missing.csv"], &dir));
    assert!(err.contains("missing.csv: no such file"), "{err}");
    assert!(!err.contains("vertex-face"), "{err}");
    // A scene line naming a missing mesh: the scene file's line.
    std::fs::write(
        dir.join("s.txt"),
        "cube.off 0 0 0 0 0 0\n\nnone.off 0 0 0 0 0 0\n",
    )
    .unwrap();
    let err = error(&cga(&["scene", "s.txt"], &dir));
    assert!(err.contains("s.txt:3") && err.contains("none.off"), "{err}");
    // A NaN vertex of an OBJ file: the line, as for OFF files.
    std::fs::write(
        dir.join("nan.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n",
    )
    .unwrap();
    let err = error(&cga(&["distance", "nan.obj", "cube.off"], &dir));
    assert!(err.contains("nan.obj:3: vertex 2"), "{err}");
}

#[test]
fn segments_are_six_comma_separated_numbers_in_query_and_scene() {
    let dir = temp_dir("segment-form");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(dir.join("s.txt"), "cube.off 0 0 0 0 0 0\n").unwrap();
    let segment = "-1,0.5,0.5,2,0.5,0.5";
    let v = json(&cga(
        &["query", "cube.off", "--segment", segment, "--json"],
        &dir,
    ));
    assert_eq!(v["hits"], 4, "{v}");
    let v = json(&cga(
        &["scene", "s.txt", "--segment", segment, "--json"],
        &dir,
    ));
    assert_eq!(v["segment_hits"].as_array().unwrap().len(), 1, "{v}");
    // The old six-word form is an error, and a wrong count says what the form is.
    error(&cga(
        &[
            "scene",
            "s.txt",
            "--segment",
            "-1",
            "0.5",
            "0.5",
            "2",
            "0.5",
            "0.5",
        ],
        &dir,
    ));
    let err = error(&cga(&["scene", "s.txt", "--segment", "-1,0.5,0.5"], &dir));
    assert!(err.contains("expected 6 comma-separated numbers"), "{err}");
}
