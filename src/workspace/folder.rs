//! One directory's names that mean something to the programs in it, found
//! in any case, as the control and Windows find them: `HEAD_DEF.SPF`,
//! `sinuprep.toml` and the subprograms (`.SPF`). The file system is not
//! asked for a name (Linux would find `HEAD_DEF.SPF` only so spelt); the
//! listing is searched instead.
//!
//! A folder made on Linux may hold two names that differ only in case
//! (`HEAD_DEF.SPF` and `head_def.spf`). The control and Windows hold one file
//! under such a name, so which of the two a copy there keeps is chance: a
//! pair used by a program is an error naming both, never a silent pick.
//! Names only: no file is read here.

use std::collections::BTreeMap;
use std::ffi::{OsStr, OsString};
use std::path::{Path, PathBuf};

use super::{SettingsError, FILE_NAME};

/// The names of one directory a program beside them may use, each kind in
/// the listing's order.
#[derive(Debug, Default)]
pub(crate) struct Listing {
    head_def: Vec<Entry>,
    /// `sinuprep.toml` in any case, a regular file (through a link too, as a
    /// settings file named by path is read).
    settings: Vec<PathBuf>,
    /// The `.SPF` files by their name without the extension, in upper case.
    subprograms: BTreeMap<OsString, Vec<Entry>>,
}

#[derive(Debug, Clone)]
struct Entry {
    path: PathBuf,
    /// A link, which names what may lie outside the tree: found only when
    /// the run follows links.
    link: bool,
}

impl Listing {
    /// The names in `dir` that matter, from one listing of it.
    pub(crate) fn read(dir: &Path) -> std::io::Result<Listing> {
        let mut listing = Listing::default();
        for entry in std::fs::read_dir(dir)?.flatten() {
            // The name decides first: a folder of thousands of files (a
            // home directory on the way up to the settings) costs one
            // comparison each, no path built.
            let name = entry.file_name();
            if name.eq_ignore_ascii_case(FILE_NAME) {
                let path = entry.path();
                if path.is_file() {
                    listing.settings.push(path);
                }
                continue;
            }
            let Some(stem) = subprogram_stem(&name) else {
                continue;
            };
            let link = entry.file_type().is_ok_and(|kind| kind.is_symlink());
            let found = Entry {
                path: entry.path(),
                link,
            };
            if stem.eq_ignore_ascii_case("HEAD_DEF") {
                listing.head_def.push(found.clone());
            }
            let key = stem.to_ascii_uppercase();
            listing.subprograms.entry(key).or_default().push(found);
        }
        Ok(listing)
    }

    /// The directory's `HEAD_DEF.SPF`, any case.
    pub(crate) fn head_def(&self, follow_links: bool) -> Result<Option<PathBuf>, SettingsError> {
        let found: Vec<&Path> = taken(&self.head_def, follow_links).collect();
        one(
            "HEAD_DEF",
            "; or name the one to use with `--heads`",
            &found,
        )
    }

    /// The directory's `sinuprep.toml`, any case.
    pub(crate) fn settings(&self) -> Result<Option<PathBuf>, SettingsError> {
        let found: Vec<&Path> = self.settings.iter().map(PathBuf::as_path).collect();
        let hint = "; or name the one to use with `--config`";
        one("the settings file", hint, &found)
    }

    /// The directory's subprograms: each name in upper case without `.SPF`,
    /// and its file.
    pub(crate) fn subprograms(
        &self,
        follow_links: bool,
    ) -> Result<Vec<(String, PathBuf)>, SettingsError> {
        let mut out = Vec::with_capacity(self.subprograms.len());
        for (name, entries) in &self.subprograms {
            let found: Vec<&Path> = taken(entries, follow_links).collect();
            let name = name.to_string_lossy().into_owned();
            let what = format!("the subprogram {name}");
            if let Some(path) = one(&what, "", &found)? {
                out.push((name, path));
            }
        }
        Ok(out)
    }
}

