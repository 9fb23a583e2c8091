//! PLY reader (ASCII, binary little-endian and binary big-endian), hand-written.
//!
//! The `ply-rs` crate (0.1.3, unmaintained since 2020) was considered and not used: its header
//! grammar unwraps integer parses (a count that overflows panics), which breaks the rule that
//! malformed input never panics. This reader keeps what a triangle mesh needs: the `x y z`
//! properties of element `vertex` and the index list (`vertex_indices` or `vertex_index`) of
//! element `face`; every other element and property is parsed and skipped.

use nalgebra::Point3;

use super::text::{capacity, check_finite, fan};
use crate::error::{shorten, Error, Location};

type Parsed = (Vec<Point3<f64>>, Vec<[u32; 3]>);

#[derive(Debug, Clone, Copy, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

#[derive(Debug)]
enum Property {
    Scalar(Scalar, String),
    List(Scalar, Scalar, String),
}

#[derive(Debug)]
struct Element {
    name: String,
    count: u64,
    properties: Vec<Property>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Encoding {
    Ascii,
    Little,
    Big,
}

/// Where values come from: ASCII tokens or binary bytes.
trait Source {
    fn value(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, Error>;
    fn location(&self) -> Location;
}

struct AsciiSource<'a> {
    file: &'a str,
    lines: std::str::Lines<'a>,
    tokens: std::str::SplitWhitespace<'a>,
    line: usize,
}

impl Source for AsciiSource<'_> {
    fn value(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, Error> {
        let token = loop {
            if let Some(t) = self.tokens.next() {
                break t;
            }
            match self.lines.next() {
                Some(l) => {
                    self.line += 1;
                    self.tokens = l.split_whitespace();
                }
                None => {
                    return Err(Error::Truncated {
                        at: self.location(),
                        expected: what(),
                    })
                }
            }
        };
        let bad = || Error::BadNumber {
            at: Location::line(self.file, self.line),
            token: shorten(token),
            expected: match ty {
                Scalar::F32 | Scalar::F64 => "a decimal floating-point number",
                _ => "an integer",
            },
        };
        match ty {
            Scalar::F32 | Scalar::F64 => token.parse::<f64>().map_err(|_| bad()),
            _ => token.parse::<i64>().map(|v| v as f64).map_err(|_| bad()),
        }
    }

    fn location(&self) -> Location {
        Location::line(self.file, self.line.max(1))
    }
}

struct BinarySource<'a> {
    file: &'a str,
    bytes: &'a [u8],
    pos: usize,
    big: bool,
}

impl Source for BinarySource<'_> {
    fn value(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, Error> {
        let n = ty.size();
        let Some(chunk) = self.bytes.get(self.pos..self.pos + n) else {
            return Err(Error::Truncated {
                at: self.location(),
                expected: what(),
            });
        };
        self.pos += n;
        let mut b = [0u8; 8];
        b[..n].copy_from_slice(chunk);
        if self.big {
            b[..n].reverse();
        }
        Ok(match ty {
            Scalar::I8 => f64::from(b[0] as i8),
            Scalar::U8 => f64::from(b[0]),
            Scalar::I16 => f64::from(i16::from_le_bytes([b[0], b[1]])),
            Scalar::U16 => f64::from(u16::from_le_bytes([b[0], b[1]])),
            Scalar::I32 => f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            Scalar::U32 => f64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            Scalar::F32 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            Scalar::F64 => f64::from_le_bytes(b),
        })
    }

    fn location(&self) -> Location {
        Location::byte(self.file, self.pos)
    }
}

fn syntax(file: &str, line: usize, message: String) -> Error {
    Error::Syntax {
        at: Location::line(file, line),
        message,
    }
}

