//! One diagnostic type for syntax errors, lint findings and refusals to rewrite.
//!
//! A diagnostic is data: a stable code, a kebab-case name, a severity, a
//! message naming what was found, a label at the primary span and a help line
//! that says how to fix it. Rendering (miette, short lines, JSON) lives in the
//! CLI; nothing here prints.

use std::borrow::Cow;

use crate::edit::Edit;
use crate::span::Span;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Info,
    Warning,
    Error,
}

impl Severity {
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// The rule that found it: its code, name and documentation.
    pub rule: &'static RuleInfo,
    /// The rule's severity, or another where the finding says so (GOTOC).
    pub severity: Severity,
    pub message: String,
    pub span: Span,
    /// Short text shown under the span. Label and help are mostly fixed
    /// texts, kept without a copy: a program can have hundreds of thousands
    /// of findings, all held until they are sorted.
    pub label: Cow<'static, str>,
    pub help: Option<Cow<'static, str>>,
    /// The edit that answers the finding, when one is known (boxed: most
    /// findings have none).
    pub fix: Option<Box<Fix>>,
    /// Another place the finding concerns (the first definition of a name
    /// defined again), which an editor shows beside it.
    pub related: Option<Box<Related>>,
}

/// A place related to a finding, and what it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Related {
    pub span: Span,
    pub message: String,
}

/// Whether a fix may be applied without a person reading it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Applicability {
    /// The program means what it meant: `check --fix` applies it.
    Safe,
    /// A guess at what was meant (a did-you-mean): applied only with
    /// `--unsafe-fixes`, offered by an editor.
    Unsafe,
}

/// Edits that answer a finding.
#[derive(Clone, Debug, PartialEq)]
pub struct Fix {
    /// What the fix does, as an editor's code action names it.
    pub title: String,
    pub applicability: Applicability,
    /// Non-overlapping, in any order.
    pub edits: Vec<Edit>,
}

impl Fix {
    /// A fix that replaces `span` with `text`.
    pub fn replace(
        title: impl Into<String>,
        applicability: Applicability,
        span: Span,
        text: impl Into<Vec<u8>>,
    ) -> Self {
        Self {
            title: title.into(),
            applicability,
            edits: vec![Edit::replace(span, text)],
        }
    }
}

impl Diagnostic {
    /// Diagnostics are made by their rule, [`RuleInfo::at`], so that every
    /// code raised is one `sinuprep rule` documents.
    fn new(rule: &'static RuleInfo, span: Span) -> Self {
        Self {
            rule,
            severity: rule.severity,
            message: String::new(),
            span,
            label: Cow::Borrowed(""),
            help: None,
            fix: None,
            related: None,
        }
    }

    /// The diagnostic with every span it holds `by` bytes earlier: the
    /// same finding told in a part of the text it was found in.
    pub fn moved_back(&self, by: usize) -> Self {
        let back =
            |span: Span| Span::new(span.start - by.min(span.start), span.end - by.min(span.end));
        let mut moved = self.clone();
        moved.span = back(moved.span);
        if let Some(related) = &mut moved.related {
            related.span = back(related.span);
        }
        if let Some(fix) = &mut moved.fix {
            for edit in &mut fix.edits {
                edit.span = back(edit.span);
            }
        }
        moved
    }

    /// The rule's code (`N005`).
    pub fn code(&self) -> &'static str {
        self.rule.code
    }

    /// The rule's name (`undefined-variable`).
    pub fn name(&self) -> &'static str {
        self.rule.name
    }

    /// Whether `rule` found it.
    pub fn is(&self, rule: &RuleInfo) -> bool {
        std::ptr::eq(self.rule, rule) || self.rule.code == rule.code
    }

    pub fn related(mut self, span: Span, message: impl Into<String>) -> Self {
        self.related = Some(Box::new(Related {
            span,
            message: message.into(),
        }));
        self
    }

    pub fn fix(mut self, fix: Fix) -> Self {
        self.fix = Some(Box::new(fix));
        self
    }

    pub fn message(mut self, message: impl Into<String>) -> Self {
        self.message = message.into();
        self
    }

    pub fn label(mut self, label: impl Into<Cow<'static, str>>) -> Self {
        self.label = label.into();
        self
    }

    pub fn help(mut self, help: impl Into<Cow<'static, str>>) -> Self {
        self.help = Some(help.into());
        self
    }
}

/// A rule's identity and documentation: one `static` a rule, which its
/// findings point at.
#[derive(Debug, PartialEq)]
pub struct RuleInfo {
    /// Stable code: `S...` syntax, `C6..` CYCLE600, `N...` general NC.
    pub code: &'static str,
    /// Kebab-case; reads as "allow `<name>`".
    pub name: &'static str,
    pub severity: Severity,
    /// Markdown with the sections What it does / Why it matters / Example / Fix.
    pub docs: &'static str,
}

impl RuleInfo {
    /// A diagnostic of this rule at `span`.
    pub fn at(&'static self, span: Span) -> Diagnostic {
        Diagnostic::new(self, span)
    }
}
