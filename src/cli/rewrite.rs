//! `sinuprep rewrite`: CYCLE600 calls become native code; every other byte
//! stays. A call that cannot be evaluated stays as it was, with a diagnostic.

use crate::cli::analysis::{self, Inputs};
use crate::cli::args::RewriteArgs;
use crate::cli::config::Config;
use crate::cli::error::CliError;
use crate::cli::input::read;
use crate::cli::output::{in_place_target, same_file, write_atomically};
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};
use crate::emit::cycle600::Options;
use std::io::Write;
use std::path::Path;

use crate::emit::{diff, write_applied};

pub fn run(args: &RewriteArgs) -> Result<ExitStatus, CliError> {
    // `-o` naming the program itself is a rewrite in place, with its rules.
    let onto_itself = args
        .output
        .as_deref()
        .is_some_and(|output| args.path != Path::new("-") && same_file(&args.path, output));
    // Refused before anything is read: stdin, a FIFO, a device.
    let in_place = if args.in_place || onto_itself {
        Some(in_place_target(&args.path)?)
    } else {
        None
    };
    let file = read(&args.path)?;
    let config = Config::find(args.analysis.input.config.as_deref(), &args.path)?;
    let inputs = Inputs::load(&args.analysis.input, &config, &args.path)?;
    let options = Options {
        keep_original: !args.no_original,
        inline_results: args.inline_results,
        ..analysis::options(&args.analysis, &config)
    };
    let analyzed = analysis::run(&file, inputs, &options);
    analysis::report(&analyzed, &file, args.analysis.message_format);

    let edits = &analyzed.rewrite.edits;
    let changed = !edits.is_empty();
    let errors = analyzed.has_errors();
    if args.check {
        if changed {
            eprintln!(
                "{}: would rewrite {} CYCLE600 call(s)",
                file.name, analyzed.rewrite.rewritten
            );
        }
        return Ok(status(errors || changed));
    }
    if args.diff {
        write_stdout(diff::unified(&file.name, &file.bytes, edits).as_bytes())?;
        return Ok(status(errors));
    }
    let output = |out: &mut dyn Write| write_applied(&file.bytes, edits, out);
    if let Some(target) = in_place {
        if errors {
            eprintln!(
                "{}: not rewritten in place, because of the errors above",
                file.name
            );
            return Ok(ExitStatus::Failure);
        }
        if changed {
            // The backup holds the bytes this run read and rewrote.
            let backup = (!args.no_backup).then_some(&file.bytes[..]);
            write_atomically(&target, output, backup)?;
        }
        return Ok(ExitStatus::Success);
    }
    match &args.output {
        Some(path) => write_atomically(path, output, None)?,
        None => write_stdout_with(output)?,
    }
    Ok(status(errors))
}

fn status(failure: bool) -> ExitStatus {
    if failure {
        ExitStatus::Failure
    } else {
        ExitStatus::Success
    }
}
