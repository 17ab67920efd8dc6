//! Diagnostics rendered in every format `check` (and `run`) prints, one
//! file a format: for people (miette, [`human`]), for problem matchers
//! ([`short`]), for GitHub Actions ([`github`]), for tools ([`json`],
//! schema in docs/guide.md; [`sarif`], SARIF 2.1.0) and the findings
//! counted per rule ([`statistics`]); each with the [`Emitter`] `check`
//! writes its report through. What they share is here: the columns they
//! count, a file's findings and their positions.

mod emitter;
mod github;
mod human;
mod json;
mod sarif;
mod short;
mod statistics;

pub use emitter::{Emitter, Program};
pub use github::GithubEmitter;
pub use human::{human, HumanEmitter};
pub use json::JsonEmitter;
pub use sarif::{Sarif, SarifEmitter};
pub use short::{short, ShortEmitter};
pub use statistics::StatisticsEmitter;

use crate::diagnostic::Diagnostic;
use crate::span::{ColumnUnit, LineIndex, Position};

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

    pub(super) fn each(&self) -> impl Iterator<Item = (&Diagnostic, Position, Position)> {
        self.diagnostics
            .iter()
            .zip(&self.positions)
            .map(|(d, &(start, end))| (d, start, end))
    }
}

/// Pretty-printed JSON moved right by `by` spaces, each line after a line
/// break (a JSON text has line breaks only between its tokens).
pub(super) fn indented(json: &str, by: usize) -> String {
    let pad = " ".repeat(by);
    let mut out = String::with_capacity(json.len() + by * 8);
    for line in json.lines() {
        out.push('\n');
        out.push_str(&pad);
        out.push_str(line);
    }
    out
}
