//! OBJ reader, on top of the `tobj` crate (with `f64` positions).
//!
//! `tobj` reports errors without a position, so the input is fed through a reader that counts
//! the lines `tobj` has consumed: `tobj` stops at the first bad line, which names it.
//!
//! Note: `tobj` renumbers vertices in order of first use and drops unused ones; the order of
//! the faces (and so every triangle index) is that of the file.

use std::io::{BufRead, Read};

use nalgebra::Point3;

use super::text::check_finite;
use crate::error::{Error, Location};

type Parsed = (Vec<Point3<f64>>, Vec<[u32; 3]>);

/// A `BufRead` over a byte slice that counts consumed newlines.
struct LineCounter<'a> {
    rest: &'a [u8],
    newlines: usize,
    partial: bool,
}

impl Read for LineCounter<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = buf.len().min(self.rest.len());
        buf[..n].copy_from_slice(&self.rest[..n]);
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for LineCounter<'_> {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        Ok(self.rest)
    }

    fn consume(&mut self, amt: usize) {
        let amt = amt.min(self.rest.len());
        let (done, rest) = self.rest.split_at(amt);
        match done.iter().rposition(|&b| b == b'\n') {
            Some(last) => {
                self.newlines += done.iter().filter(|&&b| b == b'\n').count();
                self.partial = last + 1 < done.len();
            }
            None => self.partial |= !done.is_empty(),
        }
        self.rest = rest;
    }
}

pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Parsed, Error> {
    let mut reader = LineCounter {
        rest: bytes,
        newlines: 0,
        partial: false,
    };
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    // Material libraries are not needed (and must not be read from disk).
    let loaded = tobj::load_obj_buf(&mut reader, &options, |_| {
        Err(tobj::LoadError::GenericFailure)
    });
    let (models, _materials) = loaded.map_err(|e| {
        // The line tobj was reading when it failed: the last one consumed.
        let line = reader.newlines + usize::from(reader.partial);
        let at = Location::line(file, line.max(1));
        match e {
            tobj::LoadError::PositionParseError => Error::BadNumber {
                at,
                token: "(vertex line)".into(),
                expected: "three decimal coordinates after `v`",
            },
            tobj::LoadError::FaceVertexOutOfBounds => Error::Syntax {
                at,
                message: "face refers to a vertex that does not exist (index out of range)".into(),
            },
            other => Error::Syntax {
                at,
                message: obj_message(&other),
            },
        }
    })?;

    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    let mut face = 0usize;
    for model in &models {
        let mesh = &model.mesh;
        let base = vertices.len();
        for (i, p) in mesh.positions.chunks_exact(3).enumerate() {
            let xyz = [p[0], p[1], p[2]];
            check_finite(xyz, base + i, Location::file(file))
                .map_err(|e| non_finite_vertex(bytes, file).unwrap_or(e))?;
            vertices.push(Point3::from(xyz));
        }
        let count = mesh.positions.len() / 3;
        for t in mesh.indices.chunks_exact(3) {
            let mut tri = [0u32; 3];
            for (slot, &i) in tri.iter_mut().zip(t) {
                if i as usize >= count {
                    return Err(Error::IndexOutOfRange {
                        at: Location::file(file),
                        face,
                        index: i64::from(i),
                        vertex_count: count,
                    });
                }
                *slot = u32::try_from(base + i as usize).map_err(|_| Error::Syntax {
                    at: Location::file(file),
                    message: "too many vertices for u32 indices".into(),
                })?;
            }
            triangles.push(tri);
            face += 1;
        }
    }
    Ok((vertices, triangles))
}

/// The first `v` statement with a non-finite coordinate, as the error the OFF reader gives: its
/// line, and the vertex's 0-based place among the file's `v` statements. `tobj` gives neither
/// (it renumbers vertices and has no positions), so the text is scanned again, only on this
/// error path.
fn non_finite_vertex(bytes: &[u8], file: &str) -> Option<Error> {
    let mut vertex = 0;
    for (k, line) in bytes.split(|&b| b == b'\n').enumerate() {
        let Ok(line) = std::str::from_utf8(line) else {
            continue;
        };
        let mut words = line.split_whitespace();
        if words.next() != Some("v") {
            continue;
        }
        let value = words
            .take(3)
            .filter_map(|w| w.parse::<f64>().ok())
            .find(|x| !x.is_finite());
        if let Some(value) = value {
            return Some(Error::NonFinite {
                at: Location::line(file, k + 1),
                vertex,
                value,
            });
        }
        vertex += 1;
    }
    None
}

/// What went wrong, in words a user can act on (tobj's own messages are terse: "read error").
fn obj_message(e: &tobj::LoadError) -> String {
    use tobj::LoadError as E;
    match e {
        E::ReadError => "not OBJ text: this line could not be read as UTF-8 text \
            (a binary or corrupted file, or another format with an .obj name?)"
            .into(),
        E::UnrecognizedCharacter => "unrecognised character in an OBJ statement".into(),
        E::NormalParseError => "bad vertex normal (`vn` needs three numbers)".into(),
        E::TexcoordParseError => "bad texture coordinate (`vt` needs two or three numbers)".into(),
        E::FaceParseError => {
            "bad face (`f` needs three or more vertex indices, like `f 1 2 3` or `f 1/1 2/2 3/3`)"
                .into()
        }
        E::InvalidPolygon => "a face with fewer than three vertices".into(),
        E::FaceTexCoordOutOfBounds | E::FaceNormalOutOfBounds | E::FaceColorOutOfBounds => {
            "face refers to a texture coordinate, normal or colour that does not exist".into()
        }
        other => format!("OBJ statement could not be read ({other})"),
    }
}
