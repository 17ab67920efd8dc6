//! Finding and reading the programs named on the command line.

use std::io::Read;
use std::ops::Deref;
use std::path::{Path, PathBuf};

use crate::cli::error::CliError;
use crate::cli::mapped::{Mapped, MAPPED_FROM};
use std::collections::HashSet;

/// A program's name for reports, and its bytes.
pub struct SourceFile {
    pub name: String,
    pub bytes: Bytes,
}

/// A program's bytes: read into memory, or mapped if the file is large.
pub enum Bytes {
    Read(Vec<u8>),
    Mapped(Mapped),
}

impl Bytes {
    /// Until the guard is dropped, this thread's reads of mapped bytes give
    /// their pages back as they move on (see `cli::mapped`).
    pub fn watch_reads(&self) -> Option<crate::pages::Watching> {
        match self {
            Bytes::Read(_) => None,
            Bytes::Mapped(mapped) => Some(mapped.watch_reads()),
        }
    }
}

impl Deref for Bytes {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        match self {
            Bytes::Read(bytes) => bytes,
            Bytes::Mapped(mapped) => mapped,
        }
    }
}

/// Expands the command-line paths: a directory yields its `.mpf`/`.spf` files
/// (any case, recursively, sorted); a file is taken whatever its extension.
/// Every file and directory is taken once, by its device and inode, so
/// symlinks that loop (`a -> .`, `up -> ..`) or name a file twice do not
/// repeat it.
pub fn expand(paths: &[PathBuf]) -> Vec<Result<PathBuf, CliError>> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    for path in paths {
        if path.is_dir() {
            walk(path, &mut seen, &mut out);
        } else if first_time(path, &mut seen) {
            out.push(Ok(path.clone()));
        }
    }
    out
}

/// Whether `path` has not been met before (a path that cannot be read is
/// taken, to be reported when it is read).
fn first_time(path: &Path, seen: &mut HashSet<(u64, u64)>) -> bool {
    match std::fs::metadata(path) {
        Ok(metadata) => seen.insert(identity(&metadata)),
        Err(_) => true,
    }
}

/// A file's identity: device and inode.
pub fn identity(metadata: &std::fs::Metadata) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    (metadata.dev(), metadata.ino())
}

fn walk(dir: &Path, seen: &mut HashSet<(u64, u64)>, out: &mut Vec<Result<PathBuf, CliError>>) {
    if !first_time(dir, seen) {
        return;
    }
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
            walk(&path, seen, out);
        } else if is_program(&path) && first_time(&path, seen) {
            out.push(Ok(path));
        }
    }
}

fn is_program(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("mpf") || e.eq_ignore_ascii_case("spf"))
}

/// Reads a file, or stdin for `-`; a file of [`MAPPED_FROM`] bytes or more
/// is mapped instead (stdin is read whole).
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
            bytes: Bytes::Read(bytes),
        });
    }
    if path.is_dir() {
        return Err(CliError::IsDirectory {
            path: path.to_path_buf(),
        });
    }
    let fail = |source| CliError::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut file = std::fs::File::open(path).map_err(fail)?;
    let metadata = file.metadata().map_err(fail)?;
    let bytes = if metadata.is_file() && metadata.len() >= MAPPED_FROM {
        Bytes::Mapped(Mapped::new(&file).map_err(fail)?)
    } else {
        let mut bytes = Vec::with_capacity(metadata.len().try_into().unwrap_or(0));
        file.read_to_end(&mut bytes).map_err(fail)?;
        Bytes::Read(bytes)
    };
    Ok(SourceFile {
        name: path.display().to_string(),
        bytes,
    })
}
