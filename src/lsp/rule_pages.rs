//! Where an editor finds a finding's rule documented (the diagnostic's
//! `codeDescription`, opened by clicking its code): the rule's section of
//! docs/rules.md in the project's repository when Cargo.toml names one;
//! otherwise the page `sinuprep rule CODE` prints, written once into the
//! user's cache folder, so that the link opens the rule's own words
//! wherever the server runs, with no network.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, OnceLock};

use lsp_types as lsp;

use crate::lint::reference::{help_uri, page, REPOSITORY};

/// The link to the rule `code`'s documentation; `None` for a code that
/// names no rule, or when its page cannot be written (a read-only home).
pub fn link(code: &str) -> Option<lsp::Uri> {
    let info = crate::lint::rule(code)?;
    if let Some(uri) = help_uri(REPOSITORY, info) {
        return uri.parse().ok();
    }
    static WRITTEN: OnceLock<Mutex<HashMap<&'static str, Option<lsp::Uri>>>> = OnceLock::new();
    let written = WRITTEN.get_or_init(Mutex::default);
    if let Some(known) = written.lock().ok()?.get(info.code) {
        return known.clone();
    }
    let uri = write_page(&pages_dir()?, info.code, &page(info));
    written.lock().ok()?.insert(info.code, uri.clone());
    uri
}

/// Writes `text` as `dir/CODE.md` (whole, or not at all: another server
/// may read it meanwhile) unless it is there already, and names it as a
/// `file` URI.
fn write_page(dir: &Path, code: &str, text: &str) -> Option<lsp::Uri> {
    let path = dir.join(format!("{code}.md"));
    if std::fs::read(&path).ok().as_deref() != Some(text.as_bytes()) {
        std::fs::create_dir_all(dir).ok()?;
        let temporary = dir.join(format!(".{code}.md.{}", std::process::id()));
        std::fs::write(&temporary, text).ok()?;
        if std::fs::rename(&temporary, &path).is_err() {
            let _ = std::fs::remove_file(&temporary);
            return None;
        }
    }
    super::convert::uri(&path)
}

/// `sinuprep/VERSION/rules` in the user's cache folder: `%LOCALAPPDATA%`
/// on Windows, `~/Library/Caches` on macOS, `$XDG_CACHE_HOME` or
/// `~/.cache` elsewhere (the places each system keeps what can be made
/// again). By version, so that a page is never an older release's.
fn pages_dir() -> Option<PathBuf> {
    let absolute = |name: &str| {
        let path = PathBuf::from(std::env::var_os(name)?);
        path.is_absolute().then_some(path)
    };
    let cache = if cfg!(windows) {
        absolute("LOCALAPPDATA")?
    } else if cfg!(target_os = "macos") {
        absolute("HOME")?.join("Library/Caches")
    } else {
        absolute("XDG_CACHE_HOME").or_else(|| Some(absolute("HOME")?.join(".cache")))?
    };
    Some(
        cache
            .join("sinuprep")
            .join(env!("CARGO_PKG_VERSION"))
            .join("rules"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_page_is_written_whole_once_and_named_by_its_file() {
        let dir = std::env::temp_dir().join(format!("sinuprep-rule-pages-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let uri = write_page(&dir, "N001", "# N001\n").expect("written");
        assert!(uri.as_str().starts_with("file:///"), "{}", uri.as_str());
        assert!(uri.as_str().ends_with("/N001.md"), "{}", uri.as_str());
        assert_eq!(
            std::fs::read_to_string(dir.join("N001.md")).expect("page"),
            "# N001\n"
        );
        // Written again with other text (a newer build of one version): replaced.
        write_page(&dir, "N001", "# N001 new\n").expect("written");
        assert_eq!(
            std::fs::read_to_string(dir.join("N001.md")).expect("page"),
            "# N001 new\n"
        );
        // No temporary file is left beside it.
        let names: Vec<_> = std::fs::read_dir(&dir)
            .expect("dir")
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert_eq!(names, ["N001.md"]);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
