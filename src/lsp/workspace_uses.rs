//! A name's uses beyond the document asked about: in the other NC files of
//! the workspace, for references and rename of what the control shares
//! between programs (a subprogram, a GUD variable). The workspace is what
//! the document's settings read: its own folder, and the folders of the
//! subprograms and definition files they found. Each file is searched for
//! the name's bytes before it is parsed, so that a folder of large CAM
//! programs costs a scan; an open document's unsaved text stands in for its
//! file.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::document::text::Text;
use crate::semantic::environment::Environment;
use crate::semantic::uses::{Namespace, Use, Uses};
use crate::semantic::Model;
use crate::syntax::lexer::find_ignoring_case;

/// The extensions of the files searched (any case): programs, subprograms
/// and definition files.
const SEARCHED: [&str; 3] = ["mpf", "spf", "def"];

/// The texts of the documents open in the editor, by path.
pub type Buffers = HashMap<PathBuf, Arc<[u8]>>;

/// One file's uses of a name.
pub struct InFile {
    pub path: PathBuf,
    pub text: Text,
    pub uses: Vec<Use>,
}

/// The NC files of the workspace of the document at `document`, itself
/// left out, in order.
pub fn files(document: &Path, environment: &Environment) -> Vec<PathBuf> {
    let mut folders = BTreeSet::new();
    folders.extend(document.parent().map(Path::to_path_buf));
    let defined = environment
        .procedures
        .values()
        .filter_map(|p| p.defined.as_ref());
    let declared = environment.defined_in.values();
    for (file, _) in defined.chain(declared) {
        folders.extend(file.parent().map(Path::to_path_buf));
    }
    let mut files = BTreeSet::new();
    for folder in folders {
        // A folder gone or unreadable since the settings were read holds
        // nothing.
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let searched = path
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| SEARCHED.iter().any(|s| s.eq_ignore_ascii_case(e)));
            if searched && path != document && entry.file_type().is_ok_and(|t| t.is_file()) {
                files.insert(path);
            }
        }
    }
    files.into_iter().collect()
}

/// The uses of `name` (upper case) in `namespace` in each of `files` that
/// has one, read from `buffers` where the editor holds the file.
pub fn uses_of(
    name: &str,
    namespace: Namespace,
    files: &[PathBuf],
    buffers: &Buffers,
) -> Vec<InFile> {
    let mut found = Vec::new();
    for path in files {
        let bytes = match buffers.get(path) {
            Some(buffer) => buffer.to_vec(),
            // A file that cannot be read (gone, too large) holds none.
            None => match crate::workspace::file::read(path) {
                Ok(bytes) => bytes,
                Err(_) => continue,
            },
        };
        if find_ignoring_case(&bytes, name.as_bytes()).is_none() {
            continue;
        }
        let text = Text::new(bytes);
        let model = Model::of(text.bytes());
        let uses: Vec<Use> = Uses::of(&model)
            .all()
            .iter()
            .filter(|u| u.namespace == namespace && u.name == name)
            .cloned()
            .collect();
        drop(model);
        if !uses.is_empty() {
            found.push(InFile {
                path: path.clone(),
                text,
                uses,
            });
        }
    }
    found
}
