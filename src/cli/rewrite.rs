//! `sinuprep rewrite`: CYCLE600 calls become native code; every other byte
//! stays. A call that cannot be evaluated stays as it was, with a diagnostic.
//! Several programs (or directories) are rewritten on all cores, each on its
//! own: one that fails never stops the others, and the exit status is the
//! worst of them.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::archive::Form;
use crate::cli::analysis;
use crate::cli::args::RewriteArgs;
use crate::cli::error::CliError;
use crate::cli::input::{binary, named_or_here, named_or_stdin, read, skip_binary, Found};
use crate::cli::output::{in_place_target, same_file, write_atomically, write_inside};
use crate::cli::parallel;
use crate::cli::render::printable;
use crate::cli::walk::files;
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};
use crate::document::archive::Opened;
use crate::emit::{diff, write_applied};
use crate::semantic::swivels::OnMachine;
use crate::workspace::{Given, Workspace};

/// Where a program's rewrite goes.
enum Target {
    Stdout,
    /// The file `-o` names for one program.
    File(PathBuf),
    /// The program's mirror under the folder `-o DIR` names for several:
    /// the folder and the path inside it, written through no link.
    Inside(PathBuf, PathBuf),
    /// The program itself (canonical path).
    InPlace(PathBuf),
}

/// What one program's rewrite printed, kept so that the programs' outputs
/// come in their order whatever thread did the work.
struct Outcome {
    status: ExitStatus,
    stdout: Vec<u8>,
    stderr: String,
    /// The machine the axes comments were solved on, whose findings the run
    /// tells once.
    machine: Option<Arc<OnMachine>>,
}

pub fn run(args: &RewriteArgs) -> Result<ExitStatus, CliError> {
    // Writing files or checking them takes the current folder; to stdout,
    // a filter reads stdin.
    let named = if args.check || args.in_place || args.diff || args.output.is_some() {
        named_or_here(&args.paths)
    } else {
        named_or_stdin(&args.paths, "rewrite")?
    };
    let workspace = Workspace::new(Given {
        machine: args.machine.clone(),
        table: args.table.clone(),
        follow_links: args.walk.follow_links,
        fine_offsets: args.fine_offsets,
        walk: args.walk.given(),
        ..analysis::given_to_rewrite(&args.analysis)
    })?;
    // Known before the walk: one file named, or more than one path (or a
    // folder), whose rewrites cannot all go to one stdout or one `-o` file.
    let several = named.len() > 1 || named.iter().any(|p| p.is_dir());
    let writes_files = args.in_place || args.check || args.diff || args.output.is_some();
    if several && !writes_files {
        let named = match named.iter().find(|p| p.is_dir()) {
            Some(folder) if named.len() == 1 => {
                format!("the folder {}", printable(&folder.display().to_string()))
            }
            _ => format!("{} paths", named.len()),
        };
        return Err(CliError::SeveralToStdout { named });
    }
    let walk = args.walk.walk(&workspace);
    let mut files = files(&named, &walk);
    let mut worst = ExitStatus::Success;
    let work = |found: Result<Found, CliError>| {
        found
            .and_then(|found| rewrite_file(&found, args, &workspace, several))
            .unwrap_or_else(|error| failed(format!("{:?}", miette::Report::new(error))))
    };
    // Each program's messages as soon as it and those before it are done.
    let mut told = analysis::MachinesTold::default();
    parallel::each(&mut files, work, |outcome| {
        let format = args.analysis.message_format;
        worst = worst.max(told.tell(outcome.machine.as_deref(), format));
        tell!("{}", outcome.stderr);
        write_stdout(&outcome.stdout)?;
        worst = worst.max(outcome.status);
        Ok::<(), CliError>(())
    })?;
    files.end()?;
    Ok(worst)
}

/// A program that could not be rewritten at all (exit 2).
fn failed(message: String) -> Outcome {
    Outcome {
        status: ExitStatus::Error,
        stdout: Vec::new(),
        stderr: format!("{message}\n"),
        machine: None,
    }
}

/// Where `path`'s rewrite goes, refused before anything is read when it
/// cannot be written in place (stdin, a FIFO, a device).
fn target(path: &Path, args: &RewriteArgs, several: bool) -> Result<Target, CliError> {
    // `-o` naming the program itself is a rewrite in place, with its rules.
    let onto_itself = !several
        && args
            .output
            .as_deref()
            .is_some_and(|output| path != Path::new("-") && same_file(path, output));
    if args.in_place || onto_itself {
        return Ok(Target::InPlace(in_place_target(path)?));
    }
    Ok(match &args.output {
        Some(dir) if several => Target::Inside(dir.clone(), mirror(&args.paths, path)),
        Some(file) => Target::File(file.clone()),
        None => Target::Stdout,
    })
}

