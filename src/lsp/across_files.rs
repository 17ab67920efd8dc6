//! References and rename of the names the control shares between
//! programs: a subprogram (its PROC, its calls in every program, and its
//! file, whose name is how the control finds it) and a GUD variable (its DEF
//! in a definition file, its uses in every program). The other files are
//! the workspace's ([`super::workspace_uses`]); a name of one program alone
//! stays with [`Snapshot::references`] and [`Snapshot::rename`].

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use lsp_types as lsp;

use super::answers::{refuse_new_name, Snapshot};
use super::convert;
use super::workspace_uses::{self, Buffers};
use crate::semantic::uses::{Namespace, Role, Use};
use crate::semantic::words::is_language_word;

impl Snapshot<'_, '_> {
    /// The name under the cursor if the control shares it between
    /// programs: a subprogram that is not one of the control's (a cycle,
    /// a predefined procedure), or a GUD variable (of the definition files,
    /// or one this program declares `NCK` or `CHAN`) no local DEF hides.
    pub fn shared_name(&self, position: lsp::Position) -> Option<&Use> {
        let found = self.uses().at(self.offset(position))?;
        if is_language_word(found.name.as_bytes()) {
            return None;
        }
        let declared = |global: bool| {
            (self.model.symbols.iter()).any(|s| s.name == found.name && s.global == global)
        };
        let shared = match found.namespace {
            Namespace::Subprogram => true,
            Namespace::Variable => {
                let gud = self
                    .settings
                    .environment
                    .defined_in
                    .contains_key(&found.name);
                declared(true) || (gud && !declared(false))
            }
            Namespace::Label => false,
        };
        shared.then_some(found)
    }

    /// The uses of the shared name under the cursor in the workspace's
    /// other files.
    pub fn references_elsewhere(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        with_declaration: bool,
        buffers: &Buffers,
    ) -> Vec<lsp::Location> {
        let (Some(found), Some(path)) = (self.shared_name(position), convert::path(uri)) else {
            return Vec::new();
        };
        let files = workspace_uses::files(&path, &self.settings.environment);
        let mut out = Vec::new();
        for file in workspace_uses::uses_of(&found.name, found.namespace, &files, buffers) {
            let Some(file_uri) = convert::uri(&file.path) else {
                continue;
            };
            out.extend(
                (file.uses.iter())
                    .filter(|u| with_declaration || u.role != Role::Defines)
                    .map(|u| {
                        let range = convert::range(&file.text, u.span, self.unit);
                        lsp::Location::new(file_uri.clone(), range)
                    }),
            );
        }
        out
    }

