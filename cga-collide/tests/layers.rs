//! The crate's top modules form layers: each may use only the modules listed before it in
//! `LAYERS` (the order of the module map in `src/lib.rs`). This reads the sources and fails
//! on any `crate::<module>` use (outside comments, single paths and `use crate::{…}` groups,
//! also those spanning lines) that goes the other way, so an import cycle between top modules
//! cannot come back unnoticed.

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
    "robot",
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

/// The source without comments (line numbers kept): a `//` outside a string literal ends the
/// line's code. Doc links may point anywhere.
fn code_of(text: &str) -> String {
    text.lines()
        .map(|line| {
            let mut in_string = false;
            let mut escaped = false;
            let bytes = line.as_bytes();
            for (i, &b) in bytes.iter().enumerate() {
                match b {
                    _ if escaped => escaped = false,
                    b'\\' if in_string => escaped = true,
                    b'"' => in_string = !in_string,
                    b'/' if !in_string && bytes.get(i + 1) == Some(&b'/') => return &line[..i],
                    _ => {}
                }
            }
            line
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The heads of the items of a `{…}` group whose text starts just after the `{`, each with its
/// byte offset in `group`: `a::b` gives `a`, a nested group (`a::{b, c}`) gives its head `a`
/// once. The group may span lines.
fn group_heads(group: &str) -> Vec<(usize, String)> {
    let mut heads = Vec::new();
    let mut depth = 0usize;
    let mut item_start = 0;
    let mut push = |from: usize, to: usize| {
        let item = &group[from..to];
        let head = item.split("::").next().unwrap_or("").trim();
        if !head.is_empty() {
            let offset = from + (item.len() - item.trim_start().len());
            heads.push((offset, head.to_string()));
        }
    };
    for (i, c) in group.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => {
                push(item_start, i);
                return heads;
            }
            '}' => depth -= 1,
            ',' if depth == 0 => {
                push(item_start, i);
                item_start = i + 1;
            }
            _ => {}
        }
    }
    push(item_start, group.len());
    heads
}

/// The names the code reaches through `crate::`, each with the 1-based number of the line
/// that names it: `crate::a::…` gives `a`, and `crate::{a, b::c}` gives `a` and `b`, also when
/// the group spans several lines (a multi-line `use crate::{…};` list).
fn crate_paths(code: &str) -> Vec<(usize, String)> {
    let line_of = |at: usize| code[..at].matches('\n').count() + 1;
    let mut names = Vec::new();
    for (at, _) in code.match_indices("crate::") {
        let after = at + "crate::".len();
        let rest = &code[after..];
        if let Some(group) = rest.strip_prefix('{') {
            for (offset, head) in group_heads(group) {
                names.push((line_of(after + 1 + offset), head));
            }
        } else {
            let head: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            names.push((line_of(at), head));
        }
    }
    names
}

/// The layering violations of one source file of the top module `top` (`file` names it in
/// the messages).
fn violations_in(file: &str, top: &str, text: &str) -> Vec<String> {
    let Some(own) = layer_of(top) else {
        return vec![format!("{file}: top module `{top}` is not in LAYERS")];
    };
    let mut violations = Vec::new();
    for (line, name) in crate_paths(&code_of(text)) {
        match layer_of(&name) {
            Some(used) if used > own => violations.push(format!(
                "{file}:{line}: `{top}` uses `crate::{name}`, a higher layer"
            )),
            Some(_) => {}
            None => violations.push(format!(
                "{file}:{line}: `crate::{name}` is neither a layer nor a known re-export"
            )),
        }
    }
    violations
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
        if layer_of(&top).is_some() {
            seen_modules.insert(top.clone());
        }
        let text = fs::read_to_string(file).expect("readable source file");
        violations.extend(violations_in(&relative.display().to_string(), &top, &text));
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
    let names = |code: &str| -> Vec<String> {
        crate_paths(code)
            .into_iter()
            .map(|(_, name)| name)
            .collect()
    };
    assert_eq!(names("use crate::collider::Collider;"), ["collider"]);
    assert_eq!(
        names("use crate::{Ball, bounding::Aabb};"),
        ["Ball", "bounding"]
    );
    assert!(names("use super::x;").is_empty());
    assert_eq!(
        names("use crate::{exact::{Kernel, ExactKernel}, shape::Triangle};"),
        ["exact", "shape"]
    );
}

#[test]
fn crate_paths_reads_multi_line_use_lists() {
    let code = "use core::cmp::Ordering;\nuse crate::{\n    exact::Kernel,\n    shape::{Ball, Segment},\n    Triangle,\n};\n";
    assert_eq!(
        crate_paths(code),
        [
            (3, "exact".to_string()),
            (4, "shape".to_string()),
            (5, "Triangle".to_string())
        ]
    );
}

#[test]
fn an_upward_import_in_a_multi_line_list_is_a_violation() {
    let source = "//! Docs may name [`crate::collider`].\nuse crate::{\n    exact::Kernel, // not crate::scene\n    // a comment inside the list\n    collider::Collider,\n};\n";
    let found = violations_in("query/x.rs", "query", source);
    assert_eq!(
        found,
        ["query/x.rs:5: `query` uses `crate::collider`, a higher layer"]
    );
    assert!(violations_in("collider/x.rs", "collider", source).is_empty());
}
