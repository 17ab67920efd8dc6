//! Failures of the tool itself (exit status 2), as opposed to findings in
//! the programs it reads.

use std::path::{Path, PathBuf};

use crate::cli::render::printable;

/// A path in a message, its control characters escaped.
fn shown(path: &Path) -> String {
    printable(&path.display().to_string()).into_owned()
}

#[derive(Debug, thiserror::Error, miette::Diagnostic)]
pub enum CliError {
    // The cause is `source`, which miette prints below the message.
    #[error("cannot read {}", shown(path))]
    #[diagnostic(
        code(sinuprep::read),
        help("check that the path exists and is readable")
    )]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },

    #[error("{} holds no program{why}", shown(path))]
    #[diagnostic(code(sinuprep::no_programs), help("{help}"))]
    NoPrograms {
        path: PathBuf,
        /// What the walk left out, from `; left out: `.
        why: String,
        help: String,
    },

    #[error("{}: a binary file (NUL bytes), not a program", shown(path))]
    #[diagnostic(
        code(sinuprep::binary),
        help("name a program (.mpf, .spf, an archive); a walk skips binary files with a note")
    )]
    Binary { path: PathBuf },

    #[error("{}: a UTF-16 text (its first bytes are a UTF-16 byte order mark), which the control does not read", shown(path))]
    #[diagnostic(
        code(sinuprep::utf16),
        help("save it as 8-bit text (ISO 8859-1 or UTF-8), as `iconv -f UTF-16 -t ISO-8859-1 PART.MPF > PART_8BIT.MPF`")
    )]
    Utf16 { path: PathBuf },

    #[error("the language server stopped: {0}")]
    #[diagnostic(
        code(sinuprep::lsp),
        help("`sinuprep lsp` speaks the Language Server Protocol on stdin and stdout; start it from an editor")
    )]
    Server(String),

    #[error("more than one program to rewrite ({named}), and only one standard output")]
    #[diagnostic(
        code(sinuprep::usage),
        help("give --in-place, -o DIR (the tree is mirrored there), --check or --diff")
    )]
    SeveralToStdout {
        /// What was named: `3 paths`, `the folder CAM`.
        named: String,
    },

    #[error("{}: the archive cannot be read: {error}", printable(name))]
    #[diagnostic(
        code(sinuprep::archive),
        help("the archive is damaged or truncated; save it from the control again. Nothing was written")
    )]
    Archive {
        name: String,
        error: crate::archive::ArchiveError,
    },

    #[error("{} is a directory", shown(path))]
    #[diagnostic(
        code(sinuprep::read),
        help(
            "give the directory's programs, or the directory to a command that takes directories"
        )
    )]
    IsDirectory { path: PathBuf },

    #[error("no machine file: give --machine FILE or `machine = \"...\"` in sinuprep.toml")]
    #[diagnostic(code(sinuprep::machine), help("a machine file holds the swivel data records as the control does: `$TC_CARRn[m]=value` (samples/MACHINE.SPF)"))]
    NoMachine,

    #[error("{path}: {why}")]
    #[diagnostic(
        code(sinuprep::machine),
        help("`sinuprep axes --record NAME` names one by `$TC_CARR34` or number")
    )]
    Record { path: PathBuf, why: String },

    #[error("{0}")]
    #[diagnostic(
        code(sinuprep::form),
        help("`sinuprep convert --help` lists what each form takes")
    )]
    Form(String),

    #[error("{}: {why}", shown(path))]
    #[diagnostic(
        code(sinuprep::a3200),
        help("an A3200 setup is `ROTATION n InputAxes x y z OutputAxes X Y Z`, `ROTATION n ANGLE A 1, 0` and `ROTATION n Displacement 10, 0, -15` lines, one ROTATION per rotary axis from the part outward")
    )]
    A3200 { path: PathBuf, why: String },

    #[error("`--mode {0}` is no axis-by-axis rotation of CYCLE800")]
    #[diagnostic(code(sinuprep::mode), help("give the sequence code of three rotations about the turned axes: 57 (X, Y', Z''), 45 (X, Z', Y''), 54 (Y, X', Z''), 30 (Y, Z', X''), 39 (Z, X', Y''), 27 (Z, Y', X''); the solid-angle, projection and direct modes are not computed"))]
    Mode(i64),

    #[error("{argument}: {why}")]
    #[diagnostic(code(sinuprep::measure), help("{help}"))]
    Measure {
        argument: &'static str,
        why: String,
        help: String,
    },

    #[error("no rule has the code or name `{code}`")]
    #[diagnostic(code(sinuprep::rule), help("{}`sinuprep rule --all` lists every rule", nearest.map(|n| format!("did you mean `{n}`? ")).unwrap_or_default()))]
    UnknownRule {
        code: String,
        nearest: Option<&'static str>,
    },

    #[error("sinuprep has no command `{command}`")]
    #[diagnostic(code(sinuprep::usage), help("the commands: {commands}"))]
    UnknownCommand { command: String, commands: String },

    #[error("no angles given, and stdin is a terminal")]
    #[diagnostic(code(sinuprep::angles), help("give three angles, as `sinuprep convert 30 45 60 --from e:XYZ --to i:ZXY`, or pipe one triple per line into stdin"))]
    NoAngles,

    #[error("no program given, and stdin is a terminal")]
    #[diagnostic(code(sinuprep::program), help("name the program, as `sinuprep {command} PART.MPF`, or pipe it in: `sinuprep {command} - < PART.MPF`"))]
    NoProgram { command: &'static str },

    #[error("stdin:{line}:{column}: {why}")]
    #[diagnostic(code(sinuprep::angles), help("give one triple of angles in degrees per line, separated by blanks or commas, as `30 45 -16.28`; empty lines and `#` comments are skipped"))]
    Angles {
        line: usize,
        column: usize,
        why: String,
    },

    #[error("{path} cannot be rewritten in place: {why}")]
    #[diagnostic(
        code(sinuprep::in_place),
        help("--in-place replaces a regular file; to rewrite a stream, give -o FILE or read the output from stdout")
    )]
    NotInPlace { path: PathBuf, why: String },

    #[error("{path} is not rewritten: its backup's name, with `.bak`, is longer than the file system allows")]
    #[diagnostic(
        code(sinuprep::backup_name),
        help("give --no-backup, or give the program a shorter name")
    )]
    BackupNameTooLong { path: PathBuf },

    #[error("{path} is not written: {why}")]
    #[diagnostic(
        code(sinuprep::output_link),
        help("an output folder's files are written only into folders of its own: remove the link, or give another folder to -o")
    )]
    OutputThroughLink { path: PathBuf, why: String },

    #[error("cannot write {path}")]
    #[diagnostic(code(sinuprep::write), help("check that the directory is writable and the disk not full; the original file is unchanged"))]
    WriteFile {
        path: PathBuf,
        source: std::io::Error,
    },

    #[error(transparent)]
    #[diagnostic(transparent)]
    Settings(#[from] crate::workspace::SettingsError),

    #[error("cannot write the output")]
    #[diagnostic(code(sinuprep::write))]
    Write(#[from] std::io::Error),
}

impl CliError {
    /// The archive `name` that cannot be read.
    pub fn archive(name: &str, error: crate::archive::ArchiveError) -> Self {
        CliError::Archive {
            name: name.to_string(),
            error,
        }
    }
}
