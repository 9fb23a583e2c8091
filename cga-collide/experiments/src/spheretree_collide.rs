//! `cga-experiment spheretree-collide FILE`: the sphere-tree paper's collision method (as its
//! C++ was published, and with its `Colision_Real` fixed) against the simultaneous descent of
//! `SphereTree::collides` (the `cga spheretree collide` of the product), on the first two trees
//! of a file in the paper's format; `both` checks that they agree.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use cga_collide::hierarchy::sphere_tree::{CollisionResult, SphereTree};
use cga_collide::testing::sphere_tree::{paper_method, paper_method_as_published};
use clap::{Args, ValueEnum};
use serde_json::json;

use crate::tree_file::{read_tree_pair, result_json};

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
enum Method {
    /// The paper's method (roots, leaves of X against Y's root, then each against Y), with its
    /// `Colision_Real` fixed to try every meeting child.
    Paper,
    /// the paper's C++ exactly as written (follows only the first meeting child: can miss).
    PaperAsPublished,
    /// Simultaneous descent, larger ball first.
    Simultaneous,
    /// `paper` and `simultaneous`, checking that they agree.
    Both,
}

#[derive(Args, Debug)]
pub struct CollideArgs {
    /// A file in the paper's format with at least two trees.
    file: PathBuf,
    /// Which traversal.
    #[arg(long, value_enum, default_value_t = Method::Both)]
    method: Method,
    /// Accept a file that ends early (report what is missing on stderr, use what is there).
    #[arg(long)]
    lenient: bool,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Runs `cga-experiment spheretree-collide`.
pub fn run(args: CollideArgs) -> Result<()> {
    let trees = read_tree_pair(&args.file, args.lenient, "the comparison")?;
    let (x, y) = (&trees[0], &trees[1]);
    let nodes = [x.len(), y.len()];
    let timed = |f: fn(&SphereTree, &SphereTree) -> CollisionResult| {
        let t = Instant::now();
        let r = f(x, y);
        (r, t.elapsed().as_secs_f64() * 1e6)
    };
    let method_name = match args.method {
        Method::Paper => "paper",
        Method::PaperAsPublished => "paper-as-published",
        Method::Simultaneous => "simultaneous",
        Method::Both => "both",
    };
    let single = match args.method {
        Method::Paper => Some(timed(paper_method)),
        Method::PaperAsPublished => Some(timed(paper_method_as_published)),
        Method::Simultaneous => Some(timed(SphereTree::collides)),
        Method::Both => None,
    };
    if let Some((r, micros)) = single {
        if args.json {
            let mut v = result_json(&r);
            v["method"] = json!(method_name);
            v["nodes"] = json!(nodes);
            v["micros"] = json!(micros);
            println!("{v}");
        } else {
            println!(
                "{} ({method_name}: {} sphere tests, {micros:.1} µs)",
                if r.collides {
                    "collide"
                } else {
                    "no collision"
                },
                r.sphere_tests
            );
        }
        return Ok(());
    }
    let (s, s_us) = timed(paper_method);
    let (m, m_us) = timed(SphereTree::collides);
    if s.collides != m.collides {
        // Possible only for trees whose child balls are not inside their parents.
        eprintln!(
            "warning: the methods disagree (paper: {}, simultaneous: {}); {} + {} child balls stick out of their parents",
            s.collides,
            m.collides,
            x.nesting_violations().len(),
            y.nesting_violations().len()
        );
    }
    if args.json {
        let mut sj = result_json(&s);
        sj["micros"] = json!(s_us);
        let mut mj = result_json(&m);
        mj["micros"] = json!(m_us);
        println!(
            "{}",
            json!({
                "collides": m.collides,
                "agree": s.collides == m.collides,
                "method": "both",
                "sphere_tests": s.sphere_tests + m.sphere_tests,
                "nodes": nodes,
                "paper": sj,
                "simultaneous": mj,
            })
        );
    } else {
        println!(
            "{} (paper: {} sphere tests, {s_us:.1} µs; simultaneous: {} sphere tests, {m_us:.1} µs)",
            if s.collides {
                "collide"
            } else {
                "no collision"
            },
            s.sphere_tests,
            m.sphere_tests
        );
    }
    Ok(())
}
