//! `cga scene FILE`: the touching pairs of a scene file, its errors, and the scene-file format
//! (6-number and 12-number poses, comments, meshes relative to the file, built once).

mod common;

use common::{cga, cube_off, error, json, temp_dir};

#[test]
fn touching_pairs_clearance_and_nearest() {
    let dir = temp_dir("scene");
    std::fs::create_dir_all(dir.join("parts")).unwrap();
    std::fs::write(dir.join("parts/cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(
        dir.join("stack.txt"),
        "# three unit cubes in a row, the third 0.5 away, the fourth far\n\
         parts/cube.off 0 0 0 0 0 0\n\
         parts/cube.off 0 0 90 2 0 0   # turned a quarter about z around the origin: x in [1, 2]\n\
         \n\
         parts/cube.off 1 0 0 2.5 0 1 0 0 0 0 1 0\n\
         parts/cube.off 0 0 0 10 0 0\n",
    )
    .unwrap();
    let v = json(&cga(&["scene", "stack.txt", "--json", "--nearest"], &dir));
    assert_eq!(v["objects"], 4);
    assert_eq!(v["meshes"], 1);
    assert_eq!(v["pairs"], serde_json::json!([[0, 1]]));
    assert_eq!(v["nearest"]["pair"], serde_json::json!([0, 1]));
    assert_eq!(v["nearest"]["distance"], 0.0);
    let v = json(&cga(
        &["scene", "stack.txt", "--json", "--clearance", "0.5"],
        &dir,
    ));
    assert_eq!(v["pairs"], serde_json::json!([[0, 1], [1, 2]]));
    let text = cga(&["scene", "stack.txt"], &dir);
    assert!(text.status.success());
    assert!(String::from_utf8_lossy(&text.stdout).contains("1 pairs touching"));
    // A segment along y = z = 0.5 from x = -1 to 12: objects 0, 1, 2, 3 in order, first at x = 0.
    let seg = ["--segment", "-1,0.5,0.5,12,0.5,0.5"];
    let v = json(&cga(
        &[&["scene", "stack.txt", "--json"][..], &seg].concat(),
        &dir,
    ));
    let hits = v["segment_hits"].as_array().unwrap();
    let order: Vec<u64> = hits.iter().map(|h| h["object"].as_u64().unwrap()).collect();
    assert_eq!(order, vec![0, 1, 2, 3]);
    assert_eq!(hits[0]["parameter"], 1.0 / 13.0);
    assert_eq!(hits[0]["point"], serde_json::json!([0.0, 0.5, 0.5]));
    let text = cga(&[&["scene", "stack.txt"][..], &seg].concat(), &dir);
    assert!(String::from_utf8_lossy(&text.stdout).contains("4 objects hit"));
}

#[test]
fn malformed_scene_lines_name_the_line() {
    let dir = temp_dir("scene-bad");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(
        dir.join("five.txt"),
        "cube.off 0 0 0 0 0 0\ncube.off 1 2 3 4 5\n",
    )
    .unwrap();
    let err = error(&cga(&["scene", "five.txt"], &dir));
    assert!(
        err.contains("five.txt:2") && err.contains("found 5 numbers"),
        "{err}"
    );
    std::fs::write(dir.join("nan.txt"), "cube.off 0 0 0 0 nan 0\n").unwrap();
    let err = error(&cga(&["scene", "nan.txt"], &dir));
    assert!(
        err.contains("nan.txt:1") && err.contains("not a finite number"),
        "{err}"
    );
    let err = error(&cga(&["scene", "missing.txt"], &dir));
    assert!(err.contains("missing.txt"), "{err}");
}
