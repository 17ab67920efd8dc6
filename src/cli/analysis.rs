//! What `check`, `rewrite` and `eval` share: the options that become the
//! workspace's [`Given`], a rewrite's diagnostics for stderr, and a machine
//! file's findings, told once a run.

use std::collections::HashSet;
use std::io::IsTerminal;

use crate::cli::args::{AnalysisArgs, CheckArgs, InputArgs, MessageFormat};
use crate::cli::render::{human, short, FileReport};
use crate::cli::ExitStatus;
use crate::diagnostic::Severity;
use crate::document::Rewritten;
use crate::semantic::swivels::OnMachine;
use crate::workspace::Given;

/// The settings files and values every command reads beside the programs.
fn inputs(args: &InputArgs) -> Given {
    Given {
        config: args.config.clone(),
        values: args.values.clone(),
        set: args.set.clone(),
        heads: args.heads.clone(),
        ..Given::default()
    }
}

/// What `rewrite` and `eval` are given.
pub fn given_to_rewrite(args: &AnalysisArgs) -> Given {
    Given {
        emit: args.emit,
        precision: args.precision,
        emit_runtime: args.emit_runtime,
        runtime_r: args.runtime_r,
        ..inputs(&args.input)
    }
}

/// What `check` is given.
pub fn given_to_check(args: &CheckArgs) -> Given {
    Given {
        select: args.select.clone(),
        ignore: args.ignore.clone(),
        severity_min: args.severity_min.map(Severity::from),
        deny_warnings: args.deny_warnings,
        definitions: args.definitions.clone(),
        cycles: args.cycles.clone(),
        machine: args.machine.clone(),
        fine_offsets: args.fine_offsets,
        ..inputs(&args.input)
    }
}

/// A rewrite's diagnostics as text for stderr, in the format asked for:
/// of the program `name`, whose bytes are `source`.
pub fn report(rewritten: &Rewritten, name: &str, source: &[u8], format: MessageFormat) -> String {
    let report = FileReport {
        name,
        source,
        diagnostics: &rewritten.diagnostics,
    };
    render(&report, format)
}

/// A machine file's findings (K001, syntax errors) as text for stderr, in
/// the format asked for.
pub fn machine_report(on: &OnMachine, format: MessageFormat) -> String {
    on.by_file(&on.machine.diagnostics)
        .into_iter()
        .map(|(name, source, diagnostics)| {
            let report = FileReport {
                name,
                source,
                diagnostics: &diagnostics,
            };
            render(&report, format)
        })
        .collect()
}

/// The machine files a run has told of: a file's findings are told once a
/// run, before the first program read with it, however many use it.
#[derive(Default)]
pub struct MachinesTold(HashSet<String>);

impl MachinesTold {
    /// Whether `on` comes for the first time this run.
    pub fn first(&mut self, on: &OnMachine) -> bool {
        self.0.insert(on.name.clone())
    }

    /// Tells `on`'s findings on stderr the first time the run meets it;
    /// what they make the exit status (an error fails), every time.
    pub fn tell(&mut self, on: Option<&OnMachine>, format: MessageFormat) -> ExitStatus {
        let Some(on) = on else {
            return ExitStatus::Success;
        };
        if !on.machine.diagnostics.is_empty() && self.first(on) {
            tell!("{}", machine_report(on, format));
        }
        if on.machine.has_errors() {
            ExitStatus::Failure
        } else {
            ExitStatus::Success
        }
    }
}

fn render(report: &FileReport, format: MessageFormat) -> String {
    let mut text = String::new();
    match format {
        MessageFormat::Human => human(
            report,
            crate::cli::colour(std::io::stderr().is_terminal()),
            &mut text,
        ),
        MessageFormat::Short => short(report, &mut text),
    }
    text
}
