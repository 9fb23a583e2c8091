//! Numbers in text output: the shortest text that reads back as the same `f64`, in plain decimal
//! or scientific notation, whichever is shorter (`1e-150`, not a 150-digit decimal; `0.25`, not
//! `2.5e-1`). JSON output is left to `serde_json`, whose numbers are valid JSON already.

/// `x` as the shorter of Rust's shortest round-trip decimal (`{}`) and scientific (`{:e}`)
/// forms; the decimal on a tie. Both read back as exactly `x`.
pub fn short(x: f64) -> String {
    let plain = x.to_string();
    let scientific = format!("{x:e}");
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}

/// Three coordinates as `[x, y, z]`, each [`short`].
pub fn point(p: [f64; 3]) -> String {
    format!("[{}, {}, {}]", short(p[0]), short(p[1]), short(p[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shorter_form_that_reads_back_exactly() {
        for (x, want) in [
            (1e-150, "1e-150"),
            (0.25, "0.25"),
            (100.0, "100"),
            (1e300, "1e300"),
            (-2.5e-7, "-2.5e-7"),
            (0.0, "0"),
            (f64::INFINITY, "inf"),
        ] {
            assert_eq!(short(x), want);
        }
        for x in [
            0.1 + 0.2,
            1.0 / 3.0,
            6.02214076e23,
            f64::MIN_POSITIVE,
            5e-324,
        ] {
            assert_eq!(short(x).parse::<f64>(), Ok(x));
        }
        assert_eq!(point([1e-150, 0.5, -3.0]), "[1e-150, 0.5, -3]");
    }
}
