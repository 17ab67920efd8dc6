//! `sinuprep completions SHELL` and `sinuprep manpage`: the command line
//! describing itself, from the one clap definition, so that neither can
//! fall behind the options.

use clap::CommandFactory;

use crate::cli::args::{Args, ManpageArgs};
use crate::cli::error::CliError;
use crate::cli::output::write_atomically;
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};

pub fn completions(shell: clap_complete::Shell) -> Result<ExitStatus, CliError> {
    // Into memory first: clap_complete panics when its writer fails (a
    // closed pipe), and a closed pipe is no failure here.
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Args::command(), "sinuprep", &mut script);
    write_stdout(&script)?;
    Ok(ExitStatus::Success)
}

/// The main page, a command's page, or every page written to a directory,
/// each atomically. The main page's list of commands refers to their pages
/// (`sinuprep-check(1)`), so each of them is written.
pub fn manpage(args: &ManpageArgs) -> Result<ExitStatus, CliError> {
    let pages = pages();
    if let Some(dir) = &args.dir {
        for page in &pages {
            let path = dir.join(page.get_filename());
            write_atomically(&path, |out| page.render(out), None)?;
        }
        return Ok(ExitStatus::Success);
    }
    let wanted = match &args.command {
        Some(command) => format!("sinuprep-{command}.1"),
        None => "sinuprep.1".to_string(),
    };
    let Some(page) = pages.iter().find(|page| page.get_filename() == wanted) else {
        let commands: Vec<String> = Args::command()
            .get_subcommands()
            .map(|c| c.get_name().to_string())
            .collect();
        return Err(CliError::UnknownCommand {
            command: args.command.clone().unwrap_or_default(),
            commands: commands.join(", "),
        });
    };
    write_stdout_with(|out| page.render(out))?;
    Ok(ExitStatus::Success)
}

/// The main page, then one for each command (`sinuprep-check.1`), as
/// clap_mangen names them.
fn pages() -> Vec<clap_mangen::Man> {
    let mut command = Args::command().disable_help_subcommand(true);
    command.build();
    let mut commands = vec![command.clone()];
    commands.extend(
        command
            .get_subcommands()
            .filter(|sub| !sub.is_hide_set())
            .cloned(),
    );
    // A command has no version of its own: each page names the tool's.
    let source = format!("sinuprep {}", env!("CARGO_PKG_VERSION"));
    commands
        .into_iter()
        .map(|command| clap_mangen::Man::new(command).source(source.clone()))
        .collect()
}
