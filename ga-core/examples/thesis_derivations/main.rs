//! Checks every closed form of the thesis symbolically and prints the table of verdicts.
//!
//! ```sh
//! cargo run --release -p ga-core --example thesis_derivations            # print the table
//! cargo run --release -p ga-core --example thesis_derivations -- --write # also regenerate
//!                                                      # ga-core/docs/thesis-derivations.md
//! cargo run --release -p ga-core --example thesis_derivations -- --doc   # print the document
//! cargo run --release -p ga-core --example thesis_derivations -- --list  # print the entry list
//!                                             # (ga-core/tests/fixtures/thesis_equations.txt)
//! ```

mod checks;

fn main() {
    let rows = checks::run();
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--list") {
        print!("{}", checks::equation_list(&rows));
        return;
    }
    if args.iter().any(|a| a == "--doc") {
        print!("{}", checks::document(&rows));
        return;
    }
    print!("{}", checks::table(&rows));
    if args.iter().any(|a| a == "--write") {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/thesis-derivations.md");
        match std::fs::write(path, checks::document(&rows)) {
            Ok(()) => println!("\nwrote {path}"),
            Err(e) => {
                eprintln!("could not write {path}: {e}");
                std::process::exit(1);
            }
        }
    }
}
