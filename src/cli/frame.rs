//! `sinuprep frame`: a whole frame, translation and rotation, from one form
//! to another (`convert`'s forms, with X Y Z before the rotation's
//! numbers), or the tool-to-piece frame of a tool chain and a piece chain
//! (`T_SP = T_PO⁻¹ · T_SO`, seed 004).

use crate::cli::args::FrameArgs;
use crate::cli::error::CliError;
use crate::cli::notation::{self, Notation};
use crate::cli::{write_stdout, ExitStatus};
use crate::rotation::forms::{tool_to_piece, Pose};

pub fn run(args: &FrameArgs) -> Result<ExitStatus, CliError> {
    let pose = if args.tool.is_empty() {
        let values = if args.values.is_empty() {
            vec![crate::cli::input::stdin_text(CliError::Form(
                "no frame given, and stdin is a terminal: give its values, or pipe them in".into(),
            ))?]
        } else {
            args.values.clone()
        };
        notation::read(args.from, &values, true).map_err(CliError::Form)?
    } else {
        let tool = chain(args.from, &args.tool, "--tool")?;
        let piece = chain(args.from, &args.piece, "--piece")?;
        tool_to_piece(&tool, &piece)
    };
    let written = notation::write(args.to, &pose, true, args.precision).map_err(CliError::Form)?;
    if let Some(warning) = &written.warning {
        tellln!("{warning}");
    }
    let text = if args.json {
        format!("{}\n", written.json)
    } else {
        written.text
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

/// The frames of a chain, each written in `from`, one after the other.
fn chain(from: Notation, links: &[String], option: &str) -> Result<Pose, CliError> {
    let mut product = Pose::identity();
    for (index, link) in links.iter().enumerate() {
        let frame = notation::read(from, std::slice::from_ref(link), true)
            .map_err(|why| CliError::Form(format!("{option} number {}: {why}", index + 1)))?;
        product *= frame;
    }
    Ok(product)
}
