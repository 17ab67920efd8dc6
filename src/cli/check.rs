//! `sinuprep check`: lint every program named, in parallel, and report in a
//! stable order.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::cli::analysis;
use crate::cli::args::{CheckArgs, Format};
use crate::cli::error::CliError;
use crate::cli::input::{binary, read, skip_binary, Bytes, Found};
use crate::cli::output::{in_place_target, report_to, write_atomically};
use crate::cli::parallel;
use crate::cli::render::{
    printable, Emitter, GithubEmitter, HumanEmitter, JsonEmitter, Program, SarifEmitter,
    ShortEmitter, StatisticsEmitter,
};
use crate::cli::walk::{files, Files};
use crate::cli::ExitStatus;
use crate::diagnostic::{Applicability, Diagnostic, Severity};
use crate::document::archive::Opened;
use crate::edit::apply;
use crate::lint;
use crate::semantic::swivels::OnMachine;
use crate::workspace::{Given, Workspace};

/// One file's outcome, beside its part of the report (made in the worker:
/// the source is dropped as soon as its file is checked, and the part
/// written as soon as the files before it are).
struct Checked {
    fails: bool,
    counts: Counts,
    unchecked: Unchecked,
    /// Programs reported: 1 for a file, its programs for an archive.
    files: usize,
    /// What of an archive was left unchecked, for stderr.
    notes: Option<String>,
    /// The machine the file was checked on, with its findings the
    /// selection keeps: reported once a run, before the first file.
    machine: Option<(Arc<OnMachine>, Vec<Diagnostic>)>,
}

impl Checked {
    /// A binary file a walk found: not linted, and not counted as a
    /// program checked, as a link is skipped; the note says why. One named
    /// is an error, as in every command ([`skip_binary`]).
    fn skipped(notes: String) -> Self {
        Self {
            fails: false,
            counts: Counts::default(),
            unchecked: Unchecked::default(),
            files: 0,
            notes: Some(notes),
            machine: None,
        }
    }
}

/// What a program checked without its machine's environment (no
/// definition files, axis names or cycle directories given) leaves open.
#[derive(Default)]
struct Unchecked {
    /// Subprograms called that nothing declares: their calls are unchecked.
    calls: std::collections::BTreeSet<String>,
    /// N005 findings with no defined name near them (a typo offers one),
    /// which may be globals, macros or axes of the machine.
    undefined_names: usize,
    /// Lines with syntax errors that write a name where an operator belongs,
    /// which may be a macro of the machine.
    names_as_operators: usize,
}

impl Unchecked {
    fn of(outcome: &lint::Outcome, settings: &lint::Settings) -> Self {
        if settings.environment.given {
            return Self::default();
        }
        let undefined = &crate::lint::rules::undefined_variable::RULE;
        Self {
            calls: outcome.unresolved_calls.iter().cloned().collect(),
            undefined_names: outcome
                .diagnostics
                .iter()
                .filter(|d| d.is(undefined) && d.fix.is_none())
                .count(),
            names_as_operators: outcome.names_as_operators,
        }
    }

    fn add(&mut self, other: Unchecked) {
        self.calls.extend(other.calls);
        self.undefined_names += other.undefined_names;
        self.names_as_operators += other.names_as_operators;
    }

    /// Said once a run, after the summary: what the environment would
    /// have let `check` check.
    fn note(&self) -> Option<String> {
        let mut lines = Vec::new();
        if !self.calls.is_empty() {
            let mut names: Vec<&str> = self.calls.iter().map(String::as_str).take(5).collect();
            if self.calls.len() > names.len() {
                names.push("...");
            }
            let (count, them) = match self.calls.len() {
                1 => ("1 called subprogram".to_string(), "its calls were"),
                n => (format!("{n} called subprograms"), "their calls were"),
            };
            lines.push(format!(
                "  - {count} not found beside the program ({}): {them} not checked (N018); give the cycle directories (`cycles` in sinuprep.toml, --cycles DIR)",
                names.join(", ")
            ));
        }
        if self.undefined_names > 0 {
            let count = match self.undefined_names {
                1 => "1 N005 finding".to_string(),
                n => format!("{n} N005 findings"),
            };
            lines.push(format!(
                "  - {count} may name GUD variables, macros or axes of the machine; give its definition files and machine data (`definitions`, --definitions FILE) or axes (`axes`)"
            ));
        }
        if self.names_as_operators > 0 {
            let count = match self.names_as_operators {
                1 => "1 line with a syntax error has".to_string(),
                n => format!("{n} lines with a syntax error have"),
            };
            lines.push(format!(
                "  - {count} a name where an operator belongs (`(R1 _DEC2)`), which may be a macro of the machine (`DEFINE _DEC2 AS MOD 100 DIV 10`); give its macro definition files (`definitions`, --definitions MMAC.DEF)"
            ));
        }
        (!lines.is_empty()).then(|| {
            format!(
                "note: checked without the machine's environment:\n{}",
                lines.join("\n")
            )
        })
    }
}

