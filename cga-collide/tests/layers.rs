//! The crate's top modules form layers: each may use only the modules listed before it in
//! `LAYERS` (the order of the module map in `src/lib.rs`). This reads the sources and fails
//! on any `crate::<module>` use (outside comments) that goes the other way, so an import cycle
//! between top modules cannot come back unnoticed.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

/// Bottom first. `error` and `parallel` are leaves every layer may use.
const LAYERS: &[&str] = &[
    "error",
    "parallel",
    "exact",
    "shape",
    "conformal",
    "query",
    "bounding",
    "collider",
    "motion",
    "scene",
    "hierarchy",
    "gpu",
    "testing",
];

/// Crate-root re-exports and the layer they come from.
const ROOT_REEXPORTS: &[(&str, &str)] = &[
    ("Error", "error"),
    ("Collider", "collider"),
    ("Intersects", "query"),
    ("mesh", "shape"),
    ("Ball", "shape"),
    ("Segment", "shape"),
    ("Sphere", "shape"),
    ("TriMesh", "shape"),
    ("Triangle", "shape"),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("readable source directory") {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn layer_of(name: &str) -> Option<usize> {
    let module = ROOT_REEXPORTS
        .iter()
        .find(|(item, _)| *item == name)
        .map_or(name, |(_, module)| module);
    LAYERS.iter().position(|l| *l == module)
}

/// The names a line reaches through `crate::`: `crate::a::…` gives `a`, and
/// `crate::{a, b::c}` gives `a` and `b`.
fn crate_paths(line: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut rest = line;
    while let Some(at) = rest.find("crate::") {
        rest = &rest[at + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let head = item.trim().split("::").next().unwrap_or("");
                if !head.is_empty() {
                    names.push(head.to_string());
                }
            }
        } else {
            let head: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            names.push(head);
        }
    }
    names
}

#[test]
fn top_modules_use_only_lower_layers() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut seen_modules = BTreeSet::new();
    let mut violations = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(&src).expect("file under src");
        let first = relative.components().next().expect("non-empty path");
        let top = first
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if top == "lib" || top == "bin" {
            continue;
        }
        let Some(own) = layer_of(&top) else {
            violations.push(format!(
                "{}: top module `{top}` is not in LAYERS",
                relative.display()
            ));
            continue;
        };
        seen_modules.insert(top.clone());
        let text = fs::read_to_string(file).expect("readable source file");
        for (number, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue; // doc links may point anywhere
            }
            for name in crate_paths(line) {
                match layer_of(&name) {
                    Some(used) if used > own => violations.push(format!(
                        "{}:{}: `{top}` uses `crate::{name}`, a higher layer",
                        relative.display(),
                        number + 1
                    )),
                    Some(_) => {}
                    None => violations.push(format!(
                        "{}:{}: `crate::{name}` is neither a layer nor a known re-export",
                        relative.display(),
                        number + 1
                    )),
                }
            }
        }
    }
    assert!(
        violations.is_empty(),
        "layering violations:\n{}",
        violations.join("\n")
    );
    assert!(
        seen_modules.len() >= 8,
        "expected the crate's top modules, found {seen_modules:?}"
    );
}

#[test]
fn crate_paths_reads_single_and_grouped_uses() {
    assert_eq!(crate_paths("use crate::collider::Collider;"), ["collider"]);
    assert_eq!(
        crate_paths("use crate::{Ball, bounding::Aabb};"),
        ["Ball".to_string(), "bounding".to_string()]
    );
    assert!(crate_paths("use super::x;").is_empty());
}
