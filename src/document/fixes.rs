//! What `--fix` (and an editor's "fix all") does to one file: the fixes of
//! each program it holds, an archive's members each in its place, as edits
//! of the file's bytes. The command line writes them; the language server
//! sends them as one edit.

use crate::diagnostic::{Applicability, Diagnostic};
use crate::document::archive::Opened;
use crate::edit::Edit;
use crate::lint;

/// The edits that fix a file, and what they answer.
#[derive(Debug, Default)]
pub struct Fixes {
    /// Edits of the file's bytes, in order, none overlapping.
    pub edits: Vec<Edit>,
    /// The findings they answer.
    pub answered: usize,
    /// Programs with fixes that were left as they are, and why.
    pub unfixed: Vec<(String, Unfixed)>,
}

/// Why a program's fixes were not applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unfixed {
    /// It has syntax errors and no safe fix of its own for them: the other
    /// fixes were found on trees that may not be what was meant.
    SyntaxErrors,
    /// An archive's member whose new size does not fit its header.
    ArchiveHeader,
}

impl Unfixed {
    /// Why, in words: `not fixed, because of its syntax errors`.
    pub fn describe(self) -> &'static str {
        match self {
            Unfixed::SyntaxErrors => "not fixed, because of its syntax errors",
            Unfixed::ArchiveHeader => "not fixed: its new size does not fit the archive's header",
        }
    }
}

impl Opened {
    /// The fixes of the programs in `bytes` (this file's), whose findings
    /// are `findings` (one list per program, in order, each at the
    /// program's own offsets): the safe ones, and the unsafe ones too with
    /// `unsafe_fixes` ([`lint::fix::applicable`]). With syntax errors only
    /// their own safe fixes (a byte-order mark removed) are applied.
    pub fn fixes<'d>(
        &self,
        bytes: &[u8],
        findings: impl IntoIterator<Item = &'d [Diagnostic]>,
        unsafe_fixes: bool,
    ) -> Fixes {
        let mut fixes = Fixes::default();
        for (program, diagnostics) in self.programs(bytes).iter().zip(findings) {
            let (own, count) = lint::fix::applicable(diagnostics, unsafe_fixes);
            if own.is_empty() {
                continue;
            }
            let (own, count) = match diagnostics.iter().any(|d| d.code().starts_with('S')) {
                true => lint::fix::applicable(&syntax_fixes(diagnostics), false),
                false => (own, count),
            };
            if own.is_empty() {
                fixes
                    .unfixed
                    .push((program.name.clone(), Unfixed::SyntaxErrors));
                continue;
            }
            let shifted = match (&self.archive, program.member) {
                (Some(archive), Some(member)) => archive.edits(bytes, member, &own),
                _ => Some(own),
            };
            let Some(shifted) = shifted else {
                fixes
                    .unfixed
                    .push((program.name.clone(), Unfixed::ArchiveHeader));
                continue;
            };
            fixes.edits.extend(shifted);
            fixes.answered += count;
        }
        fixes
    }
}

/// The syntax errors that carry a safe fix of their own.
fn syntax_fixes(diagnostics: &[Diagnostic]) -> Vec<Diagnostic> {
    diagnostics
        .iter()
        .filter(|d| d.code().starts_with('S'))
        .filter(|d| {
            d.fix
                .as_deref()
                .is_some_and(|fix| fix.applicability == Applicability::Safe)
        })
        .cloned()
        .collect()
}
