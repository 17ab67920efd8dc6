//! What differs between the platforms the command line runs on, in one
//! place: a file's identity, the modes and owners a replaced file keeps, a
//! temporary file nobody else reads, the rename that replaces a file, and
//! the file behind standard input.
//! Unix (Linux, macOS) keeps all of it; Windows has no owner, group or mode
//! bits to keep (the read-only, hidden, system, archive and not-indexed
//! attributes are kept; alternate data streams are not), and its identity of a
//! file is not in the standard library's stable API, so a file met twice
//! there (through a link the walk was asked to follow) is read twice.

use std::fs::{File, Metadata, OpenOptions};
use std::path::Path;

/// A file's identity (device and inode), where the platform tells it.
#[cfg(unix)]
pub fn identity(metadata: &Metadata) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    Some((metadata.dev(), metadata.ino()))
}

#[cfg(not(unix))]
pub fn identity(_metadata: &Metadata) -> Option<(u64, u64)> {
    None
}

/// How many names (hard links) a file has, where the platform tells it.
#[cfg(unix)]
pub fn names(metadata: &Metadata) -> u64 {
    use std::os::unix::fs::MetadataExt;
    metadata.nlink()
}

#[cfg(not(unix))]
pub fn names(_metadata: &Metadata) -> u64 {
    1
}

/// Whether a console shows colour escapes. Windows' console does once its
/// virtual terminal mode is on (Windows 10 and later), which is set here,
/// once, for stdout and stderr; an older console, or output that is not a
/// console, gets no colour from `auto`.
#[cfg(windows)]
pub fn console_shows_colour() -> bool {
    static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *ON.get_or_init(|| anstyle_query::windows::enable_virtual_terminal_processing().is_ok())
}

#[cfg(not(windows))]
pub fn console_shows_colour() -> bool {
    true
}

/// Whether `a` and `b` are one file: by identity, else by canonical path.
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(ma), Ok(mb)) => match (identity(&ma), identity(&mb)) {
            (Some(ia), Some(ib)) => ia == ib,
            _ => match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
                (Ok(ca), Ok(cb)) => ca == cb,
                _ => false,
            },
        },
        _ => false,
    }
}

/// Options for a new file, created exclusively. One that `replaces` a file
/// is readable by its owner only on Unix (the mode of the file it replaces
/// is given once it is written), and has its hidden, system, archive and
/// not-indexed attributes from the start on Windows (where no call of the
/// standard library sets them later); a new file has the usual mode (0666
/// less the umask).
pub fn new_file(replaces: Option<&Metadata>) -> OpenOptions {
    let mut options = OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.mode(if replaces.is_some() { 0o600 } else { 0o666 });
    }
    #[cfg(windows)]
    if let Some(like) = replaces {
        use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
        options.attributes(like.file_attributes() & KEPT_ATTRIBUTES);
    }
    #[cfg(not(any(unix, windows)))]
    let _ = replaces;
    options
}

/// The attributes a replaced file keeps on Windows: hidden (2), system (4),
/// archive (0x20), not content-indexed (0x2000). Read-only is given once the
/// file is written ([`keep_owner_and_mode`]).
#[cfg(windows)]
pub const KEPT_ATTRIBUTES: u32 = 0x2 | 0x4 | 0x20 | 0x2000;

/// A new file at `path`, readable and writable by this process only, whose
/// name is gone once the caller holds it: removed at once on Unix, deleted
/// when it is closed on Windows (where an open file cannot be removed).
pub fn unnamed_at(path: &Path) -> std::io::Result<File> {
    let mut options = OpenOptions::new();
    options.read(true).write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.mode(0o600);
        let file = options.open(path)?;
        std::fs::remove_file(path)?;
        Ok(file)
    }
    #[cfg(windows)]
    {
        use std::os::windows::fs::OpenOptionsExt;
        const FILE_FLAG_DELETE_ON_CLOSE: u32 = 0x0400_0000;
        options.custom_flags(FILE_FLAG_DELETE_ON_CLOSE);
        options.open(path)
    }
}

/// Gives `file` the owner, group and mode of `like` (the file it replaces).
/// Where the owner cannot be kept (not root), the file is this user's, and
/// the setuid and setgid bits are not put back on it. On Windows: the
/// read-only attribute.
#[cfg(unix)]
pub fn keep_owner_and_mode(file: &File, like: &Metadata) -> std::io::Result<()> {
    use std::os::unix::fs::{fchown, MetadataExt, PermissionsExt};
    let _ = fchown(file, Some(like.uid()), Some(like.gid()))
        .or_else(|_| fchown(file, None, Some(like.gid())));
    let own = file.metadata()?;
    let owner_kept = own.uid() == like.uid() && own.gid() == like.gid();
    let mut mode = like.mode() & 0o7777;
    if !owner_kept {
        mode &= !0o6000;
    }
    file.set_permissions(std::fs::Permissions::from_mode(mode))
}

#[cfg(not(unix))]
pub fn keep_owner_and_mode(file: &File, like: &Metadata) -> std::io::Result<()> {
    file.set_permissions(like.permissions())
}

/// Renames `from` over `to`, replacing it. On Windows a file that another
/// process holds open (a reader, another run, an editor, a virus scanner)
/// cannot be replaced until it is closed (access denied; Wine as well): the
/// rename is tried again for about two seconds, then fails, `to` untouched.
pub fn rename_over(from: &Path, to: &Path) -> std::io::Result<()> {
    #[cfg(windows)]
    {
        let mut wait = std::time::Duration::from_millis(5);
        let mut waited = std::time::Duration::ZERO;
        loop {
            match std::fs::rename(from, to) {
                Err(error)
                    if error.kind() == std::io::ErrorKind::PermissionDenied
                        && waited < std::time::Duration::from_secs(2) =>
                {
                    std::thread::sleep(wait);
                    waited += wait;
                    wait = (wait * 2).min(std::time::Duration::from_millis(100));
                }
                result => return result,
            }
        }
    }
    #[cfg(not(windows))]
    std::fs::rename(from, to)
}

/// What a file that is not a regular one is, for messages.
pub fn kind(metadata: &Metadata) -> &'static str {
    let file_type = metadata.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return "a FIFO";
        } else if file_type.is_char_device() || file_type.is_block_device() {
            return "a device";
        } else if file_type.is_socket() {
            return "a socket";
        }
    }
    if file_type.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

/// A stream whose file can be looked at: standard input, or a file opened.
#[cfg(unix)]
pub trait Stream: std::os::fd::AsFd {}
#[cfg(unix)]
impl<T: std::os::fd::AsFd> Stream for T {}

#[cfg(windows)]
pub trait Stream: std::os::windows::io::AsHandle {}
#[cfg(windows)]
impl<T: std::os::windows::io::AsHandle> Stream for T {}

/// The file behind `stream` (a file redirected to stdin, a pipe, a device),
/// as a file of its own.
pub fn file_behind(stream: &impl Stream) -> std::io::Result<File> {
    #[cfg(unix)]
    let owned = stream.as_fd().try_clone_to_owned()?;
    #[cfg(windows)]
    let owned = stream.as_handle().try_clone_to_owned()?;
    Ok(File::from(owned))
}
