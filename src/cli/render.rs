//! Diagnostics rendered for people (miette), for problem matchers (short
//! lines) and for tools (JSON, schema in docs/guide.md).

use std::fmt;

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents,
    SourceCode, SourceSpan, SpanContents,
};

use crate::diagnostic::{Applicability, Diagnostic, Fix, Severity};
use crate::lint::reference::{self, REPOSITORY};
use crate::span::{
    line_end, line_start, next_line_start, previous_line_end, ColumnUnit, LineIndex, Position, Span,
};

/// What every format's columns count: UTF-16 code units, as the Language
/// Server Protocol does by default, as SARIF does by default
/// (`columnKind` `utf16CodeUnits`) and as VS Code and GitHub's annotations
/// (JavaScript strings) count; for every character of the Basic
/// Multilingual Plane (`ü`, `°`, `Ø`) that is one column, the character
/// count people expect, and a character beyond it (an emoji, `𝜑`) is two.
/// A file that is not UTF-8 counts a byte as a character (its code page has
/// one byte a character). The human header, the short and GitHub lines, the
/// JSON and SARIF positions all count the same way.
pub const COLUMNS: ColumnUnit = ColumnUnit::Utf16;

/// One file's diagnostics, ready to render.
pub struct FileReport<'a> {
    pub name: &'a str,
    pub source: &'a [u8],
    pub diagnostics: &'a [Diagnostic],
}

pub use crate::document::printable;

/// `path:line:col: severity[CODE] message`, one per line.
pub fn short(report: &FileReport, out: &mut String) {
    let index = LineIndex::new(report.source);
    let name = printable(report.name);
    for diagnostic in report.diagnostics {
        let Position { row, column } = index.position_in(diagnostic.span.start, COLUMNS);
        out.push_str(&format!(
            "{name}:{row}:{column}: {}[{}] {}\n",
            diagnostic.severity.as_str(),
            diagnostic.code(),
            diagnostic.message
        ));
    }
}

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

#[derive(serde::Serialize)]
struct JsonFile<'a> {
    path: &'a str,
    diagnostics: Vec<JsonDiagnostic<'a>>,
}

#[derive(serde::Serialize)]
struct JsonDiagnostic<'a> {
    code: &'a str,
    name: &'a str,
    severity: Severity,
    message: &'a str,
    help: Option<&'a str>,
    location: Position,
    end_location: Position,
    offset: usize,
    length: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    fix: Option<JsonFix<'a>>,
}

#[derive(serde::Serialize)]
struct JsonFix<'a> {
    title: &'a str,
    applicability: Applicability,
    /// Byte offsets into the file as read; the text replaces `length` bytes.
    edits: Vec<JsonEdit>,
}

#[derive(serde::Serialize)]
struct JsonEdit {
    offset: usize,
    length: usize,
    text: String,
}

impl<'a> JsonFix<'a> {
    fn of(fix: &'a Fix) -> Self {
        Self {
            title: &fix.title,
            applicability: fix.applicability,
            edits: fix
                .edits
                .iter()
                .map(|edit| JsonEdit {
                    offset: edit.span.start,
                    length: edit.span.len(),
                    text: String::from_utf8_lossy(&edit.text).into_owned(),
                })
                .collect(),
        }
    }
}

/// One file's diagnostics with their start and end positions: what the
/// whole-run formats (JSON, SARIF) need of a file once its source is gone.
pub struct Located {
    pub name: String,
    /// The file's path, where it has one: SARIF names it by its bytes.
    pub path: Option<std::path::PathBuf>,
    pub diagnostics: Vec<Diagnostic>,
    pub positions: Vec<(Position, Position)>,
}

