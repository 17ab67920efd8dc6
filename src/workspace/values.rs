//! Measured values given beside a program: a values file of NC assignments
//! (`R10=0.215`, `;` comments) or `--set` on the command line, read by the
//! project's own parser.

use std::path::Path;

use crate::semantic::env::Env;
use crate::semantic::eval::{evaluate, variable_key};
use crate::semantic::value::Value;
use crate::semantic::Supplied;
use crate::syntax::parse;
use crate::syntax::tree::{LineKind, StatementKind};
use crate::workspace::SettingsError;

/// The assignments of a values file, each told by `path:line`.
pub(crate) fn read_file(
    path: &Path,
    bytes: &[u8],
    supplied: &mut Supplied,
) -> Result<(), SettingsError> {
    let assignments = assignments(bytes).map_err(|(line, why)| SettingsError::Values {
        path: path.to_path_buf(),
        line,
        why,
    })?;
    for (key, value, line) in assignments {
        supplied.insert(key, value, format!("{}:{line}", path.display()));
    }
    Ok(())
}

/// One assignment given as `--set TEXT`.
pub(crate) fn read_set(text: &str, supplied: &mut Supplied) -> Result<(), SettingsError> {
    let refused = |why: String| SettingsError::Set {
        text: text.to_string(),
        why,
    };
    let assignments = assignments(text.as_bytes()).map_err(|(_, why)| refused(why))?;
    if assignments.len() != 1 {
        return Err(refused("give exactly one assignment".into()));
    }
    for (key, value, _) in assignments {
        supplied.insert(key, value, format!("--set {text}"));
    }
    Ok(())
}

/// A supplied value: its variable's key, the value, the line it was given on.
type Assignment = (String, Value, usize);

/// Constant assignments, or the first line that is not one and why.
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
