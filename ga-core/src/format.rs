//! Printing multivectors in canonical blade names: `2·e1 - 0.5·e45`.
//!
//! A coefficient and its blade are joined by `·` (U+00B7), so that `2·e12` cannot be read as the
//! number `2e12` (two times ten to the twelfth).
//!
//! Used by the generated `Display` and `Debug` impls; public so hand-written types can print
//! the same way.

use core::fmt::{self, Debug, Display, Formatter, Write};

use crate::scalar::Ring;

/// Writes `c₁·b₁ ± c₂·b₂ ...` skipping zero coefficients (`0` if all are zero); the scalar part
/// is written without a blade. A negative
/// coefficient (one whose text starts with `-`) is written as a subtraction; a coefficient whose
/// text contains an operator (e.g. a polynomial) is parenthesised. The formatter's precision, if
/// any, is passed on to the coefficients.
pub fn write_terms<T: Ring + Display>(
    f: &mut Formatter<'_>,
    terms: &[(&T, &str)],
    _debug: bool,
) -> fmt::Result {
    let precision = f.precision();
    write_with(f, terms, |c, s| match precision {
        Some(p) => write!(s, "{c:.p$}"),
        None => write!(s, "{c}"),
    })
}

/// Like [`write_terms`] with the coefficients' `Debug` form.
pub fn write_terms_debug<T: Ring + Debug>(
    f: &mut Formatter<'_>,
    terms: &[(&T, &str)],
) -> fmt::Result {
    let precision = f.precision();
    write_with(f, terms, |c, s| match precision {
        Some(p) => write!(s, "{c:.p$?}"),
        None => write!(s, "{c:?}"),
    })
}

fn write_with<T: Ring>(
    f: &mut Formatter<'_>,
    terms: &[(&T, &str)],
    show: impl Fn(&T, &mut String) -> fmt::Result,
) -> fmt::Result {
    let mut first = true;
    let mut text = String::new();
    for (c, blade) in terms {
        if c.is_zero() {
            continue;
        }
        text.clear();
        show(c, &mut text)?;
        let (negative, magnitude) = match text.strip_prefix('-') {
            Some(rest) if !needs_parentheses(rest) => (true, rest),
            _ => (false, text.as_str()),
        };
        match (first, negative) {
            (true, true) => f.write_str("-")?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        first = false;
        if *blade == "1" {
            f.write_str(magnitude)?;
        } else if needs_parentheses(magnitude) {
            write!(f, "({magnitude})·{blade}")?;
        } else {
            write!(f, "{magnitude}·{blade}")?;
        }
    }
    if first {
        f.write_str("0")?;
    }
    Ok(())
}

/// A coefficient text that is not a single signed number, e.g. `x + y` or `2/3*x`.
fn needs_parentheses(text: &str) -> bool {
    text.contains([' ', '+', '*', '^', '('])
}