impl Located {
    /// Takes the diagnostics over (a program can have hundreds of thousands).
    pub fn new(name: &str, source: &[u8], diagnostics: Vec<Diagnostic>) -> Self {
        let index = LineIndex::new(source);
        let positions = diagnostics
            .iter()
            .map(|d| {
                let at = |offset| index.position_in(offset, COLUMNS);
                (at(d.span.start), at(d.span.end))
            })
            .collect();
        Self {
            name: name.to_owned(),
            path: None,
            diagnostics,
            positions,
        }
    }

    /// The same, from the file at `path`, whose name may not be UTF-8.
    pub fn at(self, path: Option<&std::path::Path>) -> Self {
        Self {
            path: path.map(std::path::Path::to_path_buf),
            ..self
        }
    }

    fn each(&self) -> impl Iterator<Item = (&Diagnostic, Position, Position)> {
        self.diagnostics
            .iter()
            .zip(&self.positions)
            .map(|(d, &(start, end))| (d, start, end))
    }
}

fn applicability(applicability: Applicability) -> &'static str {
    match applicability {
        Applicability::Safe => "safe",
        Applicability::Unsafe => "unsafe",
    }
}

/// The JSON document for all files, written a file at a time: this, then
/// each file's [`json_file`] (after [`JSON_BETWEEN`] from the second on),
/// then [`json_end`]. The text is what one pretty-printed document would be.
pub const JSON_START: &str = "{\n  \"version\": 1,\n  \"files\": [";
pub const JSON_BETWEEN: &str = ",";

/// One file's entry of the JSON document, indented for its place there,
/// preceded by its line break.
pub fn json_file(report: &Located) -> String {
    let diagnostics = report
        .each()
        .map(|(d, start, end)| JsonDiagnostic {
            code: d.code(),
            name: d.name(),
            severity: d.severity,
            message: &d.message,
            help: d.help.as_deref(),
            location: start,
            end_location: end,
            offset: d.span.start,
            length: d.span.len(),
            fix: d.fix.as_deref().map(JsonFix::of),
        })
        .collect();
    let file = JsonFile {
        path: &report.name,
        diagnostics,
    };
    indented(&serde_json::to_string_pretty(&file).unwrap_or_default(), 4)
}

/// The entry of the JSON document for a file that could not be checked
/// (not found, unreadable, a directory, a damaged archive): its path, the
/// error, and no diagnostics, so that a reader of `files` sees it without
/// reading stderr.
pub fn json_failed(name: &str, error: &str) -> String {
    #[derive(serde::Serialize)]
    struct Failed<'a> {
        path: &'a str,
        error: &'a str,
        diagnostics: [(); 0],
    }
    let file = Failed {
        path: name,
        error,
        diagnostics: [],
    };
    indented(&serde_json::to_string_pretty(&file).unwrap_or_default(), 4)
}

/// The end of the JSON document, after `files` entries.
pub fn json_end(files: usize) -> &'static str {
    match files {
        0 => "]\n}\n",
        _ => "\n  ]\n}\n",
    }
}

/// Pretty-printed JSON moved right by `by` spaces, each line after a line
/// break (a JSON text has line breaks only between its tokens).
fn indented(json: &str, by: usize) -> String {
    let pad = " ".repeat(by);
    let mut out = String::with_capacity(json.len() + by * 8);
    for line in json.lines() {
        out.push('\n');
        out.push_str(&pad);
        out.push_str(line);
    }
    out
}

/// GitHub Actions workflow commands: one `::error file=...::message` line
/// each, which the runner shows as annotations on the changed files.
pub fn github(report: &FileReport, out: &mut String) {
    let index = LineIndex::new(report.source);
    for d in report.diagnostics {
        let start = index.position_in(d.span.start, COLUMNS);
        let end = index.position_in(d.span.end, COLUMNS);
        let level = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "notice",
        };
        out.push_str(&format!(
            "::{level} file={},line={},col={},endLine={},endColumn={},title={}::{}\n",
            printable(&escape_property(report.name)),
            start.row,
            start.column,
            end.row,
            end.column,
            escape_property(&format!("{} {}", d.code(), d.name())),
            escape_data(&d.message)
        ));
    }
}

