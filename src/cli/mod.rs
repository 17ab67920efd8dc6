//! The command line: the only module that prints.

/// Writes a message to standard error. A closed standard error
/// (`sinuprep check 2>&1 | head -1`) silences the messages; it never ends
/// the run, as `eprint!` would with a panic.
macro_rules! tell {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stderr().lock(), $($arg)*);
    }};
}

/// [`tell!`], with a line ending.
macro_rules! tellln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr().lock(), $($arg)*);
    }};
}

mod analysis;
pub mod args;
mod axes;
mod axis;
mod check;
mod convert;
mod describe;
pub mod error;
pub(crate) mod eval;
mod fmt;
mod frame;
mod input;
mod machine;
mod mapped;
pub mod notation;
mod output;
mod parallel;
mod platform;
mod probe;
pub mod render;
mod rewrite;
mod rule;
mod run;
mod walk;

pub use args::Args;
pub use error::CliError;

/// 0 clean, 1 findings, 2 the tool failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum ExitStatus {
    Success = 0,
    Failure = 1,
    Error = 2,
}

/// Writes data to stdout. A reader that went away (`sinuprep check | head`)
/// ends the output but is not a failure: the command's status stands.
pub(crate) fn write_stdout(bytes: &[u8]) -> Result<(), CliError> {
    write_stdout_with(|out| out.write_all(bytes))
}

/// Writes to standard output with `write`; a reader that stopped reading
/// (`| head`) is not an error.
pub(crate) fn write_stdout_with(
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<(), CliError> {
    match write(&mut std::io::stdout().lock()) {
        Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        result => Ok(result?),
    }
}

/// The colour asked for with `--color`, set once a run.
static COLOUR: std::sync::OnceLock<args::ColorChoice> = std::sync::OnceLock::new();

/// Whether to colour what goes to a stream that is (or is not) a terminal:
/// `--color always` or `never`; with `auto`, a terminal unless `NO_COLOR`
/// is set (on Windows, a console that shows colour), and anything where
/// `CLICOLOR_FORCE` is (the conventions of no-color.org and
/// bixense.com/clicolors).
pub(crate) fn colour(terminal: bool) -> bool {
    let set = |name: &str| std::env::var_os(name).is_some_and(|v| !v.is_empty() && v != "0");
    match COLOUR.get().copied().unwrap_or(args::ColorChoice::Auto) {
        args::ColorChoice::Always => {
            // Asked for: the console is made to show it where it can be.
            platform::console_shows_colour();
            true
        }
        args::ColorChoice::Never => false,
        args::ColorChoice::Auto => {
            std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
                && ((terminal && platform::console_shows_colour()) || set("CLICOLOR_FORCE"))
        }
    }
}

pub fn run(args: &Args) -> Result<ExitStatus, CliError> {
    let _ = COLOUR.set(args.color);
    // The tool's own errors (miette's reports on stderr) follow the choice.
    use std::io::IsTerminal;
    let errors_in_colour = colour(std::io::stderr().is_terminal());
    let _ = miette::set_hook(Box::new(move |_| {
        Box::new(
            miette::MietteHandlerOpts::new()
                .color(errors_in_colour)
                .build(),
        )
    }));
    match &args.command {
        args::Command::Check(check) => check::run(check),
        args::Command::Rewrite(rewrite) => rewrite::run(rewrite),
        args::Command::Fmt(fmt) => fmt::run(fmt),
        args::Command::Eval(eval) => eval::run(eval),
        args::Command::Rule(rule) => rule::run(rule),
        args::Command::Convert(convert) => convert::run(convert),
        args::Command::Frame(frame) => frame::run(frame),
        args::Command::Axes(axes) => axes::run(axes),
        args::Command::Probe(probe) => probe::run(probe),
        args::Command::Axis(axis) => axis::run(axis),
        args::Command::Machine(machine) => machine::run(machine),
        args::Command::Run(run) => run::run(run),
        args::Command::Completions(completions) => describe::completions(completions.shell),
        args::Command::Manpage(manpage) => describe::manpage(manpage),
        args::Command::Lsp => crate::lsp::run()
            .map(|()| ExitStatus::Success)
            .map_err(CliError::Server),
    }
}
