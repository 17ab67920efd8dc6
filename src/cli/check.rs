//! `sinuprep check`: lint every program named, in parallel, and report in a
//! stable order.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use crate::cli::analysis::Inputs;
use crate::cli::args::{CheckArgs, Format};
use crate::cli::config::Config;
use crate::cli::error::CliError;
use crate::cli::input::{expand, read, SourceFile};
use crate::cli::render::{github, human, json, sarif, short, FileReport};
use crate::cli::{write_stdout, ExitStatus};
use crate::diagnostic::{Diagnostic, Severity};
use crate::lint::{self, Selection};
use crate::syntax::program_kind;

/// One file's outcome.
struct Checked {
    file: SourceFile,
    diagnostics: Vec<Diagnostic>,
    deny_warnings: bool,
}

pub fn run(args: &CheckArgs) -> Result<ExitStatus, CliError> {
    let paths = expand(&args.paths);
    let results: Vec<Mutex<Option<Result<Checked, CliError>>>> =
        paths.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let work = || loop {
        let index = next.fetch_add(1, Ordering::Relaxed);
        let Some(path) = paths.get(index) else { break };
        let outcome = match path {
            Ok(path) => check_file(path, args),
            Err(error) => Err(CliError::Read {
                path: PathBuf::new(),
                source: std::io::Error::other(error.to_string()),
            }),
        };
        if let Ok(mut slot) = results[index].lock() {
            *slot = Some(outcome);
        }
    };
    if paths.len() <= 1 {
        // The editor-on-save case: no thread to start, no cgroup files to read.
        work();
    } else {
        let workers = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(paths.len());
        std::thread::scope(|scope| {
            for _ in 0..workers {
                scope.spawn(work);
            }
        });
    }

    let mut failed = false;
    let mut checked = Vec::new();
    for slot in results {
        match slot.into_inner().ok().flatten() {
            Some(Ok(file)) => checked.push(file),
            Some(Err(error)) => {
                failed = true;
                eprintln!("{:?}", miette::Report::new(error));
            }
            None => failed = true,
        }
    }
    let reports: Vec<FileReport> = checked
        .iter()
        .map(|c| FileReport {
            name: &c.file.name,
            source: &c.file.bytes,
            diagnostics: &c.diagnostics,
        })
        .collect();
    let mut out = String::new();
    match args.format {
        Format::Json => out = json(&reports),
        Format::Sarif => out = sarif(&reports),
        Format::Short => reports.iter().for_each(|r| short(r, &mut out)),
        Format::Github => reports.iter().for_each(|r| github(r, &mut out)),
        Format::Human => {
            let colour = std::io::stdout().is_terminal();
            reports.iter().for_each(|r| human(r, colour, &mut out));
        }
    }
    write_stdout(out.as_bytes())?;

    let fails = checked.iter().any(|c| {
        c.diagnostics.iter().any(|d| {
            d.severity == Severity::Error || (c.deny_warnings && d.severity == Severity::Warning)
        })
    });
    Ok(if failed {
        ExitStatus::Error
    } else if fails {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    })
}

fn check_file(path: &Path, args: &CheckArgs) -> Result<Checked, CliError> {
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
    let mut ignore = args.ignore.clone();
    ignore.extend(config.ignore.clone().unwrap_or_default());
    let selection = Selection {
        select: if args.select.is_empty() {
            config.select.clone().unwrap_or_default()
        } else {
            args.select.clone()
        },
        ignore,
        severity_min: args
            .severity_min
            .or(config.severity_min)
            .map_or(Severity::Info, Severity::from),
    };
    let kind = program_kind(Some(&file.name), &file.bytes);
    let diagnostics = lint::check(
        &file.bytes,
        &file.name,
        kind,
        &selection,
        &inputs.supplied,
        inputs.heads.as_ref(),
    );
    Ok(Checked {
        file,
        diagnostics,
        deny_warnings: args.deny_warnings || config.deny_warnings == Some(true),
    })
}