/// Parses the header; returns encoding, elements and the byte offset of the body.
fn header(bytes: &[u8], file: &str) -> Result<(Encoding, Vec<Element>, usize), Error> {
    let mut pos = 0;
    let mut line_no = 0;
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    loop {
        let Some(len) = bytes[pos..].iter().position(|&b| b == b'\n') else {
            return Err(Error::Truncated {
                at: Location::line(file, line_no + 1),
                expected: "`end_header`".into(),
            });
        };
        let raw = &bytes[pos..pos + len];
        pos += len + 1;
        line_no += 1;
        let line = std::str::from_utf8(raw)
            .map_err(|_| syntax(file, line_no, "PLY header line is not UTF-8 text".into()))?
            .trim();
        let mut words = line.split_whitespace();
        let keyword = words.next().unwrap_or("");
        if line_no == 1 {
            if line != "ply" {
                return Err(syntax(
                    file,
                    1,
                    "not a PLY file: first line must be `ply`".into(),
                ));
            }
            continue;
        }
        match keyword {
            "" | "comment" | "obj_info" => {}
            "format" => {
                encoding = Some(match (words.next(), words.next()) {
                    (Some("ascii"), Some(_)) => Encoding::Ascii,
                    (Some("binary_little_endian"), Some(_)) => Encoding::Little,
                    (Some("binary_big_endian"), Some(_)) => Encoding::Big,
                    _ => {
                        return Err(syntax(
                            file,
                            line_no,
                            format!("bad format line {:?}", shorten(line)),
                        ))
                    }
                });
            }
            "element" => {
                let (Some(name), Some(count)) = (words.next(), words.next()) else {
                    return Err(syntax(
                        file,
                        line_no,
                        "element line needs a name and a count".into(),
                    ));
                };
                let count = count.parse::<u64>().map_err(|_| Error::BadNumber {
                    at: Location::line(file, line_no),
                    token: shorten(count),
                    expected: "a non-negative element count",
                })?;
                elements.push(Element {
                    name: name.to_owned(),
                    count,
                    properties: Vec::new(),
                });
            }
            "property" => {
                let Some(element) = elements.last_mut() else {
                    return Err(syntax(file, line_no, "property before any element".into()));
                };
                let ty = |w: Option<&str>| {
                    w.and_then(Scalar::parse).ok_or_else(|| {
                        syntax(
                            file,
                            line_no,
                            format!("unknown property type in {:?}", shorten(line)),
                        )
                    })
                };
                let first = words.next();
                let property = if first == Some("list") {
                    let count_ty = ty(words.next())?;
                    let item_ty = ty(words.next())?;
                    if matches!(count_ty, Scalar::F32 | Scalar::F64) {
                        return Err(syntax(
                            file,
                            line_no,
                            "list count type must be an integer type".into(),
                        ));
                    }
                    Property::List(count_ty, item_ty, words.next().unwrap_or("").to_owned())
                } else {
                    Property::Scalar(ty(first)?, words.next().unwrap_or("").to_owned())
                };
                element.properties.push(property);
            }
            "end_header" => break,
            other => {
                return Err(syntax(
                    file,
                    line_no,
                    format!("unknown PLY header keyword {:?}", shorten(other)),
                ))
            }
        }
    }
    let encoding =
        encoding.ok_or_else(|| syntax(file, line_no, "PLY header has no format line".into()))?;
    Ok((encoding, elements, pos))
}

pub(crate) fn parse(bytes: &[u8], file: &str) -> Result<Parsed, Error> {
    let (encoding, elements, body) = header(bytes, file)?;
    let body_bytes = &bytes[body..];
    match encoding {
        Encoding::Ascii => {
            let text = std::str::from_utf8(body_bytes).map_err(|e| Error::Syntax {
                at: Location::byte(file, body + e.valid_up_to()),
                message: "ASCII PLY body is not UTF-8 text".into(),
            })?;
            let header_lines = bytes[..body].iter().filter(|&&b| b == b'\n').count();
            let mut source = AsciiSource {
                file,
                lines: text.lines(),
                tokens: "".split_whitespace(),
                line: header_lines,
            };
            read_body(&mut source, &elements, file, body_bytes.len())
        }
        Encoding::Little | Encoding::Big => {
            let mut source = BinarySource {
                file,
                bytes,
                pos: body,
                big: encoding == Encoding::Big,
            };
            read_body(&mut source, &elements, file, body_bytes.len())
        }
    }
}

