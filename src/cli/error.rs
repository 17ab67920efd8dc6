//! Failures of the tool itself (exit status 2), as opposed to findings in
//! the programs it reads.

use std::path::PathBuf;

#[derive(Debug, thiserror::Error, miette::Diagnostic)]
pub enum CliError {
    #[error("cannot read {path}: {source}")]
    #[diagnostic(
        code(sinuprep::read),
        help("check that the path exists and is readable")
    )]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },

    #[error("{path} is a directory")]
    #[diagnostic(
        code(sinuprep::read),
        help("`rewrite` takes one program file; `check` takes directories")
    )]
    IsDirectory { path: PathBuf },

    #[error("cannot write the output: {0}")]
    #[diagnostic(code(sinuprep::write))]
    Write(#[from] std::io::Error),
}
