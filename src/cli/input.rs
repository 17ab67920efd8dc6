//! Reading the programs named on the command line or found by a walk
//! (`walk` finds them).

use std::io::{Read, Seek, Write};
use std::ops::Deref;
use std::path::{Path, PathBuf};

use crate::cli::error::CliError;
use crate::cli::mapped::{Mapped, MAPPED_FROM};
use crate::cli::platform::{self, identity};

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

/// A program to read: named on the command line, or found by a directory
/// walk.
pub struct Found {
    pub path: PathBuf,
    /// Found by a walk: read only as a regular file, and not through a link
    /// unless links are followed. A file named is read as it is named,
    /// through a link, or from a FIFO as stdin is.
    walked: Option<Links>,
}

impl Found {
    /// A path named on the command line.
    pub fn named(path: PathBuf) -> Self {
        Self { path, walked: None }
    }

    /// A file a walk found, which it reached following links or not.
    pub fn walked(path: PathBuf, links: Links) -> Self {
        Self {
            path,
            walked: Some(links),
        }
    }

    /// Whether a walk found it (it was not named).
    pub fn was_walked(&self) -> bool {
        self.walked.is_some()
    }
}

/// How much of a file [`binary`] looks at: as git's `buffer_is_binary`.
const BINARY_HEAD: usize = 8 << 10;

/// Whether `bytes` are a binary file (an executable, an image, a document)
/// rather than a program: a NUL byte in the first 8 KiB, as ripgrep and git
/// decide. No NC program holds one; linted as text, an executable gave
/// 18,845 findings. A binary archive (its own mark) is read as one.
pub fn binary(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(BINARY_HEAD)];
    memchr::memchr(0, head).is_some() && !crate::archive::binary::is_binary(bytes)
}

/// Whether `bytes` begin with a UTF-16 byte order mark (FF FE or FE FF):
/// a program an editor saved as UTF-16, whose every other byte is NUL.
pub fn utf16(bytes: &[u8]) -> bool {
    bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF])
}

/// A binary file met by any command: a walk skips it, with a note (`Ok`);
/// one named on the command line is an error, since the program asked for
/// is none. A UTF-16 text is named as such, with what to do.
pub fn skip_binary(found: &Found, name: &str, bytes: &[u8]) -> Result<String, CliError> {
    let utf16 = utf16(bytes);
    if found.was_walked() {
        let name = crate::cli::render::printable(name);
        let what = if utf16 {
            "a UTF-16 text, which the control does not read (save it as 8-bit text)"
        } else {
            "a binary file (NUL bytes), not a program"
        };
        Ok(format!("note: skipped {name}: {what}\n"))
    } else if utf16 {
        Err(CliError::Utf16 {
            path: found.path.clone(),
        })
    } else {
        Err(CliError::Binary {
            path: found.path.clone(),
        })
    }
}

/// Whether a walk follows symbolic links (`--follow-links`).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Links {
    Skip,
    Follow,
}

/// Standard input read whole as text (bytes that are no UTF-8 replaced);
/// `at_terminal` when it is a terminal, where waiting for typed input would
/// look like a hang.
pub fn stdin_text(at_terminal: CliError) -> Result<String, CliError> {
    use std::io::IsTerminal;
    if std::io::stdin().is_terminal() {
        return Err(at_terminal);
    }
    let mut input = Vec::new();
    std::io::stdin()
        .lock()
        .read_to_end(&mut input)
        .map_err(|source| CliError::Read {
            path: "<stdin>".into(),
            source,
        })?;
    Ok(String::from_utf8_lossy(&input).into_owned())
}

/// The paths named, or the current folder when none is: what a command
/// that writes files or only checks them (`fmt`, `rewrite --check`,
/// `--in-place`, `-o`, `--diff`) takes, as `check` does. Stdin is read
/// only when `-` is named: in CI stdin is no terminal, and reading it empty
/// would pass while the folder holds a file that fails.
pub fn named_or_here(paths: &[PathBuf]) -> Vec<PathBuf> {
    if paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        paths.to_vec()
    }
}

/// The paths named, or else stdin for a filter (`rewrite` and `eval` to
/// stdout), unless stdin is a terminal, where waiting would look like a hang.
pub fn named_or_stdin(paths: &[PathBuf], command: &'static str) -> Result<Vec<PathBuf>, CliError> {
    use std::io::IsTerminal;
    if !paths.is_empty() {
        return Ok(paths.to_vec());
    }
    if std::io::stdin().is_terminal() {
        return Err(CliError::NoProgram { command });
    }
    Ok(vec![PathBuf::from("-")])
}

/// Standard input, or a FIFO or device named: read whole while it is
/// small; from [`MAPPED_FROM`] bytes
/// on, what came and what follows go to an unnamed file in the temporary
/// directory (`TMPDIR`), which is mapped as a large program is: a program
/// piped in takes no more of the process's own memory than one read from a
/// file. The file is removed from its directory as soon as it is
/// made, so nothing is left behind, whatever ends the run. A file
/// redirected to stdin is mapped as it is.
fn read_stream<R: Read + platform::Stream>(stream: R) -> std::io::Result<Bytes> {
    read_stream_within(stream, SPOOLED_AT_MOST)
}

