//! Writing files so that an interrupted run never leaves a partial one.
//!
//! Every file is written into a temporary file beside it (readable by its
//! owner only, locked while the run lives), synced, given the original's
//! owner, group and mode, and renamed over it. On Linux the temporary file
//! has no name while it is written (`O_TMPFILE`): it is linked in under a
//! random name once complete and renamed at once, so a run killed before
//! that leaves nothing. Elsewhere, and on file systems without `O_TMPFILE`,
//! it is created under a random name, exclusively; a run that was killed
//! leaves it unlocked, and the next run that writes beside it removes it. A
//! rename replaces the directory entry: a file that has other hard links
//! keeps its old bytes under them. What is Linux's alone is behind `cfg`
//! here; what differs between Unix and Windows is in `cli::platform`.

use std::fs::{self, File, Metadata, OpenOptions};
use std::hash::{BuildHasher, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::cli::error::CliError;
use crate::cli::platform::{identity, keep_owner_and_mode, kind, rename_over};
use crate::workspace::file::canonical;

/// The regular file an in-place rewrite of `path` replaces: the file a
/// symlink points to (the link stays). Standard input, FIFOs, devices and
/// directories are refused, before anything is read.
pub fn in_place_target(path: &Path) -> Result<PathBuf, CliError> {
    let refuse = |why: &str| CliError::NotInPlace {
        path: path.to_path_buf(),
        why: why.to_string(),
    };
    if path == Path::new("-") {
        return Err(refuse("standard input has no file to rewrite"));
    }
    let target = canonical(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let metadata = fs::metadata(&target).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    if !metadata.is_file() {
        return Err(refuse(&format!(
            "it is {}, not a regular file",
            kind(&metadata)
        )));
    }
    Ok(target)
}

/// Whether `output` names the same file as `input` (through links).
pub fn same_file(input: &Path, output: &Path) -> bool {
    crate::cli::platform::same_file(input, output)
}

/// Writes `path` with `write`: atomically where `path` is a regular file or
/// does not exist yet, and straight into it where it is something else (a
/// device such as `/dev/stdout`, a FIFO). With `backup`, those bytes go to
/// `<path>.bak` first, atomically as well. On any failure `path` is
/// untouched (a backup already written holds its bytes), and no temporary
/// file is left.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    backup: Option<&[u8]>,
) -> Result<(), CliError> {
    let fail = |source: std::io::Error| CliError::WriteFile {
        path: path.to_path_buf(),
        source,
    };
    // A symlink is written through: the file it points to is replaced.
    let target = canonical(path).unwrap_or_else(|_| path.to_path_buf());
    let existing = fs::metadata(&target).ok();
    if let Some(metadata) = existing.as_ref().filter(|m| !m.is_file()) {
        if metadata.is_dir() {
            return Err(fail(std::io::Error::other("it is a directory")));
        }
        let mut file = OpenOptions::new().write(true).open(&target).map_err(fail)?;
        return write_buffered(&mut file, write).map_err(fail);
    }
    if existing
        .as_ref()
        .is_some_and(|m| m.permissions().readonly())
    {
        return Err(fail(std::io::Error::new(
            std::io::ErrorKind::PermissionDenied,
            "the file is read-only",
        )));
    }
    if let Some(original) = backup {
        let mut bak = target.as_os_str().to_owned();
        bak.push(".bak");
        let bak = PathBuf::from(bak);
        replace(&bak, |out| out.write_all(original), existing.as_ref()).map_err(|source| {
            if source.kind() == std::io::ErrorKind::InvalidFilename {
                CliError::BackupNameTooLong {
                    path: path.to_path_buf(),
                }
            } else {
                CliError::WriteFile {
                    path: bak.clone(),
                    source,
                }
            }
        })?;
    }
    replace(&target, write, existing.as_ref()).map_err(fail)
}

/// Writes `relative` under the output folder `dir` (`rewrite -o DIR` of
/// several programs), as [`write_atomically`] writes a file, but never
/// through a link: a symbolic link on the way, or at the file's own name, is
/// refused, so that a link planted inside the output folder cannot send a
/// file outside it. The folders on the way are made where missing. `dir`
/// itself may be a link: the user named it.
pub fn write_inside(
    dir: &Path,
    relative: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), CliError> {
    use std::path::Component;
    let mut path = dir.to_path_buf();
    let refuse = |path: &Path, why: String| CliError::OutputThroughLink {
        path: path.to_path_buf(),
        why,
    };
    let fail = |path: &Path, source: std::io::Error| CliError::WriteFile {
        path: path.to_path_buf(),
        source,
    };
    fs::create_dir_all(dir).map_err(|source| fail(dir, source))?;
    let names: Vec<_> = relative.components().collect();
    for (i, component) in names.iter().enumerate() {
        let Component::Normal(name) = component else {
            return Err(refuse(
                &dir.join(relative),
                "it does not lie inside the output folder".into(),
            ));
        };
        path.push(name);
        let last = i + 1 == names.len();
        match fs::symlink_metadata(&path) {
            Ok(metadata) if metadata.file_type().is_symlink() => {
                let why = if last {
                    "it is a symbolic link".to_string()
                } else {
                    format!(
                        "the folder {} on its way is a symbolic link",
                        path.display()
                    )
                };
                return Err(refuse(&dir.join(relative), why));
            }
            Ok(metadata) if !last && !metadata.is_dir() => {
                return Err(fail(
                    &dir.join(relative),
                    std::io::Error::other(format!("{} is not a folder", path.display())),
                ))
            }
            Ok(_) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound && !last => {
                match fs::create_dir(&path) {
                    Ok(()) => {}
                    // Made meanwhile by another program's write: looked at again.
                    Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                        if !fs::symlink_metadata(&path).is_ok_and(|m| m.is_dir()) {
                            return Err(fail(&path, e));
                        }
                    }
                    Err(e) => return Err(fail(&path, e)),
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(fail(&path, e)),
        }
    }
    let existing = fs::symlink_metadata(&path).ok();
    if let Some(metadata) = existing.as_ref().filter(|m| !m.is_file()) {
        return Err(fail(
            &path,
            std::io::Error::other(format!("it is {}, not a regular file", kind(metadata))),
        ));
    }
    if existing
        .as_ref()
        .is_some_and(|m| m.permissions().readonly())
    {
        return Err(fail(
            &path,
            std::io::Error::new(
                std::io::ErrorKind::PermissionDenied,
                "the file is read-only",
            ),
        ));
    }
    replace(&path, write, existing.as_ref()).map_err(|source| fail(&path, source))
}

/// Writes a temporary file beside `target` and renames it over `target`,
/// with the owner, group and mode of `like` (the file replaced).
fn replace(
    target: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    like: Option<&Metadata>,
) -> std::io::Result<()> {
    let dir = match target.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    remove_stale_temporaries(&dir, &name);
    let (mut file, mut temporary) = Temporary::create(&dir, &name, like)?;
    let result = (|| {
        write_buffered(&mut file, write)?;
        file.sync_all()?;
        if let Some(like) = like {
            keep_owner_and_mode(&file, like)?;
        }
        let path = temporary.named(&file, &dir, &name)?;
        rename_over(&path, target)?;
        // The rename is durable once the directory is synced.
        if let Ok(dir) = File::open(&dir) {
            let _ = dir.sync_all();
        }
        Ok(())
    })();
    if let (Err(_), Temporary::Named(path)) = (&result, &temporary) {
        let _ = fs::remove_file(path);
    }
    result
}

/// Where a write goes before it replaces the target.
enum Temporary {
    /// A file of its own name beside the target, locked while the run lives.
    Named(PathBuf),
    /// A file without a name in the target's directory (Linux `O_TMPFILE`):
    /// a run killed while it writes leaves nothing behind. It is linked in
    /// under a temporary name once complete, then renamed like the other.
    #[cfg(target_os = "linux")]
    Nameless,
}

impl Temporary {
    /// A nameless file where the platform and the file system allow, else a
    /// named one.
    fn create(
        dir: &Path,
        name: &str,
        replaces: Option<&Metadata>,
    ) -> std::io::Result<(File, Temporary)> {
        #[cfg(target_os = "linux")]
        if let Some(file) = nameless::create(dir, replaces.is_some())? {
            return Ok((file, Temporary::Nameless));
        }
        let (file, path) = create_temporary(dir, name, replaces)?;
        Ok((file, Temporary::Named(path)))
    }

    /// The complete file's path, to rename over the target: a nameless file
    /// is given its temporary name now.
    // Only a nameless file (Linux) needs what it is given.
    #[cfg_attr(not(target_os = "linux"), allow(unused_variables))]
    fn named(&mut self, file: &File, dir: &Path, name: &str) -> std::io::Result<PathBuf> {
        match self {
            Temporary::Named(path) => Ok(path.clone()),
            #[cfg(target_os = "linux")]
            Temporary::Nameless => {
                let path = nameless::link(file, dir, &temporary_prefix(name))?;
                *self = Temporary::Named(path.clone());
                Ok(path)
            }
        }
    }
}

/// Nameless temporary files (Linux 3.11 and later, on the file systems that
/// support `O_TMPFILE`: ext4, XFS, Btrfs, tmpfs and others).
#[cfg(target_os = "linux")]
mod nameless {
    use std::ffi::CString;
    use std::fs::{File, OpenOptions};
    use std::os::unix::ffi::OsStrExt;
    use std::os::unix::fs::OpenOptionsExt;
    use std::os::unix::io::AsRawFd;
    use std::path::{Path, PathBuf};

    use super::{random, TEMPORARY_SUFFIX};

    /// A new file without a name in `dir`, locked (so that once it has a
    /// name no other run's clean-up takes it), or `None` where the file
    /// system or the kernel cannot make one: the caller makes a named one.
    pub(super) fn create(dir: &Path, private: bool) -> std::io::Result<Option<File>> {
        // The file is linked in through its descriptor's entry in /proc.
        if !Path::new("/proc/self/fd").is_dir() {
            return Ok(None);
        }
        let opened = OpenOptions::new()
            .write(true)
            .custom_flags(libc::O_TMPFILE | libc::O_CLOEXEC)
            .mode(if private { 0o600 } else { 0o666 })
            .open(dir);
        let file = match opened {
            Ok(file) => file,
            // No O_TMPFILE on this file system (EOPNOTSUPP), or a kernel
            // that predates it (EISDIR: it read the flag as O_DIRECTORY; or
            // EINVAL).
            Err(e)
                if matches!(
                    e.raw_os_error(),
                    Some(libc::EOPNOTSUPP | libc::EISDIR | libc::EINVAL)
                ) =>
            {
                return Ok(None)
            }
            Err(e) => return Err(e),
        };
        file.try_lock().map_err(std::io::Error::other)?;
        Ok(Some(file))
    }

    /// Gives the complete nameless `file` a new temporary name in `dir`
    /// (`prefix`, random digits, `.tmp`), which a rename then moves over the
    /// target: `linkat` cannot replace a name. Only between the two can a
    /// killed run leave a file behind, which the next run removes.
    pub(super) fn link(file: &File, dir: &Path, prefix: &str) -> std::io::Result<PathBuf> {
        let descriptor = CString::new(format!("/proc/self/fd/{}", file.as_raw_fd()))
            .map_err(std::io::Error::other)?;
        for _ in 0..64 {
            let path = dir.join(format!("{prefix}{:016x}{TEMPORARY_SUFFIX}", random()));
            let name = CString::new(path.as_os_str().as_bytes()).map_err(std::io::Error::other)?;
            #[allow(unsafe_code)]
            // SAFETY: both arguments are NUL-terminated strings that live
            // across the call, which only reads them; no memory is shared.
            let linked = unsafe {
                libc::linkat(
                    libc::AT_FDCWD,
                    descriptor.as_ptr(),
                    libc::AT_FDCWD,
                    name.as_ptr(),
                    libc::AT_SYMLINK_FOLLOW,
                )
            };
            if linked == 0 {
                return Ok(path);
            }
            let error = std::io::Error::last_os_error();
            if error.kind() != std::io::ErrorKind::AlreadyExists {
                return Err(error);
            }
        }
        Err(std::io::Error::new(
            std::io::ErrorKind::AlreadyExists,
            "no temporary name could be given to the file",
        ))
    }
}

fn write_buffered(
    file: &mut File,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let mut buffered = std::io::BufWriter::new(file);
    write(&mut buffered)?;
    buffered.flush()
}

/// What the temporary files for `name` are called: `.NAME.sinuprep-*.tmp`,
/// the name cut to its first [`NAME_IN_TEMPORARY`] bytes, so that a
/// temporary name stays within the 255 bytes file systems allow a name
/// however long the target's is.
fn temporary_prefix(name: &str) -> String {
    let mut end = name.len().min(NAME_IN_TEMPORARY);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    format!(".{}.sinuprep-", &name[..end])
}

/// How much of the target's name a temporary name repeats (bytes): with
/// the dot, `.sinuprep-`, 16 hex digits and `.tmp`, at most 128.
const NAME_IN_TEMPORARY: usize = 96;

const TEMPORARY_SUFFIX: &str = ".tmp";

/// A new temporary file beside the target, under a name nobody can guess,
/// created exclusively, and locked for as long as this run holds it. Where
/// it replaces a file it starts readable by its owner only, and is given the
/// file's mode once written (on Windows, its attributes from the start); a
/// new file gets the usual mode (0666 less the umask).
fn create_temporary(
    dir: &Path,
    name: &str,
    replaces: Option<&Metadata>,
) -> std::io::Result<(File, PathBuf)> {
    let prefix = temporary_prefix(name);
    for _ in 0..64 {
        let path = dir.join(format!("{prefix}{:016x}{TEMPORARY_SUFFIX}", random()));
        let file = match crate::cli::platform::new_file(replaces).open(&path) {
            Ok(file) => file,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        };
        // Another run's clean-up may have taken it between its creation and
        // the lock: then it is no longer at its path, and another is made.
        let locked = file.try_lock().is_ok();
        let still_there = match (fs::symlink_metadata(&path), file.metadata()) {
            (Ok(at_path), Ok(own)) => identity(&at_path) == identity(&own),
            _ => false,
        };
        if locked && still_there {
            return Ok((file, path));
        }
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no temporary file could be created beside it",
    ))
}

/// Removes the temporary files of runs that ended without cleaning up
/// (killed): theirs are the unlocked ones. A running process holds its lock.
fn remove_stale_temporaries(dir: &Path, name: &str) {
    let prefix = temporary_prefix(name);
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some(file_name) = file_name.to_str() else {
            continue;
        };
        if !(file_name.starts_with(&prefix) && file_name.ends_with(TEMPORARY_SUFFIX)) {
            continue;
        }
        let path = entry.path();
        // Never follow a link planted under such a name.
        if !fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
            continue;
        }
        let Ok(file) = File::open(&path) else {
            continue;
        };
        if file.try_lock().is_ok() {
            let _ = fs::remove_file(&path);
        }
    }
}

