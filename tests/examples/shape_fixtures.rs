//! Writes the shape-pair fixtures of `cga shapes` (fixed seeds, exact answers):
//!
//! ```text
//! cargo run --release -p workspace-tests --example shape_fixtures -- cga-collide/cli/tests/data/shapes
//! ```

use workspace_tests::shape_oracle::generate::{fixture_files, fixture_text};

fn main() {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "cga-collide/cli/tests/data/shapes".to_string());
    std::fs::create_dir_all(&dir).expect("create the fixture directory");
    for (name, lines) in fixture_files() {
        let family = name.trim_end_matches(".jsonl");
        let path = std::path::Path::new(&dir).join(name);
        std::fs::write(&path, fixture_text(family, &lines)).expect("write a fixture");
        let yes = lines.iter().filter(|l| l.expected).count();
        println!(
            "{}: {} pairs ({} meeting, {} apart)",
            path.display(),
            lines.len(),
            yes,
            lines.len() - yes
        );
    }
}
