//! `sinuprep completions SHELL` and `sinuprep manpage`: the command line
//! describing itself, from the one clap definition, so that neither can
//! fall behind the options.

use clap::CommandFactory;

use crate::cli::args::Args;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};

pub fn completions(shell: clap_complete::Shell) -> Result<ExitStatus, CliError> {
    // Into memory first: clap_complete panics when its writer fails (a
    // closed pipe), and a closed pipe is no failure here.
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Args::command(), "sinuprep", &mut script);
    write_stdout(&script)?;
    Ok(ExitStatus::Success)
}

pub fn manpage() -> Result<ExitStatus, CliError> {
    write_stdout_with(|out| clap_mangen::Man::new(Args::command()).render(out))?;
    Ok(ExitStatus::Success)
}
