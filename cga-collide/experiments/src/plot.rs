//! Grouped bar charts as standalone SVG text (no dependencies, no fonts to install): the plots
//! of `cga-experiment double-spheres` and of the hierarchy comparison.
//!
//! ```
//! use cga_experiments::plot::{svg_bar_charts, BarChart};
//!
//! let svg = svg_bar_charts(&[BarChart {
//!     title: "Mean query time (µs)".into(),
//!     groups: vec!["cube – cube".into(), "octahedron – diamond".into()],
//!     series: vec![("ours".into(), vec![0.4, 1.2]), ("paper".into(), vec![3.9, 1.8])],
//! }]);
//! assert!(svg.starts_with("<svg") && svg.matches("<rect").count() >= 4);
//! ```

use std::fmt::Write as _;

/// One chart: groups along the horizontal axis, one bar per series in each group.
#[derive(Debug, Clone, PartialEq)]
pub struct BarChart {
    /// The title above the chart.
    pub title: String,
    /// The group labels (a `\n` starts a new line).
    pub groups: Vec<String>,
    /// `(name, one value per group)`; non-finite values are left out.
    pub series: Vec<(String, Vec<f64>)>,
}

/// The charts stacked vertically in one SVG document.
pub fn svg_bar_charts(charts: &[BarChart]) -> String {
    let mut body = String::new();
    let mut y = 0.0;
    for c in charts {
        let (s, bottom) = bar_chart(&c.title, &c.groups, &c.series, y);
        body.push_str(&s);
        y = bottom + 30.0;
    }
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{W}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n{body}</svg>\n",
        h = y - 20.0
    )
}

const W: f64 = 980.0;
const COLORS: [&str; 8] = [
    "#7f7f7f", "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
];

/// A grouped bar chart starting at height `y0`; returns the SVG and its bottom.
fn bar_chart(
    title: &str,
    groups: &[String],
    series: &[(String, Vec<f64>)],
    y0: f64,
) -> (String, f64) {
    let mut s = String::new();
    let (left, plot_h, top) = (60.0, 220.0, y0 + 40.0);
    let max = series
        .iter()
        .flat_map(|(_, v)| v.iter().copied())
        .filter(|x| x.is_finite())
        .fold(0.0f64, f64::max)
        .max(1e-9);
    let scale = plot_h / (max * 1.1);
    let group_w = (W - left - 20.0) / groups.len().max(1) as f64;
    let bar_w = (group_w - 12.0) / series.len().max(1) as f64;
    let _ = writeln!(
        s,
        "<text x=\"{left}\" y=\"{}\" font-size=\"15\">{}</text>",
        y0 + 20.0,
        escape(title)
    );
    let base = top + plot_h;
    let _ = writeln!(
        s,
        "<line x1=\"{left}\" y1=\"{base}\" x2=\"{}\" y2=\"{base}\" stroke=\"black\"/>",
        W - 20.0
    );
    for tick in 0..=4 {
        let v = max * 1.1 * tick as f64 / 4.0;
        let y = base - v * scale;
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.3}</text><line x1=\"{left}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#ddd\"/>",
            left - 4.0,
            y + 4.0,
            round_label(v),
            W - 20.0
        );
    }
    for (g, name) in groups.iter().enumerate() {
        let gx = left + g as f64 * group_w + 6.0;
        for (k, (_, values)) in series.iter().enumerate() {
            let v = values.get(g).copied().unwrap_or(f64::NAN);
            if !v.is_finite() {
                continue;
            }
            let h = v * scale;
            let _ = writeln!(
                s,
                "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{}\"><title>{}: {:.3}</title></rect>",
                gx + k as f64 * bar_w,
                base - h,
                bar_w.max(1.0),
                h,
                COLORS[k % COLORS.len()],
                escape(&series[k].0),
                v
            );
        }
        // A label may hold line breaks (`\n`): one text line each.
        let x = gx + group_w / 2.0 - 6.0;
        for (k, line) in name.lines().enumerate() {
            let _ = writeln!(
                s,
                "<text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"10\">{}</text>",
                base + 14.0 + 12.0 * k as f64,
                escape(line)
            );
        }
    }
    let label_lines = groups.iter().map(|g| g.lines().count()).max().unwrap_or(1) as f64;
    let mut ly = base + 22.0 + 12.0 * label_lines;
    let mut lx = left;
    for (k, (label, _)) in series.iter().enumerate() {
        if lx > W - 200.0 {
            lx = left;
            ly += 16.0;
        }
        let _ = writeln!(
            s,
            "<rect x=\"{lx}\" y=\"{}\" width=\"10\" height=\"10\" fill=\"{}\"/><text x=\"{}\" y=\"{}\">{}</text>",
            ly - 9.0,
            COLORS[k % COLORS.len()],
            lx + 14.0,
            ly,
            escape(label)
        );
        lx += 190.0;
    }
    (s, ly + 10.0)
}

fn round_label(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
