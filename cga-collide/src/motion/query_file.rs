//! The CCD benchmark's query files: one query is 8 rows of `x_num,x_den,y_num,y_den,z_num,z_den`
//! (optionally a 7th column, the truth, 1 or 0): the four points at `t = 0`, then the same four
//! at `t = 1`. Vertex–face rows are `v, f0, f1, f2`; edge–edge rows `a0, a1, b0, b1`.
//!
//! Numerators and denominators may exceed 64 bits; every value must be exactly an `f64` (a
//! dyadic rational with at most 53 significant bits, as in the benchmark), else the row is
//! rejected with its line: the crate's queries take `f64` inputs as the exact numbers they
//! denote, and a value that no `f64` denotes would be silently changed.

use std::io::Read;
use std::path::Path;

use nalgebra::Point3;
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

use super::{ContactTime, MovingPoint};
use crate::error::{Error, Location};

/// Which primitives a query is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueryKind {
    /// A vertex against a triangle: points `[v, f0, f1, f2]`.
    VertexFace,
    /// An edge against an edge: points `[a0, a1, b0, b1]`.
    EdgeEdge,
}

impl QueryKind {
    /// `"vertex-face"` or `"edge-edge"` (the benchmark's folder names).
    pub fn name(self) -> &'static str {
        match self {
            QueryKind::VertexFace => "vertex-face",
            QueryKind::EdgeEdge => "edge-edge",
        }
    }

    /// The kind named by a `vertex-face` or `edge-edge` component of `path`, if any.
    pub fn from_path(path: &Path) -> Option<QueryKind> {
        path.components()
            .rev()
            .find_map(|c| match c.as_os_str().to_str() {
                Some("vertex-face") => Some(QueryKind::VertexFace),
                Some("edge-edge") => Some(QueryKind::EdgeEdge),
                _ => None,
            })
    }
}

/// One query: four moving points, and the truth when the file gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionQuery {
    /// `[v, f0, f1, f2]` or `[a0, a1, b0, b1]`, as the kind says.
    pub points: [MovingPoint; 4],
    /// Whether the primitives touch for some `t ∈ [0, 1]`, when the file says.
    pub truth: Option<bool>,
}

impl MotionQuery {
    /// Whether the primitives touch, exactly ([`super::vertex_face_touch`] or
    /// [`super::edge_edge_touch`]).
    pub fn touch(&self, kind: QueryKind) -> Result<bool, Error> {
        let p = &self.points;
        match kind {
            QueryKind::VertexFace => super::vertex_face_touch(&p[0], &[p[1], p[2], p[3]]),
            QueryKind::EdgeEdge => super::edge_edge_touch(&[p[0], p[1]], &[p[2], p[3]]),
        }
    }

    /// The earliest contact time ([`super::vertex_face_first_contact`] or
    /// [`super::edge_edge_first_contact`]).
    pub fn first_contact(
        &self,
        kind: QueryKind,
        tolerance: f64,
    ) -> Result<Option<ContactTime>, Error> {
        let p = &self.points;
        match kind {
            QueryKind::VertexFace => {
                super::vertex_face_first_contact(&p[0], &[p[1], p[2], p[3]], tolerance)
            }
            QueryKind::EdgeEdge => {
                super::edge_edge_first_contact(&[p[0], p[1]], &[p[2], p[3]], tolerance)
            }
        }
    }
}

/// Reads a query file (plain or gzip-compressed).
pub fn load_queries(path: impl AsRef<Path>) -> Result<Vec<MotionQuery>, Error> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let io = |error: std::io::Error| Error::Io {
        kind: error.kind(),
        message: error.to_string(),
        file: name.clone(),
    };
    let bytes = std::fs::read(path).map_err(io)?;
    let text = if bytes.starts_with(&[0x1f, 0x8b]) {
        let mut plain = String::new();
        flate2::read::MultiGzDecoder::new(&bytes[..])
            .read_to_string(&mut plain)
            .map_err(io)?;
        plain
    } else {
        String::from_utf8(bytes).map_err(|_| Error::Syntax {
            at: Location::file(&name),
            message: "the file is not text (expected comma-separated integers)".into(),
        })?
    };
    parse_queries(&text, &name)
}

