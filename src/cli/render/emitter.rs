//! How `check` writes its report: one [`Emitter`] a format, each in the
//! format's own file, chosen once a run (as ruff's emitters are).

use std::io::{self, Write};
use std::path::Path;

use super::FileReport;
use crate::diagnostic::Diagnostic;

/// One program's findings, as `check` hands them to an [`Emitter`].
pub struct Program<'a> {
    /// The name the report gives it.
    pub name: &'a str,
    /// The file's own path, where the program is a file (SARIF names a
    /// file by its bytes, which may not be UTF-8).
    pub path: Option<&'a Path>,
    pub source: &'a [u8],
    pub diagnostics: Vec<Diagnostic>,
}

impl Program<'_> {
    pub fn file_report(&self) -> FileReport<'_> {
        FileReport {
            name: self.name,
            source: self.source,
            diagnostics: &self.diagnostics,
        }
    }
}

/// A format of `check`'s report. Each file's part is made on the worker
/// that checked it, while its source is at hand ([`Emitter::add`]), and
/// the parts are written in the files' order ([`Emitter::write`]). A
/// format that is one document (JSON, SARIF, the statistics) keeps what it
/// needs from part to part and writes what wraps them at the start and the
/// end.
pub trait Emitter: Sync {
    /// A file's part: its text, or what the end writes.
    type Part: Send + Default;
    /// What is kept from part to part, until the end.
    type Kept: Default;

    /// Writes what comes before the first file's part.
    fn start(&self, _out: &mut dyn Write) -> io::Result<()> {
        Ok(())
    }

    /// Adds a program's findings to its file's part.
    fn add(&self, part: &mut Self::Part, program: Program);

    /// Writes a file's part, or keeps it for the end.
    fn write(&self, kept: &mut Self::Kept, part: Self::Part, out: &mut dyn Write)
        -> io::Result<()>;

    /// A file that could not be checked, `error` saying why: an entry of
    /// a document; nothing where the error on stderr is all (the formats
    /// for people and for annotations).
    fn failed(
        &self,
        _kept: &mut Self::Kept,
        _name: &str,
        _error: &str,
        _out: &mut dyn Write,
    ) -> io::Result<()> {
        Ok(())
    }

    /// Writes what comes after the last file's part.
    fn end(&self, _kept: Self::Kept, _out: &mut dyn Write) -> io::Result<()> {
        Ok(())
    }

    /// An archive's programs are named by the archive and their findings
    /// placed on its lines: what code scanning and GitHub's annotations
    /// open is the file named.
    fn names_archives(&self) -> bool {
        false
    }

    /// Read by people at a terminal: the run's summary follows on stderr.
    fn for_people(&self) -> bool {
        false
    }
}

/// A format whose part of a file is text, written as it comes (human,
/// short, GitHub): all it says is how a program's findings read.
pub trait TextFormat: Sync {
    fn render(&self, report: &FileReport, out: &mut String);

    /// As [`Emitter::names_archives`].
    fn names_archives(&self) -> bool {
        false
    }

    /// As [`Emitter::for_people`].
    fn for_people(&self) -> bool {
        false
    }
}

impl<T: TextFormat> Emitter for T {
    type Part = String;
    type Kept = ();

    fn add(&self, part: &mut String, program: Program) {
        self.render(&program.file_report(), part);
    }

    fn write(&self, _: &mut (), part: String, out: &mut dyn Write) -> io::Result<()> {
        out.write_all(part.as_bytes())
    }

    fn names_archives(&self) -> bool {
        TextFormat::names_archives(self)
    }

    fn for_people(&self) -> bool {
        TextFormat::for_people(self)
    }
}
