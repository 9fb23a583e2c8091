//! `cga signed-distance MESH POINTS.txt`: one JSON object with the signed distances (negative
//! inside, 0 on the surface), their bounds and the exact inside/outside; malformed lines named
//! by file and line.

mod common;

use common::{cga, cube_off, error, json, temp_dir};
use serde_json::json;

#[test]
fn signed_distances_of_points_in_file_order() {
    let dir = temp_dir("signed-distance");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(
        dir.join("points.txt"),
        "0.5 0.5 0.25\n\n# on a face, on a vertex, outside, one ulp outside a face\n\
         1 0.5 0.5\n0 0 0\n3 0.5 0.5\n1.0000000000000002 0.5 0.5\n",
    )
    .unwrap();
    let out = cga(
        &["signed-distance", "cube.off", "points.txt", "--json"],
        &dir,
    );
    let v = json(&out);
    assert_eq!(v["points"], 5);
    assert_eq!(v["inside"], json!([true, true, true, false, false]));
    let d: Vec<f64> = v["signed_distance"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let e: Vec<f64> = v["error_bound"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let want = [-0.25, 0.0, 0.0, 2.0, 2.220446049250313e-16];
    for k in 0..5 {
        assert!((d[k] - want[k]).abs() <= e[k], "{k}: {} ± {}", d[k], e[k]);
    }
    assert_eq!((d[1], e[1], d[2], e[2]), (0.0, 0.0, 0.0, 0.0));
    assert!(v["micros_per_point"].as_f64().unwrap() >= 0.0);
    let text = cga(&["signed-distance", "cube.off", "points.txt"], &dir);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("5 points, 3 inside"), "{text}");
}

#[test]
fn malformed_lines_name_the_file_and_line() {
    let dir = temp_dir("signed-distance-bad");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    for (text, at, why) in [
        ("0 0 0\n1 2\n", "bad.txt:2", "three numbers"),
        ("\n0 0 x\n", "bad.txt:2", "`x` is not a finite number"),
        ("0 0 nan\n", "bad.txt:1", "not a finite number"),
        ("0 0 0\n0 0 1e200\n", "bad.txt:2", "beyond the limit"),
    ] {
        std::fs::write(dir.join("bad.txt"), text).unwrap();
        let e = error(&cga(
            &["signed-distance", "cube.off", "bad.txt", "--json"],
            &dir,
        ));
        assert!(e.contains(at) && e.contains(why), "{text:?}: {e}");
    }
    let e = error(&cga(&["signed-distance", "cube.off", "missing.txt"], &dir));
    assert!(e.contains("missing.txt"), "{e}");
}
