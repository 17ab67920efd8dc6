//! `textDocument/prepareRename` and `textDocument/rename` of a name the
//! program defines.

use lsp_types as lsp;

use crate::semantic::uses::{Namespace, Role, Use};
use crate::semantic::words::{is_language_word, is_machine_axis};

use super::{is_block_number, Snapshot};

impl Snapshot<'_, '_> {
    /// The name under the cursor, if it can be renamed here.
    pub fn prepare_rename(&self, position: lsp::Position) -> Result<lsp::Range, String> {
        if let Some(shared) = self.shared_name(position) {
            return Ok(self.range(shared.span));
        }
        let found = self
            .uses()
            .at(self.offset(position))
            .ok_or("no name of this program here")?;
        self.renamable(found)?;
        Ok(self.range(found.span))
    }

    /// Every use of the name under the cursor renamed `new_name`: refused
    /// for a name defined outside this program that the programs do not
    /// share (a shared one is [`Self::rename_across`]'s), for a block number (renumbering is no rename), for a
    /// name the control would not take, and for one this program already
    /// uses for another thing of the same kind.
    pub fn rename(
        &self,
        uri: &lsp::Uri,
        position: lsp::Position,
        new_name: &str,
    ) -> Result<lsp::WorkspaceEdit, String> {
        let found = self
            .uses()
            .at(self.offset(position))
            .ok_or("no name of this program here")?;
        self.renamable(found)?;
        refuse_new_name(new_name)?;
        let upper = new_name.to_ascii_uppercase();
        if upper != found.name
            && self
                .uses()
                .all()
                .iter()
                .any(|u| u.namespace == found.namespace && u.name == upper)
        {
            return Err(format!("`{new_name}` is already a name of this program"));
        }
        let edits = self
            .uses()
            .references(found)
            .map(|u| lsp::TextEdit::new(self.range(u.span), new_name.to_string()))
            .collect();
        Ok(lsp::WorkspaceEdit {
            changes: Some(std::iter::once((uri.clone(), edits)).collect()),
            ..lsp::WorkspaceEdit::default()
        })
    }

    fn renamable(&self, found: &Use) -> Result<(), String> {
        if found.namespace == Namespace::Label && is_block_number(&found.name) {
            return Err("a block number is renumbered, not renamed".to_string());
        }
        if !self
            .uses()
            .references(found)
            .any(|u| u.role == Role::Defines)
        {
            return Err(format!(
                "`{}` is not defined in this program: renaming it here would leave its other files",
                found.name
            ));
        }
        Ok(())
    }
}

/// Why `new_name` cannot be a user's name, if it cannot.
pub(in crate::lsp) fn refuse_new_name(new_name: &str) -> Result<(), String> {
    if !is_user_name(new_name) {
        return Err(format!(
            "`{new_name}` is not a name the control takes: up to 31 letters, digits and \
             underscores, the first two letters or underscores"
        ));
    }
    if is_language_word(new_name.as_bytes()) || is_machine_axis(new_name.as_bytes()) {
        return Err(format!(
            "`{new_name}` is a word of the language (a keyword, function, command, cycle \
             or machine axis), not a name the control takes for a user's"
        ));
    }
    Ok(())
}

/// A name the control takes for a variable or a label: 2 to 31 characters,
/// letters, digits and underscores, the first two letters or underscores
/// (Programming Manual Fundamentals, "Variables": user-defined names).
fn is_user_name(name: &str) -> bool {
    let bytes = name.as_bytes();
    (2..=31).contains(&bytes.len())
        && bytes[..2]
            .iter()
            .all(|b| b.is_ascii_alphabetic() || *b == b'_')
        && bytes
            .iter()
            .all(|b| b.is_ascii_alphanumeric() || *b == b'_')
}
