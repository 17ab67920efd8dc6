//! `sinuprep rule`: a rule's documentation, or the list of all rules.

use crate::cli::args::RuleArgs;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::lint;
use crate::lint::reference::{page, severity_text};

pub fn run(args: &RuleArgs) -> Result<ExitStatus, CliError> {
    let text = match &args.code {
        Some(code) if !args.all => page(lint::rule(code).ok_or_else(|| CliError::UnknownRule {
            code: code.clone(),
            nearest: lint::nearest_rule(code),
        })?),
        _ => lint::rules::all()
            .iter()
            .map(|r| {
                format!(
                    "{:<5} {:<44} {}\n",
                    r.info.code,
                    r.info.name,
                    severity_text(r.info)
                )
            })
            .collect(),
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}