/// Parses query rows from text; `name` is used in error messages.
pub fn parse_queries(text: &str, name: &str) -> Result<Vec<MotionQuery>, Error> {
    let mut rows: Vec<([[f64; 3]; 1], Option<bool>, usize)> = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line_number = index + 1;
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let at = || Location::line(name, line_number);
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != 6 && fields.len() != 7 {
            return Err(Error::Syntax {
                at: at(),
                message: format!(
                    "expected 6 or 7 comma-separated integers (x_num,x_den,y_num,y_den,z_num,z_den[,truth]), found {}",
                    fields.len()
                ),
            });
        }
        let mut xyz = [0.0; 3];
        for (axis, value) in xyz.iter_mut().enumerate() {
            *value = rational_to_f64(fields[2 * axis], fields[2 * axis + 1], &at)?;
        }
        let truth = match fields.get(6) {
            None => None,
            Some(&"0") => Some(false),
            Some(&"1") => Some(true),
            Some(other) => {
                return Err(Error::BadNumber {
                    at: at(),
                    token: shorten(other),
                    expected: "a truth value, 0 or 1",
                })
            }
        };
        rows.push(([xyz], truth, line_number));
    }
    if !rows.len().is_multiple_of(8) {
        return Err(Error::Truncated {
            at: Location::line(name, rows.last().map_or(1, |r| r.2)),
            expected: format!(
                "{} more row(s): a query is 8 rows (four points at t = 0, then at t = 1)",
                8 - rows.len() % 8
            ),
        });
    }
    rows.chunks(8)
        .map(|rows| {
            let truth = rows[0].1;
            if let Some(row) = rows.iter().find(|r| r.1 != truth) {
                return Err(Error::Syntax {
                    at: Location::line(name, row.2),
                    message: "the truth column differs within one query (all 8 rows must agree)"
                        .into(),
                });
            }
            let point = |i: usize| {
                let [a] = rows[i].0;
                let [b] = rows[i + 4].0;
                MovingPoint::new(Point3::from(a), Point3::from(b))
            };
            Ok(MotionQuery {
                points: [point(0), point(1), point(2), point(3)],
                truth,
            })
        })
        .collect()
}

fn shorten(token: &str) -> String {
    token.chars().take(40).collect()
}

/// `num / den` as the `f64` it must exactly be.
fn rational_to_f64(num: &str, den: &str, at: &dyn Fn() -> Location) -> Result<f64, Error> {
    let parse = |token: &str| {
        token.parse::<BigInt>().map_err(|_| Error::BadNumber {
            at: at(),
            token: shorten(token),
            expected: "an integer",
        })
    };
    let (mut num, mut den) = (parse(num)?, parse(den)?);
    if !den.is_positive() {
        return Err(Error::BadNumber {
            at: at(),
            token: shorten(&den.to_string()),
            expected: "a positive denominator",
        });
    }
    if num.is_zero() {
        return Ok(0.0);
    }
    // Reduce by common powers of two; what is left of the denominator must be 1.
    let shift = num
        .trailing_zeros()
        .unwrap_or(0)
        .min(den.trailing_zeros().unwrap_or(0));
    num >>= shift as usize;
    den >>= shift as usize;
    let den_twos = den.trailing_zeros().unwrap_or(0);
    let not_f64 = || {
        Error::Syntax {
        at: at(),
        message: format!(
            "the value {num}/{den} is not exactly an f64 (it needs a power-of-two denominator and at most 53 significant bits)"
        ),
    }
    };
    if den != (BigInt::from(1) << den_twos as usize) || num.bits() > 53 || den_twos > 1074 + 53 {
        return Err(not_f64());
    }
    let mut value = num.to_f64().ok_or_else(not_f64)?;
    let mut k = den_twos as i32;
    while k > 0 {
        let step = k.min(600);
        value *= 2f64.powi(-step);
        k -= step;
    }
    // Check that no bit was lost to the subnormal range.
    let mut back = value;
    let mut k = den_twos as i32;
    while k > 0 {
        let step = k.min(600);
        back *= 2f64.powi(step);
        k -= step;
    }
    if back != num.to_f64().unwrap_or(f64::NAN) {
        return Err(not_f64());
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_rows_and_rejects_what_is_not_an_f64() {
        let row = "1,2,-3,4,0,1,1\n";
        let text = row.repeat(8);
        let q = parse_queries(&text, "q.csv").unwrap();
        assert_eq!(q.len(), 1);
        assert_eq!(q[0].points[0].start, Point3::new(0.5, -0.75, 0.0));
        assert_eq!(q[0].truth, Some(true));
        let big = format!("1,{},0,1,0,1\n", BigInt::from(1) << 111usize).repeat(8);
        assert_eq!(
            parse_queries(&big, "q").unwrap()[0].points[0].end.x,
            2f64.powi(-111)
        );
        let third = "1,3,0,1,0,1\n".repeat(8);
        let e = parse_queries(&third, "q.csv").unwrap_err().to_string();
        assert!(
            e.contains("q.csv:1") && e.contains("not exactly an f64"),
            "{e}"
        );
        let short = row.repeat(7);
        assert!(parse_queries(&short, "q")
            .unwrap_err()
            .to_string()
            .contains("truncated"));
        let bad = "1,2,x,4,0,1\n".repeat(8);
        assert!(parse_queries(&bad, "q")
            .unwrap_err()
            .to_string()
            .contains("bad number"));
        let zero_den = "1,0,0,1,0,1\n".repeat(8);
        assert!(parse_queries(&zero_den, "q").is_err());
    }
}
