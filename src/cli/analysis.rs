//! What `check`, `rewrite` and `eval` share: measured values from the user,
//! HEAD_DEF and settings from sinuprep.toml, handed to the library's
//! [`Document`].

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use crate::cli::args::{AnalysisArgs, InputArgs, MessageFormat};
use crate::cli::config::Config;
use crate::cli::error::CliError;
use crate::cli::input::SourceFile;
use crate::cli::render::{human, short, FileReport};
use crate::document::{Document, Rewritten};
use crate::emit::cycle600::Options;
use crate::lint::Settings;
use crate::semantic::env::Env;
use crate::semantic::eval::{evaluate, variable_key};
use crate::semantic::value::Value;
use crate::semantic::{Heads, Supplied};
use crate::syntax::parse;
use crate::syntax::tree::{LineKind, StatementKind};

/// Measured values and accessory definitions for one program, from the
/// command line first and sinuprep.toml second.
pub struct Inputs {
    pub supplied: Supplied,
    pub heads: Option<Heads>,
}

impl Inputs {
    pub fn load(args: &InputArgs, config: &Config, program: &Path) -> Result<Inputs, CliError> {
        let mut supplied = Supplied::default();
        // A path the command line gives, or the one sinuprep.toml gives under `key`.
        let setting =
            |given: &Option<PathBuf>, file: &Option<PathBuf>, key: &'static str| match given {
                Some(path) => Some((path.clone(), None)),
                None => file.as_ref().map(|p| (config.resolve(p), Some(key))),
            };
        let read = |path: &Path, key: Option<&'static str>| {
            std::fs::read(path).map_err(|source| match key {
                Some(key) => CliError::ReadSetting {
                    path: path.to_path_buf(),
                    key,
                    config: config.describe(),
                    source,
                },
                None => CliError::Read {
                    path: path.to_path_buf(),
                    source,
                },
            })
        };
        if let Some((path, key)) = &setting(&args.values, &config.values, "values") {
            let bytes = read(path, *key)?;
            let assignments = assignments(&bytes).map_err(|(line, why)| CliError::Values {
                path: path.clone(),
                line,
                why,
            })?;
            for (key, value, line) in assignments {
                supplied.insert(key, value, format!("{}:{line}", path.display()));
            }
        }
        for text in &args.set {
            let assignments = assignments(text.as_bytes()).map_err(|(_, why)| CliError::Set {
                text: text.clone(),
                why,
            })?;
            if assignments.len() != 1 {
                return Err(CliError::Set {
                    text: text.clone(),
                    why: "give exactly one assignment".into(),
                });
            }
            for (key, value, _) in assignments {
                supplied.insert(key, value, format!("--set {text}"));
            }
        }
        let heads_path = setting(&args.heads, &config.heads, "heads")
            .or_else(|| beside(program).map(|path| (path, None)));
        let heads = match heads_path {
            Some((path, key)) => {
                let bytes = read(&path, key)?;
                Some(Heads::read(path.display().to_string(), &bytes))
            }
            None => None,
        };
        Ok(Inputs { supplied, heads })
    }
}

/// The rewrite's options: the command line, then sinuprep.toml, then defaults.
pub fn options(args: &AnalysisArgs, config: &Config) -> Options {
    let runtime = if args.emit_runtime || args.runtime_r.is_some() {
        Some(args.runtime_r)
    } else if config.emit_runtime == Some(true) || config.runtime_r.is_some() {
        Some(config.runtime_r)
    } else {
        None
    };
    Options {
        form: args.emit.or(config.emit).unwrap_or_default(),
        precision: usize::from(args.precision.or(config.precision).unwrap_or(6)),
        runtime,
        ..Options::default()
    }
}

/// A rewrite's diagnostics as text for stderr, in the format asked for.
pub fn report(rewritten: &Rewritten, file: &SourceFile, format: MessageFormat) -> String {
    let report = FileReport {
        name: &file.name,
        source: &file.bytes,
        diagnostics: &rewritten.diagnostics,
    };
    let mut text = String::new();
    match format {
        MessageFormat::Human => human(&report, std::io::stderr().is_terminal(), &mut text),
        MessageFormat::Short => short(&report, &mut text),
    }
    text
}

/// The program rewritten as `options` asks, with the values and HEAD_DEF given.
pub fn run(file: &SourceFile, inputs: Inputs, options: &Options) -> Rewritten {
    let settings = Settings {
        supplied: inputs.supplied,
        heads: inputs.heads,
        ..Settings::default()
    };
    Document::new(&file.name, &file.bytes).rewrite(&settings, options)
}

/// A supplied value: its variable's key, the value, the line it was given on.
type Assignment = (String, Value, usize);

/// Constant assignments read by the project's own parser.
fn assignments(bytes: &[u8]) -> Result<Vec<Assignment>, (usize, String)> {
    let program = parse(bytes);
    if let Some(error) = program.diagnostics.first() {
        let line = program
            .lines
            .iter()
            .position(|l| l.raw.full().end > error.span.start)
            .unwrap_or(0)
            + 1;
        return Err((line, error.message.clone()));
    }
    let env = Env::default();
    let empty = Supplied::default();
    let mut out = Vec::new();
    for (index, line) in program.lines.iter().enumerate() {
        let LineKind::Block(block) = &line.kind else {
            continue;
        };
        for statement in &block.statements {
            let StatementKind::Assign(assign) = &statement.kind else {
                return Err((
                    index + 1,
                    format!(
                        "`{}` is not an assignment",
                        String::from_utf8_lossy(statement.span.of(bytes))
                    ),
                ));
            };
            let scope = env.scope(&empty, index + 1);
            let key = variable_key(bytes, &assign.target, &scope)
                .map_err(|why| (index + 1, why.to_string()))?;
            let value = evaluate(bytes, &assign.value, &scope)
                .map_err(|why| (index + 1, format!("the value must be a constant: {why}")))?;
            out.push((key, value, index + 1));
        }
    }
    Ok(out)
}

/// A HEAD_DEF.SPF (any case) beside the program (in the current directory for stdin).
fn beside(program: &Path) -> Option<PathBuf> {
    let dir = if program == Path::new("-") {
        PathBuf::from(".")
    } else {
        program.parent().map(|p| {
            if p.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                p.to_path_buf()
            }
        })?
    };
    std::fs::read_dir(dir)
        .ok()?
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .find(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.eq_ignore_ascii_case("HEAD_DEF.SPF"))
        })
}
