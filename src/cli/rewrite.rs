//! `sinuprep rewrite`: today the program comes back byte for byte; the
//! CYCLE600 rewrite will edit only the blocks it replaces.

use crate::cli::args::RewriteArgs;
use crate::cli::error::CliError;
use crate::cli::input::read;
use crate::cli::render::{short, FileReport};
use crate::cli::{write_stdout, ExitStatus};
use crate::syntax::parse;

pub fn run(args: &RewriteArgs) -> Result<ExitStatus, CliError> {
    let file = read(&args.path)?;
    let program = parse(&file.bytes);
    if !program.diagnostics.is_empty() {
        // The program still goes through unchanged; the errors are for the user.
        let mut note = String::new();
        short(
            &FileReport {
                name: &file.name,
                source: &file.bytes,
                diagnostics: &program.diagnostics,
            },
            &mut note,
        );
        eprint!("{note}");
    }
    write_stdout(&program.print())?;
    Ok(ExitStatus::Success)
}
