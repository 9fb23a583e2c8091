//! The thesis's formulas, machine-checked: every closed form of Cap. II and Apéndice A of Roa's
//! thesis, as printed, against the same quantity computed with `ga_core`'s generated Cl(4,1)
//! products over exact symbolic polynomials ([`ga_core::symbolic::Poly`]).
//!
//! This is tooling for one document, kept out of the published `ga-core` crate: `ga-core` offers
//! the symbolic scalar and its parser ([`ga_core::symbolic::parse::parse_with`]), the generated products
//! and the dense reference; this package adds the thesis's notation and the checks.
//!
//! ```sh
//! cargo run --release -p ga-thesis              # print the table of verdicts
//! cargo run --release -p ga-thesis -- --write   # also regenerate docs/thesis-derivations.md
//!                                               # and fixtures/equations.txt
//! cargo run --release -p ga-thesis -- --doc     # print the document
//! cargo run --release -p ga-thesis -- --list    # print the entry list
//! ```
//!
//! | module | what it holds |
//! |---|---|
//! | [`multivector`] | [`SymMultivector`]: a sparse Cl(4,1) multivector over `Poly` |
//! | [`notation`] | the thesis's blade names, signs and print order ([`Notation`]) |
//! | `printing` | [`SymMultivector`] printed in either notation, plain or LaTeX |
//! | [`scope`] | [`Scope`]: reads expressions in the thesis's notation |
//! | [`fixture`] | the transcribed formulas ([`FORMULAS`]) and their format ([`Fixture`]) |
//! | `reading` | the printed or corrected reading of an entry (its definitions and formulas) |
//! | `corrections` | the errata ([`ERRATA`]) and their corrections |
//! | `products`, `objects` | the generated products, and the points and forms built with them |
//! | `checks`, `meets`, `defs`, `rules` | the checks, one per kind of entry, dispatched by a table |
//! | `verdict`, `report` | the verdicts ([`Verdict`], [`Row`]) and the report built from them |
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod fixture;
pub mod multivector;
pub mod notation;
pub mod scope;

mod checks;
mod corrections;
mod defs;
mod meets;
mod objects;
mod printing;
mod products;
mod reading;
mod report;
mod rules;
mod verdict;

pub use checks::run;
pub use corrections::ERRATA;
pub use fixture::{Entry, Fixture, FixtureError, FORMULAS};
pub use multivector::SymMultivector;
pub use notation::Notation;
pub use report::{category, distinct_errata, document, equation_list, numbered_range, table};
pub use scope::{Products, Scope};
pub use verdict::{compare, Comparison, Row, Verdict};

/// The committed entry list (`fixtures/equations.txt`): id, category and verdict of every entry.
pub const EQUATIONS: &str = include_str!("../fixtures/equations.txt");