/// 64 bits nobody can predict: the standard library's per-process random
/// hash keys, over the time and the process id.
pub(crate) fn random() -> u64 {
    let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    hasher.write_u128(nanos);
    hasher.write_u32(std::process::id());
    hasher.finish()
}

/// Runs `report`, writing what it writes to `file` (atomically, as every
/// output here: the whole report or nothing, should the run fail midway)
/// or, without one, to standard output, where a reader that went away
/// (`| head`) ends the output without ending the run.
pub fn report_to<T>(
    file: Option<&Path>,
    report: impl FnOnce(&mut dyn Write) -> Result<T, CliError>,
) -> Result<T, CliError> {
    let Some(path) = file else {
        return report(&mut Stdout);
    };
    let mut outcome = None;
    let written = write_atomically(
        path,
        |out| match report(out) {
            Ok(value) => {
                outcome = Some(Ok(value));
                Ok(())
            }
            // The run's own failure, kept to be returned; the file is
            // left as it was.
            Err(error) => {
                outcome = Some(Err(error));
                Err(std::io::Error::other("the run failed"))
            }
        },
        None,
    );
    match (outcome, written) {
        (Some(Err(error)), _) => Err(error),
        (_, Err(error)) => Err(error),
        (Some(Ok(value)), Ok(())) => Ok(value),
        // `write_atomically` calls `write` unless it failed first.
        (None, Ok(())) => Err(CliError::Write(std::io::Error::other(
            "the report was not written",
        ))),
    }
}

/// Standard output, a reader that went away taken as one that read it all.
struct Stdout;

impl Write for Stdout {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        match std::io::stdout().lock().write(bytes) {
            Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(bytes.len()),
            result => result,
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        match std::io::stdout().lock().flush() {
            Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
            result => result,
        }
    }
}
