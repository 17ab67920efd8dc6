//! `sinuprep check`: lint every program named, in parallel, and report in a
//! stable order.

use std::collections::HashMap;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::cli::analysis::Inputs;
use crate::cli::args::{CheckArgs, Format};
use crate::cli::config::Config;
use crate::cli::error::CliError;
use crate::cli::input::{expand, read, Bytes, SourceFile};
use crate::cli::output::{in_place_target, write_atomically};
use crate::cli::parallel;
use crate::cli::render::{github, human, json, sarif, short, FileReport, Located};
use crate::cli::{write_stdout, ExitStatus};
use crate::diagnostic::{Diagnostic, Severity};
use crate::document::Document;
use crate::edit::apply;
use crate::lint::{self, Selection};
use crate::semantic::Environment;
use crate::syntax::program_kind;

/// One file's outcome, with what its report needs of the source taken out
/// in the worker: the source is dropped as soon as its file is checked, so
/// checking a directory holds the findings, not every file.
struct Checked {
    report: Report,
    fails: bool,
    counts: Counts,
}

/// Findings by severity, for the summary line.
#[derive(Default, Clone, Copy)]
struct Counts {
    errors: usize,
    warnings: usize,
    infos: usize,
}

impl Counts {
    fn of(diagnostics: &[Diagnostic]) -> Self {
        let count = |severity| {
            diagnostics
                .iter()
                .filter(|d| d.severity == severity)
                .count()
        };
        Self {
            errors: count(Severity::Error),
            warnings: count(Severity::Warning),
            infos: count(Severity::Info),
        }
    }

    fn add(&mut self, other: Counts) {
        self.errors += other.errors;
        self.warnings += other.warnings;
        self.infos += other.infos;
    }

    /// `3 errors, 2 warnings in 5 files`, as ruff and clippy sum up.
    fn summary(self, files: usize) -> String {
        let plural = |n: usize, word: &str| match n {
            1 => format!("1 {word}"),
            n => format!("{n} {word}s"),
        };
        let parts: Vec<String> = [
            (self.errors, "error"),
            (self.warnings, "warning"),
            (self.infos, "info"),
        ]
        .into_iter()
        .filter(|&(n, _)| n > 0)
        .map(|(n, word)| plural(n, word))
        .collect();
        let found = if parts.is_empty() {
            "no findings".to_string()
        } else {
            parts.join(", ")
        };
        format!("{found} in {}", plural(files, "file"))
    }
}

enum Report {
    /// The file's part of a per-file format (short, GitHub, human).
    Text(String),
    /// For the whole-run formats (JSON, SARIF).
    Located(Located),
}

pub fn run(args: &CheckArgs) -> Result<ExitStatus, CliError> {
    codes(&args.select, "--select")?;
    codes(&args.ignore, "--ignore")?;
    let paths = expand(&args.paths, args.allow_empty)?;
    let definitions = Definitions::default();
    let colour = std::io::stdout().is_terminal();
    let results = parallel::each(paths.len(), |index| match &paths[index] {
        Ok(path) => check_file(path, args, colour, &definitions),
        Err(error) => Err(CliError::Read {
            path: PathBuf::new(),
            source: std::io::Error::other(error.to_string()),
        }),
    });

    let mut failed = false;
    let mut fails = false;
    let mut text = String::new();
    let mut located = Vec::new();
    let mut counts = Counts::default();
    let mut files = 0;
    for result in results {
        match result {
            Ok(checked) => {
                fails |= checked.fails;
                counts.add(checked.counts);
                files += 1;
                match checked.report {
                    // One file's report (the common case) is taken, not copied.
                    Report::Text(part) if text.is_empty() => text = part,
                    Report::Text(part) => text.push_str(&part),
                    Report::Located(file) => located.push(file),
                }
            }
            Err(error) => {
                failed = true;
                eprintln!("{:?}", miette::Report::new(error));
            }
        }
    }
    let out = match args.format {
        Format::Json => json(&located),
        Format::Sarif => sarif(&located),
        Format::Short | Format::Github | Format::Human => text,
    };
    write_stdout(out.as_bytes())?;
    // For people: on stderr, so that what tools read stays the findings.
    if matches!(args.format, Format::Human | Format::Short) && !args.quiet {
        eprintln!("{}", counts.summary(files));
    }

    Ok(if failed {
        ExitStatus::Error
    } else if fails {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    })
}

