//! The command line, declared with clap's derive API.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};

use crate::rotation::Sequence;

#[derive(Debug, Parser)]
#[command(
    name = "sinuprep",
    version,
    about = "Preprocessor and linter for Siemens Sinumerik part programs"
)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Report syntax errors in NC programs (files, directories, or `-` for stdin).
    Check(CheckArgs),
    /// Print a program back (CYCLE600 rewriting is still to come; today every
    /// byte comes back unchanged).
    Rewrite(RewriteArgs),
    /// Convert three rotation angles from one sequence to another.
    #[command(allow_negative_numbers = true)]
    Convert(ConvertArgs),
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Files or directories (searched recursively for .mpf/.spf); `-` reads stdin.
    #[arg(default_value = "-")]
    pub paths: Vec<PathBuf>,
    /// How to print the diagnostics.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// miette's report with the source line and a label.
    Human,
    /// One line each: `path:line:col: severity[CODE] message`.
    Short,
    /// One JSON document (schema in the README).
    Json,
}

#[derive(Debug, clap::Args)]
pub struct RewriteArgs {
    /// The program to rewrite; `-` reads stdin.
    #[arg(default_value = "-")]
    pub path: PathBuf,
}

#[derive(Debug, clap::Args)]
pub struct ConvertArgs {
    /// Angle of the first rotation, degrees.
    #[arg(value_parser = finite_angle)]
    pub a1: f64,
    /// Angle of the second rotation, degrees.
    #[arg(value_parser = finite_angle)]
    pub a2: f64,
    /// Angle of the third rotation, degrees.
    #[arg(value_parser = finite_angle)]
    pub a3: f64,
    /// Input sequence: `intrinsic:ZXY`, `extrinsic:XYZ`, `i:ZXY`, `e:57`.
    #[arg(long)]
    pub from: Sequence,
    /// Output sequence, same forms as --from.
    #[arg(long)]
    pub to: Sequence,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,
}

fn finite_angle(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(value),
        Ok(_) => Err(format!(
            "`{text}` is not a finite angle; give degrees such as -16.28"
        )),
        Err(_) => Err(format!(
            "`{text}` is not a number; give degrees such as -16.28"
        )),
    }
}