/// Where `path` lies under the output folder: as it lies under the
/// directory given for it (a file given by itself lands directly in it).
fn mirror(given: &[PathBuf], path: &Path) -> PathBuf {
    given
        .iter()
        .filter(|root| root.is_dir())
        .find_map(|root| path.strip_prefix(root).ok())
        .map(Path::to_path_buf)
        .or_else(|| path.file_name().map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("-"))
}

fn rewrite_file(
    found: &Found,
    args: &RewriteArgs,
    workspace: &Workspace,
    several: bool,
) -> Result<Outcome, CliError> {
    let path = found.path.as_path();
    let target = target(path, args, several)?;
    let file = read(found)?;
    if binary(&file.bytes) {
        return Ok(Outcome {
            status: ExitStatus::Success,
            stdout: Vec::new(),
            stderr: skip_binary(found, &file.name, &file.bytes)?,
            machine: None,
        });
    }
    let resolved = workspace.for_rewrite(path)?;
    let mut settings = resolved.settings;
    settings.machine = workspace.machine(&resolved.config)?;
    settings.emit.keep_original = !args.no_original;
    settings.emit.inline_results = args.inline_results;
    let opened = Opened::read(&file.bytes, &file.name)
        .map_err(|error| CliError::archive(&file.name, error))?;
    opened.settings(&file.bytes, &mut settings);
    let mut outcome = Outcome {
        status: ExitStatus::Success,
        stdout: Vec::new(),
        stderr: opened.unchecked(&file.bytes).unwrap_or_default(),
        machine: settings.machine.clone(),
    };
    // Every program's edits, as edits of the file (an archive's member's
    // shifted to where it lies, its header made to match).
    let mut edits = Vec::new();
    let mut rewritten = 0;
    let mut errors = false;
    for program in opened.programs(&file.bytes) {
        let analyzed = program.document.rewrite(&settings);
        let source = program.document.source;
        let format = args.analysis.message_format;
        outcome.stderr += &analysis::report(&analyzed, &program.name, source, format);
        errors |= analyzed.has_errors();
        let own = &analyzed.rewrite.edits;
        if own.is_empty() {
            continue;
        }
        rewritten += analyzed.rewrite.rewritten;
        let shifted = match (&opened.archive, program.member) {
            (Some(archive), Some(member)) => {
                if args.diff && archive.form == Form::Binary {
                    // A binary archive's diff is its members' own.
                    outcome
                        .stdout
                        .extend(diff::unified(&program.name, source, own).into_bytes());
                }
                archive.edits(&file.bytes, member, own)
            }
            _ => Some(own.clone()),
        };
        match shifted {
            Some(shifted) => edits.extend(shifted),
            None => {
                errors = true;
                outcome.stderr.push_str(&format!(
                    "{}: not rewritten: its new size does not fit the archive's header\n",
                    printable(&program.name)
                ));
            }
        }
    }
    outcome.status = status(errors);
    let changed = !edits.is_empty();
    if args.check {
        if changed {
            outcome.stderr.push_str(&format!(
                "{}: would rewrite {rewritten} CYCLE600 call{}\n",
                printable(&file.name),
                if rewritten == 1 { "" } else { "s" }
            ));
        }
        outcome.status = status(errors || changed);
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
        Target::InPlace(target) => {
            if errors {
                outcome.stderr.push_str(&format!(
                    "{}: not rewritten in place, because of the errors above\n",
                    printable(&file.name)
                ));
                return Ok(outcome);
            }
            if changed {
                // The backup holds the bytes this run read and rewrote.
                let backup = (!args.no_backup).then_some(&file.bytes[..]);
                write_atomically(&target, output, backup)?;
            }
        }
        Target::Inside(dir, relative) => write_inside(&dir, &relative, output)?,
        Target::File(path) => {
            if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
                std::fs::create_dir_all(parent).map_err(|source| CliError::WriteFile {
                    path: path.clone(),
                    source,
                })?;
            }
            write_atomically(&path, output, None)?;
        }
        // One program: several are refused before any is read.
        Target::Stdout => write_stdout_with(output)?,
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
