//! `sinuprep rule`: a rule's documentation, or the list of all rules.

use crate::cli::args::RuleArgs;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::lint;

pub fn run(args: &RuleArgs) -> Result<ExitStatus, CliError> {
    let text = match &args.code {
        Some(code) if !args.all => {
            let info = lint::rule(code).ok_or_else(|| CliError::UnknownRule(code.clone()))?;
            format!(
                "# {} {} ({}{})\n\n{}\n",
                info.code,
                info.name,
                info.severity.as_str(),
                off_note(info.code),
                info.docs
            )
        }
        _ => lint::rules::all()
            .iter()
            .map(|r| {
                format!(
                    "{:<5} {:<44} {}{}\n",
                    r.info.code,
                    r.info.name,
                    r.info.severity.as_str(),
                    off_note(r.info.code)
                )
            })
            .collect(),
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

/// How `check` runs the rule where that is not its plain severity: off by
/// default (`, off by default: --select N015`), or at another severity.
fn off_note(code: &str) -> String {
    if lint::off_by_default(code) {
        return format!(", off by default: --select {code}");
    }
    match lint::severity_in_check(code) {
        Some(note) => format!(", {note}"),
        None => String::new(),
    }
}
