//! Small helpers shared by the text parsers.

use crate::error::{shorten, Error, Location};

/// Parses a finite-or-not `f64` token (finiteness is checked by the caller, which knows the
/// vertex index).
pub(crate) fn parse_f64(token: &str, file: &str, line: usize) -> Result<f64, Error> {
    token.parse::<f64>().map_err(|_| Error::BadNumber {
        at: Location::line(file, line),
        token: shorten(token),
        expected: "a decimal floating-point number",
    })
}

/// Parses a non-negative integer token (count or index).
pub(crate) fn parse_u64(token: &str, file: &str, line: usize) -> Result<u64, Error> {
    token.parse::<u64>().map_err(|_| Error::BadNumber {
        at: Location::line(file, line),
        token: shorten(token),
        expected: "a non-negative integer",
    })
}

/// Checks that the three coordinates of vertex `vertex` are finite.
pub(crate) fn check_finite(xyz: [f64; 3], vertex: usize, at: Location) -> Result<(), Error> {
    match xyz.iter().find(|c| !c.is_finite()) {
        Some(&value) => Err(Error::NonFinite { at, vertex, value }),
        None => Ok(()),
    }
}

/// Non-empty, non-comment lines of a text, with 1-based line numbers; `#` starts a comment.
pub(crate) fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().filter_map(|(i, l)| {
        let l = match l.find('#') {
            Some(p) => &l[..p],
            None => l,
        };
        let l = l.trim();
        (!l.is_empty()).then_some((i + 1, l))
    })
}

/// A capacity hint bounded by what the input could possibly hold, so that a lying header cannot
/// make us allocate absurd amounts.
pub(crate) fn capacity(claimed: u64, input_len: usize, min_bytes_per_item: usize) -> usize {
    let possible = input_len / min_bytes_per_item.max(1) + 1;
    usize::try_from(claimed).unwrap_or(usize::MAX).min(possible)
}

/// Fan-triangulates a polygon given by vertex indices, appending to `out`.
pub(crate) fn fan(polygon: &[u32], out: &mut Vec<[u32; 3]>) {
    for k in 1..polygon.len().saturating_sub(1) {
        out.push([polygon[0], polygon[k], polygon[k + 1]]);
    }
}
