//! How often the certified `f64` filter of the conformal meets decides alone, and how often
//! plain `f64` signs (no error bound, no fall-back) would be wrong, on a fixed adversarial set:
//! the table of `docs/thesis.md`.
//!
//! `cargo run -p cga-experiments --release --example conformal_filter_table -- [cases per pair]`

use cga_collide::testing::conformal::filter_tallies;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    println!("| pair | cases | decided by the f64 filter | plain f64 wrong |");
    println!("|---|---|---|---|");
    for t in filter_tallies(n) {
        println!(
            "| {} | {} | {} ({:.1}%) | {} ({:.1}%) |",
            t.pair,
            t.cases,
            t.filtered,
            100.0 * t.filtered as f64 / t.cases as f64,
            t.float_wrong,
            100.0 * t.float_wrong as f64 / t.cases as f64
        );
    }
}
