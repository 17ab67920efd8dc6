//! Finding and reading the programs named on the command line.

use std::io::{Read, Seek, Write};
use std::ops::Deref;
use std::os::fd::AsFd;
use std::os::unix::fs::OpenOptionsExt;
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
/// and `.arc` archives
/// (any case, recursively, sorted); a file is taken whatever its extension.
/// Every file and directory is taken once, by its device and inode, so
/// symlinks that loop (`a -> .`, `up -> ..`) or name a file twice do not
/// repeat it.
///
/// A directory that holds no program is an error unless `allow_empty`: a
/// CI run over a mistyped or emptied folder must not pass in silence.
pub fn expand(
    paths: &[PathBuf],
    allow_empty: bool,
) -> Result<Vec<Result<PathBuf, CliError>>, CliError> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    for path in paths {
        if path.is_dir() {
            let before = out.len();
            walk(path, &mut seen, &mut out);
            if out.len() == before && !allow_empty {
                return Err(CliError::NoPrograms { path: path.clone() });
            }
        } else if first_time(path, &mut seen) {
            out.push(Ok(path.clone()));
        }
    }
    Ok(out)
}

/// Whether `path` has not been met before (a path that cannot be read is
/// taken, to be reported when it is read).
fn first_time(path: &Path, seen: &mut HashSet<(u64, u64)>) -> bool {
    match std::fs::metadata(path) {
        Ok(metadata) => seen.insert(identity(&metadata)),
        Err(_) => true,
    }
}

/// Standard input: read whole while it is small; from [`MAPPED_FROM`] bytes
/// on, what came and what follows go to an unnamed file in the temporary
/// directory (`TMPDIR`), which is mapped as a large program is: a program
/// piped in takes no more of the process's own memory than one read from a
/// file. The file is removed from its directory as soon as it is
/// made, so nothing is left behind, whatever ends the run. A file
/// redirected to stdin is mapped as it is.
fn read_stdin() -> std::io::Result<Bytes> {
    let mut stdin = std::io::stdin().lock();
    // A file redirected to stdin (`< PART.MPF`), unread so far: map it.
    let mut file = std::fs::File::from(stdin.as_fd().try_clone_to_owned()?);
    if let (Ok(metadata), Ok(0)) = (file.metadata(), file.stream_position()) {
        if metadata.is_file() && metadata.len() >= MAPPED_FROM {
            return Ok(Bytes::Mapped(Mapped::new(&file)?));
        }
    }
    let mut head = Vec::new();
    (&mut stdin).take(MAPPED_FROM).read_to_end(&mut head)?;
    if (head.len() as u64) < MAPPED_FROM {
        return Ok(Bytes::Read(head));
    }
    let mut spool = unnamed_file()?;
    spool.write_all(&head)?;
    drop(head);
    std::io::copy(&mut stdin, &mut spool)?;
    Ok(Bytes::Mapped(Mapped::new(&spool)?))
}

/// A new file in the temporary directory, already removed from it.
fn unnamed_file() -> std::io::Result<std::fs::File> {
    let dir = std::env::temp_dir();
    for _ in 0..64 {
        let path = dir.join(format!(
            ".sinuprep-stdin-{:016x}",
            crate::cli::output::random()
        ));
        match std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create_new(true)
            .mode(0o600)
            .open(&path)
        {
            Ok(file) => {
                std::fs::remove_file(&path)?;
                return Ok(file);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no file could be made in the temporary directory for standard input",
    ))
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
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
        ["mpf", "spf", "arc"]
            .iter()
            .any(|x| e.eq_ignore_ascii_case(x))
    })
}

/// Reads a file, or stdin for `-`; a file of [`MAPPED_FROM`] bytes or more
/// is mapped instead, and so is stdin from that size on, spooled to a file.
pub fn read(path: &Path) -> Result<SourceFile, CliError> {
    if path == Path::new("-") {
        let bytes = read_stdin().map_err(|source| CliError::Read {
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
