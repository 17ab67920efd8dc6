//! For people: miette's report, the source line, a label and help.

use std::fmt;

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents,
    SourceCode, SourceSpan, SpanContents,
};

use super::emitter::TextFormat;
use super::{printable, FileReport, COLUMNS};
use crate::diagnostic::{Diagnostic, Severity};
use crate::span::{line_end, line_start, next_line_start, previous_line_end, LineIndex, Span};

/// The miette report: source line, label and help, without colour when
/// `colour` is false (files, pipes, snapshots).
pub fn human(report: &FileReport, colour: bool, out: &mut String) {
    if report.diagnostics.is_empty() {
        return;
    }
    let index = LineIndex::new(report.source);
    let theme = if colour {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme).with_width(100);
    for diagnostic in report.diagnostics {
        let shown = Shown {
            diagnostic,
            window: Window::around(report, &index, diagnostic.span),
        };
        // Rendering into a String cannot fail.
        let _ = handler.render_report(out, &shown);
        out.push('\n');
    }
}

/// `check --output-format human`, in colour where `colour` says.
pub struct HumanEmitter {
    pub colour: bool,
}

impl TextFormat for HumanEmitter {
    fn render(&self, report: &FileReport, out: &mut String) {
        human(report, self.colour, out);
    }

    fn for_people(&self) -> bool {
        true
    }
}

/// The lines miette shows for one diagnostic (its own and one either side),
/// as text: a file that is not UTF-8 is read as Latin-1 (one byte, one
/// character). Handing miette the whole file made it count lines from the
/// start for every diagnostic, and copied the file twice.
///
/// Where those lines are long (a CAM block run together, a generated
/// table), the window is an excerpt of the diagnostic's own line around
/// where it starts, and the column miette prints is the line's real one:
/// miette counts columns in 16 bits and panics past 65,535.
struct Window {
    name: String,
    text: String,
    /// Where the window starts in the file, and on which line (0-based).
    start: usize,
    first_row: usize,
    /// Columns of the line before the window (an excerpt starts inside it).
    first_column: usize,
    /// The diagnostic's own column (0-based, in [`COLUMNS`]), for miette's
    /// header, which would count the bytes of the window's text.
    span_column: usize,
    latin1: bool,
    bytes: Vec<u8>,
}

/// Windows longer than this (in bytes) are cut to an excerpt of one line.
const LONGEST_WINDOW: usize = 1000;
/// How much of a long line an excerpt shows before and after the span's start.
const EXCERPT_BEFORE: usize = 60;
const EXCERPT_AFTER: usize = 240;

impl Window {
    fn around(report: &FileReport, index: &LineIndex, span: Span) -> Self {
        let source = report.source;
        let span_start = span.start.min(source.len());
        let span_end = span.end.clamp(span_start, source.len());
        let own_line = line_start(source, span_start);
        let mut start = line_start(source, previous_line_end(source, own_line));
        let mut end = line_end(source, next_line_start(source, line_end(source, span_end)));
        let mut first_column = 0;
        if end - start > LONGEST_WINDOW {
            let own_end = line_end(source, span_start);
            start = char_boundary(
                source,
                span_start.saturating_sub(EXCERPT_BEFORE).max(own_line),
            );
            end = char_boundary(source, (span_start + EXCERPT_AFTER).min(own_end));
            first_column = index.position_in(start, COLUMNS).column - 1;
        }
        let bytes = &source[start..end];
        let (text, latin1) = match std::str::from_utf8(bytes) {
            // ASCII reads the same either way: only other text asks how the
            // whole file is encoded.
            Ok(text) if text.is_ascii() || index.is_utf8() => (text.to_string(), false),
            _ => (bytes.iter().map(|&b| b as char).collect(), true),
        };
        Self {
            name: printable(report.name).into_owned(),
            text,
            start,
            first_row: index.position(start).row - 1,
            first_column,
            span_column: index.position_in(span_start, COLUMNS).column - 1,
            latin1,
            bytes: bytes.to_vec(),
        }
    }

    /// A byte offset of the file as an offset into `text`.
    fn offset(&self, offset: usize) -> usize {
        let inside = offset.clamp(self.start, self.start + self.bytes.len()) - self.start;
        if self.latin1 {
            inside + self.bytes[..inside].iter().filter(|&&b| b >= 0x80).count()
        } else {
            inside
        }
    }
}

impl SourceCode for Window {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let inner = self.text.read_span(span, before, after)?;
        // Without context lines miette reads the label's span for the
        // header's `line:column`.
        let column = match (before, after) {
            (0, 0) => self.span_column,
            _ => inner.column() + self.first_column,
        };
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            inner.data(),
            *inner.span(),
            inner.line() + self.first_row,
            column,
            inner.line_count(),
        )))
    }
}

/// `at`, moved back to the start of the UTF-8 sequence it falls inside (a
/// file read as Latin-1 has a character at every byte, and is cut anywhere).
fn char_boundary(source: &[u8], mut at: usize) -> usize {
    let mut back = 0;
    while at > 0 && at < source.len() && source[at] & 0xC0 == 0x80 && back < 3 {
        at -= 1;
        back += 1;
    }
    at
}

struct Shown<'a> {
    diagnostic: &'a Diagnostic,
    window: Window,
}

impl fmt::Debug for Shown<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.diagnostic, f)
    }
}

impl fmt::Display for Shown<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.diagnostic.message)
    }
}

impl std::error::Error for Shown<'_> {}

impl miette::Diagnostic for Shown<'_> {
    fn code<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        Some(Box::new(format!(
            "{}({})",
            self.diagnostic.code(),
            self.diagnostic.name()
        )))
    }

    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.diagnostic.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
            Severity::Info => miette::Severity::Advice,
        })
    }

    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.diagnostic
            .help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(&self.window)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let span = self.diagnostic.span;
        let start = self.window.offset(span.start);
        let len = self.window.offset(span.end) - start;
        Some(Box::new(std::iter::once(LabeledSpan::new(
            Some(self.diagnostic.label.to_string()),
            start,
            len,
        ))))
    }
}
