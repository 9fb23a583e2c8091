//! The CCD benchmark's 7,279 sample queries (Wang et al. 2021, MIT licence, copied with their
//! licence under `tests/fixtures/ccd/`): every answer equals the exact truth.

use std::path::{Path, PathBuf};

use cga_collide::motion::{load_queries, QueryKind};

fn query_files() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/ccd/sample-queries");
    let mut files = Vec::new();
    for scene in std::fs::read_dir(&root).expect("fixtures") {
        let scene = scene.expect("entry").path();
        for kind in ["vertex-face", "edge-edge"] {
            let Ok(entries) = std::fs::read_dir(scene.join(kind)) else {
                continue;
            };
            for f in entries {
                files.push(f.expect("entry").path());
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_sample_query_is_answered_exactly() {
    let files = query_files();
    assert_eq!(files.len(), 42, "fixture files");
    let (mut total, mut wrong) = (0, Vec::new());
    for file in &files {
        let kind = QueryKind::from_path(file).expect("kind folder");
        for (i, q) in load_queries(file).expect("readable").iter().enumerate() {
            total += 1;
            let answer = q.touch(kind).expect("finite inputs");
            if Some(answer) != q.truth {
                wrong.push(format!("{} query {i}: got {answer}", file.display()));
            }
        }
    }
    assert_eq!(total, 7279);
    assert!(
        wrong.is_empty(),
        "{} wrong:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}
