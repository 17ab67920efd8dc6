//! Reading the files the settings and the options name (definition files,
//! the machine's records, HEAD_DEF, measured values, `sinuprep.toml`, a
//! cycle directory's subprograms, an A3200 setup): each must be a regular
//! file of at most [`LIMIT`] bytes. A FIFO would hang the run and a device
//! never ends; no control holds a settings file near the limit. Programs are not read here: they are mapped, at any size. Also
//! the canonical path of a file, as people are shown it.

use std::io::Read;
use std::path::{Component, Path, PathBuf, Prefix};

/// The most a settings file may hold: 64 MiB.
pub const LIMIT: u64 = 64 << 20;

/// The bytes of the file at `path` (through a link), refused when it is no
/// regular file or larger than [`LIMIT`]. Whether it is one is asked before
/// it is opened (a FIFO is never opened) and of what was opened.
pub fn read(path: &Path) -> std::io::Result<Vec<u8>> {
    regular(&std::fs::metadata(path)?)?;
    let file = std::fs::File::open(path)?;
    let length = regular(&file.metadata()?)?;
    let mut bytes = Vec::with_capacity(usize::try_from(length).unwrap_or(0));
    // A file that grows while it is read stops at the limit, too.
    file.take(LIMIT + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > LIMIT {
        return Err(too_large());
    }
    Ok(bytes)
}

/// The files of the folder `dir` that hold a machine's data, as
/// (path shown, bytes): the data files the control writes (`INITIAL.INI`,
/// `_N_TO_INI`, `TEA`, `UFR`, ... in either spelling) and series start-up
/// archives (`.arc`), not the subfolders. `INITIAL` (the whole machine)
/// comes first, the others after it by name, so that what they hold wins as
/// it does when the control loads them after it.
pub fn setup_files(dir: &Path) -> std::io::Result<Vec<(String, Vec<u8>)>> {
    let mut paths: Vec<PathBuf> = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
            continue;
        };
        let is_archive = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("arc"));
        let is_data = crate::archive::MemberKind::of_name(name) == crate::archive::MemberKind::Data;
        if (is_archive || is_data) && path.is_file() {
            paths.push(path);
        }
    }
    let initial_first = |path: &PathBuf| {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().to_ascii_uppercase());
        (
            !name.as_deref().is_some_and(|n| n.contains("INITIAL")),
            name,
        )
    };
    paths.sort_by_key(initial_first);
    if paths.is_empty() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::NotFound,
            "a folder without a machine's data files (`.INI`, `_N_..._INI`, `.arc`)",
        ));
    }
    paths
        .into_iter()
        .map(|path| Ok((path.display().to_string(), read(&path)?)))
        .collect()
}

/// A regular file's length, or why it cannot be read as a settings file.
fn regular(metadata: &std::fs::Metadata) -> std::io::Result<u64> {
    if !metadata.is_file() {
        let what = if metadata.is_dir() {
            "a directory"
        } else {
            "not a regular file (a FIFO, a socket or a device)"
        };
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("{what}: settings are read from regular files"),
        ));
    }
    if metadata.len() > LIMIT {
        return Err(too_large());
    }
    Ok(metadata.len())
}

fn too_large() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::FileTooLarge,
        format!(
            "larger than {} MiB, more than any settings file of a control holds",
            LIMIT >> 20
        ),
    )
}

/// `path` made absolute with every link resolved, as
/// [`std::fs::canonicalize`] makes it, but on Windows without the verbatim
/// prefix where the path means the same without it (`C:\CAM\PART.MPF`, not
/// `\\?\C:\CAM\PART.MPF`; `\\server\share\...`, not `\\?\UNC\server\share\...`):
/// it is shown to people, and the standard library adds the prefix again
/// where a long path needs it. Elsewhere the same as `canonicalize`.
pub fn canonical(path: &Path) -> std::io::Result<PathBuf> {
    let canonical = std::fs::canonicalize(path)?;
    Ok(without_verbatim(&canonical).unwrap_or(canonical))
}

/// `path` without its verbatim prefix (`\\?\`), or `None` where there is
/// none or where a name would mean something else without it: one that
/// ends in a dot or a blank (which Windows otherwise drops), or a device's
/// name (`NUL`, `COM1`, ...). Written with `Path::components`, so it
/// compiles alike everywhere (only Windows paths have a prefix).
fn without_verbatim(path: &Path) -> Option<PathBuf> {
    let mut components = path.components();
    let Some(Component::Prefix(prefix)) = components.next() else {
        return None;
    };
    let mut plain = match prefix.kind() {
        Prefix::VerbatimDisk(letter) => PathBuf::from(format!("{}:\\", char::from(letter))),
        Prefix::VerbatimUNC(server, share) => {
            let mut unc = std::ffi::OsString::from("\\\\");
            unc.push(server);
            unc.push("\\");
            unc.push(share);
            unc.push("\\");
            PathBuf::from(unc)
        }
        _ => return None,
    };
    for component in components {
        match component {
            Component::RootDir => {}
            Component::Normal(name) => {
                let text = name.to_str()?;
                let stem = text.split('.').next().unwrap_or(text).trim_end();
                let device = ["CON", "PRN", "AUX", "NUL"]
                    .iter()
                    .any(|d| stem.eq_ignore_ascii_case(d))
                    || (stem.len() == 4
                        && ["COM", "LPT"]
                            .iter()
                            .any(|d| stem.as_bytes()[..3].eq_ignore_ascii_case(d.as_bytes()))
                        && stem.as_bytes()[3].is_ascii_digit());
                if device || text.ends_with('.') || text.ends_with(' ') {
                    return None;
                }
                plain.push(name);
            }
            _ => return None,
        }
    }
    Some(plain)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_regular_file_is_read_and_anything_else_refused() {
        let dir = std::env::temp_dir().join(format!("sinuprep-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("dir");
        let file = dir.join("GUD.DEF");
        std::fs::write(&file, b"DEF NCK INT A\n").expect("write");
        assert_eq!(read(&file).expect("regular"), b"DEF NCK INT A\n");
        let error = read(&dir).expect_err("a directory");
        assert_eq!(error.kind(), std::io::ErrorKind::InvalidInput);
        #[cfg(unix)]
        {
            let error = read(Path::new("/dev/zero")).expect_err("a device");
            assert!(error.to_string().contains("not a regular file"), "{error}");
        }
        let big = dir.join("BIG.DEF");
        let handle = std::fs::File::create(&big).expect("create");
        handle.set_len(LIMIT + 1).expect("sparse");
        let error = read(&big).expect_err("too large");
        assert_eq!(error.kind(), std::io::ErrorKind::FileTooLarge);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_verbatim_prefix_is_dropped_where_the_path_means_the_same_without() {
        if cfg!(windows) {
            let plain = |text: &str| without_verbatim(Path::new(text));
            assert_eq!(
                plain(r"\\?\C:\CAM\OUT\PART.MPF"),
                Some(PathBuf::from(r"C:\CAM\OUT\PART.MPF"))
            );
            assert_eq!(
                plain(r"\\?\UNC\server\share\PART.MPF"),
                Some(PathBuf::from(r"\\server\share\PART.MPF"))
            );
            assert_eq!(plain(r"\\?\C:\CAM\NUL.MPF"), None);
            assert_eq!(plain(r"\\?\C:\CAM\PART."), None);
            assert_eq!(plain(r"C:\CAM\PART.MPF"), None);
        } else {
            assert_eq!(without_verbatim(Path::new("/tmp/PART.MPF")), None);
        }
    }
}
