//! SARIF 2.1.0, for code-scanning tools.

use super::emitter::{Emitter, Program};
use super::{indented, Located};
use crate::diagnostic::{Applicability, Severity};
use crate::lint::reference::{self, REPOSITORY};
use crate::uri::{uri, Uri};

/// `check --output-format sarif`: the log, written at the end.
pub struct SarifEmitter;

impl Emitter for SarifEmitter {
    type Part = Sarif;
    type Kept = Sarif;

    fn add(&self, part: &mut Sarif, program: Program) {
        let located = Located::new(program.name, program.source, program.diagnostics);
        part.add(&located.at(program.path));
    }

    fn write(
        &self,
        log: &mut Sarif,
        part: Sarif,
        _: &mut dyn std::io::Write,
    ) -> std::io::Result<()> {
        log.extend(part);
        Ok(())
    }

    fn failed(
        &self,
        log: &mut Sarif,
        name: &str,
        error: &str,
        _: &mut dyn std::io::Write,
    ) -> std::io::Result<()> {
        log.failed(name, error);
        Ok(())
    }

    fn end(&self, log: Sarif, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        out.write_all(log.finish().as_bytes())
    }

    fn names_archives(&self) -> bool {
        true
    }
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
        let path = report.path.as_deref().map(crate::uri::path_bytes);
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
    match uri(path, crate::uri::WINDOWS_PATHS) {
        Uri::Absolute(uri) => serde_json::json!({ "uri": uri }),
        Uri::Relative(uri) => serde_json::json!({ "uri": uri, "uriBaseId": SOURCE_ROOT }),
    }
}

/// The working directory as a `file` URI ending in `/`.
fn working_directory() -> String {
    let dir = std::env::current_dir().unwrap_or_default();
    let uri = match uri(&crate::uri::path_bytes(&dir), crate::uri::WINDOWS_PATHS) {
        Uri::Absolute(uri) => uri,
        // The working directory is absolute; should it not be, the root.
        Uri::Relative(_) => "file:///".to_string(),
    };
    match uri.ends_with('/') {
        true => uri,
        false => uri + "/",
    }
}

fn level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    }
}

fn applicability(applicability: Applicability) -> &'static str {
    match applicability {
        Applicability::Safe => "safe",
        Applicability::Unsafe => "unsafe",
    }
}
