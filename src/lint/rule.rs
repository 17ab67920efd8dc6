//! What a lint rule is: its metadata, and the checker that sees the program
//! one line at a time.

use crate::diagnostic::{Diagnostic, Severity};
use crate::span::Span;
use crate::syntax::tree::Line;
use crate::syntax::ProgramKind;

/// A rule's identity and documentation.
#[derive(Debug)]
pub struct RuleInfo {
    /// Stable code: `S...` syntax, `C6..` CYCLE600, `N...` general NC.
    pub code: &'static str,
    /// Kebab-case; reads as "allow <name>".
    pub name: &'static str,
    pub severity: Severity,
    /// Markdown with the sections What it does / Why it matters / Example / Fix.
    pub docs: &'static str,
}

impl RuleInfo {
    /// A diagnostic of this rule at `span`.
    pub fn at(&self, span: Span) -> Diagnostic {
        Diagnostic::new(self.code, self.name, self.severity, span)
    }
}

/// The file a rule is looking at.
pub struct FileContext<'a> {
    pub source: &'a [u8],
    /// The file's name as given (`<stdin>` or `--stdin-filename`).
    pub name: &'a str,
    pub kind: ProgramKind,
}

/// A checker: fed every line in order, then told the file is over. Rules
/// keep only what they must remember (labels, names, one state flag).
pub trait Check {
    fn line(&mut self, _file: &FileContext, _row: usize, _line: &Line, _out: &mut Vec<Diagnostic>) {
    }
    fn finish(&mut self, _file: &FileContext, _out: &mut Vec<Diagnostic>) {}
}

/// A rule with the checker that implements it; rules whose findings come
/// from the parser or the CYCLE600 walk have none.
pub struct Rule {
    pub info: &'static RuleInfo,
    pub checker: Option<fn() -> Box<dyn Check>>,
}
