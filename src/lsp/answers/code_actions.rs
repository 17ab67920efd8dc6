//! `textDocument/codeAction`: fixes, suppressions, the CYCLE600 rewrite and
//! every safe fix at once.

use lsp_types as lsp;

use crate::diagnostic::Diagnostic;
use crate::document::archive::Opened;
use crate::span::{ColumnUnit, Span};

use super::{Snapshot, FIX_ALL};
use crate::lsp::convert;

impl Snapshot<'_, '_> {
    /// Within `range`: each finding's fix, a suppression comment for each
    /// finding, and the rewrite of each CYCLE600 that can be written as
    /// native code (the edits `rewrite` makes); when `only` asks for source
    /// actions (the editor's "fix on save", its source action menu), every
    /// safe fix of the document at once.
    pub fn code_actions(
        &self,
        uri: &lsp::Uri,
        range: lsp::Range,
        only: Option<&[lsp::CodeActionKind]>,
    ) -> Vec<lsp::CodeActionOrCommand> {
        let wanted = convert::span(self.text, range, self.unit);
        let touches = |span: Span| span.start <= wanted.end && wanted.start <= span.end;
        let mut actions = Vec::new();
        for found in self.findings.iter().filter(|found| touches(found.span)) {
            let diagnostic = convert::diagnostic(self.text, uri, found, self.unit);
            if let Some(fix) = &found.fix {
                let safe = fix.applicability == crate::diagnostic::Applicability::Safe;
                let mut action =
                    self.action(uri, &fix.title, &fix.edits, lsp::CodeActionKind::QUICKFIX);
                action.diagnostics = Some(vec![diagnostic.clone()]);
                action.is_preferred = Some(safe);
                actions.push(lsp::CodeActionOrCommand::CodeAction(action));
            }
            if let Some(edit) = self.suppression(found) {
                let title = format!("Ignore {} on this line", found.code());
                let mut action = self.action(uri, &title, &[edit], lsp::CodeActionKind::QUICKFIX);
                action.diagnostics = Some(vec![diagnostic]);
                actions.push(lsp::CodeActionOrCommand::CodeAction(action));
            }
        }
        let source = |kind: &lsp::CodeActionKind| {
            let kind = kind.as_str();
            FIX_ALL.starts_with(kind) && (kind == "source" || kind.starts_with("source."))
        };
        if only.is_some_and(|only| only.iter().any(source)) {
            actions.extend(self.fix_all(uri).map(lsp::CodeActionOrCommand::CodeAction));
        }
        for site in self.calls().filter(|site| touches(site.statement)) {
            let options = &self.settings.emit;
            let machine = self.settings.machine.as_deref();
            if let Some(edits) =
                crate::emit::cycle600::call_edits(self.model, site, options, machine)
            {
                let title = format!("Rewrite this CYCLE600 as {}", options.form.native());
                let kind = lsp::CodeActionKind::REFACTOR_REWRITE;
                actions.push(lsp::CodeActionOrCommand::CodeAction(
                    self.action(uri, &title, &edits, kind),
                ));
            }
        }
        actions
    }

    /// Every safe fix of the document at once, as `check --fix` makes them
    /// (the library's [`Opened::fixes`]: an archive program by program);
    /// `None` when there is nothing to fix. Its kind, `source.fixAll.sinuprep`,
    /// is what an editor asks for to fix on save.
    fn fix_all(&self, uri: &lsp::Uri) -> Option<lsp::CodeAction> {
        let bytes = self.text.bytes();
        let opened = Opened::read(bytes, self.name).ok()?;
        let fixes = if opened.archive.is_some() {
            // The archive's findings are placed in it; its programs' own,
            // at their own offsets, are what the fixes are made from.
            let outcomes: Vec<_> = opened
                .programs(bytes)
                .iter()
                .map(|program| program.document.check_outcome(self.settings))
                .collect();
            opened.fixes(bytes, outcomes.iter().map(|o| &o.diagnostics[..]), false)
        } else {
            opened.fixes(bytes, [self.findings], false)
        };
        if fixes.edits.is_empty() {
            return None;
        }
        let s = if fixes.answered == 1 { "" } else { "s" };
        let title = format!("Fix all: {} finding{s} (sinuprep)", fixes.answered);
        let kind = lsp::CodeActionKind::new(FIX_ALL);
        Some(self.action(uri, &title, &fixes.edits, kind))
    }

    fn action(
        &self,
        uri: &lsp::Uri,
        title: &str,
        edits: &[crate::edit::Edit],
        kind: lsp::CodeActionKind,
    ) -> lsp::CodeAction {
        let edits = edits
            .iter()
            .map(|edit| lsp::TextEdit {
                range: self.range(edit.span),
                new_text: String::from_utf8_lossy(&edit.text).into_owned(),
            })
            .collect();
        lsp::CodeAction {
            title: title.to_string(),
            kind: Some(kind),
            edit: Some(lsp::WorkspaceEdit {
                changes: Some(std::iter::once((uri.clone(), edits)).collect()),
                ..lsp::WorkspaceEdit::default()
            }),
            ..lsp::CodeAction::default()
        }
    }

    /// `; sinuprep: ignore CODE` at the end of the finding's line, or in its
    /// comment; none where the comment already holds a `sinuprep:` text
    /// (the first one on a line is the one read).
    fn suppression(&self, found: &Diagnostic) -> Option<crate::edit::Edit> {
        let source = self.text.bytes();
        let row = self.text.position(found.span.start, ColumnUnit::Bytes).row - 1;
        let content = self.model.lines.raw(row).content;
        let directive = format!("sinuprep: ignore {}", found.code());
        let comment = self.model.lines.block(row).and_then(|block| block.comment);
        let (at, text) = match comment {
            Some(comment) => {
                let text = String::from_utf8_lossy(comment.of(source)).to_ascii_lowercase();
                if text.contains("sinuprep:") {
                    return None;
                }
                (comment.end, format!(" {directive}"))
            }
            None if content.is_empty() => (content.end, format!("; {directive}")),
            None => (content.end, format!(" ; {directive}")),
        };
        Some(crate::edit::Edit::replace(Span::new(at, at), text))
    }
}
