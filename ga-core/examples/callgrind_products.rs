//! Instruction counts of the generated products against hand-written straight-line code,
//! measured with callgrind (deterministic: the same counts on an idle or a loaded machine).
//!
//! ```sh
//! cargo run --release -p ga-core --example callgrind_products
//! ```
//!
//! needs `valgrind` on the `PATH`. For every kernel of `benches/kernels/mod.rs` (each product,
//! generated and hand-written, as one product per call and as a batch loop), the example runs
//! itself under `valgrind --tool=callgrind --collect-atstart=no --toggle-collect=<function>`, so
//! that only the instructions executed inside that one function are counted, reads the total from
//! callgrind's output file, and prints instructions per product and the ratio generated /
//! hand-written as a Markdown table. Each kernel processes `REPS` batches of `BATCH` operand
//! pairs. Before measuring, every hand-written result is checked against the generated one.
//!
//! `callgrind_products run <function> <calls|batch>` runs one kernel (what callgrind is pointed
//! at); `--keep <dir>` keeps the callgrind output files there for `callgrind_annotate`.

#[path = "../benches/kernels/mod.rs"]
mod kernels;

use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use kernels::{kernels, run_all_and_check, Data, Kernel, Out, Side, BATCH};

/// Batches per measured run.
const REPS: usize = 50;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("run") if args.len() == 3 => run(&args[1], &args[2]),
        None => measure(None),
        Some("--keep") if args.len() == 2 => measure(Some(PathBuf::from(&args[1]))),
        _ => {
            eprintln!(
                "usage: callgrind_products [--keep <dir>]\n       callgrind_products run <function> <calls|batch>"
            );
            ExitCode::from(2)
        }
    }
}

/// Runs one kernel `REPS` times (the process callgrind measures).
fn run(function: &str, form: &str) -> ExitCode {
    let Some(kernel) = kernels()
        .into_iter()
        .find(|k| k.call_fn == function || k.batch_fn == function)
    else {
        eprintln!("no kernel function called {function}");
        return ExitCode::from(2);
    };
    let f = match form {
        "calls" => kernel.run_calls,
        "batch" => kernel.run_batch,
        _ => {
            eprintln!("form must be `calls` or `batch`, not {form}");
            return ExitCode::from(2);
        }
    };
    let data = Data::new();
    let mut out = Out::new();
    for _ in 0..REPS {
        f(black_box(&data), black_box(&mut out));
    }
    black_box(&out);
    ExitCode::SUCCESS
}

/// Instructions executed inside `function` while running `form` of its kernel. `also` names the
/// other side's function: when the compiler merged the two (identical code), the symbol callgrind
/// sees is that one; in a run of one kernel the other side's function is never called otherwise.
fn count(exe: &Path, dir: &Path, function: &str, also: &str, form: &str) -> Result<u64, String> {
    let file = dir.join(format!("callgrind.{function}.out"));
    let status = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg("--collect-atstart=no")
        .arg(format!("--toggle-collect=*kernels::{function}"))
        .arg(format!("--toggle-collect=*kernels::{also}"))
        .arg(format!("--callgrind-out-file={}", file.display()))
        .arg(exe)
        .args(["run", function, form])
        .stderr(std::process::Stdio::null())
        .status()
        .map_err(|e| format!("cannot run valgrind (is it installed?): {e}"))?;
    if !status.success() {
        return Err(format!("valgrind on {function} failed: {status}"));
    }
    let text = std::fs::read_to_string(&file)
        .map_err(|e| format!("cannot read {}: {e}", file.display()))?;
    let total = text
        .lines()
        .find_map(|l| {
            l.strip_prefix("totals:")
                .or_else(|| l.strip_prefix("summary:"))
        })
        .and_then(|v| v.split_whitespace().next()?.parse::<u64>().ok())
        .ok_or_else(|| format!("no totals line in {}", file.display()))?;
    if total == 0 {
        return Err(format!(
            "callgrind counted nothing in {function}: the toggle pattern matched no function"
        ));
    }
    Ok(total)
}

fn measure(keep: Option<PathBuf>) -> ExitCode {
    // The baselines compute what the generated code computes.
    run_all_and_check(&Data::new());
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            eprintln!("cannot find this executable: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = keep.unwrap_or_else(|| std::env::temp_dir().join("ga-core-callgrind"));
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("cannot create {}: {e}", dir.display());
        return ExitCode::FAILURE;
    }
    let products = (REPS * BATCH) as f64;
    println!(
        "callgrind instructions per product ({REPS} batches of {BATCH}; `calls`: one product per \
         #[inline(never)] call, `batch`: product inlined in a loop writing an output slice)\n"
    );
    println!("| product | form | generated | hand-written | generated / hand-written |");
    println!("|---|---|---:|---:|---:|");
    let all = kernels();
    let pairs: Vec<(&Kernel, &Kernel)> = all
        .iter()
        .filter(|k| k.side == Side::Generated)
        .filter_map(|g| {
            all.iter()
                .find(|h| h.side == Side::Hand && h.product == g.product)
                .map(|h| (g, h))
        })
        .collect();
    for (g, h) in pairs {
        for (form, gf, hf, merged) in [
            ("calls", g.call_fn, h.call_fn, g.call_addr == h.call_addr),
            (
                "batch",
                g.batch_fn,
                h.batch_fn,
                g.batch_addr == h.batch_addr,
            ),
        ] {
            let counts = (
                count(&exe, &dir, gf, hf, form),
                count(&exe, &dir, hf, gf, form),
            );
            let (gi, hi) = match counts {
                (Ok(gi), Ok(hi)) => (gi, hi),
                (Err(e), _) | (_, Err(e)) => {
                    eprintln!("{e}");
                    return ExitCode::FAILURE;
                }
            };
            let note = if merged {
                " (identical code: the compiler merged the two functions)"
            } else {
                ""
            };
            println!(
                "| {}{note} | {form} | {:.2} | {:.2} | {:.3} |",
                g.product,
                gi as f64 / products,
                hi as f64 / products,
                gi as f64 / hi as f64
            );
        }
    }
    ExitCode::SUCCESS
}