/// The `sinuprep.toml` (any case) in `dir`, without a cache. A directory
/// that cannot be listed but can be passed through is asked for the name
/// as it is spelt.
pub(crate) fn settings_in(dir: &Path) -> Result<Option<PathBuf>, SettingsError> {
    match Listing::read(dir) {
        Ok(listing) => listing.settings(),
        Err(_) => Ok(Some(dir.join(FILE_NAME)).filter(|path| path.is_file())),
    }
}

/// `name` without its `.SPF` extension (any case), as `Path::file_stem`
/// reads it (`.SPF` alone is a hidden file's name, no subprogram); the
/// extension is tested on the bytes first, so most names cost a compare.
fn subprogram_stem(name: &OsStr) -> Option<&OsStr> {
    name_ends_with(name, b".SPF")
        .then(|| Path::new(name).file_stem())
        .flatten()
}

/// Whether `name` is longer than `end` and ends in it, in any case; by its
/// bytes, never a cut of the name (a multi-byte character at its end is no
/// boundary to slice a `&str` at).
pub(crate) fn name_ends_with(name: &OsStr, end: &[u8]) -> bool {
    let bytes = name.as_encoded_bytes();
    bytes.len() > end.len() && bytes[bytes.len() - end.len()..].eq_ignore_ascii_case(end)
}

/// The entries a run takes: links only when it follows them.
fn taken(entries: &[Entry], follow_links: bool) -> impl Iterator<Item = &Path> {
    let entries = entries.iter();
    entries
        .filter(move |entry| follow_links || !entry.link)
        .map(|entry| entry.path.as_path())
}

/// The one file found, none, or an error naming two that differ only in case.
fn one(what: &str, hint: &'static str, found: &[&Path]) -> Result<Option<PathBuf>, SettingsError> {
    match found {
        [] => Ok(None),
        [path] => Ok(Some(path.to_path_buf())),
        [first, second, ..] => {
            // Sorted, so the message is the same whatever the listing's order.
            let (first, second) = if first <= second {
                (first, second)
            } else {
                (second, first)
            };
            Err(SettingsError::CaseClash {
                what: what.to_string(),
                first: first.to_path_buf(),
                second: second.to_path_buf(),
                hint,
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_found_in_any_case_and_two_that_differ_only_in_case_are_refused() {
        let dir = std::env::temp_dir().join(format!("sinuprep-folder-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("dir");
        for name in ["Head_Def.Spf", "SINUPREP.TOML", "sub.spf", "PART.MPF"] {
            std::fs::write(dir.join(name), b"").expect("write");
        }
        let listing = Listing::read(&dir).expect("listed");
        let head_def = listing.head_def(false).expect("one HEAD_DEF");
        assert_eq!(head_def, Some(dir.join("Head_Def.Spf")));
        let settings = listing.settings().expect("one settings file");
        assert_eq!(settings, Some(dir.join("SINUPREP.TOML")));
        let subprograms = listing.subprograms(false).expect("no clash");
        let names: Vec<&str> = subprograms.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["HEAD_DEF", "SUB"]);

        // A second spelling, where the file system holds both (not on a
        // case-insensitive one, as Windows' and macOS's usually are).
        std::fs::write(dir.join("HEAD_DEF.SPF"), b"").expect("write");
        std::fs::write(dir.join("sinuprep.toml"), b"").expect("write");
        if std::fs::read_dir(&dir).expect("dir").count() == 6 {
            let listing = Listing::read(&dir).expect("listed");
            let error = listing.head_def(false).expect_err("two HEAD_DEF");
            let both = format!(
                "HEAD_DEF: {} and {} differ only in case",
                dir.join("HEAD_DEF.SPF").display(),
                dir.join("Head_Def.Spf").display()
            );
            assert_eq!(error.to_string(), both);
            assert!(listing.settings().is_err());
            assert!(listing.subprograms(false).is_err());
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