fn read_body(
    source: &mut dyn Source,
    elements: &[Element],
    file: &str,
    body_len: usize,
) -> Result<Parsed, Error> {
    let vertex_count = elements
        .iter()
        .find(|e| e.name == "vertex")
        .map_or(0, |e| e.count);
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    let mut polygon = Vec::new();
    for element in elements {
        if element.properties.is_empty() {
            continue;
        }
        let role = match element.name.as_str() {
            "vertex" => {
                let find = |axis: &str| {
                    element
                        .properties
                        .iter()
                        .position(|p| matches!(p, Property::Scalar(_, n) if n == axis))
                        .ok_or_else(|| Error::Syntax {
                            at: Location::file(file),
                            message: format!(
                                "PLY element `vertex` has no scalar property `{axis}`"
                            ),
                        })
                };
                vertices.reserve(capacity(element.count, body_len, 3));
                Some([find("x")?, find("y")?, find("z")?])
            }
            _ => None,
        };
        let face_list = (element.name == "face")
            .then(|| {
                element.properties.iter().position(
                    |p| matches!(p, Property::List(_, _, n) if n == "vertex_indices" || n == "vertex_index"),
                )
            })
            .flatten();
        if element.name == "face" {
            if face_list.is_none() {
                return Err(Error::Syntax {
                    at: Location::file(file),
                    message: "PLY element `face` has no list property `vertex_indices`".into(),
                });
            }
            triangles.reserve(capacity(element.count, body_len, 4));
        }
        for item in 0..element.count {
            let mut xyz = [0.0f64; 3];
            let start = source.location();
            for (k, property) in element.properties.iter().enumerate() {
                let what = || format!("{} {item} of {}", element.name, element.count);
                match property {
                    Property::Scalar(ty, _) => {
                        let v = source.value(*ty, &what)?;
                        if let Some(axes) = role {
                            for (slot, &a) in xyz.iter_mut().zip(&axes) {
                                if a == k {
                                    *slot = v;
                                }
                            }
                        }
                    }
                    Property::List(count_ty, item_ty, _) => {
                        let n = source.value(*count_ty, &what)?;
                        if n < 0.0 {
                            return Err(Error::Syntax {
                                at: source.location(),
                                message: format!(
                                    "{} {item}: negative list length {n}",
                                    element.name
                                ),
                            });
                        }
                        let is_face = face_list == Some(k);
                        polygon.clear();
                        let mut j = 0.0;
                        while j < n {
                            let v = source.value(*item_ty, &what)?;
                            if is_face {
                                if !(v >= 0.0 && v < vertex_count as f64 && v.fract() == 0.0) {
                                    return Err(Error::IndexOutOfRange {
                                        at: start.clone(),
                                        face: usize::try_from(item).unwrap_or(usize::MAX),
                                        index: v as i64,
                                        vertex_count: usize::try_from(vertex_count)
                                            .unwrap_or(usize::MAX),
                                    });
                                }
                                polygon.push(v as u32);
                            }
                            j += 1.0;
                        }
                        if is_face {
                            if polygon.len() < 3 {
                                return Err(Error::Syntax {
                                    at: start.clone(),
                                    message: format!(
                                        "face {item} has {} vertices (at least 3 needed)",
                                        polygon.len()
                                    ),
                                });
                            }
                            fan(&polygon, &mut triangles);
                        }
                    }
                }
            }
            if role.is_some() {
                check_finite(xyz, vertices.len(), start)?;
                vertices.push(Point3::from(xyz));
            }
        }
    }
    Ok((vertices, triangles))
}
