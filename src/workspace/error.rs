//! What can be wrong with a program's settings: a file they name that cannot
//! be read, two files whose names differ only in case, `sinuprep.toml`
//! itself, a rule code, a measured value. Each names the file, line and key
//! it comes from.

use std::path::PathBuf;

#[derive(Debug, thiserror::Error, miette::Diagnostic)]
pub enum SettingsError {
    // The cause is `source`, which miette prints below the message.
    #[error("cannot read {path}")]
    #[diagnostic(
        code(sinuprep::read),
        help("check that the path exists and is readable")
    )]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },

    #[error("cannot read {path}, named by `{key}` in {config}")]
    #[diagnostic(
        code(sinuprep::read),
        help("correct `{key}` in {config}: its paths are relative to the file")
    )]
    ReadSetting {
        path: PathBuf,
        key: &'static str,
        config: String,
        source: std::io::Error,
    },

    #[error("{what}: {} and {} differ only in case", first.display(), second.display())]
    #[diagnostic(
        code(sinuprep::case),
        help("the control and Windows hold one file under a name whatever its case, so which of the two a copy there keeps is chance: remove or rename one{hint}")
    )]
    CaseClash {
        what: String,
        first: PathBuf,
        second: PathBuf,
        hint: &'static str,
    },

    #[error("{path}:{line}:{column}: {why}")]
    #[diagnostic(
        code(sinuprep::definitions),
        help("a definition file is read as the control reads it; correct it, or leave it out of `definitions`")
    )]
    Definitions {
        path: PathBuf,
        line: usize,
        column: usize,
        why: String,
    },

    #[error("{path}: the archive cannot be read: {error}")]
    #[diagnostic(
        code(sinuprep::archive),
        help("the archive is damaged or truncated; save it from the control again")
    )]
    Archive {
        path: PathBuf,
        error: crate::archive::ArchiveError,
    },

    #[error("{path}:{line}:{column}: {why}")]
    #[diagnostic(
        code(sinuprep::config),
        help("every key and its type: the Configuration part of docs/guide.md")
    )]
    Config {
        path: PathBuf,
        line: usize,
        column: usize,
        why: String,
    },

    #[error("{origin}: no rule has the code `{code}`{}", did_you_mean.map(|c| format!(" (did you mean `{c}`?)")).unwrap_or_default())]
    #[diagnostic(
        code(sinuprep::code),
        help("`sinuprep rule --all` lists every code; a prefix (`N`, `C6`) selects a family")
    )]
    UnknownCode {
        origin: String,
        code: String,
        did_you_mean: Option<&'static str>,
    },

    #[error("{origin}: the pattern `{pattern}` cannot be read: {why}")]
    #[diagnostic(
        code(sinuprep::pattern),
        help("a pattern is written as a line of a .gitignore: `*.nc`, `old`, `/parts/draft`, `**/probe/*`")
    )]
    Pattern {
        origin: String,
        pattern: String,
        why: String,
    },

    #[error("`--set {text}`: {why}")]
    #[diagnostic(code(sinuprep::set), help("write one NC assignment with a constant value, as `--set R10=0.215` or `--set _OVR[16]=-0.113`"))]
    Set { text: String, why: String },

    #[error("{path}:{line}: {why}")]
    #[diagnostic(code(sinuprep::values), help("a values file holds NC assignments with constant values, one or more per line (`R10=0.215`), and `;` comments"))]
    Values {
        path: PathBuf,
        line: usize,
        why: String,
    },

    #[error("{origin}: {why}")]
    #[diagnostic(
        code(sinuprep::table),
        help("name the rotary table's record (kinematics \"P\", one rotary axis) by its name or number, with --table or `table` in sinuprep.toml")
    )]
    Table { origin: String, why: String },
}

impl SettingsError {
    /// The file the error is in and, where known, its 1-based line and
    /// column: for an editor to show the error on that file. `None` for an
    /// error that names no one file (a flag, two files in a clash).
    pub fn place(&self) -> Option<(&std::path::Path, usize, usize)> {
        match self {
            Self::Config {
                path, line, column, ..
            }
            | Self::Definitions {
                path, line, column, ..
            } => Some((path, *line, *column)),
            Self::Values { path, line, .. } => Some((path, *line, 1)),
            Self::Read { path, .. } | Self::Archive { path, .. } => Some((path, 1, 1)),
            _ => None,
        }
    }
}
