//! The paper's text format for sphere trees (the annex of Fuentes Socorro's work), reader and writer.
//!
//! ```text
//! 2                      <- the number of trees
//! 5 5 -5 8.7 1 //raíz    <- a node: centre x y z, radius, state (1 partial, 0 full)
//! 8 8                    <- its number of children, then 8 (of 8 possible)
//! 7.5 2.5 -2.5 4.34 1    <- its first child, and so on depth-first (children follow
//! 0 8                       their parent)
//! ...
//! ```
//!
//! The reader accepts `//` comments to the end of a line (the paper marks roots with `//raíz`)
//! and blank lines anywhere (the paper's text has them at page breaks); tokens are separated
//! by any whitespace. It never panics: every problem is an [`Error`] (variants `SphereTree…`) naming the line
//! (1-based) and what was expected there. Deeply nested input is parsed without recursion.
//!
//! [`read_lenient`] additionally accepts input that ends early (a truncated file, or a document
//! extraction that lost its last lines): it returns the trees as far as they go plus a precise
//! list of [`Gap`]s (which node declared how many children and how many were found).
//!
//! The writer prints every number with Rust's shortest round-trip formatting, so
//! `read(&write(&trees)) == trees`.
//!
//! ```
//! use cga_collide::hierarchy::sphere_tree::format::{read, write};
//! let text = "1\n0 0 0 2 1 //root\n2 8\n1 0 0 1 0\n0 8\n-1 0 0 1 1\n0 8\n";
//! let trees = read(text)?;
//! assert_eq!(trees[0].len(), 3);
//! assert_eq!(read(&write(&trees))?, trees);
//! let err = read("1\n0 0 0 2 1\n2 8\n1 0 0 1 0\n").unwrap_err();
//! assert!(err.to_string().contains("line 4"));
//! # Ok::<(), cga_collide::Error>(())
//! ```

use std::fmt::Write as _;

use super::{CellState, NestedNode, SphereTree};
use crate::error::Error;
pub use crate::error::Gap;

/// Trees read by [`read_lenient`] from input that may end early.
#[derive(Debug, Clone, PartialEq)]
pub struct LenientRead {
    /// The number of trees the first line declares.
    pub declared_trees: usize,
    /// The trees read: complete ones, then (if the input ended inside a tree) that tree with
    /// the children that were complete (every node of a [`Gap`] has fewer children than it
    /// declares).
    pub trees: Vec<SphereTree>,
    /// How many of `trees` are complete.
    pub complete_trees: usize,
    /// The nodes whose declared children were not all present, outermost first.
    pub gaps: Vec<Gap>,
}

impl LenientRead {
    /// Whether nothing was missing.
    pub fn is_complete(&self) -> bool {
        self.gaps.is_empty() && self.complete_trees == self.declared_trees
    }
}

/// Reads every tree of a file in the paper's format; any deviation is an error.
pub fn read(text: &str) -> Result<Vec<SphereTree>, Error> {
    Parser::new(text).run(false).map(|r| r.trees)
}

/// Reads like [`read`], but input that ends early is not an error: the complete trees, the
/// partial tree and the [`Gap`]s are returned. Any other problem is still an error.
pub fn read_lenient(text: &str) -> Result<LenientRead, Error> {
    Parser::new(text).run(true)
}

/// Writes trees in the paper's format (count line, then each tree depth-first, every number in
/// shortest round-trip form, no comments).
pub fn write(trees: &[SphereTree]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}", trees.len());
    for tree in trees {
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            let n = tree.node(i);
            let [x, y, z] = n.centre;
            let _ = writeln!(out, "{x} {y} {z} {} {}", n.radius, n.state.code());
            let _ = writeln!(out, "{} 8", n.child_count());
            stack.extend(tree.children(i).rev());
        }
    }
    out
}

struct Open {
    line: usize,
    node: NestedNode,
    declared: usize,
}

struct Parser<'a> {
    lines: std::iter::Peekable<std::iter::Enumerate<std::str::Lines<'a>>>,
    last_line: usize,
}

