//! Checks every closed form of the thesis symbolically and prints the table of verdicts.
//!
//! ```sh
//! cargo run --release -p ga-thesis              # print the table
//! cargo run --release -p ga-thesis -- --write   # also regenerate docs/thesis-derivations.md
//!                                               # and fixtures/equations.txt
//! cargo run --release -p ga-thesis -- --doc     # print the document
//! cargo run --release -p ga-thesis -- --list    # print the entry list
//! ```
#![forbid(unsafe_code)]

fn main() {
    let rows = ga_thesis::run();
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--list") {
        print!("{}", ga_thesis::equation_list(&rows));
        return;
    }
    if args.iter().any(|a| a == "--doc") {
        print!("{}", ga_thesis::document(&rows));
        return;
    }
    print!("{}", ga_thesis::table(&rows));
    if args.iter().any(|a| a == "--write") {
        let dir = env!("CARGO_MANIFEST_DIR");
        for (path, text) in [
            (
                format!("{dir}/docs/thesis-derivations.md"),
                ga_thesis::document(&rows),
            ),
            (
                format!("{dir}/fixtures/equations.txt"),
                ga_thesis::equation_list(&rows),
            ),
        ] {
            match std::fs::write(&path, text) {
                Ok(()) => println!("\nwrote {path}"),
                Err(e) => {
                    eprintln!("could not write {path}: {e}");
                    std::process::exit(1);
                }
            }
        }
    }
}