/// Workflow-command data: `%`, CR and LF are percent-encoded.
fn escape_data(text: &str) -> String {
    text.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// Workflow-command properties: also `:` and `,`.
fn escape_property(text: &str) -> String {
    escape_data(text).replace(':', "%3A").replace(',', "%2C")
}

/// SARIF 2.1.0: one run, the rules that were found, one result each. The
/// results of each file are rendered as it comes ([`Sarif::add`]); the log
/// keeps their text and the codes found, and is written at the end, since
/// the rules stand in it after them.
#[derive(Default)]
pub struct Sarif {
    /// The results, each indented for its place and after its line break,
    /// separated by commas.
    results: String,
    codes: std::collections::BTreeSet<&'static str>,
    /// The files that could not be checked, as SARIF notifications.
    failures: Vec<serde_json::Value>,
}

impl Sarif {
    /// One file's results.
    pub fn add(&mut self, report: &Located) {
        let path = report.path.as_deref().map(crate::cli::platform::path_bytes);
        let location = artifact(path.as_deref().unwrap_or(report.name.as_bytes()));
        for (d, start, end) in report.each() {
            self.codes.insert(d.code());
            let mut result = serde_json::json!({
                "ruleId": d.code(),
                "level": level(d.severity),
                "message": { "text": match &d.help { Some(help) => format!("{} ({help})", d.message), None => d.message.clone() } },
                "locations": [{
                    "physicalLocation": {
                        "artifactLocation": location,
                        "region": { "startLine": start.row, "startColumn": start.column, "endLine": end.row, "endColumn": end.column, "byteOffset": d.span.start, "byteLength": d.span.len() }
                    }
                }],
            });
            if let Some(related) = &d.related {
                result["relatedLocations"] = serde_json::json!([{
                    "id": 1,
                    "physicalLocation": {
                        "artifactLocation": location,
                        "region": { "byteOffset": related.span.start, "byteLength": related.span.len() }
                    },
                    "message": { "text": related.message }
                }]);
            }
            if let Some(fix) = &d.fix {
                // SARIF's own fix object: byte regions replaced by text.
                let replacements: Vec<_> = fix
                    .edits
                    .iter()
                    .map(|edit| serde_json::json!({
                        "deletedRegion": { "byteOffset": edit.span.start, "byteLength": edit.span.len() },
                        "insertedContent": { "text": String::from_utf8_lossy(&edit.text) }
                    }))
                    .collect();
                result["fixes"] = serde_json::json!([{
                    "description": { "text": format!("{} ({})", fix.title, applicability(fix.applicability)) },
                    "artifactChanges": [{ "artifactLocation": location, "replacements": replacements }]
                }]);
            }
            if !self.results.is_empty() {
                self.results.push(',');
            }
            let text = serde_json::to_string_pretty(&result).unwrap_or_default();
            self.results.push_str(&indented(&text, 8));
        }
    }

    /// A file that could not be checked: a notification of the tool's
    /// execution with the file's location, and the run no success.
    pub fn failed(&mut self, name: &str, error: &str) {
        self.failures.push(serde_json::json!({
            "level": "error",
            "message": { "text": error },
            "locations": [{ "physicalLocation": { "artifactLocation": artifact(name.as_bytes()) } }],
        }));
    }

    /// Another's results after these.
    pub fn extend(&mut self, other: Sarif) {
        if !self.results.is_empty() && !other.results.is_empty() {
            self.results.push(',');
        }
        self.results.push_str(&other.results);
        self.codes.extend(other.codes);
        self.failures.extend(other.failures);
    }

    /// The log.
    pub fn finish(self) -> String {
        let rules: Vec<serde_json::Value> = self
            .codes
            .iter()
            .filter_map(|code| crate::lint::rule(code))
            .map(|info| {
                let summary = info.docs.lines().nth(1).unwrap_or_default();
                let mut rule = serde_json::json!({
                    "id": info.code,
                    "name": info.name,
                    "shortDescription": { "text": summary },
                    "fullDescription": { "text": info.docs },
                    "help": { "text": info.docs, "markdown": info.docs },
                    "defaultConfiguration": { "level": level(info.severity) },
                });
                if let Some(uri) = reference::help_uri(REPOSITORY, info) {
                    rule["helpUri"] = uri.into();
                }
                rule
            })
            .collect();
        let mut driver = serde_json::json!({ "name": "sinuprep", "version": env!("CARGO_PKG_VERSION"), "rules": rules });
        if !REPOSITORY.is_empty() {
            driver["informationUri"] = REPOSITORY.into();
        }
        let mut invocation = serde_json::json!({ "executionSuccessful": self.failures.is_empty() });
        if !self.failures.is_empty() {
            invocation["toolExecutionNotifications"] = self.failures.into();
        }
        let document = serde_json::json!({
            "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
            "version": "2.1.0",
            "runs": [{
                "tool": { "driver": driver },
                "invocations": [invocation],
                "columnKind": "utf16CodeUnits",
                "originalUriBaseIds": { SOURCE_ROOT: { "uri": working_directory() } },
                "results": [],
            }],
        });
        let mut text = serde_json::to_string_pretty(&document).unwrap_or_default();
        if !self.results.is_empty() {
            // The empty list's text: no string holds it (a quote inside a
            // string is escaped), so it is the key's.
            let empty = "\"results\": []";
            if let Some(at) = text.find(empty) {
                let filled = format!("\"results\": [{}\n      ]", self.results);
                text.replace_range(at..at + empty.len(), &filled);
            }
        }
        text.push('\n');
        text
    }
}

/// The base the relative paths of a SARIF log are read against: the
/// directory `check` ran in.
const SOURCE_ROOT: &str = "%SRCROOT%";

/// A file as a SARIF artifact location: a relative path as a relative
/// reference against [`SOURCE_ROOT`], an absolute one as a `file` URI.
/// `path` is the name's bytes as the file system holds them (not the text
/// printed for people, where a byte that is no UTF-8 became U+FFFD).
fn artifact(path: &[u8]) -> serde_json::Value {
    match uri(path, crate::cli::platform::WINDOWS_PATHS) {
        Uri::Absolute(uri) => serde_json::json!({ "uri": uri }),
        Uri::Relative(uri) => serde_json::json!({ "uri": uri, "uriBaseId": SOURCE_ROOT }),
    }
}

#[derive(Debug, PartialEq)]
enum Uri {
    Absolute(String),
    Relative(String),
}

/// A path as a URI (RFC 8089): `/a/b` as `file:///a/b`; with `windows`,
/// `\` read as `/`, `C:\CAM\PART.MPF` as `file:///C:/CAM/PART.MPF`,
/// `\\server\share\PART.MPF` as `file://server/share/PART.MPF`, and the
/// verbatim forms (`\\?\C:\...`, `\\?\UNC\server\...`) as the paths
/// they stand for. Anything else is a relative reference (`./` dropped).
/// Every byte but the unreserved characters and `/` is percent-encoded,
/// those of a name that is no UTF-8 as they are.
fn uri(path: &[u8], windows: bool) -> Uri {
    let mut path = path.to_vec();
    if windows {
        for byte in &mut path {
            if *byte == b'\\' {
                *byte = b'/';
            }
        }
        let unc = [&b"//?/UNC/"[..], b"//./UNC/"]
            .iter()
            .find_map(|prefix| path.strip_prefix(*prefix));
        let verbatim = [&b"//?/"[..], b"//./"]
            .iter()
            .find_map(|prefix| path.strip_prefix(*prefix));
        path = match (unc, verbatim) {
            (Some(server), _) => [&b"//"[..], server].concat(),
            (None, Some(local)) => local.to_vec(),
            (None, None) => path,
        };
        if let [drive, b':', rest @ ..] = &path[..] {
            if drive.is_ascii_alphabetic() && (rest.is_empty() || rest[0] == b'/') {
                return Uri::Absolute(format!(
                    "file:///{}:{}",
                    *drive as char,
                    percent_encoded(rest)
                ));
            }
        }
        if let Some(server) = path.strip_prefix(b"//") {
            return Uri::Absolute(format!("file://{}", percent_encoded(server)));
        }
    }
    if path.starts_with(b"/") {
        return Uri::Absolute(format!("file://{}", percent_encoded(&path)));
    }
    let relative = path.strip_prefix(b"./").unwrap_or(&path);
    Uri::Relative(percent_encoded(relative))
}

/// An absolute path as a `file` URI (an editor's server names other files
/// by it); `None` for a relative one.
pub(crate) fn file_uri(path: &std::path::Path) -> Option<String> {
    let bytes = crate::cli::platform::path_bytes(path);
    match uri(&bytes, crate::cli::platform::WINDOWS_PATHS) {
        Uri::Absolute(uri) => Some(uri),
        Uri::Relative(_) => None,
    }
}

/// The working directory as a `file` URI ending in `/`.
fn working_directory() -> String {
    let dir = std::env::current_dir().unwrap_or_default();
    let uri = match uri(
        &crate::cli::platform::path_bytes(&dir),
        crate::cli::platform::WINDOWS_PATHS,
    ) {
        Uri::Absolute(uri) => uri,
        // The working directory is absolute; should it not be, the root.
        Uri::Relative(_) => "file:///".to_string(),
    };
    match uri.ends_with('/') {
        true => uri,
        false => uri + "/",
    }
}

/// RFC 3986: every byte but the unreserved characters and `/` as `%XX`.
fn percent_encoded(path: &[u8]) -> String {
    let mut out = String::with_capacity(path.len());
    for &byte in path {
        if byte.is_ascii_alphanumeric() || matches!(byte, b'-' | b'.' | b'_' | b'~' | b'/') {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

fn level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    }
}

/// Findings per rule (`check --statistics`), summed over a run.
#[derive(Default)]
pub struct Statistics {
    rules: std::collections::BTreeMap<&'static str, Statistic>,
}

#[derive(Clone, Copy)]
struct Statistic {
    name: &'static str,
    count: usize,
    /// Whether `--fix` (with `--unsafe-fixes`, where given) answers any of them.
    fixable: bool,
}

impl Statistics {
    /// Counts `diagnostics`; `unsafe_fixes`: whether unsafe fixes count as fixable.
    pub fn add(&mut self, diagnostics: &[Diagnostic], unsafe_fixes: bool) {
        for d in diagnostics {
            let fixable = d
                .fix
                .as_deref()
                .is_some_and(|fix| fix.applicability == Applicability::Safe || unsafe_fixes);
            let entry = self.rules.entry(d.code()).or_insert(Statistic {
                name: d.name(),
                count: 0,
                fixable: false,
            });
            entry.count += 1;
            entry.fixable |= fixable;
        }
    }

    pub fn extend(&mut self, other: Statistics) {
        for (code, theirs) in other.rules {
            let ours = self.rules.entry(code).or_insert(Statistic {
                count: 0,
                fixable: false,
                ..theirs
            });
            ours.count += theirs.count;
            ours.fixable |= theirs.fixable;
        }
    }

    /// The most frequent first, then by code.
    fn sorted(&self) -> Vec<(&'static str, Statistic)> {
        let mut rules: Vec<_> = self.rules.iter().map(|(&c, &s)| (c, s)).collect();
        rules.sort_by(|a, b| b.1.count.cmp(&a.1.count).then(a.0.cmp(b.0)));
        rules
    }

    /// One line a rule, as ruff prints them: the count, the code, `[*]`
    /// where `--fix` answers some of its findings (`[ ]` where it answers
    /// none; no column when no rule is fixable), the rule's name.
    pub fn text(&self) -> String {
        let rules = self.sorted();
        let count_width = rules
            .iter()
            .map(|(_, s)| s.count.to_string().len())
            .max()
            .unwrap_or(0);
        let code_width = rules.iter().map(|(c, _)| c.len()).max().unwrap_or(0);
        let any_fixable = rules.iter().any(|(_, s)| s.fixable);
        let mut out = String::new();
        for (code, s) in rules {
            let mark = match (any_fixable, s.fixable) {
                (false, _) => "",
                (true, true) => "[*] ",
                (true, false) => "[ ] ",
            };
            out.push_str(&format!(
                "{:>count_width$}\t{code:<code_width$}\t{mark}{}\n",
                s.count, s.name
            ));
        }
        out
    }

    /// The table in `format`: JSON for `json`, text for the others.
    pub fn render(&self, format: crate::cli::args::Format) -> String {
        match format {
            crate::cli::args::Format::Json => self.json(),
            _ => self.text(),
        }
    }

    /// A JSON array of `{code, name, count, fixable}`, as ruff's.
    pub fn json(&self) -> String {
        let rules: Vec<_> = self
            .sorted()
            .into_iter()
            .map(|(code, s)| {
                serde_json::json!({ "code": code, "name": s.name, "count": s.count, "fixable": s.fixable })
            })
            .collect();
        let mut text = serde_json::to_string_pretty(&rules).unwrap_or_default();
        text.push('\n');
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn absolute(uri: &str) -> Uri {
        Uri::Absolute(uri.to_string())
    }

    fn relative(uri: &str) -> Uri {
        Uri::Relative(uri.to_string())
    }

    #[test]
    fn unix_paths_are_file_uris_or_relative_references() {
        assert_eq!(
            uri(b"/home/cam/OUT/PART 1.MPF", false),
            absolute("file:///home/cam/OUT/PART%201.MPF")
        );
        assert_eq!(uri(b"./OUT/PART.MPF", false), relative("OUT/PART.MPF"));
        assert_eq!(uri(b"OUT/PART.MPF", false), relative("OUT/PART.MPF"));
        // On Unix a backslash and a colon are a name's own characters.
        assert_eq!(uri(b"C:\\PART.MPF", false), relative("C%3A%5CPART.MPF"));
    }

    #[test]
    fn a_name_that_is_no_utf8_keeps_its_bytes() {
        // `Kühl.MPF` saved in Latin-1: ü is the byte 0xFC, not U+FFFD.
        assert_eq!(uri(b"K\xfchl.MPF", false), relative("K%FChl.MPF"));
        assert_eq!(
            uri("/cam/Kühl.MPF".as_bytes(), false),
            absolute("file:///cam/K%C3%BChl.MPF")
        );
    }

    #[test]
    fn windows_paths_are_file_uris_with_their_drive_or_server() {
        assert_eq!(
            uri(b"C:\\CAM\\OUT\\PART.MPF", true),
            absolute("file:///C:/CAM/OUT/PART.MPF")
        );
        assert_eq!(
            uri(b"d:/CAM/PART.MPF", true),
            absolute("file:///d:/CAM/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\server\\share\\OUT\\PART.MPF", true),
            absolute("file://server/share/OUT/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\?\\C:\\CAM\\PART.MPF", true),
            absolute("file:///C:/CAM/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\?\\UNC\\server\\share\\PART.MPF", true),
            absolute("file://server/share/PART.MPF")
        );
        assert_eq!(uri(b"OUT\\PART 2.MPF", true), relative("OUT/PART%202.MPF"));
        assert_eq!(uri(b".\\PART.MPF", true), relative("PART.MPF"));
    }
}
