//! `cga ccd`: the CCD benchmark's query files (answers, false positives and negatives, JSON)
//! and a deforming mesh's step (two frames), with their errors.

mod common;

use common::{cga, error, json, temp_dir};

/// One vertex–face query: a vertex falling from z = 1 to z = -1 through the triangle z = 0
/// (touches), and one passing beside it (does not), with a truth column.
fn query_rows(x: &str, truth: u8) -> String {
    let rows = [
        format!("{x},1,4,1,1"),
        "0,1,0,1,0,1".into(),
        "1,1,0,1,0,1".into(),
        "0,1,1,1,0,1".into(),
        format!("{x},1,4,-1,1"),
        "0,1,0,1,0,1".into(),
        "1,1,0,1,0,1".into(),
        "0,1,1,1,0,1".into(),
    ];
    rows.iter().map(|r| format!("{r},{truth}\n")).collect()
}

#[test]
fn query_files_report_answers_and_truth() {
    let dir = temp_dir("ccd-queries");
    std::fs::create_dir_all(dir.join("vertex-face")).unwrap();
    // x = 1/4 touches; x = 10 passes beside; the second query's truth is deliberately wrong.
    let text = query_rows("1,4", 1) + &query_rows("10,1", 1);
    std::fs::write(dir.join("vertex-face/q.csv"), text).unwrap();
    let v = json(&cga(
        &["ccd", "--json", "--repeat", "1", "vertex-face/q.csv"],
        &dir,
    ));
    assert_eq!(v["kind"], "vertex-face");
    assert_eq!(v["queries"], 2);
    assert_eq!(v["answers"], serde_json::json!([true, false]));
    assert_eq!(v["false_positives"], 0);
    assert_eq!(v["false_negatives"], 1);
    assert!(v["micros_max"].as_f64().unwrap() >= 0.0);
    // Without a kind folder, --kind is required.
    std::fs::copy(dir.join("vertex-face/q.csv"), dir.join("plain.csv")).unwrap();
    let e = error(&cga(&["ccd", "plain.csv"], &dir));
    assert!(e.contains("--kind"), "{e}");
    let v = json(&cga(
        &["ccd", "--json", "--kind", "vertex-face", "plain.csv"],
        &dir,
    ));
    assert_eq!(v["answers"], serde_json::json!([true, false]));
    // --first-contact: the same answers, and the contact at t = 1/2 within the tolerance.
    let v = json(&cga(
        &[
            "ccd",
            "--json",
            "--repeat",
            "1",
            "--first-contact",
            "--tolerance",
            "1e-6",
            "vertex-face/q.csv",
        ],
        &dir,
    ));
    assert_eq!(v["answers"], serde_json::json!([true, false]));
    let toi = &v["toi"];
    assert!(toi[1].is_null(), "{toi}");
    let (lo, hi) = (toi[0][0].as_f64().unwrap(), toi[0][1].as_f64().unwrap());
    assert!(lo <= 0.5 && 0.5 <= hi && hi - lo <= 1e-6, "{toi}");
}

#[test]
fn bad_query_files_are_errors_with_their_line() {
    let dir = temp_dir("ccd-bad");
    std::fs::write(dir.join("third.csv"), "1,3,0,1,0,1\n".repeat(8)).unwrap();
    let e = error(&cga(&["ccd", "--kind", "edge-edge", "third.csv"], &dir));
    assert!(
        e.contains("third.csv:1") && e.contains("not exactly an f64"),
        "{e}"
    );
    std::fs::write(dir.join("short.csv"), "1,2,0,1,0,1\n".repeat(5)).unwrap();
    let e = error(&cga(&["ccd", "--kind", "edge-edge", "short.csv"], &dir));
    assert!(e.contains("truncated"), "{e}");
    let e = error(&cga(&["ccd", "--kind", "edge-edge", "missing.csv"], &dir));
    assert!(e.contains("missing.csv"), "{e}");
}

/// Two triangles; the second falls through the first during the step.
fn frame(z: f64) -> String {
    format!(
        "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0.2 0.2 {z}\n0.3 0.2 {z}\n0.2 0.3 {z}\n3 0 1 2\n3 3 4 5\n"
    )
}

#[test]
fn a_deforming_step_lists_every_contact_and_the_first_time() {
    let dir = temp_dir("ccd-step");
    std::fs::write(dir.join("f0.off"), frame(1.0)).unwrap();
    std::fs::write(dir.join("f1.off"), frame(-1.0)).unwrap();
    let v = json(&cga(&["ccd", "--json", "f0.off", "f1.off"], &dir));
    assert_eq!(
        (v["vertices"].as_u64(), v["faces"].as_u64()),
        (Some(6), Some(2))
    );
    assert_eq!(
        v["vertex_face"],
        serde_json::json!([[3, 0], [4, 0], [5, 0]])
    );
    assert_eq!(v["edge_edge"], serde_json::json!([]));
    let toi = v["toi"].as_array().unwrap();
    let (lo, hi) = (toi[0].as_f64().unwrap(), toi[1].as_f64().unwrap());
    assert!(lo <= 0.5 && 0.5 <= hi && hi - lo <= 1e-9);
    // Frames of different meshes are an error that says so.
    std::fs::write(
        dir.join("other.off"),
        "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    )
    .unwrap();
    let e = error(&cga(&["ccd", "f0.off", "other.off"], &dir));
    assert!(e.contains("not two frames of one mesh"), "{e}");
}
