//! `sinuprep check`: parse every program named and report its diagnostics.

use std::io::IsTerminal;

use crate::cli::args::{CheckArgs, Format};
use crate::cli::error::CliError;
use crate::cli::input::{expand, read, SourceFile};
use crate::cli::render::{human, json, short, FileReport};
use crate::cli::{write_stdout, ExitStatus};
use crate::diagnostic::{Diagnostic, Severity};
use crate::syntax;

pub fn run(args: &CheckArgs) -> Result<ExitStatus, CliError> {
    let mut checked: Vec<(SourceFile, Vec<Diagnostic>)> = Vec::new();
    let mut failed = false;
    for path in expand(&args.paths) {
        match path.and_then(|path| read(&path)) {
            Ok(file) => {
                let diagnostics = syntax::diagnostics(&file.bytes);
                checked.push((file, diagnostics));
            }
            Err(error) => {
                failed = true;
                eprintln!("{:?}", miette::Report::new(error));
            }
        }
    }
    let reports: Vec<FileReport> = checked
        .iter()
        .map(|(file, diagnostics)| FileReport {
            name: &file.name,
            source: &file.bytes,
            diagnostics,
        })
        .collect();

    let mut out = String::new();
    match args.format {
        Format::Json => out = json(&reports),
        Format::Short => reports.iter().for_each(|r| short(r, &mut out)),
        Format::Human => {
            let colour = std::io::stdout().is_terminal();
            reports.iter().for_each(|r| human(r, colour, &mut out));
        }
    }
    write_stdout(out.as_bytes())?;

    let has_error = reports
        .iter()
        .flat_map(|r| r.diagnostics)
        .any(|d| d.severity == Severity::Error);
    Ok(if failed {
        ExitStatus::Error
    } else if has_error {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    })
}
