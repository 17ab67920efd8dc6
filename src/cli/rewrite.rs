//! `sinuprep rewrite`: CYCLE600 calls become native code; every other byte
//! stays. A call that cannot be evaluated stays as it was, with a diagnostic.

use crate::cli::analysis::{self, Inputs};
use crate::cli::args::RewriteArgs;
use crate::cli::config::Config;
use crate::cli::error::CliError;
use crate::cli::input::read;
use crate::cli::output::write_atomically;
use crate::cli::{write_stdout, write_stdout_with, ExitStatus};
use crate::emit::cycle600::Options;
use std::io::Write;

use crate::emit::{diff, write_applied};

pub fn run(args: &RewriteArgs) -> Result<ExitStatus, CliError> {
    let file = read(&args.path)?;
    let _pages = file.bytes.watch_reads();
    let config = Config::find(args.analysis.input.config.as_deref(), &args.path)?;
    let inputs = Inputs::load(&args.analysis.input, &config, &args.path)?;
    let options = Options {
        keep_original: !args.no_original,
        inline_results: args.inline_results,
        ..analysis::options(&args.analysis, &config)
    };
    let analyzed = analysis::run(&file, &inputs, &options);
    analyzed.report(&file, args.analysis.message_format);

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
    if args.in_place {
        if errors {
            eprintln!(
                "{}: not rewritten in place, because of the errors above",
                file.name
            );
            return Ok(ExitStatus::Failure);
        }
        if changed {
            write_atomically(&args.path, output, !args.no_backup)?;
        }
        return Ok(ExitStatus::Success);
    }
    match &args.output {
        Some(path) => write_atomically(path, output, false)?,
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