fn check_file(
    path: &Path,
    args: &CheckArgs,
    colour: bool,
    definitions: &Definitions,
) -> Result<Checked, CliError> {
    // Refused before anything is read: stdin, a FIFO, a device.
    let fix_target = args.fix.then(|| in_place_target(path)).transpose()?;
    let mut file = read(path)?;
    // stdin with --stdin-filename: report and look things up as that file.
    let named = match (&args.stdin_filename, path == Path::new("-")) {
        (Some(name), true) => {
            file.name = name.display().to_string();
            name.clone()
        }
        _ => path.to_path_buf(),
    };
    let lookup = if named == Path::new("-") {
        PathBuf::from(".")
    } else {
        named.clone()
    };
    let config = Config::find(args.input.config.as_deref(), &lookup)?;
    let inputs = Inputs::load(&args.input, &config, &named)?;
    let in_config = |what: &str| format!("{} ({what})", config.describe());
    // A list on the command line replaces the file's (both are checked).
    let list = |given: &[String], flag: &str, file: &Option<Vec<String>>, key: &str| {
        let from_file = codes(file.as_deref().unwrap_or_default(), &in_config(key))?;
        if given.is_empty() {
            Ok(from_file)
        } else {
            codes(given, flag)
        }
    };
    let selection = Selection {
        select: list(&args.select, "--select", &config.select, "select")?,
        ignore: list(&args.ignore, "--ignore", &config.ignore, "ignore")?,
        severity_min: args
            .severity_min
            .or(config.severity_min)
            .map_or(Severity::Info, Severity::from),
    };
    let kind = program_kind(Some(&file.name), &file.bytes);
    let settings = lint::Settings {
        selection,
        supplied: inputs.supplied,
        heads: inputs.heads,
        environment: environment(args, &config, definitions)?,
    };
    let check = |source: &[u8]| {
        let document = Document {
            name: &file.name,
            source,
            kind,
        };
        document.check(&settings)
    };
    let mut diagnostics = check(&file.bytes);
    if let Some(target) = fix_target {
        if let Some(fixed) = fix(&target, &file, &diagnostics, args.unsafe_fixes)? {
            diagnostics = check(&fixed);
            file.bytes = Bytes::Read(fixed);
        }
    }
    let deny_warnings = args.deny_warnings || config.deny_warnings == Some(true);
    let counts = Counts::of(&diagnostics);
    let fails = diagnostics.iter().any(|d| {
        d.severity == Severity::Error || (deny_warnings && d.severity == Severity::Warning)
    });
    let file_report = FileReport {
        name: &file.name,
        source: &file.bytes,
        diagnostics: &diagnostics,
    };
    let mut text = String::new();
    match args.format {
        Format::Short => short(&file_report, &mut text),
        Format::Github => github(&file_report, &mut text),
        Format::Human => human(&file_report, colour, &mut text),
        Format::Json | Format::Sarif => {
            let report = Report::Located(Located::new(&file.name, &file.bytes, diagnostics));
            return Ok(Checked {
                report,
                fails,
                counts,
            });
        }
    }
    Ok(Checked {
        report: Report::Text(text),
        fails,
        counts,
    })
}

/// The machine's names: axes from sinuprep.toml, globals and macros from
/// the definition files of the command line (or else of sinuprep.toml).
/// The definition files are read once a run for all programs that name
/// the same ones (`read`), not once a program.
fn environment(
    args: &CheckArgs,
    config: &Config,
    read: &Definitions,
) -> Result<Environment, CliError> {
    let files: Vec<PathBuf> = if args.definitions.is_empty() {
        let listed = config.definitions.iter().flatten();
        listed.map(|path| config.resolve(path)).collect()
    } else {
        args.definitions.clone()
    };
    let known = read.lock().ok().and_then(|r| r.get(&files).cloned());
    let mut environment = match known {
        Some(environment) => environment,
        None => {
            let environment = definitions(&files)?;
            if let Ok(mut read) = read.lock() {
                read.insert(files, environment.clone());
            }
            environment
        }
    };
    environment.axes = Environment::with_axes(config.axes.iter().flatten()).axes;
    Ok(environment)
}

/// Definition files read so far, by the list of files.
type Definitions = Mutex<HashMap<Vec<PathBuf>, Environment>>;

/// What the definition files `files` define.
fn definitions(files: &[PathBuf]) -> Result<Environment, CliError> {
    let mut environment = Environment::default();
    for path in files.iter().cloned() {
        let bytes = std::fs::read(&path).map_err(|source| CliError::Read {
            path: path.clone(),
            source,
        })?;
        if let Err(errors) = environment.read_definitions(&bytes) {
            let Some(first) = errors.first() else {
                continue;
            };
            let position = crate::span::LineIndex::new(&bytes).position(first.span.start);
            return Err(CliError::Definitions {
                path,
                line: position.row,
                column: position.column,
                why: first.message.clone(),
            });
        }
    }
    Ok(environment)
}

/// Applies the fixes `--fix` takes to `file` and writes it to `target`
/// atomically: the fixed bytes, or `None` when there was nothing to fix or
/// the file has syntax errors (its trees may not be what was meant).
fn fix(
    target: &Path,
    file: &SourceFile,
    diagnostics: &[Diagnostic],
    unsafe_fixes: bool,
) -> Result<Option<Vec<u8>>, CliError> {
    let (edits, answered) = lint::fix::applicable(diagnostics, unsafe_fixes);
    if edits.is_empty() {
        return Ok(None);
    }
    if diagnostics.iter().any(|d| d.code.starts_with('S')) {
        eprintln!("{}: not fixed, because of its syntax errors", file.name);
        return Ok(None);
    }
    let fixed = apply(&file.bytes, &edits);
    write_atomically(target, |out| out.write_all(&fixed), None)?;
    let s = if answered == 1 { "" } else { "s" };
    eprintln!("{}: fixed {answered} finding{s}", file.name);
    Ok(Some(fixed))
}

/// `list` as rule codes: trimmed, upper case, each naming a rule or a family.
fn codes(list: &[String], origin: &str) -> Result<Vec<String>, CliError> {
    lint::codes::normalize(list).map_err(|unknown| CliError::UnknownCode {
        origin: origin.to_string(),
        code: unknown.code,
        did_you_mean: unknown.did_you_mean,
    })
}
