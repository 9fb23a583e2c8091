//! OFF reader (hand-written: the format is tiny).
//!
//! Accepted: an optional header keyword `OFF` (or `COFF`, `NOFF`, `CNOFF`, `STOFF`, …: any
//! word ending in `OFF`) possibly followed on the same line by the counts; the counts line
//! `vertices faces [edges]`; one vertex per line (the first three numbers are x y z, anything
//! after, such as colours or normals, is ignored); one face per line, `n i1 … in` followed by an
//! optional colour. Polygons with more than three vertices are fan-triangulated; `#` starts a
//! comment anywhere.

use nalgebra::Point3;

use super::text::{capacity, check_finite, content_lines, fan, parse_f64, parse_u64};
use crate::error::{Error, Location};

type Parsed = (Vec<Point3<f64>>, Vec<[u32; 3]>);

pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Parsed, Error> {
    let text = std::str::from_utf8(bytes).map_err(|e| Error::Syntax {
        at: Location::byte(file, e.valid_up_to()),
        message: "OFF file is not valid UTF-8 text (binary OFF is not supported)".into(),
    })?;
    let mut lines = content_lines(text);
    let last_line = text.lines().count().max(1);
    let truncated = |expected: String| Error::Truncated {
        at: Location::line(file, last_line),
        expected,
    };

    // Header and counts.
    let (mut line_no, mut line) = lines
        .next()
        .ok_or_else(|| truncated("the OFF header".into()))?;
    let first = line.split_whitespace().next().unwrap_or("");
    if first.ends_with("OFF") {
        if first.len() > 3 && !first.starts_with(['C', 'N', 'S', '4']) {
            return Err(Error::Syntax {
                at: Location::line(file, line_no),
                message: format!("unknown OFF header keyword {first:?}"),
            });
        }
        if first.contains('4') || first.contains('n') {
            return Err(Error::Syntax {
                at: Location::line(file, line_no),
                message: format!("OFF variant {first:?} (not 3-dimensional) is not supported"),
            });
        }
        let rest = line[first.len()..].trim();
        if rest.is_empty() {
            (line_no, line) = lines
                .next()
                .ok_or_else(|| truncated("the OFF counts line".into()))?;
        } else {
            line = rest;
        }
    }
    let mut counts = line.split_whitespace();
    let mut count = |what: &str| -> Result<u64, Error> {
        let token = counts.next().ok_or_else(|| Error::Syntax {
            at: Location::line(file, line_no),
            message: format!("OFF counts line lacks the number of {what}"),
        })?;
        parse_u64(token, file, line_no)
    };
    let nv = count("vertices")?;
    let nf = count("faces")?;

    let mut vertices = Vec::with_capacity(capacity(nv, text.len(), 6));
    for v in 0..nv {
        let (line_no, line) = lines
            .next()
            .ok_or_else(|| truncated(format!("vertex {v} of {nv}")))?;
        let mut tokens = line.split_whitespace();
        let mut xyz = [0.0; 3];
        for c in &mut xyz {
            let token = tokens.next().ok_or_else(|| Error::Syntax {
                at: Location::line(file, line_no),
                message: format!("vertex {v} has fewer than 3 coordinates"),
            })?;
            *c = parse_f64(token, file, line_no)?;
        }
        check_finite(xyz, v as usize, Location::line(file, line_no))?;
        vertices.push(Point3::from(xyz));
    }

    let mut triangles = Vec::with_capacity(capacity(nf, text.len(), 6));
    let mut polygon = Vec::new();
    for f in 0..nf {
        let (line_no, line) = lines
            .next()
            .ok_or_else(|| truncated(format!("face {f} of {nf}")))?;
        let mut tokens = line.split_whitespace();
        let n = parse_u64(tokens.next().unwrap_or(""), file, line_no)?;
        if n < 3 {
            return Err(Error::Syntax {
                at: Location::line(file, line_no),
                message: format!("face {f} has {n} vertices (at least 3 needed)"),
            });
        }
        polygon.clear();
        for k in 0..n {
            let token = tokens.next().ok_or_else(|| Error::Syntax {
                at: Location::line(file, line_no),
                message: format!("face {f} announces {n} vertices but lists {k}"),
            })?;
            let index = parse_u64(token, file, line_no)?;
            if index >= vertices.len() as u64 {
                return Err(Error::IndexOutOfRange {
                    at: Location::line(file, line_no),
                    face: f as usize,
                    index: i64::try_from(index).unwrap_or(i64::MAX),
                    vertex_count: vertices.len(),
                });
            }
            polygon.push(index as u32);
        }
        fan(&polygon, &mut triangles);
    }
    Ok((vertices, triangles))
}
