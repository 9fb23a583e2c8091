//! `cga shapes FILE.jsonl…`: answers in file order, one JSON object a file, the SHAPE
//! spellings, and malformed lines named by file and line. `cga scene` files naming shapes.

mod common;

use std::path::Path;

use common::{cga, cube_off, error, json, temp_dir};
use serde_json::json;

/// Pairs of balls, segments and triangles with known answers, in file order.
const BASIC: &str = r#"{"a": {"ball": {"center": [0, 0, 0], "radius": 1}}, "b": {"ball": {"center": [2, 0, 0], "radius": 1}}}
{"a": {"ball": {"center": [0, 0, 0], "radius": 1}}, "b": {"ball": {"center": [2.0000000000000004, 0, 0], "radius": 1}}, "note": "other keys are ignored"}

{"a": {"segment": {"points": [[0.25, 0.25, -1], [0.25, 0.25, 1]]}}, "b": {"triangle": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}}
{"a": {"segment": {"points": [[0.5, 0.5, 1e-300], [0.5, 0.5, 1]]}}, "b": {"triangle": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}}
{"a": {"triangle": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}, "b": {"ball": {"center": [0.5, 0.5, 0.1], "radius": 0.1}}}
"#;

#[test]
fn answers_come_in_file_order_one_object_a_file() {
    let dir = temp_dir("shapes");
    std::fs::write(dir.join("basic.jsonl"), BASIC).unwrap();
    std::fs::write(dir.join("empty.jsonl"), "\n").unwrap();
    let out = cga(&["shapes", "basic.jsonl", "empty.jsonl", "--json"], &dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 2);
    let v = &lines[0];
    assert_eq!(v["file"], "basic.jsonl");
    assert_eq!(v["pairs"], 5);
    // Touching, one ulp apart, crossing, 1e-300 above the face, touching the face from above.
    assert_eq!(v["answers"], json!([true, false, true, false, true]));
    let (mean, max) = (
        v["micros_mean"].as_f64().unwrap(),
        v["micros_max"].as_f64().unwrap(),
    );
    assert!(0.0 <= mean && mean <= max, "{v}");
    assert_eq!(lines[1]["pairs"], 0);
    assert_eq!(lines[1]["answers"], json!([]));
    let text = cga(&["shapes", "basic.jsonl"], &dir);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("5 pairs, 3 intersecting") && text.contains("10101"),
        "{text}"
    );
}

#[test]
fn repeat_times_loops_and_keeps_the_answers() {
    let dir = temp_dir("shapes-repeat");
    std::fs::write(dir.join("basic.jsonl"), BASIC).unwrap();
    let out = cga(&["shapes", "basic.jsonl", "--json", "--repeat", "10"], &dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value =
        serde_json::from_str(String::from_utf8(out.stdout).unwrap().trim()).unwrap();
    assert_eq!(v["answers"], json!([true, false, true, false, true]));
    let (median, max) = (
        v["micros_median"].as_f64().unwrap(),
        v["micros_max"].as_f64().unwrap(),
    );
    assert!(0.0 <= median && median <= max, "{v}");
}

#[test]
fn malformed_lines_name_the_file_and_line() {
    let dir = temp_dir("shapes-bad");
    let ball = r#"{"ball": {"center": [0, 0, 0], "radius": 1}}"#;
    let cases = [
        (format!("{{\"a\": {ball}, \"b\": {ball}}}\n{{\"a\": {ball}}}\n"), "bad.jsonl:2", "missing key \"b\""),
        ("{\"a\": 1,\n".to_owned(), "bad.jsonl:1", "not a JSON object"),
        (format!("\n{{\"a\": {ball}, \"b\": {{\"ball\": {{\"centre\": [0, 0, 0], \"radius\": 1}}}}}}\n"), "bad.jsonl:2", "unknown field `centre`"),
        (format!("{{\"a\": {ball}, \"b\": {{\"box\": {{}}}}}}\n"), "bad.jsonl:1", "unknown shape kind `box`"),
        (format!("{{\"a\": {ball}, \"b\": {{\"ball\": {{\"center\": [0, 0, 0], \"radius\": -1}}}}}}\n"), "bad.jsonl:1", "negative"),
        (format!("{{\"a\": {ball}, \"b\": {{\"ball\": {{\"center\": [0, 0, 1e999], \"radius\": 1}}}}}}\n"), "bad.jsonl:1", "JSON"),
        (format!("{{\"a\": {ball}, \"b\": {{\"ball\": {{\"center\": [0, 0, 1e200], \"radius\": 1}}}}}}\n"), "bad.jsonl:1", "beyond the limit"),
    ];
    for (text, at, why) in cases {
        std::fs::write(dir.join("bad.jsonl"), &text).unwrap();
        let e = error(&cga(&["shapes", "bad.jsonl", "--json"], &dir));
        assert!(e.contains(at) && e.contains(why), "{text:?}: {e}");
    }
    let e = error(&cga(&["shapes", "missing.jsonl"], &dir));
    assert!(e.contains("missing.jsonl"), "{e}");
}

/// The example file of the docs: every SHAPE kind, with the exact answers.
#[test]
fn the_example_file_is_answered_exactly() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let v = json(&cga(&["shapes", "shapes.jsonl", "--json"], &data));
    assert_eq!(v["pairs"], 8);
    assert_eq!(
        v["answers"],
        json!([true, false, true, true, true, true, false, true])
    );
}