fn content(raw: &str) -> &str {
    match raw.find("//") {
        Some(k) => raw[..k].trim(),
        None => raw.trim(),
    }
}

fn clip(s: &str) -> String {
    const MAX: usize = 80;
    match s.char_indices().nth(MAX) {
        Some((k, _)) => format!("{}…", &s[..k]),
        None => s.to_owned(),
    }
}

impl<'a> Parser<'a> {
    fn new(text: &'a str) -> Self {
        Parser {
            lines: text.lines().enumerate().peekable(),
            last_line: 0,
        }
    }

    /// The next non-blank line (number, content without comment).
    fn next_line(&mut self) -> Option<(usize, &'a str)> {
        for (i, raw) in self.lines.by_ref() {
            self.last_line = i + 1;
            let c = content(raw);
            if !c.is_empty() {
                return Some((i + 1, c));
            }
        }
        None
    }

    fn run(mut self, lenient: bool) -> Result<LenientRead, Error> {
        let count_expected = "the number of trees (a non-negative integer)";
        let Some((line, c)) = self.next_line() else {
            return Err(Error::SphereTreeUnexpectedEnd {
                line: self.last_line,
                expected: count_expected.into(),
                declared_trees: 0,
                complete_trees: 0,
                gaps: Vec::new(),
            });
        };
        let declared: usize = match c.parse() {
            Ok(n) => n,
            Err(_) => {
                return Err(Error::SphereTreeSyntax {
                    line,
                    expected: count_expected.into(),
                    found: clip(c),
                })
            }
        };
        let mut trees = Vec::new();
        for t in 0..declared {
            match self.tree(t)? {
                Ok((root_line, root)) => {
                    trees.push(SphereTree::from_nested(&root).map_err(|source| {
                        Error::SphereTreeAtLine {
                            line: root_line,
                            source: Box::new(source),
                        }
                    })?)
                }
                Err((expected, partial, gaps)) => {
                    if !lenient {
                        return Err(Error::SphereTreeUnexpectedEnd {
                            line: self.last_line,
                            expected,
                            declared_trees: declared,
                            complete_trees: t,
                            gaps,
                        });
                    }
                    let complete_trees = trees.len();
                    if let Some((root_line, root)) = partial {
                        trees.push(SphereTree::from_nested(&root).map_err(|source| {
                            Error::SphereTreeAtLine {
                                line: root_line,
                                source: Box::new(source),
                            }
                        })?);
                    }
                    return Ok(LenientRead {
                        declared_trees: declared,
                        trees,
                        complete_trees,
                        gaps,
                    });
                }
            }
        }
        if let Some((line, c)) = self.next_line() {
            return Err(Error::SphereTreeTrailingContent {
                line,
                declared_trees: declared,
                found: clip(c),
            });
        }
        Ok(LenientRead {
            declared_trees: declared,
            complete_trees: trees.len(),
            trees,
            gaps: Vec::new(),
        })
    }

    /// One tree. `Ok(Err(..))` when the input ends inside it: what was expected, the partial
    /// tree (if its root was read) and the open nodes.
    #[allow(clippy::type_complexity)]
    fn tree(
        &mut self,
        t: usize,
    ) -> Result<Result<(usize, NestedNode), (String, Option<(usize, NestedNode)>, Vec<Gap>)>, Error>
    {
        let mut stack: Vec<Open> = Vec::new();
        loop {
            let node_expected = if stack.is_empty() {
                format!("the root of tree {} (`cx cy cz r state`)", t + 1)
            } else {
                let top = stack.last().map_or(0, |o| o.node.children.len() + 1);
                format!(
                    "child {top} of the node at line {} (`cx cy cz r state`)",
                    stack.last().map_or(0, |o| o.line)
                )
            };
            let Some((line, c)) = self.next_line() else {
                return Ok(Err(ended(t, node_expected, stack)));
            };
            let (centre, radius, state) = node_line(line, c)?;
            let counts_expected = format!("the children line `k 8` of the node at line {line}");
            let Some((cline, cc)) = self.next_line() else {
                stack.push(Open {
                    line,
                    node: NestedNode::leaf(centre, radius, state),
                    declared: 0,
                });
                let mut r = ended(t, counts_expected, stack);
                // The node whose children line is missing is complete as far as we know.
                r.2.pop();
                return Ok(Err(r));
            };
            let k = children_line(cline, cc, line)?;
            let node = NestedNode::leaf(centre, radius, state);
            if k > 0 {
                stack.push(Open {
                    line,
                    node,
                    declared: k,
                });
                continue;
            }
            // Attach the finished node, closing every parent it completes.
            let mut done = (line, node);
            loop {
                match stack.last_mut() {
                    None => return Ok(Ok(done)),
                    Some(top) => {
                        top.node.children.push(done.1);
                        if top.node.children.len() == top.declared {
                            let Some(o) = stack.pop() else { unreachable!() };
                            done = (o.line, o.node);
                        } else {
                            break;
                        }
                    }
                }
            }
        }
    }
}