/// [`read_stream`], spooling at most `limit` bytes after the first
/// [`MAPPED_FROM`].
fn read_stream_within<R: Read + platform::Stream>(
    mut stream: R,
    limit: u64,
) -> std::io::Result<Bytes> {
    // A file redirected to stdin (`< PART.MPF`), unread so far: map it.
    let mut file = platform::file_behind(&stream)?;
    if let (Ok(metadata), Ok(0)) = (file.metadata(), file.stream_position()) {
        if metadata.is_file() && metadata.len() >= MAPPED_FROM {
            return Ok(Bytes::Mapped(Mapped::new(&file)?));
        }
    }
    let mut head = Vec::new();
    (&mut stream).take(MAPPED_FROM).read_to_end(&mut head)?;
    if (head.len() as u64) < MAPPED_FROM {
        return Ok(Bytes::Read(head));
    }
    let mut spool = unnamed_file()?;
    spool.write_all(&head)?;
    drop(head);
    let spooled = std::io::copy(&mut (&mut stream).take(limit), &mut spool)?;
    if spooled == limit && stream.read(&mut [0])? > 0 {
        return Err(std::io::Error::new(
            std::io::ErrorKind::FileTooLarge,
            format!(
                "more than {} MiB came, all a stream is read to (a device such as /dev/zero \
                 never ends); give the program as a file, which is read at any size",
                (MAPPED_FROM + limit) >> 20
            ),
        ));
    }
    Ok(Bytes::Mapped(Mapped::new(&spool)?))
}

/// The most of a stream spooled to the temporary directory after its
/// first [`MAPPED_FROM`] bytes: a stream that never ends (a device, a
/// runaway pipe) must not fill the disk. Files are mapped at any size.
const SPOOLED_AT_MOST: u64 = 4 << 30;

/// A new file in the temporary directory, already removed from it.
fn unnamed_file() -> std::io::Result<std::fs::File> {
    let dir = std::env::temp_dir();
    for _ in 0..64 {
        let path = dir.join(format!(
            ".sinuprep-stdin-{:016x}",
            crate::cli::output::random()
        ));
        match platform::unnamed_at(&path) {
            Ok(file) => return Ok(file),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no file could be made in the temporary directory for standard input",
    ))
}

/// Reads a program: stdin for `-`; a file of [`MAPPED_FROM`] bytes or
/// more is mapped instead, and so is stdin from that size on, spooled to a
/// file, and a FIFO or device named on the command line as stdin is. A file
/// a walk found is opened only if it is still the regular file the walk
/// saw (a link, unless followed, or a FIFO put in its place is refused).
pub fn read(found: &Found) -> Result<SourceFile, CliError> {
    let path = found.path.as_path();
    let fail = |source| CliError::Read {
        path: path.to_path_buf(),
        source,
    };
    if path == Path::new("-") {
        let bytes = read_stream(std::io::stdin().lock()).map_err(fail)?;
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
    let seen = match found.walked {
        None => None,
        Some(Links::Skip) => Some(std::fs::symlink_metadata(path).map_err(fail)?),
        Some(Links::Follow) => Some(std::fs::metadata(path).map_err(fail)?),
    };
    if seen.as_ref().is_some_and(|m| !m.is_file()) {
        return Err(fail(not_regular()));
    }
    let mut file = std::fs::File::open(path).map_err(fail)?;
    let metadata = file.metadata().map_err(fail)?;
    if let Some(seen) = &seen {
        if !metadata.is_file() || identity(&metadata) != identity(seen) {
            return Err(fail(not_regular()));
        }
    }
    let bytes = if !metadata.is_file() {
        // A FIFO or device named on the command line: read as stdin is.
        read_stream(file).map_err(fail)?
    } else if metadata.len() >= MAPPED_FROM {
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

fn not_regular() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidInput,
        "no longer the regular file the directory walk found",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Seek, SeekFrom};

    /// A stream is spooled up to its bound, and one that goes on past it is
    /// refused with what to do instead.
    #[test]
    fn a_stream_is_spooled_up_to_its_bound() {
        let path = std::env::temp_dir().join(format!(
            "sinuprep-spool-{:016x}",
            crate::cli::output::random()
        ));
        let length = MAPPED_FROM + (3 << 20);
        std::fs::write(&path, vec![b'\n'; length as usize]).expect("written");
        let open = || {
            let mut file = std::fs::File::open(&path).expect("opened");
            // Not at its start: read as a stream, not mapped.
            file.seek(SeekFrom::Start(1)).expect("seek");
            file
        };
        let spooled = read_stream_within(open(), 3 << 20).expect("within the bound");
        assert_eq!(spooled.len() as u64, length - 1);
        let Err(error) = read_stream_within(open(), 1 << 20) else {
            panic!("a stream past the bound was read");
        };
        assert_eq!(error.kind(), std::io::ErrorKind::FileTooLarge);
        assert!(
            error.to_string().contains("more than 5 MiB came"),
            "{error}"
        );
        let _ = std::fs::remove_file(&path);
    }
}
