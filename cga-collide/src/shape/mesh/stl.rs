//! STL reader (ASCII and binary), hand-written so that errors carry lines and byte offsets.
//!
//! STL stores a triangle soup of `f32` corners; corners with identical coordinates are merged
//! into one vertex (`-0.0` counts as `0.0`). Coordinates are widened to `f64` exactly.
//! A file is read as binary when its size is exactly `84 + 50·n` for the triangle count `n`
//! in its header, and as ASCII when it starts with `solid` otherwise.

use std::collections::HashMap;

use nalgebra::Point3;

use super::text::{capacity, check_finite, parse_f64};
use crate::error::{Error, Location};

type Parsed = (Vec<Point3<f64>>, Vec<[u32; 3]>);

/// Merges identical corners.
#[derive(Default)]
struct Welder {
    vertices: Vec<Point3<f64>>,
    index: HashMap<[u64; 3], u32>,
}

impl Welder {
    fn add(&mut self, xyz: [f64; 3]) -> u32 {
        // Adding 0.0 turns -0.0 into +0.0.
        let key = xyz.map(|c| (c + 0.0).to_bits());
        let vertices = &mut self.vertices;
        *self.index.entry(key).or_insert_with(|| {
            vertices.push(Point3::from(xyz.map(|c| c + 0.0)));
            (vertices.len() - 1) as u32
        })
    }
}

pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Parsed, Error> {
    if bytes.len() >= 84 {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        if bytes.len() as u64 == 84 + 50 * n as u64 {
            return binary(bytes, file, n);
        }
    }
    let looks_ascii = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .is_some_and(|p| bytes[p..].starts_with(b"solid"));
    if looks_ascii {
        return ascii(bytes, file);
    }
    if bytes.len() < 84 {
        return Err(Error::Truncated {
            at: Location::byte(file, bytes.len()),
            expected: "the 84-byte binary STL header".into(),
        });
    }
    let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64;
    if (bytes.len() as u64) < 84 + 50 * n {
        let complete = (bytes.len() - 84) / 50;
        Err(Error::Truncated {
            at: Location::byte(file, 84 + 50 * complete),
            expected: format!("triangle {complete} of {n} (binary STL, 50 bytes each)"),
        })
    } else {
        Err(Error::Syntax {
            at: Location::byte(file, 84 + 50 * n as usize),
            message: format!(
                "binary STL announces {n} triangles but has {} trailing bytes",
                bytes.len() as u64 - 84 - 50 * n
            ),
        })
    }
}

fn binary(bytes: &[u8], file: &str, n: usize) -> Result<Parsed, Error> {
    let mut welder = Welder::default();
    let mut triangles = Vec::with_capacity(n);
    for t in 0..n {
        let rec = &bytes[84 + 50 * t..84 + 50 * t + 50];
        let mut tri = [0u32; 3];
        for (c, slot) in tri.iter_mut().enumerate() {
            let mut xyz = [0.0; 3];
            for (k, x) in xyz.iter_mut().enumerate() {
                let o = 12 + 12 * c + 4 * k;
                *x = f64::from(f32::from_le_bytes([
                    rec[o],
                    rec[o + 1],
                    rec[o + 2],
                    rec[o + 3],
                ]));
            }
            check_finite(
                xyz,
                welder.vertices.len(),
                Location::byte(file, 84 + 50 * t + 12 + 12 * c),
            )?;
            *slot = welder.add(xyz);
        }
        triangles.push(tri);
    }
    Ok((welder.vertices, triangles))
}

fn ascii(bytes: &[u8], file: &str) -> Result<Parsed, Error> {
    let text = std::str::from_utf8(bytes).map_err(|e| Error::Syntax {
        at: Location::byte(file, e.valid_up_to()),
        message: "ASCII STL is not UTF-8 text".into(),
    })?;
    let mut welder = Welder::default();
    let mut triangles = Vec::with_capacity(capacity(u64::MAX, bytes.len(), 100));
    let mut corners: Vec<u32> = Vec::new();
    let mut in_loop = false;
    let mut facet = 0usize;
    let mut last_line = 1;
    for (i, line) in text.lines().enumerate() {
        let line_no = i + 1;
        last_line = line_no;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("outer") => {
                if in_loop {
                    return Err(Error::Syntax {
                        at: Location::line(file, line_no),
                        message: "`outer loop` inside a loop".into(),
                    });
                }
                in_loop = true;
                corners.clear();
            }
            Some("vertex") => {
                if !in_loop {
                    return Err(Error::Syntax {
                        at: Location::line(file, line_no),
                        message: "`vertex` outside `outer loop` … `endloop`".into(),
                    });
                }
                let mut xyz = [0.0; 3];
                for x in &mut xyz {
                    let token = words.next().ok_or_else(|| Error::Syntax {
                        at: Location::line(file, line_no),
                        message: "`vertex` needs three coordinates".into(),
                    })?;
                    *x = parse_f64(token, file, line_no)?;
                }
                check_finite(xyz, welder.vertices.len(), Location::line(file, line_no))?;
                corners.push(welder.add(xyz));
            }
            Some("endloop") => {
                if !in_loop {
                    return Err(Error::Syntax {
                        at: Location::line(file, line_no),
                        message: "`endloop` without `outer loop`".into(),
                    });
                }
                if corners.len() < 3 {
                    return Err(Error::Syntax {
                        at: Location::line(file, line_no),
                        message: format!(
                            "facet {facet} has {} vertices (at least 3 needed)",
                            corners.len()
                        ),
                    });
                }
                super::text::fan(&corners, &mut triangles);
                in_loop = false;
                facet += 1;
            }
            _ => {} // solid, facet normal, endfacet, endsolid, blank lines
        }
    }
    if in_loop {
        return Err(Error::Truncated {
            at: Location::line(file, last_line),
            expected: format!("`endloop` of facet {facet}"),
        });
    }
    Ok((welder.vertices, triangles))
}