/// The error data for input ending inside tree `t`: fold the open nodes into a partial tree.
fn ended(
    t: usize,
    expected: String,
    stack: Vec<Open>,
) -> (String, Option<(usize, NestedNode)>, Vec<Gap>) {
    let gaps: Vec<Gap> = stack
        .iter()
        .map(|o| Gap {
            tree: t,
            line: o.line,
            declared: o.declared,
            read: o.node.children.len(),
        })
        .collect();
    let mut partial: Option<(usize, NestedNode)> = None;
    for o in stack.into_iter().rev() {
        let mut node = o.node;
        if let Some((_, child)) = partial.take() {
            node.children.push(child);
        }
        partial = Some((o.line, node));
    }
    (expected, partial, gaps)
}

fn node_line(line: usize, c: &str) -> Result<([f64; 3], f64, CellState), Error> {
    let syntax = |expected: String| Error::SphereTreeSyntax {
        line,
        expected,
        found: clip(c),
    };
    let tokens: Vec<&str> = c.split_whitespace().collect();
    if tokens.len() != 5 {
        return Err(syntax(format!(
            "a node line `cx cy cz r state` (5 fields), not {} fields",
            tokens.len()
        )));
    }
    let names = ["centre x", "centre y", "centre z", "radius"];
    let mut v = [0.0; 4];
    for (k, name) in names.iter().enumerate() {
        match tokens[k].parse::<f64>() {
            Ok(x) if x.is_finite() => v[k] = x,
            _ => {
                return Err(syntax(format!(
                    "a finite number for the {name} (field {}), not `{}`",
                    k + 1,
                    clip(tokens[k])
                )))
            }
        }
    }
    if v[3] < 0.0 {
        return Err(syntax(format!(
            "a non-negative radius (field 4), not {}",
            v[3]
        )));
    }
    let state = match tokens[4] {
        "0" => CellState::Full,
        "1" => CellState::Partial,
        other => {
            return Err(syntax(format!(
                "the state `0` (full) or `1` (partial) in field 5, not `{}`",
                clip(other)
            )))
        }
    };
    Ok(([v[0], v[1], v[2]], v[3], state))
}

fn children_line(line: usize, c: &str, node_line: usize) -> Result<usize, Error> {
    let syntax = |expected: String| Error::SphereTreeSyntax {
        line,
        expected,
        found: clip(c),
    };
    let tokens: Vec<&str> = c.split_whitespace().collect();
    let what = format!("the children line `k 8` (k = 0..8) of the node at line {node_line}");
    if tokens.len() != 2 {
        return Err(syntax(format!(
            "{what}, with 2 fields, not {}",
            tokens.len()
        )));
    }
    let k = match tokens[0].parse::<usize>() {
        Ok(k) if k <= 8 => k,
        _ => {
            return Err(syntax(format!(
                "{what}: k must be an integer from 0 to 8, not `{}`",
                clip(tokens[0])
            )))
        }
    };
    if tokens[1] != "8" {
        return Err(syntax(format!(
            "{what}: the second field must be 8, not `{}`",
            clip(tokens[1])
        )));
    }
    Ok(k)
}
