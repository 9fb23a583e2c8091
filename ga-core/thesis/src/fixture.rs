//! The fixture: the thesis's formulas as printed, in a line-based text format.
//!
//! Transcribing is kept apart from checking: [`FORMULAS`] holds every equation as the thesis
//! prints it (points, `let` definitions of auxiliary symbols, the printed steps, the cases of a
//! rule), and [`Fixture::parse`] reads it without interpreting the expressions. Which
//! definitions an entry sees is the reading's business (`Reading::scope`, printed or corrected).

/// The fixture of transcribed formulas, compiled in (`fixtures/formulas.txt`).
pub const FORMULAS: &str = include_str!("../fixtures/formulas.txt");

/// One entry of a formula fixture: an equation of the thesis as printed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The equation number (`II.53`).
    pub id: String,
    /// A short title.
    pub title: String,
    /// The `key = value` fields in file order (`source`, `kind`, `formula`, `cases`, `note`,
    /// `uses`); continuation lines are joined with a space.
    pub fields: Vec<(String, String)>,
    /// The auxiliary symbols defined by `let` lines, in order.
    pub lets: Vec<(String, String)>,
    /// The 1-based line of the `[ID]` header.
    pub line: usize,
}

impl Entry {
    /// The ids in the `uses` field, in order.
    pub fn uses(&self) -> Vec<String> {
        self.field("uses")
            .map(|u| {
                u.split(',')
                    .map(|s| s.trim().to_string())
                    .filter(|s| !s.is_empty())
                    .collect()
            })
            .unwrap_or_default()
    }
    /// The first value of a field.
    pub fn field(&self, key: &str) -> Option<&str> {
        self.fields
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// Errors reading a fixture.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FixtureError {
    /// A line that is not a header, a `key = value`, a `let`, a `point` or a continuation.
    #[error("line {line}: {message}")]
    Syntax {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// `uses` names an entry that does not exist.
    #[error("entry {entry} uses unknown entry {missing}; define an entry `[{missing}]` in the fixture or fix the `uses` field")]
    UnknownEntry {
        /// The entry with the `uses` field.
        entry: String,
        /// The missing id.
        missing: String,
    },
}

/// A fixture of transcribed formulas (format documented at the top of
/// `ga-core/thesis/fixtures/formulas.txt`).
#[derive(Clone, Debug, Default)]
pub struct Fixture {
    /// Declared points `(name, [coordinate variables])`.
    pub points: Vec<(String, [String; 3])>,
    /// The entries in file order.
    pub entries: Vec<Entry>,
}

impl Fixture {
    /// Parses the fixture text.
    ///
    /// ```
    /// use ga_thesis::Fixture;
    /// let f = Fixture::parse("point x = a1 a2 a3\n[E1] A point\nformula = 2x + x^2 n\n  - nbar\n").unwrap();
    /// assert_eq!(f.entries[0].field("formula"), Some("2x + x^2 n - nbar"));
    /// ```
    pub fn parse(text: &str) -> Result<Fixture, FixtureError> {
        let mut fx = Fixture::default();
        // Target of continuation lines: (is_let, index).
        let mut last: Option<(bool, usize)> = None;
        for (i, raw) in text.lines().enumerate() {
            let line_no = i + 1;
            let syntax = |m: &str| FixtureError::Syntax {
                line: line_no,
                message: m.to_string(),
            };
            let trimmed = raw.trim();
            if trimmed.is_empty() || trimmed.starts_with('#') {
                continue;
            }
            if raw.starts_with(char::is_whitespace) {
                let entry = fx
                    .entries
                    .last_mut()
                    .ok_or_else(|| syntax("continuation line outside an entry"))?;
                let target = match last {
                    Some((true, k)) => &mut entry.lets[k].1,
                    Some((false, k)) => &mut entry.fields[k].1,
                    None => return Err(syntax("continuation line without a key")),
                };
                target.push(' ');
                target.push_str(trimmed);
                continue;
            }
            if let Some(rest) = trimmed.strip_prefix('[') {
                let (id, title) = rest
                    .split_once(']')
                    .ok_or_else(|| syntax("header without `]`"))?;
                fx.entries.push(Entry {
                    id: id.trim().to_string(),
                    title: title.trim().to_string(),
                    fields: Vec::new(),
                    lets: Vec::new(),
                    line: line_no,
                });
                last = None;
                continue;
            }
            if let Some(rest) = trimmed.strip_prefix("point ") {
                let (name, coords) = rest
                    .split_once('=')
                    .ok_or_else(|| syntax("`point NAME = C1 C2 C3` expected"))?;
                let c: Vec<&str> = coords.split_whitespace().collect();
                if c.len() != 3 {
                    return Err(syntax("a point needs three coordinate names"));
                }
                fx.points.push((
                    name.trim().to_string(),
                    [c[0].to_string(), c[1].to_string(), c[2].to_string()],
                ));
                last = None;
                continue;
            }
            let entry = fx
                .entries
                .last_mut()
                .ok_or_else(|| syntax("field outside an entry"))?;
            if let Some(rest) = trimmed.strip_prefix("let ") {
                let (name, expr) = rest
                    .split_once('=')
                    .ok_or_else(|| syntax("`let NAME = EXPR` expected"))?;
                entry
                    .lets
                    .push((name.trim().to_string(), expr.trim().to_string()));
                last = Some((true, entry.lets.len() - 1));
                continue;
            }
            let (key, value) = trimmed
                .split_once('=')
                .ok_or_else(|| syntax("`key = value` expected"))?;
            entry
                .fields
                .push((key.trim().to_string(), value.trim().to_string()));
            last = Some((false, entry.fields.len() - 1));
        }
        for e in &fx.entries {
            for u in e.uses() {
                if fx.entry(&u).is_none() {
                    return Err(FixtureError::UnknownEntry {
                        entry: e.id.clone(),
                        missing: u,
                    });
                }
            }
        }
        Ok(fx)
    }

    /// The entry with this id.
    pub fn entry(&self, id: &str) -> Option<&Entry> {
        self.entries.iter().find(|e| e.id == id)
    }
}
