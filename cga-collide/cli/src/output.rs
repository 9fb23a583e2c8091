//! Output files (`--image`, `--pairs`, `--contacts`, `-o`, ...), checked before any work: a run
//! that would only fail at the end, after minutes of work, fails at once instead; and written
//! with errors that name the option and the file.

use std::fs::{self, OpenOptions};
use std::io::{BufWriter, Write as _};
use std::path::Path;

use anyhow::{bail, Context, Result};

/// Checks that the output file `path` of option `flag` can be written: the name ends in
/// `.{extension}` when one is required (the format written), it is not a directory, its
/// directory exists, and the file can be opened for writing. An existing file is left as it is
/// (it is overwritten only by the run); a new one is created and removed again.
pub fn check(flag: &str, path: &Path, extension: Option<&str>) -> Result<()> {
    let shown = path.display();
    if let Some(ext) = extension {
        let given = path.extension().and_then(|e| e.to_str());
        if !given.is_some_and(|g| g.eq_ignore_ascii_case(ext)) {
            bail!(
                "{flag} {shown}: the file is written as {}, so its name must end in .{ext} \
                 (e.g. {flag} out.{ext}); {}",
                ext.to_ascii_uppercase(),
                match given {
                    Some(g) => format!("other formats (.{g}) are not supported"),
                    None => "the name has no extension".to_owned(),
                }
            );
        }
    }
    if path.is_dir() {
        bail!("{flag} {shown}: is a directory; give a file name");
    }
    let parent = path.parent().filter(|p| !p.as_os_str().is_empty());
    if let Some(dir) = parent {
        if !dir.is_dir() {
            bail!(
                "{flag} {shown}: the directory {} does not exist; create it first, or give \
                 another path",
                dir.display()
            );
        }
    }
    let existed = path.exists();
    let opened = if existed {
        OpenOptions::new().append(true).open(path)
    } else {
        OpenOptions::new().write(true).create_new(true).open(path)
    };
    match opened {
        Ok(file) => {
            drop(file);
            if !existed {
                // Best effort: the run writes it again at the end.
                let _ = fs::remove_file(path);
            }
            Ok(())
        }
        Err(e) => bail!("{flag} {shown}: cannot create the file: {e}"),
    }
}

/// [`check`] for an optional output.
pub fn check_opt(flag: &str, path: Option<&Path>, extension: Option<&str>) -> Result<()> {
    path.map_or(Ok(()), |p| check(flag, p, extension))
}

/// Writes `lines` to the output file `path` of option `flag`, one per line; an error (at
/// creation, at any write, at the final flush) names the option and the file: `--pairs
/// /proc/version: cannot write the file: Input/output error (os error 5)`.
pub fn write_lines(flag: &str, path: &Path, lines: impl Iterator<Item = String>) -> Result<()> {
    let failed = |what: &str| format!("{flag} {}: cannot {what} the file", path.display());
    let file = fs::File::create(path).with_context(|| failed("create"))?;
    let mut out = BufWriter::new(file);
    for line in lines {
        writeln!(out, "{line}").with_context(|| failed("write"))?;
    }
    out.flush().with_context(|| failed("write"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_outputs_are_named_with_their_flag() {
        let dir = std::env::temp_dir().join(format!("cga-output-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let e = check("--image", &dir.join("a.jpg"), Some("png")).unwrap_err();
        assert!(e.to_string().contains("--image") && e.to_string().contains(".png"));
        let e = check("--pairs", &dir.join("no/such/p.txt"), None).unwrap_err();
        assert!(e.to_string().contains("does not exist"), "{e}");
        let e = check("--pairs", &dir, None).unwrap_err();
        assert!(e.to_string().contains("is a directory"), "{e}");
        let ok = dir.join("p.txt");
        check("--pairs", &ok, None).unwrap();
        assert!(!ok.exists(), "the check leaves no file behind");
        check("--image", &dir.join("x.PNG"), Some("png")).unwrap();
        fs::remove_dir_all(&dir).unwrap();
    }
}