/// Findings by severity, for the summary line.
#[derive(Default, Clone, Copy)]
struct Counts {
    errors: usize,
    warnings: usize,
    infos: usize,
    /// Findings with a safe fix (`--fix` applies it), and with an unsafe one.
    fixable: usize,
    unsafe_fixable: usize,
}

impl Counts {
    fn of(diagnostics: &[Diagnostic]) -> Self {
        let count = |severity| {
            diagnostics
                .iter()
                .filter(|d| d.severity == severity)
                .count()
        };
        let fixes = |applicability| {
            diagnostics
                .iter()
                .filter_map(|d| d.fix.as_deref())
                .filter(|fix| fix.applicability == applicability)
                .count()
        };
        Self {
            errors: count(Severity::Error),
            warnings: count(Severity::Warning),
            infos: count(Severity::Info),
            fixable: fixes(Applicability::Safe),
            unsafe_fixable: fixes(Applicability::Unsafe),
        }
    }

    fn add(&mut self, other: Counts) {
        self.errors += other.errors;
        self.warnings += other.warnings;
        self.infos += other.infos;
        self.fixable += other.fixable;
        self.unsafe_fixable += other.unsafe_fixable;
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
        let mut summary = format!("{found} in {}", plural(files, "file"));
        match (self.fixable, self.unsafe_fixable) {
            (0, 0) => {}
            (0, n) => summary += &format!(" ({n} fixable with `--fix --unsafe-fixes`)"),
            (n, 0) => summary += &format!(" ({n} fixable with `--fix`)"),
            (n, more) => {
                summary +=
                    &format!(" ({n} fixable with `--fix`, {more} more with `--unsafe-fixes`)")
            }
        }
        summary
    }
}

pub fn run(args: &CheckArgs) -> Result<ExitStatus, CliError> {
    let workspace = Workspace::new(Given {
        follow_links: args.walk.follow_links,
        walk: args.walk.given(),
        ..analysis::given_to_check(args)
    })?;
    // No path: the current directory, as ruff and ripgrep do; stdin only
    // with `-` (or with --stdin-filename, the editors' way).
    let named = match (args.paths.is_empty(), &args.stdin_filename) {
        (false, _) => args.paths.clone(),
        (true, Some(_)) => vec![PathBuf::from("-")],
        (true, None) => vec![PathBuf::from(".")],
    };
    let walk = args.walk.walk(&workspace);
    let mut files = files(&named, &walk);
    let colour = args.output_file.is_none() && crate::cli::colour(std::io::stdout().is_terminal());
    // The format is chosen here, once: the rest of the run is each
    // emitter's own code.
    let (files, workspace) = (&mut files, &workspace);
    match args.format {
        format if args.statistics => {
            let emitter = StatisticsEmitter {
                json: format == Format::Json,
                unsafe_fixes: args.unsafe_fixes,
                for_people: matches!(format, Format::Human | Format::Short),
            };
            report_through(&emitter, args, files, workspace)
        }
        Format::Human => report_through(&HumanEmitter { colour }, args, files, workspace),
        Format::Short => report_through(&ShortEmitter, args, files, workspace),
        Format::Github => report_through(&GithubEmitter, args, files, workspace),
        Format::Json => report_through(&JsonEmitter, args, files, workspace),
        Format::Sarif => report_through(&SarifEmitter, args, files, workspace),
    }
}

/// The report of the files through `emitter`, to the output file or stdout.
fn report_through(
    emitter: &impl Emitter,
    args: &CheckArgs,
    files: &mut Files,
    workspace: &Workspace,
) -> Result<ExitStatus, CliError> {
    report_to(args.output_file.as_deref(), |out| {
        report(args, files, emitter, workspace, out)
    })
}

