use std::process::ExitCode;

use clap::Parser;
use sinuprep::cli::{run, Args, ExitStatus};

fn main() -> ExitCode {
    let args = Args::parse();
    let status = match run(&args) {
        Ok(status) => status,
        Err(error) => {
            eprintln!("{:?}", miette::Report::new(error));
            ExitStatus::Error
        }
    };
    ExitCode::from(status as u8)
}
