//! Finding and reading the programs named on the command line.

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::cli::error::CliError;

/// A program's name for reports, and its bytes.
pub struct SourceFile {
    pub name: String,
    pub bytes: Vec<u8>,
}

/// Expands the command-line paths: a directory yields its `.mpf`/`.spf` files
/// (any case, recursively, sorted); a file is taken whatever its extension.
pub fn expand(paths: &[PathBuf]) -> Vec<Result<PathBuf, CliError>> {
    let mut out = Vec::new();
    for path in paths {
        if path.is_dir() {
            walk(path, &mut out);
        } else {
            out.push(Ok(path.clone()));
        }
    }
    out
}

fn walk(dir: &Path, out: &mut Vec<Result<PathBuf, CliError>>) {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(source) => {
            return out.push(Err(CliError::Read {
                path: dir.to_path_buf(),
                source,
            }))
        }
    };
    let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    for path in paths {
        if path.is_dir() {
            walk(&path, out);
        } else if is_program(&path) {
            out.push(Ok(path));
        }
    }
}

fn is_program(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("mpf") || e.eq_ignore_ascii_case("spf"))
}

/// Reads a file, or stdin for `-`.
pub fn read(path: &Path) -> Result<SourceFile, CliError> {
    if path == Path::new("-") {
        let mut bytes = Vec::new();
        std::io::stdin()
            .read_to_end(&mut bytes)
            .map_err(|source| CliError::Read {
                path: path.to_path_buf(),
                source,
            })?;
        return Ok(SourceFile {
            name: "<stdin>".to_string(),
            bytes,
        });
    }
    if path.is_dir() {
        return Err(CliError::IsDirectory {
            path: path.to_path_buf(),
        });
    }
    let bytes = std::fs::read(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    Ok(SourceFile {
        name: path.display().to_string(),
        bytes,
    })
}
