use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use sinuprep::cli::{run, Args, ExitStatus};

fn main() -> ExitCode {
    let args = Args::parse();
    let status = match run(&args) {
        Ok(status) => status,
        Err(error) => {
            // A closed standard error silences the message, not the status.
            let _ = writeln!(std::io::stderr(), "{:?}", miette::Report::new(error));
            ExitStatus::Error
        }
    };
    ExitCode::from(status as u8)
}