    /// The shared name under the cursor renamed `new_name` in every file of
    /// the workspace, and a subprogram's file with it (`renames_files`: the
    /// client takes file renames); refused where the rename would leave a
    /// use or the definition behind, or take a name the workspace has.
    pub fn rename_across(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        new_name: &str,
        buffers: &Buffers,
        renames_files: bool,
    ) -> Result<lsp::WorkspaceEdit, String> {
        let found = self
            .shared_name(position)
            .ok_or("no name the programs share here")?;
        refuse_new_name(new_name)?;
        let path = convert::path(uri)
            .ok_or("the document is not saved in the workspace: its other files are not known")?;
        let environment = &self.settings.environment;
        let files = workspace_uses::files(&path, environment);
        let upper = new_name.to_ascii_uppercase();
        if upper != found.name {
            let here = (self.uses().all().iter())
                .any(|u| u.namespace == found.namespace && u.name == upper);
            let known = match found.namespace {
                Namespace::Subprogram => environment.procedures.contains_key(&upper),
                _ => {
                    environment.variables.contains(&upper)
                        || environment.macros.contains_key(&upper)
                }
            };
            if here || known {
                return Err(format!("`{new_name}` is already a name in the workspace"));
            }
            let taken = workspace_uses::uses_of(&upper, found.namespace, &files, buffers);
            if let Some(file) = taken.first() {
                return Err(format!(
                    "`{new_name}` is already a name in `{}`",
                    file.path.display()
                ));
            }
        }
        let elsewhere = workspace_uses::uses_of(&found.name, found.namespace, &files, buffers);
        let here: Vec<&Use> = self.uses().references(found).collect();
        let defines = |uses: &[&Use]| uses.iter().any(|u| u.role == Role::Defines);
        let defined_in = match defines(&here) {
            true => Some(path.clone()),
            false => (elsewhere.iter())
                .find(|f| f.uses.iter().any(|u| u.role == Role::Defines))
                .map(|f| f.path.clone()),
        };
        let Some(defined_in) = defined_in else {
            return Err(format!(
                "`{}` is not defined in a file of the workspace (an archive's, or nowhere): \
                 renaming its uses would leave its definition behind",
                found.name
            ));
        };
        let mut edits: Vec<(lsp::Uri, Vec<lsp::TextEdit>)> = Vec::new();
        let edit = |range| lsp::TextEdit::new(range, new_name.to_string());
        edits.push((
            uri.clone(),
            here.iter().map(|u| edit(self.range(u.span))).collect(),
        ));
        for file in &elsewhere {
            let file_uri = convert::uri(&file.path).ok_or("a file of the workspace has no URI")?;
            let ranges = file
                .uses
                .iter()
                .map(|u| convert::range(&file.text, u.span, self.unit));
            edits.push((file_uri, ranges.map(edit).collect()));
        }
        let renamed = match found.namespace {
            Namespace::Subprogram => renamed_file(&defined_in, &found.name, new_name)?,
            _ => None,
        };
        let Some((old, new)) = renamed else {
            return Ok(lsp::WorkspaceEdit {
                changes: Some(edits.into_iter().collect::<HashMap<_, _>>()),
                ..lsp::WorkspaceEdit::default()
            });
        };
        if !renames_files {
            return Err(format!(
                "the control calls `{}` by its file's name, and this editor cannot rename files: \
                 rename `{}` to `{}` with it",
                found.name,
                old.display(),
                new.file_name().map_or(new.display().to_string(), |n| n
                    .to_string_lossy()
                    .into_owned())
            ));
        }
        let (old_uri, new_uri) = match (convert::uri(&old), convert::uri(&new)) {
            (Some(old), Some(new)) => (old, new),
            _ => return Err("the subprogram's file has no URI".to_string()),
        };
        let mut operations: Vec<lsp::DocumentChangeOperation> = edits
            .into_iter()
            .map(|(uri, edits)| {
                lsp::DocumentChangeOperation::Edit(lsp::TextDocumentEdit {
                    text_document: lsp::OptionalVersionedTextDocumentIdentifier {
                        uri,
                        version: None,
                    },
                    edits: edits.into_iter().map(lsp::OneOf::Left).collect(),
                })
            })
            .collect();
        operations.push(lsp::DocumentChangeOperation::Op(lsp::ResourceOp::Rename(
            lsp::RenameFile {
                old_uri,
                new_uri,
                options: None,
                annotation_id: None,
            },
        )));
        Ok(lsp::WorkspaceEdit {
            document_changes: Some(lsp::DocumentChanges::Operations(operations)),
            ..lsp::WorkspaceEdit::default()
        })
    }
}

/// The file `defined_in` renamed for the subprogram's new name where its
/// name is the subprogram's (how the control finds it), in the case of the
/// old one; refused where a file of that name is there already.
fn renamed_file(
    defined_in: &Path,
    old_name: &str,
    new_name: &str,
) -> Result<Option<(PathBuf, PathBuf)>, String> {
    let Some(stem) = defined_in.file_stem().and_then(|s| s.to_str()) else {
        return Ok(None);
    };
    if !stem.eq_ignore_ascii_case(old_name) {
        return Ok(None);
    }
    let new_stem = match stem.bytes().any(|b| b.is_ascii_uppercase()) {
        true => new_name.to_ascii_uppercase(),
        false => new_name.to_ascii_lowercase(),
    };
    let mut new = defined_in.with_file_name(new_stem);
    if let Some(extension) = defined_in.extension() {
        new.set_extension(extension);
    }
    if new.exists() && !same_file_in_other_case(defined_in, &new) {
        return Err(format!("`{}` is there already", new.display()));
    }
    Ok(Some((defined_in.to_path_buf(), new)))
}

/// A rename that changes only the name's case finds the file itself on a
/// file system that ignores case.
fn same_file_in_other_case(old: &Path, new: &Path) -> bool {
    old.to_string_lossy()
        .eq_ignore_ascii_case(&new.to_string_lossy())
}
