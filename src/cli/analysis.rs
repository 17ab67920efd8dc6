//! What `check`, `rewrite` and `eval` share: the options that become the
//! workspace's [`Given`], and a rewrite's diagnostics for stderr.

use std::io::IsTerminal;

use crate::cli::args::{AnalysisArgs, CheckArgs, InputArgs, MessageFormat};
use crate::cli::render::{human, short, FileReport};
use crate::diagnostic::Severity;
use crate::document::Rewritten;
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
    let mut text = String::new();
    match format {
        MessageFormat::Human => human(&report, std::io::stderr().is_terminal(), &mut text),
        MessageFormat::Short => short(&report, &mut text),
    }
    text
}
