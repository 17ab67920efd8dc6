//! `textDocument/publishDiagnostics` and `textDocument/diagnostic`: the document's
//! findings (on the machine the settings name, the software limits its dry
//! run passes among them, K007); at most [`MOST_SHOWN_FINDINGS`] of them.

use lsp_types as lsp;

use super::{Snapshot, MOST_SHOWN_FINDINGS};
use crate::lsp::convert;

impl Snapshot<'_, '_> {
    /// The findings of the document at `uri`: the first
    /// [`MOST_SHOWN_FINDINGS`] by position, and past those one more that
    /// says how many there are and where every one is listed.
    pub fn diagnostics(&self, uri: &lsp::Uri) -> Vec<lsp::Diagnostic> {
        if let Some(why) = self.refused {
            return vec![lsp::Diagnostic {
                range: lsp::Range::default(),
                severity: Some(lsp::DiagnosticSeverity::ERROR),
                source: Some("sinuprep".to_string()),
                message: why.to_string(),
                ..lsp::Diagnostic::default()
            }];
        }
        let findings = self.findings;
        let mut shown: Vec<lsp::Diagnostic> = findings
            .iter()
            .take(MOST_SHOWN_FINDINGS)
            .map(|found| convert::diagnostic(self.text, uri, found, self.unit))
            .collect();
        if let Some(first_unshown) = findings.get(MOST_SHOWN_FINDINGS) {
            let start = self.range(first_unshown.span).start;
            let check = match convert::path(uri) {
                Some(path) => format!(
                    "`sinuprep check {}` (and `sinuprep run` for K007)",
                    path.display()
                ),
                None => {
                    "`sinuprep check` of the saved file (and `sinuprep run` for K007)".to_string()
                }
            };
            shown.push(lsp::Diagnostic {
                range: lsp::Range::new(start, start),
                severity: Some(lsp::DiagnosticSeverity::INFORMATION),
                source: Some("sinuprep".to_string()),
                message: format!(
                    "{MOST_SHOWN_FINDINGS} of the {} findings are shown, those before here; \
                     {check} lists every one",
                    findings.len(),
                ),
                ..lsp::Diagnostic::default()
            });
        }
        shown
    }
}
