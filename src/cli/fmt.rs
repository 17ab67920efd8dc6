//! `sinuprep fmt`: programs laid out, their words' case set and (asked
//! for) their blocks renumbered, in place by default, with the writes of
//! `rewrite --in-place` (a temporary file beside the target, renamed over
//! it); `-` from stdin to stdout. A program with syntax errors is left as
//! it is and its errors are said. An archive's members are formatted as
//! edits of the archive, its headers' sizes and checksums made to match.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::archive::Form;
use crate::cli::args::FmtArgs;
use crate::cli::error::CliError;
use crate::cli::input::{binary, named_or_here, read, skip_binary, Found};
use crate::cli::output::{in_place_target, write_atomically};
use crate::cli::parallel;
use crate::cli::render::{human, printable, FileReport};
use crate::cli::walk::files;
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};
use crate::document::archive::Opened;
use crate::edit::write_applied;
use crate::emit::diff;
use crate::format::{format, format_merged};
use crate::span::LineIndex;
use crate::workspace::{Given, Workspace};

/// What one file's formatting printed, kept so that the files' outputs
/// come in their order whatever thread did the work.
struct Outcome {
    status: ExitStatus,
    stdout: Vec<u8>,
    stderr: String,
}

pub fn run(args: &FmtArgs) -> Result<ExitStatus, CliError> {
    let named = named_or_here(&args.paths);
    let workspace = Workspace::new(Given {
        config: args.config.clone(),
        follow_links: args.walk.follow_links,
        walk: args.walk.given(),
        ..Given::default()
    })?;
    let walk = args.walk.walk(&workspace);
    let mut files = files(&named, &walk);
    let mut worst = ExitStatus::Success;
    let work = |found: Result<Found, CliError>| {
        found
            .and_then(|found| format_file(&found, args, &workspace))
            .unwrap_or_else(|error| failed(format!("{:?}", miette::Report::new(error))))
    };
    parallel::each(&mut files, work, |outcome| {
        tell!("{}", outcome.stderr);
        write_stdout(&outcome.stdout)?;
        worst = worst.max(outcome.status);
        Ok::<(), CliError>(())
    })?;
    files.end()?;
    Ok(worst)
}

fn failed(message: String) -> Outcome {
    Outcome {
        status: ExitStatus::Error,
        stdout: Vec::new(),
        stderr: format!("{message}\n"),
    }
}

fn format_file(found: &Found, args: &FmtArgs, workspace: &Workspace) -> Result<Outcome, CliError> {
    let path = found.path.as_path();
    let stdin = path == Path::new("-");
    let writes = !stdin && !args.check && !args.diff;
    // Refused before anything is read when it cannot be written in place.
    let target: Option<PathBuf> = if writes {
        Some(in_place_target(path)?)
    } else {
        None
    };
    let file = read(found)?;
    let mut outcome = Outcome {
        status: ExitStatus::Success,
        stdout: Vec::new(),
        stderr: String::new(),
    };
    if binary(&file.bytes) {
        outcome.stderr = skip_binary(found, &file.name, &file.bytes)?;
        return Ok(outcome);
    }
    let mut settings = workspace.for_format(path)?;
    settings.renumber = args.renumber;
    let opened = Opened::read(&file.bytes, &file.name)
        .map_err(|error| CliError::archive(&file.name, error))?;
    let mut edits = Vec::new();
    let mut findings = false;
    for program in opened.programs(&file.bytes) {
        let source = program.document.source;
        // Merged edits for a file written whole; a diff shows lines.
        let format = if args.diff { format } else { format_merged };
        let formatted = format(
            program.document.name,
            source,
            program.document.kind,
            &settings,
        );
        if !formatted.syntax.is_empty() {
            findings = true;
            let report = FileReport {
                name: &program.name,
                source,
                diagnostics: &formatted.syntax,
            };
            let mut text = String::new();
            use std::io::IsTerminal;
            human(
                &report,
                crate::cli::colour(std::io::stderr().is_terminal()),
                &mut text,
            );
            outcome.stderr += &text;
            outcome.stderr += &format!(
                "{}: not formatted, because of the syntax errors above\n",
                printable(&program.name)
            );
        }
        let index = LineIndex::new(source);
        for note in &formatted.notes {
            findings |= note.refused;
            let name = printable(&program.name);
            // A note on the whole file has an empty span at its start.
            let place = if note.span.is_empty() && note.span.start == 0 {
                name.to_string()
            } else {
                let at = index.position(note.span.start);
                format!("{name}:{}:{}", at.row, at.column)
            };
            outcome.stderr += &format!("{place}: note: {}\n", note.message);
        }
        let own = formatted.edits;
        if own.is_empty() {
            continue;
        }
        let shifted = match (&opened.archive, program.member) {
            (Some(archive), Some(member)) => {
                if args.diff && archive.form == Form::Binary {
                    // A binary archive's diff is its members' own.
                    outcome
                        .stdout
                        .extend(diff::unified(&program.name, source, &own).into_bytes());
                }
                archive.edits(&file.bytes, member, &own)
            }
            _ => Some(own),
        };
        match shifted {
            Some(shifted) => edits.extend(shifted),
            None => {
                findings = true;
                outcome.stderr += &format!(
                    "{}: not formatted: its new size does not fit the archive's header\n",
                    printable(&program.name)
                );
            }
        }
    }
    let changed = !edits.is_empty();
    outcome.status = status(findings);
    if args.check {
        if changed {
            // The files that would change are the command's data.
            outcome.stdout = format!("{}\n", printable(&file.name)).into_bytes();
        }
        outcome.status = status(findings || changed);
        return Ok(outcome);
    }
    if args.diff {
        if opened.archive.as_ref().is_none_or(|a| a.form == Form::Text) {
            outcome.stdout = diff::unified(&file.name, &file.bytes, &edits).into_bytes();
        }
        return Ok(outcome);
    }
    let output = |out: &mut dyn Write| write_applied(&file.bytes, &edits, out);
    match target {
        Some(target) if changed => write_atomically(&target, output, None)?,
        Some(_) => {}
        None => write_stdout_with(output)?,
    }
    Ok(outcome)
}

fn status(failure: bool) -> ExitStatus {
    if failure {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    }
}

/// `START,STEP` of `--renumber` (`10,10`; a lone `START` steps by 10).
pub fn renumbering(text: &str) -> Result<(u64, u64), String> {
    let (start, step) = text.split_once(',').unwrap_or((text, "10"));
    let number = |t: &str| {
        t.trim()
            .parse::<u64>()
            .map_err(|_| format!("`{t}` is no whole number: write START,STEP as `10,10`"))
    };
    let (start, step) = (number(start)?, number(step)?);
    if step == 0 {
        return Err("a step of 0 would give every block one number".to_string());
    }
    Ok((start, step))
}