/// Checks the files as the walk finds them, writing the report to `out` as
/// each file is done and the summary to stderr.
fn report<E: Emitter>(
    args: &CheckArgs,
    walk: &mut Files,
    emitter: &E,
    workspace: &Workspace,
    out: &mut dyn Write,
) -> Result<ExitStatus, CliError> {
    // A failure comes with the name of the file, for the JSON and SARIF reports.
    let work = |found: Result<Found, CliError>| match found {
        Ok(found) => {
            let mut part = E::Part::default();
            let add = &mut |program: Program| emitter.add(&mut part, program);
            let checked = check_file(&found, args, emitter.names_archives(), workspace, add)
                .map_err(|error| (shown_name(&found.path, args), error))?;
            Ok((checked, part))
        }
        Err(error) => Err((walked_name(&error), error)),
    };

    // Files that could not be read or checked (an error each, on stderr).
    let mut failed = 0;
    let mut fails = false;
    let mut counts = Counts::default();
    let mut unchecked = Unchecked::default();
    let mut files = 0;
    let mut kept = E::Kept::default();
    let mut told = analysis::MachinesTold::default();
    emitter.start(out)?;
    // Each file's part written as soon as it and those before it are done.
    parallel::each(&mut *walk, work, |result| {
        match result {
            Ok((mut checked, part)) => {
                if let Some(notes) = &checked.notes {
                    tell!("{notes}");
                }
                // The machine file's findings, as those of one more file.
                if let Some((on, diagnostics)) = checked.machine.take() {
                    if !diagnostics.is_empty() && told.first(&on) {
                        counts.add(Counts::of(&diagnostics));
                        fails |= diagnostics.iter().any(|d| d.severity == Severity::Error);
                        for (name, source, diagnostics) in on.by_file(&diagnostics) {
                            let mut part = E::Part::default();
                            let program = Program {
                                name,
                                path: None,
                                source,
                                diagnostics,
                            };
                            emitter.add(&mut part, program);
                            emitter.write(&mut kept, part, out)?;
                            files += 1;
                        }
                    }
                }
                fails |= checked.fails;
                counts.add(checked.counts);
                unchecked.add(checked.unchecked);
                emitter.write(&mut kept, part, out)?;
                files += checked.files;
            }
            Err((name, error)) => {
                failed += 1;
                emitter.failed(&mut kept, &name, &error_chain(&error), out)?;
                tellln!("{:?}", miette::Report::new(error));
            }
        }
        Ok::<(), CliError>(())
    })?;
    // What ended the walk early (unreadable settings, a folder without
    // programs) is the run's error, once the reports begun are complete.
    let walked = walk.end();
    emitter.end(kept, out)?;
    walked?;
    // For people: on stderr, so that what tools read stays the findings.
    // Nothing checked after an error: the error says it all ("no findings
    // in 0 files" read as a pass).
    let summary = !(failed > 0 && files == 0);
    if emitter.for_people() && !args.quiet && summary {
        match failed {
            0 => tellln!("{}", counts.summary(files)),
            1 => tellln!("{}; 1 file could not be checked", counts.summary(files)),
            n => tellln!("{}; {n} files could not be checked", counts.summary(files)),
        }
        if let Some(note) = unchecked.note() {
            tellln!("{note}");
        }
    }

    Ok(if failed > 0 {
        ExitStatus::Error
    } else if fails && !args.exit_zero {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    })
}

/// An error and its causes, on one line.
fn error_chain(error: &CliError) -> String {
    let mut text = error.to_string();
    let mut cause = std::error::Error::source(error);
    while let Some(inner) = cause {
        text.push_str(&format!(": {inner}"));
        cause = inner.source();
    }
    text
}