#[test]
fn scene_files_name_shapes_beside_meshes() {
    let dir = temp_dir("scene-shapes");
    std::fs::write(dir.join("cube.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(
        dir.join("mixed.txt"),
        "cube.off 0 0 0 0 0 0\n\
         {\"ball\": {\"center\": [0.5, 0.5, 1.5], \"radius\": 0.5}}   # resting on the top face\n\
         {\"ball\": {\"center\": [0, 0, 0], \"radius\": 0.5}} 0 0 0 5 0 0\n\
         {\"triangle\": {\"points\": [[5, -1, -1], [5, 1, -1], [5, 0, 2]]}} 1 0 0 0.5 0 1 0 0 0 0 1 0\n",
    )
    .unwrap();
    let v = json(&cga(&["scene", "mixed.txt", "--json", "--nearest"], &dir));
    assert_eq!(
        (
            v["objects"].clone(),
            v["meshes"].clone(),
            v["shapes"].clone()
        ),
        (json!(4), json!(1), json!(3))
    );
    assert_eq!(v["pairs"], json!([[0, 1], [2, 3]]));
    // A segment along y = z = 0.5 from x = -1 to 9: the cube at x = 0, then the triangle
    // (x = 5 moved to 5.5); it passes the ball (centre (5, 0, 0), radius 0.5) by.
    let v = json(&cga(
        &[
            "scene",
            "mixed.txt",
            "--json",
            "--segment",
            "-1,0.5,0.5,9,0.5,0.5",
        ],
        &dir,
    ));
    let hits = v["segment_hits"].as_array().unwrap();
    assert_eq!(hits[0]["object"], 0);
    assert_eq!(hits.len(), 2);
    assert_eq!(hits[0]["parameter"], 0.1);
    assert_eq!(
        (hits[1]["object"].clone(), hits[1]["parameter"].clone()),
        (json!(3), json!(0.65))
    );
    let e = error(&cga(
        &["scene", "mixed.txt", "--segment", "-1,0,0,9,0,0"],
        &dir,
    ));
    assert!(
        e.contains("segment_hits_along") && e.contains("ball"),
        "{e}"
    );
    std::fs::write(
        dir.join("bad.txt"),
        "cube.off 0 0 0 0 0 0\n{\"ball\": {\"center\": [0, 0], \"radius\": 1}}\n",
    )
    .unwrap();
    let e = error(&cga(&["scene", "bad.txt"], &dir));
    assert!(e.contains("bad.txt:2") && e.contains("center"), "{e}");
    std::fs::write(
        dir.join("bad.txt"),
        "{\"ball\": {\"center\": [0, 0, 0], \"radius\": 1}} 1 2\n",
    )
    .unwrap();
    let e = error(&cga(&["scene", "bad.txt"], &dir));
    assert!(
        e.contains("bad.txt:1") && e.contains("found 2 numbers"),
        "{e}"
    );
}