/// Checks one file, handing each of its programs' findings to `add`;
/// `names_archives`: an archive's programs are reported as the archive
/// ([`Emitter::names_archives`]).
fn check_file(
    found: &Found,
    args: &CheckArgs,
    names_archives: bool,
    workspace: &Workspace,
    add: &mut dyn FnMut(Program),
) -> Result<Checked, CliError> {
    let path = found.path.as_path();
    // Refused before anything is read: stdin, a FIFO, a device.
    let fix_target = args.fix.then(|| in_place_target(path)).transpose()?;
    let mut file = read(found)?;
    // stdin with --stdin-filename: report and look things up as that file.
    let named = match (&args.stdin_filename, path == Path::new("-")) {
        (Some(name), true) => {
            file.name = name.display().to_string();
            name.clone()
        }
        _ => path.to_path_buf(),
    };
    if binary(&file.bytes) {
        return Ok(Checked::skipped(skip_binary(
            found,
            &file.name,
            &file.bytes,
        )?));
    }
    let resolved = workspace.for_check(&named)?;
    let deny_warnings = resolved.deny_warnings;
    let mut settings = resolved.settings;
    let mut opened = Opened::read(&file.bytes, &file.name)
        .map_err(|error| CliError::archive(&file.name, error))?;
    // The archive's definitions and subprograms, which a fix leaves alone.
    let unreadable = opened.settings(&file.bytes, &mut settings);
    let mut outcomes = outcomes(&opened, &file.bytes, &settings);
    if let Some(target) = fix_target {
        if let Some(fixed) = fix(&target, &opened, &file.bytes, &outcomes, args.unsafe_fixes)? {
            file.bytes = Bytes::Read(fixed);
            opened = Opened::read(&file.bytes, &file.name)
                .map_err(|error| CliError::archive(&file.name, error))?;
            outcomes = self::outcomes(&opened, &file.bytes, &settings);
        }
    }
    let mut checked = Checked {
        fails: false,
        counts: Counts::default(),
        unchecked: Unchecked::default(),
        files: 0,
        notes: opened.unchecked(&file.bytes),
        machine: settings.machine.as_ref().map(|on| {
            let selection = &settings.selection;
            let kept =
                on.machine.diagnostics.iter().filter(|d| {
                    selection.enables(d.code()) && d.severity >= selection.severity_min
                });
            (on.clone(), kept.cloned().collect())
        }),
    };
    let mut reports = Vec::new();
    for (program, outcome) in opened.programs(&file.bytes).into_iter().zip(outcomes) {
        checked.unchecked.add(Unchecked::of(&outcome, &settings));
        reports.push((
            program.name,
            program.document.source,
            outcome.diagnostics,
            program.member,
        ));
    }
    for member in unreadable {
        let source = opened.member_bytes(&file.bytes, member.member);
        reports.push((
            opened.member_name(member.member),
            source,
            member.diagnostics,
            Some(member.member),
        ));
    }
    for (name, source, diagnostics, member) in reports {
        checked.files += 1;
        checked.counts.add(Counts::of(&diagnostics));
        checked.fails |= diagnostics.iter().any(|d| {
            d.severity == Severity::Error || (deny_warnings && d.severity == Severity::Warning)
        });
        let (name, source, diagnostics) = match member {
            Some(member) if names_archives => (
                opened.name.clone(),
                &file.bytes[..],
                opened.in_archive(&file.bytes, member, diagnostics),
            ),
            _ => (name, source, diagnostics),
        };
        // The file's own path, which SARIF names by its bytes.
        let path = (member.is_none() || names_archives)
            .then_some(named.as_path())
            .filter(|path| *path != Path::new("-"));
        add(Program {
            name: &name,
            path,
            source,
            diagnostics,
        });
    }
    Ok(checked)
}

/// The name a file that could not be checked goes by in the reports.
fn shown_name(path: &Path, args: &CheckArgs) -> String {
    match (&args.stdin_filename, path == Path::new("-")) {
        (Some(name), true) => name.display().to_string(),
        (None, true) => "<stdin>".to_string(),
        _ => path.display().to_string(),
    }
}

/// The entry a walk could not read (a folder), as reports call it.
fn walked_name(error: &CliError) -> String {
    match error {
        CliError::Read { path, .. } | CliError::IsDirectory { path } => path.display().to_string(),
        other => other.to_string(),
    }
}

/// What `check` reports of each program of `opened`, in their order.
fn outcomes(opened: &Opened, bytes: &[u8], settings: &lint::Settings) -> Vec<lint::Outcome> {
    opened
        .programs(bytes)
        .iter()
        .map(|program| program.document.check_outcome(settings))
        .collect()
}

/// Applies the fixes `--fix` takes to every program of `opened` and writes
/// the file to `target` atomically: the fixed bytes, or `None` when there
/// was nothing to fix. A program with syntax errors is not fixed (its
/// trees may not be what was meant); the others of an archive are.
fn fix(
    target: &Path,
    opened: &Opened,
    bytes: &[u8],
    outcomes: &[lint::Outcome],
    unsafe_fixes: bool,
) -> Result<Option<Vec<u8>>, CliError> {
    let findings = outcomes.iter().map(|outcome| &outcome.diagnostics[..]);
    let fixes = opened.fixes(bytes, findings, unsafe_fixes);
    for (name, why) in &fixes.unfixed {
        tellln!("{}: {}", printable(name), why.describe());
    }
    if fixes.edits.is_empty() {
        return Ok(None);
    }
    let fixed = apply(bytes, &fixes.edits);
    write_atomically(target, |out| out.write_all(&fixed), None)?;
    let answered = fixes.answered;
    let s = if answered == 1 { "" } else { "s" };
    tellln!("{}: fixed {answered} finding{s}", printable(&opened.name));
    Ok(Some(fixed))
}
